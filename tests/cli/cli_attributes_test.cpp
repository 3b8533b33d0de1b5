// What a mesh carries through the `meshedit` commands (docs/attributes.md): info lists it,
// --strict refuses to drop it, a second texture coordinate set is named, texture paths are
// written relative to the output.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "meshedit/files/files.h"
#include "run.h"

namespace meshedit::test {
namespace {

nlohmann::json info_json(const std::filesystem::path& file) {
    const RunResult r = run_meshedit({"info", file.string(), "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

const std::filesystem::path kAssimp = "/usr/share/assimp/models";

// --strict: what would be dropped is an error, exit 1 and no file; without it a note.
TEST(CliAttributes, StrictRefusesToDropAnything) {
    TempDir tmp;
    const auto creased = (repo_root() / "dae/creased.dae").string();
    const auto out = tmp / "c.obj";
    for (const char* command : {"convert", "subdivide", "simplify", "repair"}) {
        SCOPED_TRACE(command);
        std::vector<std::string> args = {command, creased, out.string(), "--strict"};
        if (std::string(command) == "simplify") {
            args.insert(args.end(), {"--ratio", "0.5"});
        } else if (std::string(command) == "subdivide") {
            args.insert(args.end(), {"-n", "1"});
        }
        const RunResult r = run_meshedit(args);
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_NE(r.err.find("c.obj: not written (--strict): the format cannot keep "),
                  std::string::npos)
            << r.err;
        EXPECT_NE(r.err.find("crease marks (OBJ has no crease edges)"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
    // A format that keeps everything writes as without --strict.
    const RunResult kept = run_meshedit({"convert", creased, (tmp / "c.dae").string(), "--strict"});
    EXPECT_EQ(kept.exit_code, 0) << kept.err;
    EXPECT_TRUE(std::filesystem::exists(tmp / "c.dae"));
}

// info lists what a mesh carries: texture coordinates with their seams, colours, materials.
TEST(CliAttributes, InfoListsAttributesAndMaterials) {
    TempDir tmp;
    std::ofstream(tmp / "q.mtl") << "newmtl red\nKd 1 0 0\nnewmtl wood\nmap_Kd wood.png\n";
    std::ofstream(tmp / "q.obj") << "mtllib q.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                                    "usemtl red\nf 1/1 2/2 3/3\nusemtl wood\nf 1/5 3/3 4/4\n";
    const RunResult r = run_meshedit({"info", (tmp / "q.obj").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("texture coordinates:   per corner, 1 seam edges"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("materials:             2, 1 border edges"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("material 0:            'red' colour 1 0 0"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("material 1:            'wood' texture wood.png (missing)"),
              std::string::npos)
        << r.out;
    const auto j = info_json(tmp / "q.obj")["attributes"];
    EXPECT_EQ(j["texcoords"], true);
    EXPECT_EQ(j["uv_seam_edges"], 1);
    EXPECT_EQ(j["vertex_colours"], false);
    EXPECT_EQ(j["materials"][1]["texture_found"], false);
}

// assimp's cube with two texture coordinate sets, and a glTF with TEXCOORD_1: the first set
// is kept, the other named, never dropped without a word.
TEST(CliAttributes, ASecondTextureCoordinateSetIsNamed) {
    if (!std::filesystem::exists(kAssimp / "Collada/cube_with_2UVs.DAE")) {
        GTEST_SKIP() << "install assimp-testmodels (scripts/install-deps.sh does)";
    }
    const auto j = info_json(kAssimp / "Collada/cube_with_2UVs.DAE");
    EXPECT_EQ(j["attributes"]["texcoords"], true);
    bool said = false;
    for (const auto& notice : j["notices"]) {
        said = said ||
               notice.get<std::string>().find("texture coordinate set 2 of") != std::string::npos;
    }
    EXPECT_TRUE(said) << j["notices"].dump();
}

// A texture path goes into the output relative to the output's folder, and reads back as the
// same file.
TEST(CliAttributes, TexturePathsAreWrittenRelativeToTheOutput) {
    const auto duck = kAssimp / "Collada/duck.dae";
    if (!std::filesystem::exists(duck)) {
        GTEST_SKIP() << "install assimp-testmodels (scripts/install-deps.sh does)";
    }
    TempDir tmp;
    std::filesystem::create_directories(tmp / "a/b");
    for (const char* name : {"a/b/duck.obj", "a/b/duck.dae", "a/b/duck.gltf"}) {
        SCOPED_TRACE(name);
        const RunResult r = run_meshedit({"convert", duck.string(), (tmp / name).string()});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const auto j = info_json(tmp / name);
        EXPECT_EQ(j["attributes"]["materials"][0]["texture"],
                  (kAssimp / "Collada/duckCM.tga").string());
        EXPECT_EQ(j["attributes"]["materials"][0]["texture_found"], true);
    }
    const std::string mtl = read_file(tmp / "a/b/duck.mtl");
    const std::string relative =
        std::filesystem::relative(kAssimp / "Collada/duckCM.tga", tmp / "a/b").generic_string();
    EXPECT_NE(mtl.find("map_Kd " + relative + "\n"), std::string::npos) << mtl;
}

}  // namespace
}  // namespace meshedit::test
