// weld(): two boundary edges glued into one interior edge. The expected meshes move each
// surviving end to the midpoint, rename the other edge's ends and erase them.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>

#include "core/op_test_util.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

using test::Indexed;

void expect_refused(Mesh& mesh, Edge e1, Edge e2, std::string_view reason) {
    const Mesh before = mesh;
    EXPECT_EQ(is_weld_ok(mesh, e1, e2).reason(), reason);
    const OpResult<Edge> r = weld(mesh, e1, e2);
    EXPECT_FALSE(r);
    EXPECT_EQ(r.reason(), reason);
    EXPECT_TRUE(test::identical(mesh, before));
}

Edge edge(const Mesh& mesh, std::uint32_t u, std::uint32_t v) {
    const Edge e = mesh.find_edge(Vertex(u), Vertex(v));
    EXPECT_TRUE(e.is_valid()) << u << "-" << v;
    return e;
}

// Two triangles whose boundary edges 0-1 and 4-3 face each other across a small gap; the
// weld joins them along one edge, 3 merging into 0 and 4 into 1.
//        2                   2
//      /   \ (0,1,2)        /   \ (0,1,2)
//     0 --- 1     =>      0 --- 1
//     3 --- 4              \   / (0,5,1)
//      \   / (3,5,4)         5
//        5
TEST(Weld, TwoTrianglesFacingEachOther) {
    Mesh mesh = test::mesh_from_faces(
        {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0, -0.1, 0}, {1, -0.1, 0}, {0.5, -1, 0}},
        {{0, 1, 2}, {3, 5, 4}});
    Indexed expected = test::indexed(mesh);
    expected.positions[0] = {0, -0.05, 0};
    expected.positions[1] = {1, -0.05, 0};
    expected.rename(3, 0);
    expected.rename(4, 1);
    expected.erase_vertex(4);
    expected.erase_vertex(3);
    const Edge e1 = edge(mesh, 0, 1);
    ASSERT_TRUE(is_weld_ok(mesh, e1, edge(mesh, 3, 4)));
    const OpResult<Edge> r = weld(mesh, e1, edge(mesh, 3, 4));
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(*r, e1);
    EXPECT_FALSE(mesh.is_boundary(e1));
    EXPECT_TRUE(mesh.is_deleted(Vertex(3)));
    EXPECT_TRUE(mesh.is_deleted(Vertex(4)));
    mesh.garbage_collection();
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// A fan of six triangles around 0 cut along one spoke (1 and 7 are the two sides of the cut,
// at the same place): zipping 0-1 to 0-7 closes the disk.
TEST(Weld, ZipsASlitFanShut) {
    std::vector<Vec3> positions{{0, 0, 0}};
    for (int k = 0; k < 6; ++k) {
        const double t = 2 * std::numbers::pi * k / 6;
        positions.push_back({std::cos(t), std::sin(t), 0});
    }
    positions.push_back(positions[1]);
    Mesh mesh = test::mesh_from_faces(
        positions, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 6}, {0, 6, 7}});
    ASSERT_TRUE(mesh.is_boundary(Vertex(0)));
    const OpResult<Edge> r = weld(mesh, edge(mesh, 0, 1), edge(mesh, 0, 7));
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_FALSE(mesh.is_boundary(Vertex(0))) << "the zip closes the slit at the centre";
    EXPECT_EQ(test::boundary_loops(mesh), 1u);
    mesh.garbage_collection();
    EXPECT_TRUE(test::same_faces_by_position(mesh, shapes::disk(6)));
}

// A strip of three quads rolled up: its two end sides 0-4 and 3-7 meet in a tube with two
// boundary loops (3 merges into 0, 7 into 4).
TEST(Weld, QuadStripIntoATube) {
    Mesh mesh = test::quad_strip(3);
    ASSERT_EQ(test::boundary_loops(mesh), 1u);
    const OpResult<Edge> r = weld(mesh, edge(mesh, 0, 4), edge(mesh, 3, 7));
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(test::boundary_loops(mesh), 2u);
    EXPECT_EQ(mesh.n_vertices(), 6u);
    EXPECT_EQ(mesh.n_edges(), 9u);
    EXPECT_EQ(test::euler(mesh), 0) << "a tube";
    EXPECT_EQ(mesh.position(Vertex(0)), (Vec3{1.5, 0, 0}));
    EXPECT_EQ(mesh.position(Vertex(4)), (Vec3{1.5, 1, 0}));
}

TEST(Weld, Refusals) {
    {
        Mesh mesh = shapes::grid(2, 2);
        expect_refused(mesh, edge(mesh, 0, 1), edge(mesh, 1, 4),
                       "cannot weld: both edges must be on the boundary");
        expect_refused(mesh, edge(mesh, 0, 1), edge(mesh, 0, 1),
                       "cannot weld: the two edges are the same");
    }
    {  // a lone triangle's two sides
        Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        expect_refused(mesh, edge(mesh, 0, 1), edge(mesh, 1, 2),
                       "cannot weld: the edges belong to the same face");
    }
    {  // (0,1,2) and (1,3,2): 1 would merge with 3, and edge 1-3 would join 1 to itself
        Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}},
                                          {{0, 1, 2}, {1, 3, 2}});
        expect_refused(mesh, edge(mesh, 0, 1), edge(mesh, 3, 2),
                       "cannot weld: an edge would join a vertex to itself");
    }
    {  // two quads rolled on themselves: 0-1 and 2-1 would both become 0-1
        Mesh mesh = test::quad_strip(2);
        expect_refused(mesh, edge(mesh, 0, 3), edge(mesh, 2, 5),
                       "cannot weld: two edges would join the same vertices");
    }
    {  // three quads: welding 0-1 to 5-6 merges 1 with 6 and 0 with 5, and 1-5 doubles 0-1
        Mesh mesh = test::quad_strip(3);
        expect_refused(mesh, edge(mesh, 0, 1), edge(mesh, 5, 6),
                       "cannot weld: two edges would join the same vertices");
    }
    {  // a hexagon with triangles (0,5,6) and (4,3,7) on two sides: welding 6-0 to 3-7 would
       // merge the hexagon's opposite corners 0 and 3, which share no neighbour
        std::vector<Vec3> positions;
        for (int k = 0; k < 6; ++k) {
            const double t = 2 * std::numbers::pi * k / 6;
            positions.push_back({std::cos(t), std::sin(t), 0});
        }
        positions.push_back({1.5, -1, 0});
        positions.push_back({-1.5, 1, 0});
        Mesh mesh = test::mesh_from_faces(positions, {{0, 1, 2, 3, 4, 5}, {0, 5, 6}, {4, 3, 7}});
        ASSERT_VALID(mesh);
        expect_refused(mesh, edge(mesh, 6, 0), edge(mesh, 3, 7),
                       "cannot weld: a face would visit a vertex twice");
    }
}

}  // namespace
}  // namespace meshedit
