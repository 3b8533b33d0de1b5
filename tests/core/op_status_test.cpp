// OpStatus, the one refusal type: literal and composed reasons behave alike, a composed
// reason outlives the text it was made from, and equal texts share one copy.

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/op_status.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"

namespace meshedit {
namespace {

TEST(OpStatus, OkIsEmptyAndTrue) {
    const OpStatus ok = OpStatus::ok();
    EXPECT_TRUE(ok);
    EXPECT_EQ(ok, "");
    EXPECT_EQ(OpStatus::composed(""), "");
    EXPECT_TRUE(OpStatus::composed(""));
    std::ostringstream out;
    out << ok;
    EXPECT_EQ(out.str(), "ok");
}

TEST(OpStatus, AComposedReasonOutlivesItsTextAndIsKeptOnce) {
    OpStatus first = OpStatus::ok();
    {
        std::string text = "cannot subdivide: level " + std::to_string(3) + " is too big";
        first = OpStatus::composed(text);
        text.assign(text.size(), 'x');  // the caller's buffer changes and goes away
    }
    EXPECT_FALSE(first);
    EXPECT_EQ(first, "cannot subdivide: level 3 is too big");
    const OpStatus second = OpStatus::composed("cannot subdivide: level 3 is too big");
    EXPECT_EQ(second.reason().data(), first.reason().data());  // one copy per distinct text
    std::ostringstream out;
    out << second;
    EXPECT_EQ(out.str(), "cannot subdivide: level 3 is too big");
}

// Local predicates and whole-mesh checks answer with the same type and wording.
TEST(OpStatus, LocalAndWholeMeshChecksSpeakAlike) {
    Mesh line = shapes::grid(1, 1);
    const OpStatus local = is_flip_ok(line, Edge(0));
    const OpStatus whole = check_remesh(Mesh(), RemeshOptions{});
    EXPECT_EQ(local.reason().rfind("cannot flip: ", 0), 0u) << local;
    EXPECT_EQ(whole, "cannot remesh: the mesh has no faces");
    SubdivisionPlan plan = plan_loop(line, 40);
    EXPECT_FALSE(plan.ok());
    EXPECT_EQ(plan.status.reason().rfind("cannot subdivide: level ", 0), 0u) << plan.status;
}

}  // namespace
}  // namespace meshedit
