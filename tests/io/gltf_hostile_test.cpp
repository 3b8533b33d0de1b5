// glTF files made to hurt the reader: deep node chains, node graphs that are not trees,
// deeply nested JSON, and buffer URIs that point out of the model's folder. Each file is
// generated here, at the smallest size that broke the reader before it was fixed.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <string>

#include "io/formats_test_util.h"
#include "meshedit/io/gltf.h"
#include "meshedit/io/io.h"

namespace meshedit {
namespace {

using test::io_error_of;
using test::ScratchDir;

// One triangle (0,0,0), (1,0,0), (0,1,0) as 36 bytes of little-endian floats.
std::string triangle_bytes() {
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    return std::string(reinterpret_cast<const char*>(xyz), sizeof xyz);
}

// A glTF whose one mesh reads its positions from buffer `uri`; `nodes` and `scene_nodes`
// are JSON arrays; `extras` goes into "asset".
std::string gltf_text(const std::string& uri, const std::string& nodes = R"([{"mesh": 0}])",
                      const std::string& scene_nodes = "[0]", const std::string& extras = "") {
    return R"({"asset": {"version": "2.0")" + (extras.empty() ? "" : ", \"extras\": " + extras) +
           R"(},
 "scene": 0, "scenes": [{"nodes": )" +
           scene_nodes + R"(}],
 "nodes": )" +
           nodes +
           R"(,
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "buffers": [{"byteLength": 36, "uri": ")" +
           uri + R"("}]})";
}

// The buffer embedded as a data: URI, so only the structure under test matters.
const std::string kEmbedded =
    "data:application/octet-stream;base64,"
    "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";

// A chain of `n` nodes, each the only child of the one before and moved by +1 in x; the
// last one holds the mesh.
std::string node_chain(int n) {
    std::string nodes = "[";
    for (int i = 0; i < n; ++i) {
        nodes += i ? "," : "";
        nodes += R"({"translation": [1, 0, 0])";
        nodes +=
            i + 1 < n ? R"(, "children": [)" + std::to_string(i + 1) + "]}" : R"(, "mesh": 0})";
    }
    return nodes + "]";
}

TEST(GltfHostile, EmbeddedBufferLoads) {
    ScratchDir dir;
    test::spit(dir / "t.gltf", gltf_text(kEmbedded));
    const MeshSoup soup = read_gltf(dir / "t.gltf");
    ASSERT_EQ(soup.soup.positions.size(), 3u);
    EXPECT_EQ(soup.soup.positions[1], Vec3(1, 0, 0));
}

// 20,000 levels overflowed the stack of the recursive walk (SIGSEGV); the walk now keeps its
// own stack, so the chain loads and every translation is applied.
TEST(GltfHostile, DeepNodeChainLoads) {
    ScratchDir dir;
    test::spit(dir / "chain.gltf", gltf_text(kEmbedded, node_chain(20000)));
    const MeshSoup soup = read_gltf(dir / "chain.gltf");
    ASSERT_EQ(soup.soup.positions.size(), 3u);
    EXPECT_EQ(soup.soup.positions[0], Vec3(20000, 0, 0));
    EXPECT_EQ(soup.soup.positions[1], Vec3(20001, 0, 0));
}

// Every node lists the next one twice: 2^40 paths through 41 nodes. A node with two parents
// breaks the spec's tree rule and is refused at its second visit.
TEST(GltfHostile, NodeWithTwoParentsIsRefused) {
    std::string nodes = "[";
    for (int i = 0; i < 40; ++i) {
        nodes += R"({"children": [)" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]},";
    }
    nodes += R"({"mesh": 0}])";
    ScratchDir dir;
    test::spit(dir / "dag.gltf", gltf_text(kEmbedded, nodes));
    const std::string message = io_error_of([&] { read_gltf(dir / "dag.gltf"); });
    EXPECT_CONTAINS(message, "node 40: the node is reached twice");
    EXPECT_CONTAINS(message, "must be trees");
}

TEST(GltfHostile, CycleAndRepeatedRootAreRefused) {
    ScratchDir dir;
    test::spit(dir / "cycle.gltf",
               gltf_text(kEmbedded, R"([{"children": [1]}, {"children": [0], "mesh": 0}])"));
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "cycle.gltf"); }),
                    "node 0: the node is reached twice");
    test::spit(dir / "roots.gltf", gltf_text(kEmbedded, R"([{"mesh": 0}])", "[0, 0]"));
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "roots.gltf"); }), "reached twice");
    test::spit(dir / "missing.gltf", gltf_text(kEmbedded, R"([{"children": [7]}])"));
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "missing.gltf"); }),
                    "refers to node 7, which does not exist");
}

// glTF 1.0 is named, not "holds no faces" or tinygltf's '"asset" object not found': declared
// in the asset, guessed from 1.0's object of meshes, or read from a binary header (issue 40).
TEST(GltfHostile, GltfOneIsNamed) {
    ScratchDir dir;
    const std::string wanted = "a glTF 1.0 file; MeshEdit reads glTF 2.0";
    test::spit(dir / "declared.gltf", R"({"asset": {"version": "1.0"}, "meshes": {}})");
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "declared.gltf"); }), wanted);
    test::spit(dir / "keyed.gltf", R"({"meshes": {"box": {"primitives": []}}, "shaders": {}})");
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "keyed.gltf"); }), wanted);
    const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<char*>(&v), 4); };
    const std::string json = R"({"asset": {"version": "1.0"}})";
    test::spit(dir / "old.glb",
               "glTF" + u32(1) + u32(20 + json.size()) + u32(json.size()) + u32(0) + json);
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "old.glb"); }), wanted);
}

