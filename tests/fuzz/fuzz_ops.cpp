// Fuzz target: the edit language. The input is an --ops list; when it parses, it runs on a
// small closed mesh and a small open one (steps the mesh refuses, or that name elements it
// does not have, stop the list cleanly), and the result must validate.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_common.h"
#include "fuzz_steps.h"
#include "meshedit/core/budget.h"
#include "meshedit/ops/ops.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace meshedit;
    static const bool ready = (fuzz::set_up(), true);
    (void)ready;
    std::vector<ops::Step> steps;
    try {
        steps = ops::parse(std::string_view(reinterpret_cast<const char*>(data), size));
    } catch (const ops::SyntaxError&) {
        return 0;
    }
    fuzz::run_steps_on_two_meshes(steps, "an --ops list left an invalid mesh");
    return 0;
}
