// A repaired load must save and reload as the same mesh, in every format. (Before the
// builder glued slits, a load repaired into 62 edges and 12 boundary loops read back from
// .obj, .dae or .glb as 56 edges and 6 loops: files cannot hold two edges between the same
// two vertices.)

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "io/formats_test_util.h"
#include "meshedit/core/topology.h"
#include "meshedit/io/io.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

// A wildly non-manifold soup over few vertices: triangles, or polygons of 3-5 corners.
PolygonSoup random_soup(std::mt19937& rng, bool triangles_only) {
    const int nv = 3 + static_cast<int>(rng() % 8);
    const int nf = 1 + static_cast<int>(rng() % 14);
    PolygonSoup soup;
    for (int v = 0; v < nv; ++v) {
        soup.positions.push_back({0.5 * v, double(v * v % 7), double(v % 3)});
    }
    for (int f = 0; f < nf; ++f) {
        const int k = triangles_only ? 3 : 3 + static_cast<int>(rng() % 3);
        std::vector<std::uint32_t> corners;
        for (int c = 0; c < k; ++c) {
            corners.push_back(static_cast<std::uint32_t>(rng() % nv));
        }
        soup.add_face_range(corners);
    }
    return soup;
}

::testing::AssertionResult same_mesh(const Mesh& actual, const Mesh& expected) {
    if (actual.n_vertices() != expected.n_vertices() || actual.n_edges() != expected.n_edges() ||
        actual.n_faces() != expected.n_faces() ||
        count_boundary_loops(actual) != count_boundary_loops(expected)) {
        return ::testing::AssertionFailure()
               << "V E F loops " << actual.n_vertices() << " " << actual.n_edges() << " "
               << actual.n_faces() << " " << count_boundary_loops(actual) << ", expected "
               << expected.n_vertices() << " " << expected.n_edges() << " " << expected.n_faces()
               << " " << count_boundary_loops(expected);
    }
    if (test::canonical_faces(actual) != test::canonical_faces(expected)) {
        return ::testing::AssertionFailure() << "same counts, different faces";
    }
    return ::testing::AssertionSuccess();
}

TEST(RepairedRoundTrip, EveryFormatReloadsTheRepairedMesh) {
    test::ScratchDir dir;
    std::mt19937 rng(2024);
    int repaired = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const bool triangles = trial % 2 == 0;
        BuildReport report;
        const Mesh mesh = build_mesh(random_soup(rng, triangles), &report);
        repaired += report.repaired() ? 1 : 0;
        if (mesh.n_faces() == 0) {
            continue;
        }
        // glTF stores triangles: only the triangle soups go there.
        for (const char* ext : {".obj", ".dae", ".glb"}) {
            if (!triangles && std::string(ext) == ".glb") {
                continue;
            }
            const auto file = dir / (std::string("t") += ext);
            write_mesh(mesh, file);
            const LoadedMesh again = read_mesh(file);
            ASSERT_TRUE(same_mesh(again.mesh, mesh)) << "trial " << trial << ", " << ext;
            ASSERT_FALSE(again.repairs.repaired())
                << "trial " << trial << ", " << ext << ": " << again.repairs.summary();
        }
    }
    EXPECT_GT(repaired, 200) << "the soups should need repairs";
}

TEST(RepairedRoundTrip, PillowAndEar) {
    test::ScratchDir dir;
    const Mesh mesh = build_mesh(test::pillow_and_ear_soup());
    for (const char* name : {"p.obj", "p.dae", "p.gltf"}) {
        write_mesh(mesh, dir / name);
        EXPECT_TRUE(same_mesh(read_mesh(dir / name).mesh, mesh)) << name;
    }
}

}  // namespace
}  // namespace meshedit
