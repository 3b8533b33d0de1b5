// glTF compression extensions: EXT_meshopt_compression files built here with meshoptimizer's
// own encoder load exactly as their uncompressed twins; corrupt compressed views and files that
// require an extension MeshEdit does not read (Draco) are refused by name.

#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "io/formats_test_util.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/gltf.h"
#include "meshedit/io/io.h"

namespace meshedit {
namespace {

using test::io_error_of;

std::string base64(const std::string& in) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const std::uint32_t v = (std::uint32_t(std::uint8_t(in[i])) << 16) |
                                (std::uint32_t(std::uint8_t(in[i + 1])) << 8) |
                                std::uint8_t(in[i + 2]);
        out += {k[v >> 18], k[(v >> 12) & 63], k[(v >> 6) & 63], k[v & 63]};
    }
    if (i + 1 == in.size()) {
        const std::uint32_t v = std::uint32_t(std::uint8_t(in[i])) << 16;
        out += {k[v >> 18], k[(v >> 12) & 63], '=', '='};
    } else if (i + 2 == in.size()) {
        const std::uint32_t v = (std::uint32_t(std::uint8_t(in[i])) << 16) |
                                (std::uint32_t(std::uint8_t(in[i + 1])) << 8);
        out += {k[v >> 18], k[(v >> 12) & 63], k[(v >> 6) & 63], '='};
    }
    return out;
}

template <class T>
std::string bytes_of(const std::vector<T>& v) {
    return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

void pad4(std::string& s, char c) {
    while (s.size() % 4 != 0) {
        s.push_back(c);
    }
}

/// A float icosphere: positions and 32-bit triangle indices.
struct Geometry {
    std::vector<float> positions;
    std::vector<std::uint32_t> indices;
    std::size_t n_vertices() const { return positions.size() / 3; }
};

Geometry sphere() {
    const PolygonSoup soup = to_polygon_soup(shapes::icosphere(2));
    Geometry g;
    for (const Vec3& p : soup.positions) {
        g.positions.insert(g.positions.end(), {float(p.x), float(p.y), float(p.z)});
    }
    g.indices = soup.indices;
    return g;
}

std::string accessors_and_mesh(const Geometry& g) {
    return R"("accessors":[{"bufferView":0,"componentType":5126,"type":"VEC3","count":)" +
           std::to_string(g.n_vertices()) +
           R"(,"min":[-1,-1,-1],"max":[1,1,1]},{"bufferView":1,"componentType":5125,"type":"SCALAR","count":)" +
           std::to_string(g.indices.size()) +
           R"(}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0)";
}

/// The plain file: one buffer, two views.
std::string plain_gltf(const Geometry& g) {
    const std::string data = bytes_of(g.positions) + bytes_of(g.indices);
    return R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":)" + std::to_string(data.size()) +
           R"(,"uri":"data:application/octet-stream;base64,)" + base64(data) +
           R"("}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" +
           std::to_string(g.positions.size() * 4) +
           R"(,"byteStride":12},{"buffer":0,"byteOffset":)" +
           std::to_string(g.positions.size() * 4) + R"(,"byteLength":)" +
           std::to_string(g.indices.size() * 4) + "}]," + accessors_and_mesh(g) + "}";
}

/// The compressed data of `g` (vertices, then indices in `index_mode`), and the JSON that
/// describes it with buffer 0 holding that data (at `buffer0_uri`, or the GLB chunk when
/// empty) and buffer 1 the data-less fallback, as gltfpack writes them.
struct Compressed {
    std::string data;
    std::string json;
};

