// Global counts: Euler characteristic, boundary loops, components, genus.
#include <gtest/gtest.h>

#include "meshedit/core/build.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/topology.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

TEST(Topology, TwoTriangles) {
    const MeshStats s = compute_stats(test::two_triangles());
    EXPECT_EQ(s.vertices, 4u);
    EXPECT_EQ(s.edges, 5u);
    EXPECT_EQ(s.faces, 2u);
    EXPECT_EQ(s.boundary_loops, 1u);
    EXPECT_EQ(s.components, 1u);
    EXPECT_EQ(s.euler_characteristic, 1);
    EXPECT_EQ(s.genus, 0);
}

TEST(Topology, ClosedShapes) {
    const MeshStats cube = compute_stats(shapes::cube());
    EXPECT_EQ(cube.euler_characteristic, 2);
    EXPECT_EQ(cube.genus, 0);
    EXPECT_EQ(cube.boundary_loops, 0u);
    const MeshStats torus = compute_stats(shapes::torus(8, 5));
    EXPECT_EQ(torus.euler_characteristic, 0);
    EXPECT_EQ(torus.genus, 1);
    EXPECT_EQ(torus.components, 1u);
}

TEST(Topology, CylinderHasTwoBoundaryLoops) {
    const MeshStats s = compute_stats(shapes::cylinder(6, 2));
    EXPECT_EQ(s.boundary_loops, 2u);
    EXPECT_EQ(s.euler_characteristic, 0);
    EXPECT_EQ(s.genus, 0);
}

TEST(Topology, IsolatedVerticesAreComponentsButNotGenus) {
    Mesh mesh = test::two_triangles();
    mesh.new_vertex({7, 7, 7});
    const MeshStats s = compute_stats(mesh);
    EXPECT_EQ(s.components, 2u);
    EXPECT_EQ(s.euler_characteristic, 2);
    EXPECT_EQ(s.genus, 0);
}

TEST(Topology, BowtieAfterRepairHasTwoComponents) {
    const Mesh mesh = build_mesh(test::bowtie_soup());
    EXPECT_EQ(count_components(mesh), 2u);
    EXPECT_EQ(count_boundary_loops(mesh), 2u);
    EXPECT_EQ(compute_stats(mesh).genus, 0);
}

TEST(Topology, ClosedMeansNoBoundaryHalfedge) {
    EXPECT_TRUE(is_closed(shapes::cube()));
    EXPECT_TRUE(is_closed(shapes::torus(8, 5)));
    EXPECT_FALSE(is_closed(test::two_triangles()));
    EXPECT_FALSE(is_closed(shapes::cylinder(6, 2)));
    EXPECT_TRUE(is_closed(Mesh()));
    // A cube without its last face has a hole.
    PolygonSoup open_box = to_polygon_soup(shapes::cube());
    open_box.indices.resize(open_box.face_offsets[open_box.n_faces() - 1]);
    open_box.face_offsets.pop_back();
    EXPECT_FALSE(is_closed(build_mesh(open_box)));
}

}  // namespace
}  // namespace meshedit
