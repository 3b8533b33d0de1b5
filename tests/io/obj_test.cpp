// OBJ: polygons stay polygons, doubles survive exactly, every corner form and relative
// indices parse, and bad files give IoErrors naming the file and line.

#include <gtest/gtest.h>

#include <cmath>

#include "io/formats_test_util.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/obj.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using test::data_file;
using test::io_error_of;

std::vector<std::vector<std::uint32_t>> faces_of(const PolygonSoup& soup) {
    std::vector<std::vector<std::uint32_t>> faces;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        faces.emplace_back(soup.indices.begin() + soup.face_offsets[f],
                           soup.indices.begin() + soup.face_offsets[f + 1]);
    }
    return faces;
}

TEST(Obj, QuadSphereRoundTripKeepsQuadsAndExactDoubles) {
    test::ScratchDir dir;
    const Mesh mesh = shapes::quad_sphere(3);
    write_obj(mesh, dir / "ball.obj", {});
    const MeshSoup soup = read_obj(dir / "ball.obj");
    const PolygonSoup expected = to_polygon_soup(mesh);
    // Positions are the same doubles (shortest round-trip text, double-precision loader).
    EXPECT_EQ(soup.soup.positions, expected.positions);
    EXPECT_EQ(faces_of(soup.soup), faces_of(expected));
    for (std::size_t f = 0; f < soup.soup.n_faces(); ++f) {
        EXPECT_EQ(soup.soup.face_offsets[f + 1] - soup.soup.face_offsets[f], 4u);
    }
    // Written normals are per vertex, so they come back as the soup's normals.
    EXPECT_EQ(soup.normals.size(), expected.positions.size());
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"ball.obj"});
}

TEST(Obj, ReadMeshThroughTheFrontDoor) {
    test::ScratchDir dir;
    const Mesh mesh = shapes::torus(7, 5);
    write_mesh(mesh, dir / "torus.OBJ");  // extensions are case-insensitive
    const LoadedMesh loaded = read_mesh(dir / "torus.OBJ");
    EXPECT_FALSE(loaded.repairs.repaired());
    EXPECT_EQ(test::canonical_faces(loaded.mesh), test::canonical_faces(mesh));
    EXPECT_TRUE(test::same_faces_by_position(loaded.mesh, mesh, 0.0));
}

TEST(Obj, WithoutNormals) {
    test::ScratchDir dir;
    IoFlags flags;
    flags.write_normals = false;
    write_obj(shapes::cube(), dir / "cube.obj", flags);
    const std::string text = test::slurp(dir / "cube.obj");
    EXPECT_EQ(text.find("vn"), std::string::npos);
    EXPECT_EQ(text.find("//"), std::string::npos);
    EXPECT_NE(text.find("\nf "), std::string::npos);
    EXPECT_TRUE(read_obj(dir / "cube.obj").normals.empty());
}

TEST(Obj, CornerFormsAndNegativeIndices) {
    const MeshSoup soup = read_obj(data_file("obj_corner_forms.obj"));
    ASSERT_EQ(soup.soup.positions.size(), 6u);
    EXPECT_EQ(soup.soup.positions[4], Vec3(2, 0, 0));
    const std::vector<std::vector<std::uint32_t>> expected = {
        {0, 1, 2, 3}, {1, 4, 5}, {1, 5, 2}, {1, 4, 5, 2}};
    EXPECT_EQ(faces_of(soup.soup), expected);
    // Vertices 4 and 5 have corners without normals: no per-vertex normals.
    EXPECT_TRUE(soup.normals.empty());
}

TEST(Obj, PerVertexNormalsAreKept) {
    const MeshSoup soup = read_obj(data_file("obj_normals.obj"));
    ASSERT_EQ(soup.normals.size(), 3u);
    EXPECT_EQ(soup.normals[1], Vec3(0, 0.6, 0.8));
    EXPECT_EQ(soup.normals[2], Vec3(1, 0, 0));
}