Compressed compress(const Geometry& g, const std::string& index_mode,
                    const std::string& buffer0_uri) {
    std::vector<unsigned char> vb(meshopt_encodeVertexBufferBound(g.n_vertices(), 12));
    vb.resize(
        meshopt_encodeVertexBuffer(vb.data(), vb.size(), g.positions.data(), g.n_vertices(), 12));
    std::vector<unsigned char> ib(meshopt_encodeIndexBufferBound(g.indices.size(), g.n_vertices()));
    if (index_mode == "TRIANGLES") {
        ib.resize(
            meshopt_encodeIndexBuffer(ib.data(), ib.size(), g.indices.data(), g.indices.size()));
    } else {
        ib.resize(
            meshopt_encodeIndexSequence(ib.data(), ib.size(), g.indices.data(), g.indices.size()));
    }
    Compressed c;
    c.data = bytes_of(vb);
    pad4(c.data, '\0');
    const std::size_t index_at = c.data.size();
    c.data += bytes_of(ib);
    pad4(c.data, '\0');
    const std::size_t vbytes = g.positions.size() * 4, ibytes = g.indices.size() * 4;
    const std::string uri = buffer0_uri.empty() ? "" : R"(,"uri":")" + buffer0_uri + "\"";
    c.json =
        R"({"asset":{"version":"2.0"},"extensionsUsed":["EXT_meshopt_compression"],"extensionsRequired":["EXT_meshopt_compression"],"buffers":[{"byteLength":)" +
        std::to_string(c.data.size()) + uri + R"(},{"byteLength":)" +
        std::to_string(vbytes + ibytes) +
        R"(,"extensions":{"EXT_meshopt_compression":{"fallback":true}}}],"bufferViews":[{"buffer":1,"byteOffset":0,"byteLength":)" +
        std::to_string(vbytes) +
        R"(,"byteStride":12,"extensions":{"EXT_meshopt_compression":{"buffer":0,"byteOffset":0,"byteLength":)" +
        std::to_string(vb.size()) + R"(,"byteStride":12,"count":)" +
        std::to_string(g.n_vertices()) + R"(,"mode":"ATTRIBUTES"}}},{"buffer":1,"byteOffset":)" +
        std::to_string(vbytes) + R"(,"byteLength":)" + std::to_string(ibytes) +
        R"(,"extensions":{"EXT_meshopt_compression":{"buffer":0,"byteOffset":)" +
        std::to_string(index_at) + R"(,"byteLength":)" + std::to_string(ib.size()) +
        R"(,"byteStride":4,"count":)" + std::to_string(g.indices.size()) + R"(,"mode":")" +
        index_mode + R"("}}}],)" + accessors_and_mesh(g) + "}";
    return c;
}

std::string glb(std::string json, const std::string& bin) {
    pad4(json, ' ');
    auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    return "glTF" + u32(2) + u32(std::uint32_t(12 + 8 + json.size() + 8 + bin.size())) +
           u32(std::uint32_t(json.size())) + "JSON" + json + u32(std::uint32_t(bin.size())) +
           "BIN" + std::string(1, '\0') + bin;
}

void expect_same_soup(const MeshSoup& a, const MeshSoup& b) {
    EXPECT_EQ(a.soup.positions, b.soup.positions);
    EXPECT_EQ(a.soup.indices, b.soup.indices);
    EXPECT_EQ(a.soup.face_offsets, b.soup.face_offsets);
}

TEST(GltfMeshopt, CompressedFilesLoadExactlyAsTheirUncompressedTwin) {
    const Geometry g = sphere();
    test::ScratchDir dir;
    for (const std::string mode : {"TRIANGLES", "INDICES"}) {
        SCOPED_TRACE(mode);
        // TRIANGLES coding may rotate a triangle's corners (the extension allows it): the
        // twin holds the same triangles rotated as the decoder returns them.
        Geometry twin = g;
        if (mode == "TRIANGLES") {
            std::vector<unsigned char> ib(
                meshopt_encodeIndexBufferBound(g.indices.size(), g.n_vertices()));
            ib.resize(meshopt_encodeIndexBuffer(ib.data(), ib.size(), g.indices.data(),
                                                g.indices.size()));
            ASSERT_EQ(meshopt_decodeIndexBuffer(twin.indices.data(), twin.indices.size(), 4,
                                                ib.data(), ib.size()),
                      0);
            for (std::size_t t = 0; t < g.indices.size(); t += 3) {
                const auto* a = &g.indices[t];
                const auto* b = &twin.indices[t];
                EXPECT_TRUE((a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) ||
                            (a[0] == b[1] && a[1] == b[2] && a[2] == b[0]) ||
                            (a[0] == b[2] && a[1] == b[0] && a[2] == b[1]))
                    << "triangle " << t / 3;
            }
        }
        test::spit(dir / "plain.gltf", plain_gltf(twin));
        const MeshSoup plain = read_soup(dir / "plain.gltf");
        ASSERT_EQ(plain.soup.n_faces(), g.indices.size() / 3);
        Compressed c = compress(g, mode, "");
        test::spit(dir / "packed.glb", glb(c.json, c.data));
        expect_same_soup(read_soup(dir / "packed.glb"), plain);
        c = compress(g, mode,
                     "data:application/octet-stream;base64," + base64(compress(g, mode, "").data));
        test::spit(dir / "packed.gltf", c.json);
        expect_same_soup(read_soup(dir / "packed.gltf"), plain);
    }
}