// 16,000 nested arrays in asset.extras crashed tinygltf's recursive JSON conversion; the
// depth is now checked before tinygltf sees the text, in .gltf and in a .glb's JSON chunk.
TEST(GltfHostile, DeeplyNestedJsonIsRefused) {
    const std::string deep = std::string(16000, '[') + std::string(16000, ']');
    ScratchDir dir;
    test::spit(dir / "deep.gltf", gltf_text(kEmbedded, R"([{"mesh": 0}])", "[0]", deep));
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "deep.gltf"); }),
                    "deep.gltf: line 1: JSON nested deeper than 512 levels");

    std::string json = gltf_text(kEmbedded, R"([{"mesh": 0}])", "[0]", deep);
    json.resize((json.size() + 3) / 4 * 4, ' ');
    const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<char*>(&v), 4); };
    const std::string glb = "glTF" + u32(2) + u32(static_cast<std::uint32_t>(20 + json.size())) +
                            u32(static_cast<std::uint32_t>(json.size())) + "JSON" + json;
    test::spit(dir / "deep.glb", glb);
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "deep.glb"); }),
                    "JSON chunk, line 1: JSON nested deeper than 512 levels");

    // Brackets inside strings do not count; the file nests about 500 levels.
    const std::string ok = "[\"" + std::string(1000, '[') + "\"," + std::string(500, '[') +
                           std::string(500, ']') + "]";
    test::spit(dir / "ok.gltf", gltf_text(kEmbedded, R"([{"mesh": 0}])", "[0]", ok));
    EXPECT_EQ(read_gltf(dir / "ok.gltf").soup.positions.size(), 3u);
}

TEST(GltfHostile, BufferBesideTheModelLoads) {
    ScratchDir dir;
    std::filesystem::create_directories(dir / "model" / "bin");
    test::spit(dir / "model" / "bin" / "tri.bin", triangle_bytes());
    test::spit(dir / "model" / "t.gltf", gltf_text("bin/tri.bin"));
    EXPECT_EQ(read_gltf(dir / "model" / "t.gltf").soup.positions.size(), 3u);
    // A ".." that stays inside the folder is fine too.
    test::spit(dir / "model" / "u.gltf", gltf_text("bin/../bin/tri.bin"));
    EXPECT_EQ(read_gltf(dir / "model" / "u.gltf").soup.positions.size(), 3u);
}

// "../../../../etc/passwd" was read relative to the model's folder and converted into vertex
// coordinates. Files outside the folder, absolute paths, links leading out and anything but
// regular files are refused by name, and nothing is read from them.
TEST(GltfHostile, BufferOutsideTheFolderIsRefused) {
    ScratchDir dir;
    std::filesystem::create_directories(dir / "model");
    test::spit(dir / "secret.bin", triangle_bytes());
    test::spit(dir / "model" / "up.gltf", gltf_text("../secret.bin"));
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "model" / "up.gltf"); }),
                    "buffer URI '../secret.bin' lies outside the model's folder");

    const std::string absolute = (dir / "secret.bin").string();
    test::spit(dir / "model" / "abs.gltf", gltf_text(absolute));
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "model" / "abs.gltf"); }),
                    "is an absolute path");

    std::filesystem::create_symlink(dir / "secret.bin", dir / "model" / "link.bin");
    test::spit(dir / "model" / "link.gltf", gltf_text("link.bin"));
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "model" / "link.gltf"); }),
                    "buffer URI 'link.bin' lies outside the model's folder");

    std::filesystem::create_directories(dir / "model" / "sub");
    test::spit(dir / "model" / "dir.gltf", gltf_text("sub"));
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "model" / "dir.gltf"); }),
                    "buffer URI 'sub' is not a regular file");
}

// A URI naming a FIFO blocked the reader forever; it is refused before anything opens it.
TEST(GltfHostile, FifoBufferIsRefusedWithoutBlocking) {
    ScratchDir dir;
    ASSERT_EQ(::mkfifo((dir / "pipe.bin").c_str(), 0600), 0) << std::strerror(errno);
    test::spit(dir / "fifo.gltf", gltf_text("pipe.bin"));
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "fifo.gltf"); }),
                    "buffer URI 'pipe.bin' is not a regular file");
}

// tinygltf also searches the current folder; a buffer found only there is not read.
TEST(GltfHostile, CurrentFolderIsNotSearched) {
    ScratchDir dir;
    std::filesystem::create_directories(dir / "model");
    test::spit(dir / "only_here.bin", triangle_bytes());
    test::spit(dir / "model" / "t.gltf", gltf_text("only_here.bin"));
    const std::filesystem::path old = std::filesystem::current_path();
    std::filesystem::current_path(dir.path());
    const std::string message = io_error_of([&] { read_gltf(dir / "model" / "t.gltf"); });
    std::filesystem::current_path(old);
    EXPECT_CONTAINS(message, "only_here.bin");
}

}  // namespace
}  // namespace meshedit