TEST(Obj, Errors) {
    EXPECT_CONTAINS(io_error_of([] { read_obj(data_file("obj_bad_index.obj")); }),
                    "obj_bad_index.obj: line 6: face 2 refers to a vertex that does not exist");
    const std::string zero = io_error_of([] { read_obj(data_file("obj_zero_index.obj")); });
    EXPECT_CONTAINS(zero, "obj_zero_index.obj: ");
    EXPECT_CONTAINS(zero, "line 4");
    test::ScratchDir dir;
    EXPECT_CONTAINS(io_error_of([&] { read_obj(dir / "absent.obj"); }), "absent.obj: no such file");
    EXPECT_CONTAINS(io_error_of([&] { read_mesh(dir / "absent.obj"); }),
                    "absent.obj: no such file");
    // A relative path says where it was looked for (issue 40: a viewer started elsewhere).
    EXPECT_CONTAINS(io_error_of([&] { read_mesh("absent_here.obj"); }),
                    "absent_here.obj: no such file (looked for it in " +
                        std::filesystem::current_path().string() + ")");
    test::spit(dir / "abc.obj", "v 0 0 0\nv 1 abc 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_CONTAINS(io_error_of([&] { read_obj(dir / "abc.obj"); }),
                    "abc.obj: line 2: expected a number, found 'abc'");
    test::spit(dir / "plus.obj", "v +1 0 0\r\nv 1 +2.5e0 0\r\nv 0 1 -0\r\nf 1 2 3\r\n");
    EXPECT_EQ(read_obj(dir / "plus.obj").soup.positions[1], Vec3(1, 2.5, 0));
    // Polygons of any size (tinyobjloader, used before, counted corners in a byte).
    std::string big;
    // Appended piecewise: `"v " + std::string` trips a GCC 12 -Wrestrict false positive.
    for (int i = 0; i < 300; ++i) {
        big += "v ";
        big += std::to_string(std::cos(i * 0.021));
        big += ' ';
        big += std::to_string(std::sin(i * 0.021));
        big += " 0\n";
    }
    big += "f";
    for (int i = 1; i <= 300; ++i) {
        big += ' ';
        big += std::to_string(i);
    }
    test::spit(dir / "big.obj", big + "\n");
    const MeshSoup big_soup = read_obj(dir / "big.obj");
    ASSERT_EQ(big_soup.soup.n_faces(), 1u);
    EXPECT_EQ(big_soup.soup.indices.size(), 300u);
    test::spit(dir / "nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_CONTAINS(io_error_of([&] { read_obj(dir / "nan.obj"); }),
                    "nan.obj: line 2: vertex 2 is not finite");
}

// What loaded silently wrong before: a byte-order mark that ate the first vertex, an index
// that overflowed into a relative one, faces with fewer than three corners that vanished.
TEST(Obj, ByteOrderMarkIsSkipped) {
    const MeshSoup soup = parse_obj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "bom.obj");
    ASSERT_EQ(soup.soup.positions.size(), 3u);
    EXPECT_EQ(faces_of(soup.soup), (std::vector<std::vector<std::uint32_t>>{{0, 1, 2}}));
}

TEST(Obj, Utf16AndBinaryDataAreRefused) {
    const std::string utf16(
        "\xFF\xFEv\0 \0"
        "0\0",
        9);
    EXPECT_CONTAINS(io_error_of([&] { parse_obj(utf16, "wide.obj"); }),
                    "wide.obj: UTF-16 or UTF-32 text; save the file as UTF-8");
    const std::string nul("v 0 0 0\n\0\0\0\0", 12);
    EXPECT_CONTAINS(io_error_of([&] { parse_obj(nul, "zero.obj"); }),
                    "zero.obj: line 2: binary data (a NUL byte): not an OBJ text file");
}

TEST(Obj, IndicesAreCheckedWithTheirLine) {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_CONTAINS(io_error_of([&] { parse_obj(tri + "f 1 2 99999999999999999999\n", "o.obj"); }),
                    "o.obj: line 4: face 1: vertex index 99999999999999999999 is out of range");
    EXPECT_CONTAINS(io_error_of([&] { parse_obj(tri + "f 1 2 -4\n", "r.obj"); }),
                    "r.obj: line 4: face 1 refers to a vertex that does not exist (relative index "
                    "-4, 3 so far)");
    EXPECT_CONTAINS(io_error_of([&] { parse_obj(tri + "f 1 2 0\n", "z.obj"); }),
                    "z.obj: line 4: face 1 uses vertex index 0; OBJ indices start at 1");
    // A missing normal or texture coordinate drops that attribute, said in one line; the
    // mesh loads.
    const MeshSoup normals = parse_obj(tri + "vn 0 0 1\nf 1//1 2//2 3//1\n", "n.obj");
    EXPECT_EQ(normals.soup.n_faces(), 1u);
    EXPECT_TRUE(normals.corner_normals.empty());
    ASSERT_EQ(normals.notices.size(), 1u);
    EXPECT_EQ(
        normals.notices[0],
        "normals not kept: n.obj: line 5: face 1 refers to a normal that does not exist (the file "
        "has 3 vertices, 1 normals and 0 texture coordinates); the mesh loads without them");
    const MeshSoup relative = parse_obj(tri + "vt 0 0\nf 1/1 2/-2 3/1\n", "t.obj");
    EXPECT_TRUE(relative.corner_texcoords.empty());
    ASSERT_EQ(relative.notices.size(), 1u);
    EXPECT_CONTAINS(relative.notices[0], "texture coordinates not kept: t.obj: line 5: face 1");
    // A face may name a vertex defined after it.
    EXPECT_EQ(parse_obj("f 1 2 3\n" + tri, "late.obj").soup.n_faces(), 1u);
}

TEST(Obj, FacesWithFewerThanThreeCornersAreDroppedAndReported) {
    test::ScratchDir dir;
    test::spit(dir / "short.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1\nf 1 2\nf 1 2 3\n");
    const LoadedMesh loaded = read_mesh(dir / "short.obj");
    EXPECT_EQ(loaded.mesh.n_faces(), 1u);
    EXPECT_EQ(loaded.repairs.dropped_faces, (std::vector<std::uint32_t>{0, 1}));
    EXPECT_CONTAINS(loaded.repairs.summary(), "dropped 2 degenerate faces");
}

}  // namespace
}  // namespace meshedit