TEST(GltfMeshopt, CorruptOrTruncatedCompressedDataIsRefusedNamingTheFile) {
    const Geometry g = sphere();
    test::ScratchDir dir;
    Compressed c = compress(g, "TRIANGLES", "");
    // Damaged bytes: the vertex stream's header byte is wrong.
    std::string bad = c.data;
    bad[0] = char(0x00);
    test::spit(dir / "corrupt.glb", glb(c.json, bad));
    EXPECT_CONTAINS(io_error_of([&] { read_soup(dir / "corrupt.glb"); }),
                    "corrupt.glb: bufferView 0: the EXT_meshopt_compression data is corrupt");
    // The compressed view points past the end of its buffer.
    test::spit(dir / "short.glb", glb(c.json, c.data.substr(0, 16)));
    EXPECT_CONTAINS(io_error_of([&] { read_soup(dir / "short.glb"); }), "short.glb: ");
    // A count far beyond what the compressed bytes can hold is refused before allocating.
    std::string huge = c.json;
    const std::string count = "\"count\":" + std::to_string(g.n_vertices());
    huge.replace(huge.find(count), count.size(), "\"count\":2000000000");
    test::spit(dir / "huge.glb", glb(huge, c.data));
    EXPECT_CONTAINS(io_error_of([&] { read_soup(dir / "huge.glb"); }),
                    "huge.glb: bufferView 0: count 2000000000 is too large");
}

TEST(GltfMeshopt, QuantizedAndFilteredFilesWrittenByGltfpackLoad) {
    // gltfpack -cc: KHR_mesh_quantization (16-bit integer positions under a dequantizing node
    // scale, 8-bit normalized normals with the OCTAHEDRAL filter); -cc -vpf: float positions
    // with the EXPONENTIAL filter. Quantized to 14 bits over a 2-unit bowl: within 1e-4.
    const MeshSoup plain = read_soup(test::data_file("gltfpack_bowl_plain.glb"));
    ASSERT_EQ(plain.normals.size(), plain.soup.positions.size());
    for (const char* name : {"gltfpack_bowl_quantized.glb", "gltfpack_bowl_exp_filter.glb"}) {
        SCOPED_TRACE(name);
        const MeshSoup packed = read_soup(test::data_file(name));
        ASSERT_EQ(packed.soup.positions.size(), plain.soup.positions.size());
        ASSERT_EQ(packed.normals.size(), packed.soup.positions.size());
        EXPECT_EQ(packed.soup.n_faces(), plain.soup.n_faces());
        for (std::size_t v = 0; v < packed.soup.positions.size(); ++v) {
            std::size_t best = 0;
            for (std::size_t w = 1; w < plain.soup.positions.size(); ++w) {
                if (distance(packed.soup.positions[v], plain.soup.positions[w]) <
                    distance(packed.soup.positions[v], plain.soup.positions[best])) {
                    best = w;
                }
            }
            EXPECT_LT(distance(packed.soup.positions[v], plain.soup.positions[best]), 1e-4) << v;
            EXPECT_GT(dot(packed.normals[v], plain.normals[best]), 0.99) << v;
        }
    }
}

