// What a mesh carries through the `meshedit` commands (docs/attributes.md): info lists it,
// --strict refuses to drop it, a second texture coordinate set survives the formats that hold
// one bit for bit and is named by those that do not, texture paths are written relative to
// the output.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
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

// `meshedit compare a b` at tolerance 0: both texture coordinate sets the same on every
// corner.
void expect_both_sets_equal(const std::filesystem::path& a, const std::filesystem::path& b) {
    SCOPED_TRACE(a.filename().string() + " against " + b.filename().string());
    const RunResult r = run_meshedit({"compare", a.string(), b.string()});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("texture coordinates:   the same ("), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("second texture coordinate set: the same ("), std::string::npos) << r.out;
}

// A file with two sets: info lists both, each with its seams; .dae and .glb keep both, and
// reading what was written and writing it again in the same format gives both bit for bit
// (the .glb as the floats it holds, equal to the .dae written from it); .obj names the set it
// drops in one line, and --strict refuses it with nothing written.
void expect_second_set_kept(const std::filesystem::path& input, const std::string& seams) {
    SCOPED_TRACE(input.filename().string());
    const auto j = info_json(input);
    EXPECT_EQ(j["attributes"]["texcoords"], true);
    EXPECT_EQ(j["attributes"]["second_texcoords"], true);
    EXPECT_EQ(j["attributes"]["second_uv_seam_edges"].dump(), seams);
    for (const auto& notice : j["notices"]) {
        EXPECT_EQ(notice.get<std::string>().find("not kept"), std::string::npos) << notice;
    }
    TempDir tmp;
    // Each conversion keeps both sets (an embedded texture COLLADA cannot hold may be named).
    const auto convert = [&](const std::filesystem::path& from, const std::string& name) {
        const RunResult r = run_meshedit({"convert", from.string(), (tmp / name).string()});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        std::istringstream lines(r.err);
        for (std::string line; std::getline(lines, line);) {
            EXPECT_TRUE(line.find("not kept") == std::string::npos ||
                        line.find("texture coordinate") == std::string::npos)
                << line;
        }
        return tmp / name;
    };
    const auto dae = convert(input, "a.dae");
    if (file_extension(input) == ".dae") {
        expect_both_sets_equal(input, dae);
    }
    expect_both_sets_equal(dae, convert(dae, "b.dae"));
    const auto glb = convert(input, "a.glb");
    expect_both_sets_equal(glb, convert(glb, "b.glb"));
    expect_both_sets_equal(glb, convert(glb, "c.dae"));
    expect_both_sets_equal(glb, convert(glb, "c.gltf"));

    const RunResult obj = run_meshedit({"convert", input.string(), (tmp / "a.obj").string()});
    EXPECT_EQ(obj.exit_code, 0) << obj.err;
    EXPECT_NE(obj.err.find("a.obj: not kept: the second texture coordinate set (OBJ has one set "
                           "at most; COLLADA and glTF keep it)\n"),
              std::string::npos)
        << obj.err;
    EXPECT_TRUE(info_json(tmp / "a.obj")["attributes"]["texcoords"]);
    const RunResult strict =
        run_meshedit({"convert", input.string(), (tmp / "s.obj").string(), "--strict"});
    EXPECT_EQ(strict.exit_code, 1) << strict.err;
    EXPECT_NE(strict.err.find("s.obj: not written (--strict): the format cannot keep the second "
                              "texture coordinate set"),
              std::string::npos)
        << strict.err;
    EXPECT_FALSE(std::filesystem::exists(tmp / "s.obj"));
    EXPECT_FALSE(std::filesystem::exists(tmp / "s.mtl"));
}

// assimp's cube with two COLLADA TEXCOORD sets (set="1" and set="2", each with its own offset
// and indices) and assimp's glTF box with TEXCOORD_0 and TEXCOORD_1.
TEST(CliAttributes, ASecondTextureCoordinateSetIsKept) {
    for (const auto& [file, seams] :
         {std::pair{"Collada/cube_with_2UVs.DAE", "12"},
          std::pair{"glTF2/BoxTexcoords-glTF/boxTexcoords.gltf", "7"}}) {
        if (!std::filesystem::exists(kAssimp / file)) {
            GTEST_SKIP() << "install assimp-testmodels (scripts/install-deps.sh does)";
        }
        expect_second_set_kept(kAssimp / file, seams);
    }
}

