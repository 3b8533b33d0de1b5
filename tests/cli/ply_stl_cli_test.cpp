// `meshedit convert` to and from PLY and STL: binary by default, text with --ascii, what STL
// cannot keep said on stderr, and `meshedit info` reads the results.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "meshedit/files/files.h"
#include "run.h"

namespace meshedit::test {
namespace {

using Json = nlohmann::json;

Json info_of(const std::filesystem::path& file) {
    const RunResult r = run_meshedit({"info", file.string(), "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return Json::parse(r.out);
}

TEST(CliPlyStl, ConvertOffToPlyAndStlAndBack) {
    TempDir tmp;
    const std::string ball = (repo_root() / "dae/quadball.dae").string();
    RunResult r = run_meshedit({"convert", ball, (tmp / "q.off").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;

    r = run_meshedit({"convert", (tmp / "q.off").string(), (tmp / "q.ply").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("not kept"), std::string::npos) << r.err;
    EXPECT_EQ(read_file(tmp / "q.ply").substr(0, 36), "ply\nformat binary_little_endian 1.0\n");
    Json j = info_of(tmp / "q.ply");
    EXPECT_EQ(j["vertices"], 98);
    EXPECT_EQ(j["faces"], 96);

    r = run_meshedit({"convert", (tmp / "q.off").string(), (tmp / "t.ply").string(), "--ascii"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_file(tmp / "t.ply").substr(0, 21), "ply\nformat ascii 1.0\n");
    // The text and the binary file hold the same doubles: converted back to OFF, the same bytes.
    ASSERT_EQ(
        run_meshedit({"convert", (tmp / "t.ply").string(), (tmp / "t.off").string()}).exit_code, 0);
    ASSERT_EQ(
        run_meshedit({"convert", (tmp / "q.ply").string(), (tmp / "b.off").string()}).exit_code, 0);
    EXPECT_EQ(read_file(tmp / "t.off"), read_file(tmp / "b.off"));
    EXPECT_EQ(read_file(tmp / "t.off"), read_file(tmp / "q.off"));

    r = run_meshedit({"convert", (tmp / "q.off").string(), (tmp / "q.stl").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("q.stl: not kept: 96 polygons (STL stores triangles: each is fanned)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(read_file(tmp / "q.stl").size(), 84u + 50u * 192u);
    r = run_meshedit({"convert", (tmp / "q.off").string(), (tmp / "a.stl").string(), "--ascii"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_file(tmp / "a.stl").substr(0, 15), "solid meshedit\n");

    for (const char* stl : {"q.stl", "a.stl"}) {
        r = run_meshedit({"convert", (tmp / stl).string(), (tmp / "from_stl.off").string()});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.err.find("welded 478 vertices by exact position"), std::string::npos) << r.err;
        j = info_of(tmp / "from_stl.off");
        EXPECT_EQ(j["vertices"], 98);
        EXPECT_EQ(j["faces"], 192);
    }
}

TEST(CliPlyStl, BadFilesAreRefusedWithTheirReason) {
    TempDir tmp;
    {
        std::ofstream(tmp / "short.ply")
            << "ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\n"
               "property float y\nproperty float z\nend_header\n";
    }
    RunResult r = run_meshedit({"info", (tmp / "short.ply").string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("short.ply: the header announces 100 'vertex' records of at least 12 "
                         "bytes, but only 0 bytes of the binary body remain"),
              std::string::npos)
        << r.err;
    r = run_meshedit(
        {"convert", (repo_root() / "dae/cube.dae").string(), (tmp / "out.xyz").string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(".dae, .gltf, .glb, .obj, .off, .ply or .stl"), std::string::npos)
        << r.err;
}

}  // namespace
}  // namespace meshedit::test