TEST(GltfMeshopt, DecodedSizeIsCheckedAgainstTheMemoryBudget) {
    const std::string bytes = test::slurp(test::data_file("gltfpack_bowl_meshopt.glb"));
    set_memory_budget_without_floor(1000);  // the vertices alone decode to more
    const std::string error = io_error_of([&] { parse_gltf(bytes, "bowl.glb", std::nullopt); });
    set_memory_budget_without_floor(0);
    EXPECT_CONTAINS(error, "bowl.glb: bufferView ");
    EXPECT_CONTAINS(error, ": decoding the compressed data would need about");
}

TEST(GltfMeshopt, OtherRequiredExtensionsAreRefusedByName) {
    const Geometry g = sphere();
    test::ScratchDir dir;
    std::string json = plain_gltf(g);
    json.insert(1, R"("extensionsRequired":["KHR_draco_mesh_compression"],)");
    test::spit(dir / "draco.gltf", json);
    EXPECT_CONTAINS(io_error_of([&] { read_soup(dir / "draco.gltf"); }),
                    "draco.gltf: the file requires the glTF extension KHR_draco_mesh_compression, "
                    "which MeshEdit does not read");
    json = plain_gltf(g);
    json.insert(
        1, R"("extensionsRequired":["EXT_meshopt_compression","KHR_draco_mesh_compression"],)");
    test::spit(dir / "both.gltf", json);
    EXPECT_CONTAINS(io_error_of([&] { read_soup(dir / "both.gltf"); }),
                    "both.gltf: the file requires the glTF extension KHR_draco_mesh_compression");
    // Material-only extensions change nothing MeshEdit reads.
    json = plain_gltf(g);
    json.insert(1, R"("extensionsRequired":["KHR_materials_unlit","KHR_texture_transform"],)");
    test::spit(dir / "unlit.gltf", json);
    EXPECT_EQ(read_soup(dir / "unlit.gltf").soup.n_faces(), g.indices.size() / 3);
}

/// The triangles of `s` as position triples, each rotated to start at its smallest corner,
/// sorted: the geometry without vertex numbering or triangle order (gltfpack reorders both).
std::vector<std::array<Vec3, 3>> triangles_of(const MeshSoup& s) {
    const auto less = [](const Vec3& a, const Vec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    std::vector<std::array<Vec3, 3>> out;
    for (std::size_t f = 0; f < s.soup.n_faces(); ++f) {
        const std::uint32_t* c = &s.soup.indices[s.soup.face_offsets[f]];
        std::array<Vec3, 3> t = {s.soup.positions[c[0]], s.soup.positions[c[1]],
                                 s.soup.positions[c[2]]};
        while (less(t[1], t[0]) || less(t[2], t[0])) {
            std::rotate(t.begin(), t.begin() + 1, t.end());
        }
        out.push_back(t);
    }
    std::sort(out.begin(), out.end(), [&](const auto& a, const auto& b) {
        return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), less);
    });
    return out;
}

TEST(GltfMeshopt, FilesWrittenByGltfpackLoad) {
    // gltfpack 1.3 (npm) from dae/bowl.dae: -noq (plain), -cc -noq (GLB), -c -noq (.gltf with
    // a .bin); both compressed ones have a data-less fallback buffer.
    const MeshSoup plain = read_soup(test::data_file("gltfpack_bowl_plain.glb"));
    ASSERT_EQ(plain.soup.n_faces(), 264u);
    for (const char* name : {"gltfpack_bowl_meshopt.glb", "gltfpack_bowl_meshopt.gltf"}) {
        SCOPED_TRACE(name);
        const MeshSoup packed = read_soup(test::data_file(name));
        EXPECT_EQ(packed.soup.positions.size(), plain.soup.positions.size());
        EXPECT_TRUE(triangles_of(packed) == triangles_of(plain));
    }
}

TEST(GltfMeshopt, AssimpDracoModelIsRefusedByName) {
    const std::filesystem::path draco = "/usr/share/assimp/models/glTF2/draco/2CylinderEngine.gltf";
    if (!std::filesystem::exists(draco)) {
        GTEST_SKIP() << "assimp-testmodels is not installed";
    }
    EXPECT_CONTAINS(io_error_of([&] { read_soup(draco); }),
                    "2CylinderEngine.gltf: the file requires the glTF extension "
                    "KHR_draco_mesh_compression, which MeshEdit does not read");
}

}  // namespace
}  // namespace meshedit
