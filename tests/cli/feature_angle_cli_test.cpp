// Sharp edges found by angle from the command line: `--ops crease_by_angle:D`, and
// `--feature-angle DEG` of `meshedit remesh` and `meshedit simplify`, which keeps the sharp
// edges of a file without crease marks (CGAL's fandisk.off) where they were.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "meshedit/core/attributes.h"
#include "meshedit/core/closest_point.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/validate.h"
#include "meshedit/io/io.h"
#include "run.h"
#include "support/demo_meshes.h"
#include "support/fixtures.h"

namespace meshedit::test {
namespace {

std::filesystem::path fandisk() {
    return demo_mesh("fandisk", std::filesystem::path(MESHEDIT_BUILD_DIR) / "demo_data");
}

TEST(CliFeatureAngle, CreaseByAngleMarksTheCubesEdges) {
    TempDir tmp;
    write_mesh(shapes::cube(), tmp / "cube.obj");
    const RunResult r = run_meshedit({"convert", (tmp / "cube.obj").string(),
                                      (tmp / "sharp.dae").string(), "--ops", "crease_by_angle:60"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Mesh sharp = read_mesh(tmp / "sharp.dae").mesh;  // COLLADA keeps crease marks
    EXPECT_EQ(crease_count(sharp), 12u);
    EXPECT_FALSE(validate(sharp));
    const RunResult none =
        run_meshedit({"convert", (tmp / "cube.obj").string(), (tmp / "none.dae").string(), "--ops",
                      "crease_by_angle:100"});
    ASSERT_EQ(none.exit_code, 0) << none.err;
    EXPECT_EQ(crease_count(read_mesh(tmp / "none.dae").mesh), 0u);
}

TEST(CliFeatureAngle, BadAnglesAreRefusedAndWriteNothing) {
    TempDir tmp;
    write_mesh(shapes::cube(), tmp / "cube.obj");
    const std::string in = (tmp / "cube.obj").string(), out = (tmp / "out.dae").string();
    const std::string why = "the angle must be from 0 to 180 degrees, not ";
    for (const auto& [args, message] :
         std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"convert", in, out, "--ops", "crease_by_angle:-1"}, why + "-1"},
             {{"convert", in, out, "--ops", "crease_by_angle:nan"}, why + "nan"},
             {{"remesh", in, out, "--feature-angle", "181"},
              "cannot remesh: the feature angle must be from 0 to 180 degrees (infinity: off), "
              "not 181"},
             {{"simplify", in, out, "--ratio", "0.5", "--feature-angle", "-3"},
              "cannot simplify: the feature angle must be from 0 to 180 degrees (infinity: off), "
              "not -3"}}) {
        const RunResult r = run_meshedit(args);
        EXPECT_EQ(r.exit_code, 1) << args[0] << " " << args.back() << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << args.back();
    }
}

// The triangulated cube remeshed and simplified with --feature-angle, written as COLLADA
// (which keeps the marks): still a cube, its crease vertices on its edges.
TEST(CliFeatureAngle, RemeshAndSimplifyKeepTheCube) {
    TempDir tmp;
    write_mesh(shapes::cube(), tmp / "cube.obj");
    const RunResult r =
        run_meshedit({"remesh", (tmp / "cube.obj").string(), (tmp / "fine.dae").string(),
                      "--length", "0.25", "--feature-angle", "60"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Mesh fine = read_mesh(tmp / "fine.dae").mesh;
    EXPECT_FALSE(validate(fine));
    EXPECT_GT(crease_count(fine), 12u * 6u);
    const RunResult s =
        run_meshedit({"simplify", (tmp / "fine.dae").string(), (tmp / "coarse.dae").string(),
                      "--ratio", "0.2", "--feature-angle", "60"});
    ASSERT_EQ(s.exit_code, 0) << s.err;
    for (const Mesh& mesh : {fine, read_mesh(tmp / "coarse.dae").mesh}) {
        const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
        ASSERT_TRUE(crease);
        for (Vertex v : mesh.vertices()) {
            const Vec3& p = mesh.position(v);
            int sides = 0;
            for (double c : {p.x, p.y, p.z}) {
                sides += std::abs(std::abs(c) - 1.0) < 1e-9;
            }
            EXPECT_GE(sides, 1) << "vertex " << v.idx() << " left the cube";
            int crease_edges = 0;
            for (Edge e : mesh.edges(v)) {
                crease_edges += crease[e] != 0;
            }
            if (crease_edges >= 2) {
                EXPECT_GE(sides, 2) << "crease vertex " << v.idx() << " left the cube's edges";
            }
        }
    }
}

// How far the surface of `out` is from the input's sharp edges (those above 40 degrees): the
// largest distance from a vertex on them to `out`, over the bounding-box diagonal.
double sharp_edge_drift(const Mesh& input, const Mesh& out) {
    Mesh marked = input;
    crease_by_angle(marked, 40.0);
    const auto crease = marked.get_property<Edge, std::uint8_t>(kCreaseProperty);
    const TriangleTree tree(out);
    double largest = 0.0;
    for (Edge e : marked.edges()) {
        if (crease[e] != 0) {
            for (int end = 0; end < 2; ++end) {
                const Vec3& p = marked.position(marked.vertex(e, end));
                largest = std::max(largest, tree.closest(p).distance_squared);
            }
        }
    }
    return std::sqrt(largest) / input.bounds().diagonal();
}

// Remeshing fandisk.off (an OFF file: no crease marks) rounds every sharp edge off; with
// --feature-angle 40 its sharp edges stay where they were.
TEST(CliFeatureAngle, FandiskKeepsItsSharpEdges) {
    TempDir tmp;
    const std::filesystem::path in = fandisk();
    const Mesh input = read_mesh(in).mesh;
    struct Case {
        std::vector<std::string> args;
        double bound;  // the largest drift allowed with the option, as a share of the diagonal
    };
    for (const Case& c :
         {Case{{"remesh", "--length", "0.02"}, 1e-4}, Case{{"simplify", "--ratio", "0.1"}, 3e-4}}) {
        double drift[2];
        for (int with = 0; with < 2; ++with) {
            std::vector<std::string> args = {c.args[0], in.string(), (tmp / "out.off").string(),
                                             c.args[1], c.args[2]};
            if (with == 1) {
                args.insert(args.end(), {"--feature-angle", "40"});
            }
            const RunResult r = run_meshedit(args, 60.0);
            ASSERT_EQ(r.exit_code, 0) << r.err;
            const Mesh out = read_mesh(tmp / "out.off").mesh;
            EXPECT_FALSE(validate(out));
            drift[with] = sharp_edge_drift(input, out);
        }
        char measured[160];
        std::snprintf(measured, sizeof measured,
                      "%s: the sharp edges drift %.3g of the diagonal without --feature-angle, "
                      "%.3g with it",
                      c.args[0].c_str(), drift[0], drift[1]);
        EXPECT_LT(drift[1], c.bound) << measured;
        EXPECT_GT(drift[0], c.bound) << measured;
        RecordProperty(c.args[0] + "_drift", measured);
        std::printf("%s\n", measured);
    }
}

}  // namespace
}  // namespace meshedit::test
