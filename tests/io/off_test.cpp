// OFF: polygons stay polygons, doubles survive exactly, Geomview's header variants parse,
// and counts that lie, indices out of range and binary or 4D files give IoErrors naming the
// file and line.

#include <gtest/gtest.h>

#include "io/formats_test_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/off.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using test::Faces;
using test::faces_of;
using test::io_error_of;

std::string off_error(const std::string& text) {
    return io_error_of([&] { parse_off(text, "t.off"); });
}

TEST(Off, QuadSphereRoundTripKeepsQuadsAndExactDoubles) {
    test::ScratchDir dir;
    const Mesh mesh = shapes::quad_sphere(3);
    write_off(mesh, dir / "ball.off");
    const MeshSoup soup = read_off(dir / "ball.off");
    const PolygonSoup expected = to_polygon_soup(mesh);
    EXPECT_EQ(soup.soup.positions, expected.positions);
    EXPECT_EQ(faces_of(soup.soup), faces_of(expected));
    EXPECT_TRUE(soup.normals.empty());
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"ball.off"});
    // The header counts vertices, faces and edges.
    EXPECT_EQ(test::slurp(dir / "ball.off").substr(0, 4), "OFF\n");
    EXPECT_CONTAINS(test::slurp(dir / "ball.off"), "OFF\n" + std::to_string(mesh.n_vertices()) +
                                                       ' ' + std::to_string(mesh.n_faces()) + ' ' +
                                                       std::to_string(mesh.n_edges()) + '\n');
}

TEST(Off, ReadMeshThroughTheFrontDoorAndCreasesAreReportedLost) {
    test::ScratchDir dir;
    Mesh mesh = shapes::torus(7, 5);
    mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0)[Edge(3)] = 1;
    const std::vector<std::string> unkept = write_mesh(mesh, dir / "torus.OFF");
    EXPECT_EQ(unkept, std::vector<std::string>{"1 crease mark (OFF has no crease edges)"});
    const LoadedMesh loaded = read_mesh(dir / "torus.OFF");
    EXPECT_FALSE(loaded.repairs.repaired());
    EXPECT_EQ(test::canonical_faces(loaded.mesh), test::canonical_faces(mesh));
    EXPECT_TRUE(test::same_faces_by_position(loaded.mesh, mesh, 0.0));
}

TEST(Off, HeaderVariantsCommentsAndExtraColumns) {
    // Counts on the keyword's line, comments anywhere, a face colour after the indices.
    const MeshSoup a = parse_off(
        "OFF 4 2 0 # a square\n"
        "0 0 0\n1 0 0   # x\n1 1 0\n0 1 0\n\n"
        "3 0 1 2 255 0 0\n3 0 2 3\n",
        "a.off");
    EXPECT_EQ(a.soup.positions[2], Vec3(1, 1, 0));
    EXPECT_EQ(faces_of(a.soup), (Faces{{0, 1, 2}, {0, 2, 3}}));
    // A colour on one face but not the other: face colours are dropped, with a word.
    EXPECT_TRUE(a.face_colors.empty());
    EXPECT_EQ(a.notices, (std::vector<std::string>{"face colours not kept: face 1 (line 8) has "
                                                   "none; the mesh loads without them"}));
    // NOFF: a normal after each position; STCOFF colours and texture coordinates after it.
    const MeshSoup n =
        parse_off("NOFF\n3 1 3\n0 0 0 0 0 1\n1 0 0 0 0.6 0.8\n0 1 0 1 0 0\n3 0 1 2\n", "n.off");
    ASSERT_EQ(n.normals.size(), 3u);
    EXPECT_EQ(n.normals[1], Vec3(0, 0.6, 0.8));
    const MeshSoup c = parse_off(
        "STCOFF\n3 1 0\n0 0 0 1 0 0 1 0.5 0.5\n2 0 0 1 0 0 1 0 0\n0 2 0 1 0 0 1 1 1\n3 0 1 2\n",
        "c.off");
    EXPECT_EQ(c.soup.positions[1], Vec3(2, 0, 0));
    EXPECT_TRUE(c.normals.empty());
    EXPECT_EQ(c.colors, std::vector<Vec4>(3, Vec4{1, 0, 0, 1}));
    EXPECT_EQ(c.corner_texcoords, (std::vector<Vec2>{{0.5, 0.5}, {0, 0}, {1, 1}}));
    // No keyword at all (Geomview allows it), CRLF line ends, a polygon of five corners.
    const MeshSoup bare =
        parse_off("5 1 5\r\n0 0 0\r\n1 0 0\r\n2 1 0\r\n1 2 0\r\n0 1 0\r\n5 0 1 2 3 4\r\n", "b.off");
    EXPECT_EQ(faces_of(bare.soup), (Faces{{0, 1, 2, 3, 4}}));
    // Lines after the last face are reported, not silently dropped.
    const MeshSoup extra =
        parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n", "e.off");
    EXPECT_EQ(extra.notices,
              std::vector<std::string>{"ignored 1 line(s) after the last of the 1 faces the "
                                       "header announced"});
}

