// `meshedit repair`: a broken OBJ written here (unwelded, one triangle flipped, a duplicate, a
// floating triangle) comes out whole with its texture coordinates, each repair said in one
// line; repairing the output again says nothing; bad usage and a repair that would leave no
// face write nothing.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "meshedit/core/attributes.h"
#include "meshedit/io/io.h"
#include "run.h"
#include "support/mesh_compare.h"

namespace meshedit::test {
namespace {

// Two triangles of a unit square with their own corners (the second wound backwards), the
// first again, and a small triangle far away; each position has its own texture coordinate.
const char* const kBrokenObj =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 0 1 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n"
    "v 5 5 5\n"
    "v 5.1 5 5\n"
    "v 5 5.1 5\n"
    "vt 0 0\n"
    "vt 1 0\n"
    "vt 0 1\n"
    "vt 1 1\n"
    "f 1/1 2/2 3/3\n"
    "f 4/2 6/3 5/4\n"
    "f 1/1 2/2 3/3\n"
    "f 7/1 8/2 9/3\n";

std::filesystem::path write_broken(const TempDir& tmp) {
    const std::filesystem::path in = tmp / "broken.obj";
    std::ofstream(in) << kBrokenObj;
    return in;
}

TEST(CliRepair, ABrokenObjComesOutWholeWithItsTextureCoordinates) {
    TempDir tmp;
    const std::string in = write_broken(tmp).string();
    const std::string out = (tmp / "whole.obj").string();
    const RunResult r = run_meshedit({"repair", in, out, "--min-component-faces", "2"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    const std::vector<std::string> lines = split_lines(r.err);
    ASSERT_EQ(lines.size(), 4u) << r.err;
    const std::string prefix = "meshedit: " + in + ": ";
    EXPECT_EQ(lines[0].rfind(prefix + "merged 2 vertices into others within ", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find("(1e-06 of the bounding-box diagonal), 9 → 7 vertices: 3, 5"),
              std::string::npos)
        << lines[0];
    EXPECT_EQ(lines[1],
              prefix + "removed 1 duplicate face (the same vertices as an earlier face): 2");
    EXPECT_EQ(lines[2], prefix + "turned over 1 face to agree with its neighbours: 1");
    EXPECT_EQ(lines[3], prefix +
                            "removed 1 component of fewer than 2 faces (1 face in all; the first "
                            "face of each: 2); removed 3 vertices only they used");

    const LoadedMesh whole = read_mesh(out);
    ASSERT_VALID(whole.mesh);
    EXPECT_FALSE(whole.repairs.repaired());
    EXPECT_EQ(whole.mesh.n_vertices(), 4u);
    EXPECT_EQ(whole.mesh.n_faces(), 2u);
    EXPECT_EQ(whole.mesh.n_edges(), 5u);
    // Every face corner has the texture coordinate its position had in the file.
    const std::map<std::tuple<double, double>, Vec2> uv_at{
        {{0, 0}, {0, 0}}, {{1, 0}, {1, 0}}, {{0, 1}, {0, 1}}, {{1, 1}, {1, 1}}};
    const auto uv = whole.mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    ASSERT_TRUE(uv);
    for (const Halfedge h : whole.mesh.halfedges()) {
        if (!whole.mesh.is_boundary(h)) {
            const Vec3& p = whole.mesh.position(whole.mesh.to_vertex(h));
            EXPECT_EQ(uv[h], uv_at.at({p.x, p.y}));
        }
    }

    // Repairing the repaired file says nothing and changes nothing.
    const std::string again = (tmp / "again.obj").string();
    const RunResult r2 = run_meshedit({"repair", out, again, "--min-component-faces", "2"});
    ASSERT_EQ(r2.exit_code, 0) << r2.err;
    EXPECT_TRUE(r2.err.empty()) << r2.err;
    EXPECT_EQ(canonical_faces(read_mesh(again).mesh), canonical_faces(whole.mesh));
}

TEST(CliRepair, QuietSaysNothingAndNotesWhatTheOutputCannotKeep) {
    TempDir tmp;
    const std::string in = write_broken(tmp).string();
    const RunResult quiet = run_meshedit({"repair", in, (tmp / "q.obj").string(), "--quiet"});
    ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
    EXPECT_TRUE(quiet.err.empty()) << quiet.err;
    // STL has no texture coordinates: said as convert says it.
    const std::string stl = (tmp / "q.stl").string();
    const RunResult r = run_meshedit({"repair", in, stl, "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // (5.1 is no float either: a second note says so.)
    const std::vector<std::string> lines = split_lines(r.err);
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines[0], "meshedit: note: " + stl +
                            ": not kept: texture coordinates (STL has none; COLLADA, glTF, "
                            "OBJ, OFF and PLY keep them)");
    for (const std::string& line : lines) {
        EXPECT_EQ(line.rfind("meshedit: note: " + stl + ": not kept: ", 0), 0u) << line;
    }
}

TEST(CliRepair, BadUsageAndRefusalsWriteNothing) {
    TempDir tmp;
    const std::string in = write_broken(tmp).string();
    TempDir out_dir;
    const std::string out = (out_dir / "out.obj").string();
    const struct {
        std::vector<std::string> args;
        int status;
        std::string message;
    } cases[] = {
        {{"repair", in, out, "--merge-distance", "-1"},
         2,
         "meshedit: repair: --merge-distance must be a finite number of at least 0, not -1"},
        {{"repair", in, out, "--merge-relative", "nan"},
         2,
         "meshedit: repair: --merge-relative must be a finite number of at least 0, not nan"},
        {{"repair", in, out, "--min-component-faces", "-3"},
         2,
         "meshedit: repair: --min-component-faces must be a whole number from 0 to 4294967295, "
         "not -3"},
        {{"repair", in, out, "--no-merge", "--merge-distance", "1"}, 2, "excludes"},
        {{"repair", (tmp / "missing.obj").string(), out}, 2, "missing.obj: no such file"},
        {{"repair", (repo_root() / "bez/teapot.bez").string(), out}, 2, "not a mesh"},
        {{"repair", in, (out_dir / "out.xyz").string()}, 2, "unknown extension '.xyz'"},
        {{"repair", in}, 2, "OUT"},
        // A merge distance larger than the mesh merges every corner of every face.
        {{"repair", in, out, "--merge-relative", "2"},
         1,
         "broken.obj: repair refused: no face of 4 would be left"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.args.back());
        const RunResult r = run_meshedit(c.args);
        EXPECT_EQ(r.exit_code, c.status) << r.err;
        const std::vector<std::string> lines = split_lines(r.err);
        ASSERT_EQ(lines.size(), 1u) << r.err;
        EXPECT_NE(lines[0].find(c.message), std::string::npos) << lines[0];
        EXPECT_TRUE(out_dir.entries().empty()) << out_dir.entries().front();
    }
}

TEST(CliRepair, FillsSmallHolesWhenAsked) {
    // An open box: five quads of the unit cube.
    TempDir tmp;
    const std::filesystem::path in = tmp / "box.off";
    std::ofstream(in) << "OFF\n8 5 0\n"
                         "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                         "4 0 3 2 1\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
    const std::string out = (tmp / "closed.off").string();
    const RunResult r = run_meshedit({"repair", in.string(), out, "--fill-holes", "4"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "meshedit: " + in.string() +
                         ": filled 1 hole of at most 4 edges (4 edges in all; a vertex of each: "
                         "4)\n");
    const LoadedMesh closed = read_mesh(out);
    ASSERT_VALID(closed.mesh);
    EXPECT_EQ(closed.mesh.n_faces(), 6u);
    for (const Halfedge h : closed.mesh.halfedges()) {
        EXPECT_FALSE(closed.mesh.is_boundary(h));
    }
}

// The `repair` verb of the edit language makes the mesh `meshedit repair` makes, on the
// broken OBJ and on assimp's spider (a soup with 4 faces wound against their neighbours):
// `meshedit compare` finds them the same up to renumbering.
TEST(CliRepair, TheRepairVerbMakesWhatTheCommandMakes) {
    TempDir tmp;
    std::vector<std::string> inputs{write_broken(tmp).string()};
    const std::string spider = "/usr/share/assimp/models/STL/Spider_binary.stl";
    if (std::filesystem::exists(spider)) {
        inputs.push_back(spider);
    }
    for (const std::string& in : inputs) {
        const std::string by_command = (tmp / "command.ply").string();
        const std::string by_verb = (tmp / "verb.ply").string();
        const RunResult a = run_meshedit({"repair", in, by_command});
        ASSERT_EQ(a.exit_code, 0) << a.err;
        const RunResult b = run_meshedit({"convert", in, by_verb, "--ops", "repair"});
        ASSERT_EQ(b.exit_code, 0) << b.err;
        const RunResult same = run_meshedit({"compare", by_command, by_verb});
        EXPECT_EQ(same.exit_code, 0) << in << "\n" << same.out << same.err;
        ASSERT_VALID(read_mesh(by_verb).mesh);
    }
}

}  // namespace
}  // namespace meshedit::test

namespace meshedit::test {
namespace {

// `check --problems`: the broken OBJ's problems one line each and as JSON, exit 1; after
// `repair` only the floating triangle's hole and part are left (exit 1), and a closed cube
// has none (exit 0).
TEST(CliCheckProblems, NamesEachProblemAndItsPlace) {
    TempDir tmp;
    const std::string in = write_broken(tmp).string();
    RunResult r = run_meshedit({"check", in, "--problems"});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    const std::vector<std::string> lines = split_lines(r.out);
    ASSERT_FALSE(lines.empty());
    EXPECT_NE(r.out.find(in + ": hole: hole of "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(in + ": small part: part of 1 face at face "), std::string::npos) << r.out;
    EXPECT_EQ(lines.back().rfind(in + ": ", 0), 0u);

    r = run_meshedit({"check", in, "--problems", "--json"});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j["valid"].get<bool>());
    EXPECT_GT(j["counts"]["hole"].get<int>(), 0);
    EXPECT_EQ(j["counts"]["self-intersection"].get<int>(), 0);
    ASSERT_FALSE(j["problems"].empty());
    EXPECT_FALSE(j["problems"][0]["element"].get<std::string>().empty());

    const std::string cube = (tmp / "cube.obj").string();
    std::ofstream(cube) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\n"
                           "v 0 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\n"
                           "f 4 1 5 8\n";
    r = run_meshedit({"check", cube, "--problems"});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.out, cube + ": no problems\n");

    r = run_meshedit({"check", cube, "--json"});
    EXPECT_EQ(r.exit_code, 2) << "--json needs --problems";
}

}  // namespace
}  // namespace meshedit::test
