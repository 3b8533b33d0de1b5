// `meshedit simplify` and `meshedit remesh`: the target reached and the file valid; the same
// mesh as the `--ops` verb; refusals (polygons, targets out of range) and bad usage write
// nothing. `--ops smooth:…` last.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "meshedit/core/smoothing.h"
#include "meshedit/core/validate.h"
#include "meshedit/io/io.h"
#include "run.h"
#include "support/mesh_compare.h"

namespace meshedit::test {
namespace {

std::string teapot() {
    return (repo_root() / "dae/teapot.dae").string();
}

TEST(CliSimplify, RatioReachesItsTargetAndMatchesTheOpsVerb) {
    TempDir tmp;
    const RunResult r =
        run_meshedit({"simplify", teapot(), (tmp / "small.dae").string(), "--ratio", "0.1"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Mesh small = read_mesh(tmp / "small.dae").mesh;
    EXPECT_LE(small.n_faces(), 403u);  // round(0.1 × 4032)
    EXPECT_GE(small.n_faces(), 395u);
    EXPECT_FALSE(validate(small));
    const RunResult ops =
        run_meshedit({"convert", teapot(), (tmp / "ops.dae").string(), "--ops", "simplify:0.1"});
    ASSERT_EQ(ops.exit_code, 0) << ops.err;
    EXPECT_EQ(canonical_faces(read_mesh(tmp / "ops.dae").mesh), canonical_faces(small));
}

// --attributes: aware (the default) and blind are the verb's `attributes=`; on the duck
// (texture coordinates with seams) they differ, on the teapot (none) they are the same bits.
TEST(CliSimplify, AttributesAwareOrBlind) {
    TempDir tmp;
    const auto read_file = [](const std::filesystem::path& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    for (const char* mode : {"aware", "blind"}) {
        const RunResult r =
            run_meshedit({"simplify", teapot(), (tmp / (std::string(mode) + ".obj")).string(),
                          "--ratio", "0.1", "--attributes", mode});
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    EXPECT_EQ(read_file(tmp / "aware.obj"), read_file(tmp / "blind.obj"));
    const RunResult bad = run_meshedit({"simplify", teapot(), (tmp / "x.obj").string(), "--ratio",
                                        "0.1", "--attributes", "smart"});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_FALSE(std::filesystem::exists(tmp / "x.obj"));
    const std::filesystem::path duck = "/usr/share/assimp/models/Collada/duck.dae";
    if (!std::filesystem::exists(duck)) {
        GTEST_SKIP() << duck << " missing (assimp-testmodels)";
    }
    for (const char* mode : {"aware", "blind"}) {
        const RunResult r = run_meshedit(
            {"convert", duck.string(), (tmp / (std::string("duck_") + mode + ".obj")).string(),
             "--ops", std::string("triangulate,simplify:0.1:attributes=") + mode});
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    EXPECT_NE(read_file(tmp / "duck_aware.obj"), read_file(tmp / "duck_blind.obj"));
}

TEST(CliSimplify, FacesAndErrorBound) {
    TempDir tmp;
    const RunResult r =
        run_meshedit({"simplify", teapot(), (tmp / "a.obj").string(), "--faces", "1000"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_LE(read_mesh(tmp / "a.obj").mesh.n_faces(), 1000u);
    // A tiny bound stops long before 10 faces, and says so.
    const RunResult bounded = run_meshedit(
        {"simplify", teapot(), (tmp / "b.obj").string(), "--faces", "10", "--max-error", "1e-7"});
    ASSERT_EQ(bounded.exit_code, 0) << bounded.err;
    EXPECT_NE(bounded.err.find(": stopped at "), std::string::npos) << bounded.err;
    EXPECT_NE(bounded.err.find("faces: the next collapse exceeds the error bound 1e-07"),
              std::string::npos)
        << bounded.err;
    EXPECT_GT(read_mesh(tmp / "b.obj").mesh.n_faces(), 1000u);
}

TEST(CliSimplify, RefusalsAndBadUsageWriteNothing) {
    TempDir tmp;
    const std::string out = (tmp / "x.dae").string();
    struct Case {
        std::vector<std::string> args;
        int exit_code;
        std::string message;
    };
    const std::vector<Case> cases = {
        {{"simplify", teapot(), out, "--faces", "0"},
         1,
         "teapot.dae: simplify:0 refused: cannot simplify: the target must be from 1 to 4031 "
         "faces"},
        {{"simplify", teapot(), out, "--faces", "5000"}, 1, "the mesh has 4032"},
        {{"simplify", teapot(), out, "--ratio", "2"},
         2,
         "simplify: --ratio must be above 0 and below 1, not 2"},
        {{"simplify", teapot(), out, "--ratio", "0"}, 2, "--ratio must be above 0"},
        {{"simplify", teapot(), out}, 2, "simplify: give --faces N or --ratio R"},
        {{"simplify", (repo_root() / "dae/quadball.dae").string(), out, "--ratio", "0.5"},
         1,
         "QEM needs triangles and 96 of the 96 faces are polygons"},
        {{"convert", teapot(), out, "--ops", "simplify:1.5"},
         1,
         "keep a share of the faces above 0 and below 1, or a whole number of faces, not 1.5"},
    };
    for (const Case& c : cases) {
        const RunResult r = run_meshedit(c.args);
        EXPECT_EQ(r.exit_code, c.exit_code) << c.args.back() << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out)) << c.message;
    }
}

// Remeshing the teapot to L = 0.15: valid, edges near 0.15 on average, the same mesh as
// `--ops remesh:0.15`; refusals write nothing.
TEST(CliRemesh, LengthReachedAndSameAsTheVerb) {
    TempDir tmp;
    const RunResult r =
        run_meshedit({"remesh", teapot(), (tmp / "even.dae").string(), "--length", "0.15"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Mesh even = read_mesh(tmp / "even.dae").mesh;
    EXPECT_FALSE(validate(even));
    double sum = 0.0;
    for (Edge e : even.edges()) {
        sum += distance(even.position(even.vertex(e, 0)), even.position(even.vertex(e, 1)));
    }
    const double mean = sum / static_cast<double>(even.n_edges());
    EXPECT_GT(mean, 0.12);
    EXPECT_LT(mean, 0.18);
    const RunResult ops =
        run_meshedit({"convert", teapot(), (tmp / "ops.dae").string(), "--ops", "remesh:0.15"});
    ASSERT_EQ(ops.exit_code, 0) << ops.err;
    EXPECT_EQ(canonical_faces(read_mesh(tmp / "ops.dae").mesh), canonical_faces(even));

    const std::string out = (tmp / "x.dae").string();
    for (const auto& [args, message] :
         std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"remesh", teapot(), out, "--iterations", "0"}, "iterations must be a whole number"},
             {{"remesh", teapot(), out, "--length", "0.0001"}, "(at most 100,000,000)"},
             {{"remesh", teapot(), out, "--length", "-1"}, "must be a positive number"},
             {{"remesh", (repo_root() / "dae/quadball.dae").string(), out},
              "remeshing needs triangles"},
         }) {
        const RunResult bad = run_meshedit(args);
        EXPECT_EQ(bad.exit_code, 1) << bad.err;
        EXPECT_NE(bad.err.find(message), std::string::npos) << bad.err;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
}

// `--ops smooth:…` through the CLI: the torus keeps its connectivity, its vertices move, the
// volume option gives the volume back (to what OBJ's shortest round-trip digits keep); a
// refusal (the volume of an open mesh) exits 1 and writes nothing.
TEST(CliSmooth, OpsSmoothMovesPositionsOnly) {
    TempDir tmp;
    const std::string torus = (repo_root() / "dae/torus.dae").string();
    const Mesh input = read_mesh(torus).mesh;
    for (const char* ops : {"smooth:5,0.5", "smooth_cotan:5,0.5,1", "taubin",
                            "smooth_implicit:1,2,1", "fair:f10..40"}) {
        const std::string out = (tmp / "smooth.obj").string();
        const RunResult r = run_meshedit({"convert", torus, out, "--ops", ops});
        ASSERT_EQ(r.exit_code, 0) << ops << ": " << r.err;
        const Mesh smoothed = read_mesh(out).mesh;
        EXPECT_FALSE(validate(smoothed)) << ops;
        EXPECT_EQ(canonical_faces(smoothed), canonical_faces(input)) << ops;
        EXPECT_FALSE(same_faces_by_position(smoothed, input, 1e-6)) << ops;
        if (std::string(ops).ends_with(",1")) {
            EXPECT_NEAR(enclosed_volume(smoothed) / enclosed_volume(input), 1.0, 1e-9) << ops;
        }
    }
    const std::string out = (tmp / "x.obj").string();
    const RunResult bad = run_meshedit({"convert", teapot(), out, "--ops", "smooth:5,0.5,1"});
    EXPECT_EQ(bad.exit_code, 1) << bad.err;
    EXPECT_NE(bad.err.find("smooth:5,0.5,1 refused: cannot smooth: keeping the volume needs a "
                           "closed mesh"),
              std::string::npos)
        << bad.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace meshedit::test
