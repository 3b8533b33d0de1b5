// collapse_face(): a face shrinks to one vertex at the average of its corners. The expected
// meshes rename every corner to the survivor (the smallest index), drop the corners a
// neighbour now holds twice in a row, remove the faces that disappear and erase the merged
// vertices.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/op_test_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

using test::Corners;
using test::Indexed;

// A 3 x 3 grid of quads on [0,3]², vertex (i, j) = 4j + i, cell (i, j) =
// (4j+i, 4j+i+1, 4j+i+5, 4j+i+4).
Mesh quad_grid() {
    std::vector<Vec3> positions;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            positions.push_back({static_cast<double>(i), static_cast<double>(j), 0});
        }
    }
    std::vector<Corners> faces;
    for (std::uint32_t j = 0; j < 3; ++j) {
        for (std::uint32_t i = 0; i < 3; ++i) {
            const std::uint32_t v = 4 * j + i;
            faces.push_back({v, v + 1, v + 5, v + 4});
        }
    }
    return test::mesh_from_faces(positions, faces);
}

// The input with `corners` merged into the smallest at their average and the faces
// `gone` removed.
Mesh expected_collapse(const Mesh& input, Corners corners, const std::vector<Corners>& gone) {
    Indexed expected = test::indexed(input);
    for (const Corners& f : gone) {
        expected.remove(f);
    }
    std::sort(corners.begin(), corners.end());
    Vec3 centre{0, 0, 0};
    for (const std::uint32_t c : corners) {
        centre += expected.positions[c] / static_cast<double>(corners.size());
    }
    expected.positions[corners[0]] = centre;
    for (const std::uint32_t c : corners) {
        expected.rename(c, corners[0]);
    }
    for (Corners& f : expected.faces) {  // a run of the survivor becomes one corner
        Corners kept;
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (f[i] != corners[0] || f[(i + 1) % f.size()] != corners[0]) {
                kept.push_back(f[i]);
            }
        }
        f = kept;
    }
    for (auto it = corners.rbegin(); it + 1 != corners.rend(); ++it) {
        expected.erase_vertex(*it);
    }
    return expected.build();
}

void expect_collapse_face(Mesh& mesh, const Corners& corners, const std::vector<Corners>& gone) {
    const Mesh input = mesh;
    const Face f = test::face_with(mesh, corners);
    ASSERT_TRUE(is_collapse_face_ok(mesh, f));
    const OpResult<Vertex> r = collapse_face(mesh, f);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(r.value().idx(), *std::min_element(corners.begin(), corners.end()));
    EXPECT_EQ(test::euler(mesh), test::euler(input));
    mesh.garbage_collection();
    ASSERT_VALID(mesh);
    std::vector<Corners> removed = gone;
    removed.push_back(corners);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected_collapse(input, corners, removed)));
}

void expect_refused(Mesh& mesh, const Corners& corners, std::string_view reason) {
    const Mesh before = mesh;
    const OpResult<Vertex> r = collapse_face(mesh, test::face_with(mesh, corners));
    EXPECT_FALSE(r);
    EXPECT_EQ(r.reason(), reason);
    EXPECT_TRUE(test::identical(mesh, before));
}

// The middle quad (5,6,10,9) of the grid becomes vertex 5 at its centre (1.5, 1.5). The quads
// across its sides lose a corner, e.g. (6,7,11,10) -> (5,7,11); those at its corners keep
// four, renamed, e.g. (2,3,7,6) -> (2,3,7,5).
//   12 - 13 - 14 - 15
//    |    |    |    |
//    8 -- 9 - 10 - 11
//    |    | f  |    |
//    4 -- 5 -- 6 -- 7
//    |    |    |    |
//    0 -- 1 -- 2 -- 3
TEST(CollapseFace, MiddleQuadOfAGrid) {
    Mesh mesh = quad_grid();
    expect_collapse_face(mesh, {5, 6, 10, 9}, {});
}

// The middle cell's lower triangle of grid(3,3): the three triangles across its sides
// disappear with it.
TEST(CollapseFace, TriangleAmongTriangles) {
    Mesh mesh = shapes::grid(3, 3);
    expect_collapse_face(mesh, {5, 6, 10}, {{1, 6, 5}, {6, 11, 10}, {5, 10, 9}});
}

