// flip_orientation(): every face and boundary loop reversed, nothing created or deleted.

#include <gtest/gtest.h>

#include <algorithm>

#include "core/op_test_util.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

// The input's faces, each with its corners in reverse order.
Mesh reversed_faces(const Mesh& mesh) {
    test::Indexed in = test::indexed(mesh);
    for (test::Corners& f : in.faces) {
        std::reverse(f.begin(), f.end());
    }
    return in.build();
}

TEST(FlipOrientation, ClosedCubeTurnsInsideOut) {
    Mesh mesh = shapes::cube();
    const Mesh before = mesh;
    const Mesh expected = reversed_faces(mesh);
    ASSERT_GT(signed_volume(mesh), 0.0);
    flip_orientation(mesh);
    ASSERT_VALID(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
    EXPECT_LT(signed_volume(mesh), 0.0);
    EXPECT_EQ(mesh.n_vertices(), before.n_vertices());
    EXPECT_EQ(mesh.n_edges(), before.n_edges());
    EXPECT_EQ(mesh.n_faces(), before.n_faces());
    flip_orientation(mesh);
    EXPECT_TRUE(test::identical(mesh, before)) << "twice is the identity, bit for bit";
}

// An open polygon mesh: boundary vertices stay anchored at outgoing boundary halfedges
// (validate() checks it), and faces keep their handles.
TEST(FlipOrientation, OpenPolygonMeshKeepsBoundaryAnchors) {
    Mesh mesh = test::mesh_from_faces(
        {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {1, 2, 0}},
        {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 6}, {4, 5, 6}});
    const Mesh before = mesh;
    const Mesh expected = reversed_faces(mesh);
    flip_orientation(mesh);
    ASSERT_VALID(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
    for (const Face f : before.faces()) {
        EXPECT_EQ(mesh.halfedge(f), before.halfedge(f)) << "face " << f.idx();
    }
    for (const Vertex v : mesh.vertices()) {
        EXPECT_EQ(mesh.is_boundary(v), before.is_boundary(v)) << "vertex " << v.idx();
    }
    flip_orientation(mesh);
    EXPECT_TRUE(test::identical(mesh, before));
}

// Tombstones (a collapse not yet garbage-collected) are carried along untouched.
TEST(FlipOrientation, MeshWithDeletedElements) {
    Mesh mesh = shapes::icosahedron();
    ASSERT_TRUE(collapse(mesh, mesh.find_edge(Vertex(0), Vertex(1))));
    Mesh expected = mesh;
    expected.garbage_collection();
    expected = reversed_faces(expected);
    flip_orientation(mesh);
    ASSERT_VALID(mesh);
    mesh.garbage_collection();
    ASSERT_VALID(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

}  // namespace
}  // namespace meshedit
