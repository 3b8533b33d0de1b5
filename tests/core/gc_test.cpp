// garbage_collection(): compacts, keeps live elements in order, remaps every reference and
// permutes user properties with their elements.
#include <gtest/gtest.h>

#include "meshedit/core/topology.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

// Two separate triangles; deleting the first by hand leaves a valid mesh with garbage.
//   0 1 2  (face 0, deleted)      3 4 5  (face 1, kept)
Mesh two_islands() {
    return test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 0, 0}, {4, 0, 0}, {3, 1, 0}},
                                 {{0, 1, 2}, {3, 4, 5}});
}

void delete_face_and_its_elements(Mesh& mesh, Face f) {
    std::vector<Halfedge> loop;
    for (Halfedge h : mesh.halfedges(f)) {
        loop.push_back(h);
    }
    for (Halfedge h : loop) {
        mesh.mark_deleted(Mesh::edge(h));
        mesh.mark_deleted(mesh.to_vertex(h));
    }
    mesh.mark_deleted(f);
}

TEST(GarbageCollection, CompactsAndRemaps) {
    Mesh mesh = two_islands();
    auto label = mesh.add_property<Vertex, int>("v:label");
    for (Vertex v : mesh.vertices()) {
        label[v] = static_cast<int>(10 + v.idx());
    }
    delete_face_and_its_elements(mesh, Face(0));
    ASSERT_VALID(mesh);
    EXPECT_TRUE(mesh.has_garbage());
    EXPECT_EQ(mesh.n_vertices(), 3u);
    EXPECT_EQ(mesh.vertices_size(), 6u);

    GarbageCollectionMap map;
    mesh.garbage_collection(&map);
    ASSERT_VALID(mesh);
    EXPECT_FALSE(mesh.has_garbage());
    EXPECT_EQ(mesh.vertices_size(), 3u);
    EXPECT_EQ(mesh.edges_size(), 3u);
    EXPECT_EQ(mesh.faces_size(), 1u);
    EXPECT_FALSE(map.vertices[0].is_valid());
    EXPECT_EQ(map.vertices[3], Vertex(0));
    EXPECT_EQ(map.vertices[5], Vertex(2));
    EXPECT_EQ(map.faces[1], Face(0));
    EXPECT_EQ(map.halfedges[7], Halfedge(1));
    // Order and positions kept; the user property moved with its vertices.
    EXPECT_EQ(mesh.position(Vertex(0)), (Vec3{3, 0, 0}));
    EXPECT_EQ(mesh.position(Vertex(2)), (Vec3{3, 1, 0}));
    EXPECT_EQ(label[Vertex(0)], 13);
    EXPECT_EQ(label[Vertex(2)], 15);
    EXPECT_EQ(test::canonical_faces(mesh), (std::vector<std::vector<std::uint32_t>>{{0, 1, 2}}));
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
}

TEST(GarbageCollection, WithoutGarbageChangesNothing) {
    Mesh mesh = test::one_ring(5);
    const Mesh before = mesh;
    mesh.garbage_collection();
    EXPECT_TRUE(test::identical(mesh, before));
}

TEST(GarbageCollection, EverythingDeletedLeavesEmptyMesh) {
    Mesh mesh = two_islands();
    delete_face_and_its_elements(mesh, Face(0));
    delete_face_and_its_elements(mesh, Face(1));
    ASSERT_VALID(mesh);
    mesh.garbage_collection();
    ASSERT_VALID(mesh);
    EXPECT_TRUE(mesh.is_empty());
    EXPECT_EQ(mesh.halfedges_size(), 0u);
}

}  // namespace
}  // namespace meshedit