TEST(Off, Errors) {
    EXPECT_EQ(off_error(""), "t.off: empty file: no OFF header");
    EXPECT_EQ(off_error("PLY\n3 1 0\n"),
              "t.off: line 1: not an OFF file: it should start with the keyword OFF, found 'PLY'");
    EXPECT_EQ(off_error("OFF BINARY\n"),
              "t.off: line 1: binary OFF is not read; save the file as ASCII OFF");
    EXPECT_EQ(off_error("4OFF\n1 0 0\n0 0 0 1\n"),
              "t.off: line 1: '4OFF' holds points of four dimensions; MeshEdit reads 3D OFF");
    EXPECT_EQ(off_error("OFF\n"),
              "t.off: line 1: the file ends after its header, before the vertex and face counts");
    EXPECT_EQ(off_error("OFF\n3\n"), "t.off: line 2: the header ends before the face count");
    EXPECT_EQ(off_error("OFF\n-3 1 0\n"),
              "t.off: line 2: the vertex count should be a whole number below 4,294,967,295, "
              "found '-3'");
    // A count that lies: nothing is reserved for it, and the end says how far the file got.
    EXPECT_EQ(off_error("OFF\n4000000000 1 0\n0 0 0\n1 0 0\n"),
              "t.off: line 4: the file ends after 2 of the 4000000000 vertices the header "
              "announced");
    EXPECT_EQ(off_error("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "t.off: line 6: the file ends after 1 of the 2 faces the header announced");
    EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
              "t.off: line 4: vertex 1 is not finite (NaN or infinity)");
    EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n"),
              "t.off: line 4: vertex 1: the line ends too early");
    EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n"),
              "t.off: line 4: vertex 1: expected a number, found 'x'");
    EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
              "t.off: line 6: face 0 refers to vertex 3, but the file has 3 vertices (0 to 2)");
    EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n"),
              "t.off: line 6: face 0 refers to vertex -1, but the file has 3 vertices (0 to 2)");
    EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000 0 1 2\n"),
              "t.off: line 6: face 0 has 4000000 corners but its line lists 3 vertex indices");
    EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\nthree 0 1 2\n"),
              "t.off: line 6: face 0 should start with its number of corners, found 'three'");
    // A header that over-counts vertices: the first face line is not eaten as a vertex.
    EXPECT_EQ(off_error("OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n"),
              "t.off: line 6: vertex 3 reads as a face line ('3 …'): the header announces 4 "
              "vertices, more than the file has");
    const std::string nul("OFF\n3 1 0\n\0\0", 12);
    EXPECT_EQ(off_error(nul), "t.off: line 3: binary data (a NUL byte): not an ASCII OFF file");
    test::ScratchDir dir;
    EXPECT_CONTAINS(io_error_of([&] { read_mesh(dir / "absent.off"); }),
                    "absent.off: no such file");
}

TEST(Off, FacesWithFewerThanThreeCornersAreDroppedAndReportedByBuild) {
    test::ScratchDir dir;
    test::spit(dir / "two.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n2 0 1\n");
    const LoadedMesh loaded = read_mesh(dir / "two.off");
    EXPECT_EQ(loaded.mesh.n_faces(), 1u);
    EXPECT_TRUE(loaded.repairs.repaired());
}

}  // namespace
}  // namespace meshedit
