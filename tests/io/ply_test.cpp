// PLY: ASCII and binary of both endiannesses give the exact soup they hold, for every integer
// type of list counts and indices and for float and double coordinates; what MeshEdit does not
// keep is named in a notice; doubles round-trip bit for bit; and headers that lie give IoErrors
// naming the file and the problem, never a crash or a huge allocation.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "io/formats_test_util.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/ply.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using test::Faces;
using test::faces_of;
using test::io_error_of;

std::string ply_error(const std::string& bytes) {
    return io_error_of([&] { parse_ply(bytes, "t.ply"); });
}

// Binary bytes in either endianness.
struct Bytes {
    bool big = false;
    std::string s;
    template <class T>
    Bytes& put(T v) {
        char b[sizeof(T)];
        std::memcpy(b, &v, sizeof b);
        if (big) {
            std::reverse(b, b + sizeof b);
        }
        s.append(b, sizeof b);
        return *this;
    }
};

const std::vector<Vec3> kFive = {{0, 0, 0}, {1.5, 0, 0}, {1.5, -2.25, 0}, {0, 1, 0.125}, {3, 3, 3}};
const Faces kTwoFaces = {{0, 1, 2, 3}, {3, 2, 4}};

// Five vertices (x y z as C, then a colour as K) and a quad and a triangle (counts as N,
// indices as I), in binary of the given endianness.
template <class C, class K, class N, class I>
std::string binary_ply(bool big, const std::string& c, const std::string& k, const std::string& n,
                       const std::string& i) {
    Bytes b{big, "ply\nformat binary_" + std::string(big ? "big" : "little") +
                     "_endian 1.0\ncomment made by the test\nobj_info nothing\nelement vertex 5\n" +
                     "property " + c + " x\nproperty " + c + " y\nproperty " + c + " z\n" +
                     "property " + k + " red\nproperty " + k + " green\nproperty " + k +
                     " blue\nelement face 2\nproperty list " + n + " " + i +
                     " vertex_indices\nend_header\n"};
    for (const Vec3& p : kFive) {
        b.put(static_cast<C>(p.x)).put(static_cast<C>(p.y)).put(static_cast<C>(p.z));
        b.put(static_cast<K>(1)).put(static_cast<K>(0)).put(static_cast<K>(1));
    }
    for (const auto& face : kTwoFaces) {
        b.put(static_cast<N>(face.size()));
        for (const std::uint32_t v : face) {
            b.put(static_cast<I>(v));
        }
    }
    return b.s;
}

template <class C, class K, class N, class I>
void expect_five(const std::string& c, const std::string& k, const std::string& n,
                 const std::string& i) {
    for (const bool big : {false, true}) {
        SCOPED_TRACE(std::string(big ? "big" : "little") + " endian " + c + " " + k + " " + n +
                     " " + i);
        const MeshSoup s = parse_ply(binary_ply<C, K, N, I>(big, c, k, n, i), "b.ply");
        EXPECT_EQ(s.soup.positions, kFive);
        EXPECT_EQ(faces_of(s.soup), kTwoFaces);
        EXPECT_TRUE(s.normals.empty());
        EXPECT_TRUE(s.notices.empty());
        // The colour becomes the vertex colour (0–1): a uchar 1 is 1/255, a float 1 is 1.
        EXPECT_TRUE(s.vertex_properties.empty());
        const double one = k == "float" || k == "float32" ? 1.0 : 1.0 / 255.0;
        EXPECT_EQ(s.colors, std::vector<Vec4>(5, Vec4{one, 0, one, 1}));
    }
}