// A glTF written here with TEXCOORD_1 of known values: read as MeshEdit's second set with v
// turned over as TEXCOORD_0's is, in the corners' own order.
TEST(CliAttributes, GltfTexcoord1ReadsAsTheSecondSet) {
    TempDir tmp;
    // One triangle: positions, TEXCOORD_0 and TEXCOORD_1 as float32 in one base64 buffer.
    const float data[] = {0,     0,    0,     1,      0,    0, 0, 1, 0,  // POSITION
                          0,     0,    1,     0,      0,    1,           // TEXCOORD_0
                          0.25f, 0.5f, 0.75f, 0.125f, 0.5f, 1};          // TEXCOORD_1
    static_assert(sizeof data == 84);  // a multiple of 3: base64 without padding
    const auto* bytes = reinterpret_cast<const unsigned char*>(data);
    static const char* const kB64 =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string b64;
    for (std::size_t i = 0; i < sizeof data; i += 3) {
        const unsigned n = unsigned{bytes[i]} << 16 | unsigned{bytes[i + 1]} << 8 | bytes[i + 2];
        for (int k = 0; k < 4; ++k) {
            b64 += kB64[(n >> (18 - 6 * k)) & 63];
        }
    }
    std::ofstream(tmp / "t.gltf")
        << R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1,"TEXCOORD_1":2}}]}],)"
        << R"("buffers":[{"byteLength":84,"uri":"data:application/octet-stream;base64,)" << b64
        << R"("}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)"
        << R"({"buffer":0,"byteOffset":36,"byteLength":24},{"buffer":0,"byteOffset":60,"byteLength":24}],)"
        << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
        << R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"},)"
        << R"({"bufferView":2,"componentType":5126,"count":3,"type":"VEC2"}]})";
    const RunResult r =
        run_meshedit({"convert", (tmp / "t.gltf").string(), (tmp / "t.dae").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // The COLLADA file holds the second set as written: its corners in face order, each the
    // file's (u, 1 - v).
    const std::string dae = read_file(tmp / "t.dae");
    const auto source = dae.find("mesh-map-1");
    ASSERT_NE(source, std::string::npos) << dae;
    EXPECT_NE(dae.find(">0.25 0.5 0.75 0.875 0.5 0</float_array>", source), std::string::npos)
        << dae;
    EXPECT_NE(
        dae.find("<input semantic=\"TEXCOORD\" source=\"#mesh-map-1\" offset=\"1\" set=\"1\"/>"),
        std::string::npos);
}

// A material whose texture reads the second texture coordinate set (glTF's
// baseColorTexture.texCoord 1) keeps that through glTF, GLB and COLLADA (a bind_vertex_input
// to the second set's number) and back; OBJ, with one set, says it drops it.
TEST(CliAttributes, ATextureOnTheSecondSetStaysOnIt) {
    TempDir tmp;
    const std::filesystem::path square =
        repo_root() / "tests/golden/data/second_uv_set_square.gltf";
    const auto set_of = [](const std::filesystem::path& file) {
        return info_json(file)["attributes"]["materials"][0]["texture_texcoord_set"];
    };
    EXPECT_EQ(set_of(square), 1);
    for (const char* name : {"a.dae", "a.glb", "a.gltf"}) {
        SCOPED_TRACE(name);
        const RunResult r = run_meshedit({"convert", square.string(), (tmp / name).string()});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(r.err.find("not kept"), std::string::npos) << r.err;
        EXPECT_EQ(set_of(tmp / name), 1);
        const RunResult back =
            run_meshedit({"convert", (tmp / name).string(), (tmp / "back.gltf").string()});
        ASSERT_EQ(back.exit_code, 0) << back.err;
        EXPECT_EQ(set_of(tmp / "back.gltf"), 1);
    }
    // A texture on a set MeshEdit does not keep (TEXCOORD_3) is drawn with the first, said.
    std::string text = read_file(square);
    text.replace(text.find("\"texCoord\": 1"), 13, "\"texCoord\": 3");
    std::ofstream(tmp / "third.gltf") << text;
    const auto j = info_json(tmp / "third.gltf");
    EXPECT_EQ(j["attributes"]["materials"][0]["texture_texcoord_set"], 0);
    EXPECT_NE(j["notices"].dump().find("material 0's texture reads texCoord 3, which is not "
                                       "kept: it is drawn with TEXCOORD_0"),
              std::string::npos)
        << j["notices"].dump();
    const RunResult obj = run_meshedit({"convert", square.string(), (tmp / "a.obj").string()});
    EXPECT_EQ(obj.exit_code, 0) << obj.err;
    EXPECT_NE(obj.err.find("a.obj: not kept: material 'second_set''s texture on the second "
                           "texture coordinate set (OBJ has one set; COLLADA and glTF keep it)"),
              std::string::npos)
        << obj.err;
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