// A crease on 1-6, the edge of the triangle (6,5,1) across side 5-6 that goes, passes to
// 1-5, the edge that takes its place.
TEST(CollapseFace, MergedEdgeKeepsItsCrease) {
    Mesh mesh = shapes::grid(3, 3);
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    crease[mesh.find_edge(Vertex(1), Vertex(6))] = 1;
    expect_collapse_face(mesh, {5, 6, 10}, {{1, 6, 5}, {6, 11, 10}, {5, 10, 9}});
    std::size_t creases = 0;
    for (const Edge e : mesh.edges()) {
        creases += crease[e] != 0 ? 1 : 0;
    }
    EXPECT_EQ(creases, 1u);
    EXPECT_NE(crease[mesh.find_edge(Vertex(1), Vertex(5))], 0);
}

// A quad on the rim: the boundary loses its side and the new vertex stays on the boundary.
TEST(CollapseFace, QuadOnTheRim) {
    Mesh mesh = quad_grid();
    expect_collapse_face(mesh, {1, 2, 6, 5}, {});
    EXPECT_EQ(test::boundary_loops(mesh), 1u);
    EXPECT_TRUE(mesh.is_boundary(mesh.halfedge(Vertex(1)))) << "boundary anchor";
}

// A face of the octahedron: the three triangles across its sides go with it, and what is
// left is a tetrahedron (the survivor and the three far corners).
TEST(CollapseFace, OctahedronFaceLeavesATetrahedron) {
    Mesh mesh = test::mesh_from_faces(
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
        {{0, 1, 2}, {1, 3, 2}, {3, 4, 2}, {4, 0, 2}, {1, 0, 5}, {3, 1, 5}, {4, 3, 5}, {0, 4, 5}});
    ASSERT_VALID(mesh);
    expect_collapse_face(mesh, {0, 1, 2}, {{1, 3, 2}, {4, 0, 2}, {1, 0, 5}});
    EXPECT_EQ(mesh.n_vertices(), 4u);
    EXPECT_EQ(mesh.n_faces(), 4u);
}

TEST(CollapseFace, Refusals) {
    {  // a lone quad: nothing would be left around the point
        Mesh mesh =
            test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}});
        expect_refused(mesh, {0, 1, 2, 3},
                       "cannot collapse face: the new vertex would not be manifold (two holes, "
                       "or no face left)");
    }
    {  // the middle of three quads touches the rim on two separate sides: two holes
        Mesh mesh = test::quad_strip(3);
        expect_refused(mesh, {1, 2, 6, 5},
                       "cannot collapse face: the new vertex would not be manifold (two holes, "
                       "or no face left)");
    }
    {  // a face of a tetrahedron: the apex is joined to all three corners
        Mesh mesh = shapes::tetrahedron();
        Corners corners;
        for (const Vertex v : mesh.vertices(Face(0))) {
            corners.push_back(v.idx());
        }
        expect_refused(mesh, corners,
                       "cannot collapse face: two edges would join the same vertices");
    }
    {  // the hexagon (0,3,4,2,5,6) holds corners 0 and 2 of f = (0,1,2) apart: it would visit
       // the new vertex twice (triangles (1,0,6) and (2,1,5) join them to f)
        Mesh mesh = test::mesh_from_faces({{0, 0, 0},
                                           {1, 0, 0},
                                           {0.5, 1, 0},
                                           {-1, 0, 0},
                                           {-0.5, 2, 0},
                                           {1.5, 1.5, 0},
                                           {1.5, -0.5, 0}},
                                          {{0, 1, 2}, {0, 3, 4, 2, 5, 6}, {1, 0, 6}, {2, 1, 5}});
        ASSERT_VALID(mesh);
        expect_refused(mesh, {0, 1, 2},
                       "cannot collapse face: a face would visit the new vertex twice");
    }
    {  // f = (0,1,2) beside the quad (2,1,0,3), which holds all three of its corners and would
       // be left with two: the new vertex and 3
        Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                          {{0, 1, 2}, {2, 1, 0, 3}, {0, 2, 3}});
        ASSERT_VALID(mesh);
        expect_refused(mesh, {0, 1, 2},
                       "cannot collapse face: a face would shrink below three corners");
    }
    {  // a face collapsed already
        Mesh mesh = shapes::grid(3, 3);
        const Face f = test::face_with(mesh, {5, 6, 10});
        ASSERT_TRUE(collapse_face(mesh, f));
        const Mesh before = mesh;
        const OpResult<Vertex> r = collapse_face(mesh, f);
        EXPECT_EQ(r.reason(), "cannot collapse face: the face is deleted");
        EXPECT_TRUE(test::identical(mesh, before));
    }
}

}  // namespace
}  // namespace meshedit
