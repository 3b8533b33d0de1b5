// PLY user properties: vertex and face properties MeshEdit has no meaning for ("float quality",
// "uchar flags", "int label") become typed mesh properties ("v:ply:quality") that survive
// build_mesh()'s repairs and are written back, ASCII and binary, with their types and exact
// values.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "io/formats_test_util.h"
#include "meshedit/io/ply.h"

namespace meshedit {
namespace {

using test::io_error_of;

// Two triangles sharing vertex 0 only (a bow tie: vertex 0 is split), a degenerate face that
// build_mesh() drops, and a triangle apart; every integer type, float and double.
const char* kHeader =
    "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
    "property float z\nproperty float quality\nproperty uchar flags\nproperty char c8\n"
    "property short s16\nproperty ushort u16\nproperty uint u32\nproperty double weight\n"
    "property list uchar float ignored_list\n"
    "element face 4\nproperty int label\nproperty list uchar int vertex_indices\n"
    "property double area\nend_header\n";
const char* kBody =
    "0 0 0 0.1 255 -128 -32768 65535 4294967295 0.30000000000000004 0\n"
    "1 0 0 1.5 1 127 32767 0 0 -1e-300 1 7\n"
    "0 1 0 -2.25 2 0 0 1 1 1e300 0\n"
    "-1 0 0 3.4028235e38 3 -1 -1 2 2 2 0\n"
    "0 -1 0 1e-45 4 1 1 3 3 3 0\n"
    "5 5 5 5 5 5 5 5 5 5 0\n"
    "6 5 5 6 6 6 6 6 6 6 0\n"
    "5 6 5 7 7 7 7 7 7 7 0\n"
    "-2147483648 3 0 1 2 0.5\n"
    "2147483647 3 0 3 4 0.25\n"
    "9 3 5 5 6 9\n"
    "-7 3 5 6 7 -0.125\n";

template <class H, class T>
std::vector<T> values_of(const Mesh& mesh, const std::string& name, std::size_t n) {
    const auto prop = mesh.get_property<H, T>(name);
    EXPECT_TRUE(prop) << name << " is missing or has another type";
    std::vector<T> out;
    for (std::size_t i = 0; prop && i < n; ++i) {
        out.push_back(prop[H(static_cast<std::uint32_t>(i))]);
    }
    return out;
}

void expect_kept(const Mesh& m) {
    ASSERT_EQ(m.n_vertices(), 9u);  // vertex 0 split in two
    ASSERT_EQ(m.n_faces(), 3u);     // the degenerate face dropped
    // Vertex 8 is the copy of vertex 0 and takes its values.
    EXPECT_EQ((values_of<Vertex, float>(m, "v:ply:quality", 9)),
              (std::vector<float>{0.1f, 1.5f, -2.25f, 3.4028235e38f, 1e-45f, 5, 6, 7, 0.1f}));
    EXPECT_EQ((values_of<Vertex, std::uint8_t>(m, "v:ply:flags", 9)),
              (std::vector<std::uint8_t>{255, 1, 2, 3, 4, 5, 6, 7, 255}));
    EXPECT_EQ((values_of<Vertex, std::int8_t>(m, "v:ply:c8", 9)),
              (std::vector<std::int8_t>{-128, 127, 0, -1, 1, 5, 6, 7, -128}));
    EXPECT_EQ((values_of<Vertex, std::int16_t>(m, "v:ply:s16", 9)),
              (std::vector<std::int16_t>{-32768, 32767, 0, -1, 1, 5, 6, 7, -32768}));
    EXPECT_EQ((values_of<Vertex, std::uint16_t>(m, "v:ply:u16", 9)),
              (std::vector<std::uint16_t>{65535, 0, 1, 2, 3, 5, 6, 7, 65535}));
    EXPECT_EQ((values_of<Vertex, std::uint32_t>(m, "v:ply:u32", 9)),
              (std::vector<std::uint32_t>{4294967295u, 0, 1, 2, 3, 5, 6, 7, 4294967295u}));
    EXPECT_EQ((values_of<Vertex, double>(m, "v:ply:weight", 9)),
              (std::vector<double>{0.30000000000000004, -1e-300, 1e300, 2, 3, 5, 6, 7,
                                   0.30000000000000004}));
    EXPECT_FALSE(m.has_property<Vertex>("v:ply:ignored_list"));
    EXPECT_EQ((values_of<Face, std::int32_t>(m, "f:ply:label", 3)),
              (std::vector<std::int32_t>{std::numeric_limits<std::int32_t>::min(),
                                         std::numeric_limits<std::int32_t>::max(), -7}));
    EXPECT_EQ((values_of<Face, double>(m, "f:ply:area", 3)),
              (std::vector<double>{0.5, 0.25, -0.125}));
}

TEST(PlyProperties, UnknownPropertiesAreKeptTypedThroughRepairs) {
    test::ScratchDir dir;
    test::spit(dir / "in.ply", std::string(kHeader) + kBody);
    const LoadedMesh loaded = read_mesh(dir / "in.ply");
    EXPECT_TRUE(loaded.repairs.repaired());
    expect_kept(loaded.mesh);
    EXPECT_EQ(loaded.notices, (std::vector<std::string>{"ignored properties "
                                                        "vertex.ignored_list (MeshEdit has no "
                                                        "place for them)"}));
}

TEST(PlyProperties, WrittenBackWithTheirTypesAsciiAndBinary) {
    test::ScratchDir dir;
    test::spit(dir / "in.ply", std::string(kHeader) + kBody);
    const LoadedMesh loaded = read_mesh(dir / "in.ply");
    for (const bool ascii : {false, true}) {
        SCOPED_TRACE(ascii ? "ascii" : "binary");
        IoFlags flags;
        flags.ascii = ascii;
        write_ply(loaded.mesh, dir / "out.ply", flags);
        const std::string text = test::slurp(dir / "out.ply");
        for (const char* line :
             {"property uchar flags\n", "property char c8\n", "property short s16\n",
              "property ushort u16\n", "property uint u32\n", "property float quality\n",
              "property double weight\n", "property int label\n", "property double area\n"}) {
            EXPECT_NE(text.find(line), std::string::npos) << line;
        }
        const LoadedMesh back = read_mesh(dir / "out.ply");
        EXPECT_FALSE(back.repairs.repaired()) << back.repairs.summary();
        expect_kept(back.mesh);
        EXPECT_TRUE(back.notices.empty());
        EXPECT_TRUE(unkept_by_format(back.mesh, ".ply").empty());
    }
    EXPECT_EQ(unkept_by_format(loaded.mesh, ".dae"),
              (std::vector<std::string>{
                  "the PLY properties v:ply:quality, v:ply:flags, v:ply:c8, v:ply:s16, "
                  "v:ply:u16, v:ply:u32, v:ply:weight, f:ply:label, f:ply:area (only PLY keeps "
                  "them)"}));
}

TEST(PlyProperties, ALoneNxIsKeptButNotWrittenTwiceBesideTheNormals) {
    test::ScratchDir dir;
    test::spit(dir / "nx.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nproperty float nx\nelement face 1\n"
               "property list uchar int vertex_indices\nend_header\n"
               "0 0 0 7\n1 0 0 8\n0 1 0 9\n3 0 1 2\n");
    const LoadedMesh loaded = read_mesh(dir / "nx.ply");
    EXPECT_EQ((values_of<Vertex, float>(loaded.mesh, "v:ply:nx", 3)),
              (std::vector<float>{7, 8, 9}));
    write_ply(loaded.mesh, dir / "out.ply", {});
    EXPECT_NO_THROW(read_mesh(dir / "out.ply"));
    IoFlags no_normals;
    no_normals.write_normals = false;
    write_ply(loaded.mesh, dir / "out.ply", no_normals);
    EXPECT_EQ((values_of<Vertex, float>(read_mesh(dir / "out.ply").mesh, "v:ply:nx", 3)),
              (std::vector<float>{7, 8, 9}));
}

TEST(PlyProperties, BinaryBigEndianValuesAreKept) {
    // One triangle; vertex "ushort id" and face "float tag", big-endian.
    std::string bytes =
        "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nproperty ushort id\nelement face 1\n"
        "property list uchar uint vertex_indices\nproperty float tag\nend_header\n";
    auto put_be = [&](auto v) {
        char b[sizeof v];
        std::memcpy(b, &v, sizeof b);
        for (std::size_t i = sizeof b; i-- > 0;) {
            bytes.push_back(b[i]);
        }
    };
    const float xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int v = 0; v < 3; ++v) {
        put_be(xyz[v][0]);
        put_be(xyz[v][1]);
        put_be(xyz[v][2]);
        put_be(static_cast<std::uint16_t>(1000 * v + 7));
    }
    put_be(std::uint8_t{3});
    put_be(std::uint32_t{0});
    put_be(std::uint32_t{1});
    put_be(std::uint32_t{2});
    put_be(-0.75f);
    const MeshSoup s = parse_ply(bytes, "be.ply");
    ASSERT_EQ(s.vertex_properties.size(), 1u);
    EXPECT_EQ(s.vertex_properties[0].name, "v:ply:id");
    EXPECT_EQ(s.vertex_properties[0].type, UserProperty::Type::U16);
    EXPECT_EQ(s.vertex_properties[0].values, (std::vector<double>{7, 1007, 2007}));
    ASSERT_EQ(s.face_properties.size(), 1u);
    EXPECT_EQ(s.face_properties[0].name, "f:ply:tag");
    EXPECT_EQ(s.face_properties[0].values, (std::vector<double>{-0.75}));
}

TEST(PlyProperties, ValuesOutOfTheirTypesRangeAreRefused) {
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nproperty uchar flags\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    EXPECT_CONTAINS(
        io_error_of([&] { parse_ply(header + "0 0 0 1\n1 0 0 256\n0 1 0 3\n3 0 1 2\n", "r.ply"); }),
        "r.ply: line 12: vertex 1: 'flags' is out of range for its type");
    EXPECT_CONTAINS(
        io_error_of([&] { parse_ply(header + "0 0 0 -1\n1 0 0 2\n0 1 0 3\n3 0 1 2\n", "r.ply"); }),
        "r.ply: line 11: vertex 0: 'flags' is out of range");
}

}  // namespace
}  // namespace meshedit