TEST(Ply, BinaryBothEndiansEveryIntegerTypeFloatAndDouble) {
    expect_five<float, std::uint8_t, std::uint8_t, std::int32_t>("float", "uchar", "uchar", "int");
    expect_five<double, float, std::uint8_t, std::uint32_t>("double", "float", "uint8", "uint32");
    expect_five<float, std::uint8_t, std::int8_t, std::int8_t>("float32", "uint8", "char", "int8");
    expect_five<double, std::uint8_t, std::uint16_t, std::uint8_t>("float64", "uchar", "ushort",
                                                                   "uchar");
    expect_five<float, float, std::int16_t, std::int16_t>("float", "float32", "int16", "short");
    expect_five<float, std::uint8_t, std::uint32_t, std::uint16_t>("float", "uchar", "uint",
                                                                   "uint16");
    // Integer coordinates are allowed too.
    expect_five<float, std::uint8_t, std::int32_t, std::int32_t>("float", "uchar", "int32", "int");
}

TEST(Ply, BinaryIntegerCoordinates) {
    Bytes b{true,
            "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty int x\n"
            "property short y\nproperty uchar z\nelement face 1\n"
            "property list uchar uint vertex_indices\nend_header\n"};
    b.put(std::int32_t{-7}).put(std::int16_t{300}).put(std::uint8_t{200});
    b.put(std::int32_t{1}).put(std::int16_t{0}).put(std::uint8_t{0});
    b.put(std::int32_t{0}).put(std::int16_t{1}).put(std::uint8_t{0});
    b.put(std::uint8_t{3}).put(std::uint32_t{0}).put(std::uint32_t{1}).put(std::uint32_t{2});
    const MeshSoup s = parse_ply(b.s, "i.ply");
    EXPECT_EQ(s.soup.positions, (std::vector<Vec3>{{-7, 300, 200}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(faces_of(s.soup), (Faces{{0, 1, 2}}));
    EXPECT_TRUE(s.notices.empty());
}

TEST(Ply, AsciiWithNormalsColoursTextureCoordinatesAndOtherElements) {
    const MeshSoup s = parse_ply(
        "ply\r\nformat ascii 1.0\r\ncomment hello\r\nobj_info scanner 7\r\n"
        "element vertex 4\r\nproperty double x\r\nproperty double y\r\nproperty double z\r\n"
        "property float nx\r\nproperty float ny\r\nproperty float nz\r\n"
        "property float red\r\nproperty float green\r\nproperty float blue\r\n"
        "property float alpha\r\nproperty float texture_u\r\nproperty float texture_v\r\n"
        "property float confidence\r\n"
        "element face 2\r\nproperty list uchar int vertex_index\r\n"
        "property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\n"
        "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
        "0.1 0.2 0.3 0 0 1 1 0.5 0 1 0.25 0.75 0.9\r\n"
        "1e300 -2 3 0 1 0 0 0 0 1 0 0 1\r\n"
        "4 5 6 1 0 0 0 0 0 1 0 0 1\r\n"
        "7 8 9 0 0 -1 0 0 0 1 0 0 1\r\n"
        "3 0 1 2 255 0 0\r\n"
        "3 0 2 3 0 255 0\r\n"
        "0 1\r\n",
        "a.ply");
    EXPECT_EQ(s.soup.positions,
              (std::vector<Vec3>{{0.1, 0.2, 0.3}, {1e300, -2, 3}, {4, 5, 6}, {7, 8, 9}}));
    EXPECT_EQ(s.normals, (std::vector<Vec3>{{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}}));
    EXPECT_EQ(faces_of(s.soup), (Faces{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(
        s.notices,
        (std::vector<std::string>{"skipped elements 'edge' (1) (MeshEdit reads vertex and face)"}));
    // Colours and texture coordinates become MeshEdit's own (per vertex; UVs on every corner
    // of the vertex); a property MeshEdit has no meaning for is kept as a user property.
    EXPECT_EQ(s.colors,
              (std::vector<Vec4>{{1, 0.5, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}}));
    const Vec2 a{0.25, 0.75}, o{0, 0};
    EXPECT_EQ(s.corner_texcoords, (std::vector<Vec2>{a, o, o, a, o, o}));
    ASSERT_EQ(s.vertex_properties.size(), 1u);
    EXPECT_EQ(s.vertex_properties[0].name, "v:ply:confidence");
    EXPECT_EQ(s.vertex_properties[0].type, UserProperty::Type::F32);
    EXPECT_EQ(s.vertex_properties[0].values, (std::vector<double>{double{0.9f}, 1, 1, 1}));
    ASSERT_EQ(s.face_properties.size(), 3u);
    EXPECT_EQ(s.face_properties[0].name, "f:ply:red");
    EXPECT_EQ(s.face_properties[0].type, UserProperty::Type::U8);
    EXPECT_EQ(s.face_properties[0].values, (std::vector<double>{255, 0}));
    EXPECT_EQ(s.face_properties[1].values, (std::vector<double>{0, 255}));
}

TEST(Ply, AnyElementOrderAndTextureCoordinateNames) {
    // Faces before vertices: the indices are checked once the vertices are known.
    const MeshSoup s = parse_ply(
        "ply\nformat ascii 1.0\nelement material 1\nproperty list uchar float k\n"
        "element face 1\nproperty list uint8 uint32 vertex_indices\n"
        "property list uchar float texcoord\n"
        "element vertex 3\nproperty float s\nproperty float x\nproperty float y\nproperty "
        "float z\nproperty float t\nend_header\n"
        "2 0.5 0.25\n"
        "3 2 1 0 6 0 0 1 0 0 1\n"
        "0.5 0 0 0 0.5\n0.5 1 0 0 0.5\n0.5 0 1 0 0.5\n",
        "o.ply");
    EXPECT_EQ(s.soup.positions, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(faces_of(s.soup), (Faces{{2, 1, 0}}));
    EXPECT_EQ(s.notices, (std::vector<std::string>{
                             "skipped elements 'material' (1) (MeshEdit reads vertex and face)"}));
    // The vertex pair s t and the face's texcoord list both become corner UVs; the list,
    // which can hold seams, wins.
    EXPECT_TRUE(s.vertex_properties.empty());
    EXPECT_EQ(s.corner_texcoords, (std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}}));
    EXPECT_CONTAINS(ply_error("ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int "
                              "vertex_indices\nelement vertex 3\nproperty float x\nproperty "
                              "float y\nproperty float z\nend_header\n3 0 1 3\n0 0 0\n1 0 0\n0 "
                              "1 0\n"),
                    "t.ply: face 0 refers to vertex 3, but the file has 3 vertices (0 to 2)");
}

// Coordinates no float holds, and a polygon: binary keeps every bit, ASCII too.
Mesh awkward_mesh() {
    Mesh mesh = shapes::quad_sphere(2);
    for (const Vertex v : mesh.vertices()) {
        Vec3& p = mesh.position(v);
        p = p * (1.0 + 1e-13 * v.idx()) + Vec3(1e-300, -1e7 / 3.0, 0.1);
    }
    return mesh;
}

TEST(Ply, RoundTripIsExactInBinaryAndAscii) {
    test::ScratchDir dir;
    const Mesh mesh = awkward_mesh();
    const PolygonSoup expected = to_polygon_soup(mesh);
    for (const bool ascii : {false, true}) {
        IoFlags flags;
        flags.ascii = ascii;
        const auto path = dir / (ascii ? "a.ply" : "b.ply");
        EXPECT_TRUE(write_mesh(mesh, path, flags).empty());
        const std::string bytes = test::slurp(path);
        const std::string start = ascii ? "ply\nformat ascii 1.0\ncomment MeshEdit\n"
                                        : "ply\nformat binary_little_endian 1.0\n";
        EXPECT_EQ(bytes.substr(0, start.size()), start);
        const MeshSoup s = read_ply(path);
        EXPECT_EQ(s.soup.positions, expected.positions);
        EXPECT_EQ(faces_of(s.soup), faces_of(expected));
        EXPECT_EQ(s.normals.size(), expected.positions.size());
        EXPECT_TRUE(s.notices.empty());
        // And a second round gives the same file.
        const LoadedMesh again = read_mesh(path);
        write_mesh(again.mesh, dir / "again.ply", flags);
        EXPECT_EQ(test::slurp(dir / "again.ply"), bytes);
    }
    IoFlags bare;
    bare.write_normals = false;
    write_ply(mesh, dir / "bare.ply", bare);
    EXPECT_TRUE(read_ply(dir / "bare.ply").normals.empty());
}

TEST(Ply, PolygonsOfMoreThan255CornersUseUintCounts) {
    test::ScratchDir dir;
    PolygonSoup soup;
    std::vector<std::uint32_t> ring;
    for (std::uint32_t i = 0; i < 300; ++i) {
        const double a = 2 * M_PI * i / 300;
        soup.positions.push_back(Vec3(std::cos(a), std::sin(a), 0));
        ring.push_back(i);
    }
    soup.add_face_range(ring);
    const Mesh mesh = build_mesh(soup);
    write_ply(mesh, dir / "ring.ply");
    EXPECT_CONTAINS(test::slurp(dir / "ring.ply"), "property list uint uint vertex_indices");
    const MeshSoup s = read_ply(dir / "ring.ply");
    EXPECT_EQ(faces_of(s.soup), faces_of(to_polygon_soup(mesh)));
}

const std::string kHead =
    "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
    "property float y\nproperty float z\n";

std::string three_vertices() {
    Bytes b;
    for (int i = 0; i < 9; ++i) {
        b.put(static_cast<float>(i == 0 || i == 4 || i == 8 ? 1 : 0));
    }
    return b.s;
}

TEST(Ply, LyingHeadersAreRefusedWithoutHugeAllocations) {
    EXPECT_EQ(ply_error(""), "t.ply: empty file: no PLY header");
    EXPECT_EQ(ply_error("PLY\nformat ascii 1.0\n"),
              "t.ply: not a PLY file: it should start with the line 'ply'");
    EXPECT_EQ(ply_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"),
              "t.ply: the header has no 'end_header' line (a truncated file, or not PLY)");
    EXPECT_EQ(ply_error("ply\nelement vertex 0\nend_header\n"),
              "t.ply: the header has no 'format' line");
    EXPECT_EQ(ply_error("ply\nformat binary_middle_endian 1.0\nend_header\n"),
              "t.ply: line 2: unknown format 'binary_middle_endian' (expected ascii, "
              "binary_little_endian or binary_big_endian)");
    EXPECT_EQ(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\n"),
              "t.ply: line 4: unknown property type 'float128'");
    EXPECT_EQ(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int i\n"),
              "t.ply: line 4: a list's count type must be an integer type");
    EXPECT_EQ(ply_error("ply\nformat ascii 1.0\nelement vertex 99999999999\n"),
              "t.ply: line 3: an element line should be 'element NAME COUNT' with a whole count "
              "below 4,294,967,295");
    EXPECT_EQ(
        ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n"),
        "t.ply: the 'vertex' element has no x, y and z properties");
    // Element counts past the end of the file.
    EXPECT_EQ(ply_error(kHead + "end_header\n" + three_vertices().substr(0, 30)),
              "t.ply: the header announces 3 'vertex' records of at least 12 bytes, but only 30 "
              "bytes of the binary body remain");
    EXPECT_EQ(ply_error("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                        "property float x\nproperty float y\nproperty float z\nend_header\n"),
              "t.ply: the header announces 4000000000 'vertex' records of at least 12 bytes, but "
              "only 0 bytes of the binary body remain");
    EXPECT_EQ(ply_error("ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\n"
                        "property float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n"),
              "t.ply: the file ends after 2 of the 4000000000 'vertex' records the header "
              "announced");
    // A list count of 2^32 − 1, and one larger than the bytes left.
    const std::string faces =
        "element face 1\nproperty list uint uint vertex_indices\nend_header\n";
    Bytes huge;
    huge.put(std::uint32_t{0xFFFFFFFF}).put(std::uint32_t{0});
    EXPECT_EQ(ply_error(kHead + faces + three_vertices() + huge.s),
              "t.ply: face 0: list 'vertex_indices' claims 4294967295 items, but only 4 bytes "
              "of the file remain");
    Bytes four;
    four.put(std::uint32_t{4}).put(std::uint32_t{0}).put(std::uint32_t{1}).put(std::uint32_t{2});
    EXPECT_EQ(ply_error(kHead + faces + three_vertices() + four.s),
              "t.ply: face 0: list 'vertex_indices' claims 4 items, but only 12 bytes of the file "
              "remain");
    // A binary body shorter than declared, inside a record with lists.
    const std::string flagged =
        "element face 1\nproperty list uchar uint vertex_indices\n"
        "property int flags\nend_header\n";
    Bytes three;
    three.put(std::uint8_t{3}).put(std::uint32_t{0}).put(std::uint32_t{1}).put(std::uint32_t{2});
    EXPECT_EQ(ply_error(kHead + flagged + three_vertices() + three.s),
              "t.ply: the binary body ends inside 'face' record 0 of the 1 the header announced "
              "(" +
                  std::to_string(kHead.size() + flagged.size() + 36 + 13) + " bytes in the file)");
    // Negative list counts and indices, indices out of range.
    Bytes negative;
    negative.put(std::int32_t{3}).put(std::int32_t{0}).put(std::int32_t{-1}).put(std::int32_t{2});
    const std::string int_faces =
        "element face 1\nproperty list int int vertex_indices\nend_header\n";
    EXPECT_EQ(ply_error(kHead + int_faces + three_vertices() + negative.s),
              "t.ply: face 0 refers to vertex -1, but the file has 3 vertices (0 to 2)");
    Bytes beyond;
    beyond.put(std::int32_t{3}).put(std::int32_t{0}).put(std::int32_t{1}).put(std::int32_t{3});
    EXPECT_EQ(ply_error(kHead + int_faces + three_vertices() + beyond.s),
              "t.ply: face 0 refers to vertex 3, but the file has 3 vertices (0 to 2)");
    Bytes minus;
    minus.put(std::int32_t{-5});
    EXPECT_EQ(ply_error(kHead + int_faces + three_vertices() + minus.s),
              "t.ply: face 0: list 'vertex_indices' claims -5 items, but only 0 bytes of the "
              "file remain");
    // NaN coordinates: binary names the vertex, ASCII the line too.
    Bytes nan;
    nan.put(0.0f).put(std::numeric_limits<float>::quiet_NaN()).put(0.0f);
    EXPECT_EQ(ply_error(kHead + "end_header\n" + three_vertices().substr(0, 24) + nan.s),
              "t.ply: vertex 2 is not finite (NaN or infinity)");
    const std::string ascii_head =
        "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
        "property float y\nproperty float z\n";
    EXPECT_EQ(ply_error(ascii_head + "end_header\n0 0 0\n1 nan 0\n"),
              "t.ply: line 9: vertex 1 is not finite (NaN or infinity)");
    EXPECT_EQ(ply_error(ascii_head + "end_header\n0 0 0\n1 0\n"),
              "t.ply: line 9: vertex 1: the line ends before its 'z' value");
    EXPECT_EQ(ply_error(ascii_head + "end_header\n0 0 0\n1 x 0\n"),
              "t.ply: line 9: vertex 1: 'y' should be a number, found 'x'");
    EXPECT_EQ(ply_error(ascii_head + "element face 1\nproperty list uchar int vertex_indices\n"
                                     "end_header\n0 0 0\n1 0 0\n3 0 1 2\n"),
              "t.ply: line 12: face 0 refers to vertex 2, but the file has 2 vertices (0 to 1)");
    EXPECT_EQ(ply_error(ascii_head + "element face 1\nproperty list uchar int vertex_indices\n"
                                     "end_header\n0 0 0\n1 0 0\n4294967295 0 1 2\n"),
              "t.ply: line 12: face 0: list 'vertex_indices' of 4294967295 items does not fit on "
              "its line");
    EXPECT_EQ(ply_error(ascii_head + "element face 1\nproperty list uchar int vertex_indices\n"
                                     "end_header\n0 0 0\n1 0 0\n3 0 1.5 1\n"),
              "t.ply: line 12: face 0: 'vertex_indices' should be a whole number, found '1.5'");
    test::ScratchDir dir;
    EXPECT_CONTAINS(io_error_of([&] { read_mesh(dir / "absent.ply"); }),
                    "absent.ply: no such file");
}

// Every truncation and many single-byte changes of valid files: a soup or an IoError, never
// a crash or another exception (run under ASan in the sanitizer build).
TEST(Ply, TruncatedAndDamagedFilesGiveASoupOrAnIoError) {
    const std::vector<std::string> files = {
        binary_ply<double, float, std::uint8_t, std::uint32_t>(false, "double", "float", "uchar",
                                                               "uint"),
        binary_ply<float, std::uint8_t, std::int16_t, std::int8_t>(true, "float", "uchar", "short",
                                                                   "char"),
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
        "float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 "
        "0\n0 1 0\n3 0 1 2\n"};
    std::size_t soups = 0;
    std::size_t errors = 0;
    const auto attempt = [&](const std::string& bytes) {
        try {
            parse_ply(bytes, "d.ply");
            ++soups;
        } catch (const IoError&) {
            ++errors;
        }
    };
    for (const std::string& file : files) {
        for (std::size_t n = 0; n < file.size(); ++n) {
            attempt(file.substr(0, n));
        }
        for (std::size_t i = 0; i < file.size(); ++i) {
            for (const char c : {'\0', '\xFF', '\x7F', '9', ' '}) {
                std::string damaged = file;
                damaged[i] = c;
                attempt(damaged);
            }
        }
    }
    EXPECT_GT(errors, 0u);
    EXPECT_GT(soups, 0u);
}

TEST(Ply, PointCloudsAreRefusedByTheFrontDoor) {
    test::ScratchDir dir;
    test::spit(dir / "points.ply",
               "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
               "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar "
               "blue\nend_header\n0 0 0 1 2 3\n1 1 1 1 2 3\n");
    EXPECT_EQ(io_error_of([&] { read_mesh(dir / "points.ply"); }),
              (dir / "points.ply").string() + ": holds no faces to load");
}

}  // namespace
}  // namespace meshedit

namespace meshedit {
namespace {

// A file's colours follow edits: the midpoint of a split gets the average colour, rounded
// for uchar, and the copy of a face its face's value.
TEST(Ply, ColoursBlendThroughEdits) {
    test::ScratchDir dir;
    test::spit(dir / "c.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nproperty uchar red\nproperty int label\nelement face 1\n"
               "property list uchar int vertex_indices\nproperty uchar green\nend_header\n"
               "0 0 0 0 5\n1 0 0 255 6\n0 1 0 100 7\n3 0 1 2 42\n");
    LoadedMesh loaded = read_mesh(dir / "c.ply");
    Mesh& mesh = loaded.mesh;
    const Edge e = mesh.find_edge(Vertex(0), Vertex(1));
    const Vertex m = *split(mesh, e);
    const auto red = mesh.get_property<Vertex, std::uint8_t>("v:ply:red");
    const auto label = mesh.get_property<Vertex, std::int32_t>("v:ply:label");
    const auto green = mesh.get_property<Face, std::uint8_t>("f:ply:green");
    ASSERT_TRUE(red && label && green);
    EXPECT_EQ(red[m], 128);  // (0 + 255) / 2 = 127.5, to the nearest even
    EXPECT_TRUE(label[m] == 5 || label[m] == 6) << label[m];  // a label: one end's
    for (const Face f : mesh.faces()) {
        EXPECT_EQ(green[f], 42);
    }
}

}  // namespace
}  // namespace meshedit
