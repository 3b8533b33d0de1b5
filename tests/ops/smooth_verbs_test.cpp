// The smoothing verbs and fair through the edit language: each step runs the core function
// with the amounts written, says the volume change, and a refused step leaves the mesh bit
// for bit.

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

#include "meshedit/core/shapes.h"
#include "meshedit/core/smoothing.h"
#include "meshedit/ops/ops.h"
#include "support/mesh_compare.h"

namespace meshedit::ops {
namespace {

std::string refusal(Mesh& mesh, const std::string& text) {
    const Mesh before = mesh;
    try {
        run_step(mesh, parse_step(text));
    } catch (const OpError& e) {
        const auto& a = mesh.position_vector();
        const auto& b = before.position_vector();
        // memcmp of an empty mesh's null data is undefined (UBSan says so): nothing to compare.
        EXPECT_TRUE(a.size() == b.size() &&
                    (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0))
            << text;
        EXPECT_EQ(test::canonical_faces(mesh), test::canonical_faces(before)) << text;
        return e.what();
    }
    ADD_FAILURE() << text << " ran";
    return {};
}

TEST(SmoothVerbs, EachVerbRunsItsMethodAndSaysTheVolumeChange) {
    const Mesh sphere = shapes::icosphere(3);
    Mesh by_verb = sphere, by_core = sphere;
    const StepResult result = run_step(by_verb, parse_step("smooth:10,0.5"));
    SmoothOptions options;  // the defaults: uniform, 10 steps of 0.5
    const SmoothReport report = smooth(by_core, options);
    EXPECT_TRUE(test::identical(by_verb, by_core));
    const double percent = (report.volume_after / report.volume_before - 1.0) * 100.0;
    char expected[64];
    std::snprintf(expected, sizeof expected, "smoothed 10 iterations: volume −%.3g %%", -percent);
    EXPECT_EQ(result.message, expected);
    EXPECT_FALSE(result.renumbers);

    Mesh kept = sphere;
    EXPECT_EQ(run_step(kept, parse_step("smooth_cotan:5,0.5,1")).message,
              "smoothed 5 iterations: volume unchanged");
    EXPECT_NEAR(enclosed_volume(kept) / enclosed_volume(sphere), 1.0, 1e-9);
    Mesh taubin = sphere;
    EXPECT_EQ(run_step(taubin, parse_step("taubin"))
                  .message.rfind("Taubin-smoothed 10 iterations: volume ", 0),
              0u);
    Mesh implicit = sphere;
    EXPECT_EQ(run_step(implicit, parse_step("smooth_implicit:2,3"))
                  .message.rfind("smoothed implicitly (t = 2, 3 steps, solved in ", 0),
              0u);
    Mesh open = shapes::grid(6, 6);
    open.position(Vertex(24)).z = 1.0;
    EXPECT_EQ(run_step(open, parse_step("smooth:1,0.5")).message,
              "smoothed 1 iteration: largest move 0.5");
    EXPECT_VALID(open);
}

TEST(SmoothVerbs, FairFlattensTheRegionItNames) {
    Mesh mesh = shapes::grid(6, 6);
    mesh.position(Vertex(24)).z = 0.7;  // (3, 3), inside the faces of cells (2..3, 2..3)
    const StepResult result = run_step(mesh, parse_step("fair:f28..31+f40..43"));
    EXPECT_EQ(result.message.rfind("faired 1 inner vertices of 8 faces (border fixed)", 0), 0u)
        << result.message;
    EXPECT_NEAR(mesh.position(Vertex(24)).z, 0.0, 1e-12);
    EXPECT_VALID(mesh);
}

// smooth_region moves only the inner vertices of the faces it names: the bump inside the
// region halves in one step of 0.5 (its grid neighbours are flat), a bump outside and the
// region's border stay bit for bit; over every face of a closed mesh it is smooth exactly.
TEST(SmoothVerbs, SmoothRegionMovesOnlyItsInnerVertices) {
    Mesh mesh = shapes::grid(6, 6);
    mesh.position(Vertex(24)).z = 0.7;  // inside the faces of cells (2..3, 2..3)
    mesh.position(Vertex(10)).z = 0.3;  // outside them
    const Mesh before = mesh;
    const StepResult result = run_step(mesh, parse_step("smooth_region:f28..31+f40..43:1,0.5"));
    EXPECT_EQ(result.message,
              "smoothed 1 iteration of 1 inner vertex of 8 faces (border fixed): largest move "
              "0.35");
    EXPECT_EQ(mesh.position(Vertex(24)).z, 0.35);
    for (const Vertex v : mesh.vertices()) {
        if (v != Vertex(24)) {
            EXPECT_EQ(mesh.position(v), before.position(v)) << v.idx();
        }
    }
    EXPECT_EQ(result.selected, ElementRef::face(Face(28)));
    EXPECT_EQ(result.selected_too.size(), 7u);
    EXPECT_VALID(mesh);

    const Mesh sphere = shapes::icosphere(2);
    Mesh region = sphere, whole = sphere;
    const StepResult all = run_step(region, parse_step("smooth_region:f0..319"));
    run_step(whole, parse_step("smooth"));
    EXPECT_TRUE(test::identical(region, whole));
    EXPECT_EQ(all.message.rfind("smoothed 10 iterations of 162 inner vertices of 320 faces "
                                "(border fixed): volume −",
                                0),
              0u)
        << all.message;
}

TEST(SmoothVerbs, RefusalsNameTheirReasonAndLeaveTheMesh) {
    Mesh sphere = shapes::icosphere(2);
    EXPECT_NE(
        refusal(sphere, "smooth:0").find("iterations must be a whole number from 1 to 1000, not 0"),
        std::string::npos);
    EXPECT_NE(refusal(sphere, "smooth:2.5").find("iterations must be a whole number"),
              std::string::npos);
    EXPECT_NE(refusal(sphere, "smooth:5,0.5,2").find("keep the volume is 1 (yes) or 0 (no), not 2"),
              std::string::npos);
    EXPECT_NE(refusal(sphere, "taubin:5,0.5,-0.3").find("μ must be below"), std::string::npos);
    EXPECT_NE(refusal(sphere, "smooth_implicit:-1").find("time step t must be above 0"),
              std::string::npos);
    EXPECT_NE(refusal(sphere, "fair:f0..319").find("covers a whole closed part"),
              std::string::npos);
    EXPECT_NE(refusal(sphere, "fair:f3").find("no inner vertex"), std::string::npos);
    EXPECT_NE(refusal(sphere, "smooth_region:f3")
                  .find("cannot smooth: every vertex of the 1 face is on their border"),
              std::string::npos);
    EXPECT_NE(refusal(sphere, "smooth_region:f0..319:0").find("iterations must be a whole number"),
              std::string::npos);
    Mesh open = shapes::grid(4, 4);
    EXPECT_NE(refusal(open, "smooth:5,0.5,1").find("needs a closed mesh"), std::string::npos);
    Mesh quads = shapes::quad_grid(4, 4);
    EXPECT_NE(refusal(quads, "smooth_cotan").find("cotangent weights need triangles"),
              std::string::npos);
    Mesh nan = shapes::icosphere(1);
    nan.position(Vertex(2)).z = std::numeric_limits<double>::quiet_NaN();
    // fair reads only the region and two rings around it: here the region is every face, so
    // the NaN is among what it reads (a NaN far away does not stop it: Fair.* tests).
    for (const char* step : {"smooth", "smooth_cotan", "taubin", "smooth_implicit", "fair:f0..79",
                             "smooth_region:f0..79"}) {
        EXPECT_NE(refusal(nan, step).find("not a finite number"), std::string::npos) << step;
    }
    Mesh empty;
    EXPECT_NE(refusal(empty, "smooth").find("the mesh has no faces"), std::string::npos);
}

}  // namespace
}  // namespace meshedit::ops
