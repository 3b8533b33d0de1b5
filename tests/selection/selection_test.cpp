// Region selection (selection.h) on meshes whose answer is known by construction: quad grids
// and tori, a cube, two separate pieces.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/build.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"
#include "meshedit/selection/selection.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

// Quad grids and tori (shapes.h): vertex (i, j) of a grid at (i, j, 0) is j·(nx+1) + i,
// its quad (i, j) face j·nx + i; with two pieces, a copy beside it, numbered after.
Mesh quad_grid(int nx, int ny, bool two = false) {
    const Mesh one = shapes::quad_grid(nx, ny);
    return two ? test::two_copies(one, {double(nx + 2), 0, 0}) : one;
}

using shapes::quad_torus;

Edge edge_between(const Mesh& mesh, std::uint32_t a, std::uint32_t b) {
    const Edge e = mesh.find_edge(Vertex(a), Vertex(b));
    EXPECT_TRUE(e.is_valid()) << a << "-" << b;
    return e;
}

std::set<std::uint32_t> indices(const std::vector<Edge>& edges) {
    std::set<std::uint32_t> out;
    for (const Edge e : edges) {
        out.insert(e.idx());
    }
    return out;
}

// The edges whose two ends satisfy `on`.
template <class On>
std::set<std::uint32_t> edges_where(const Mesh& mesh, const On& on) {
    std::set<std::uint32_t> out;
    for (const Edge e : mesh.edges()) {
        if (on(mesh.position(mesh.vertex(e, 0))) && on(mesh.position(mesh.vertex(e, 1)))) {
            out.insert(e.idx());
        }
    }
    return out;
}

TEST(EdgeLoop, RunsAcrossAGridAndStopsAtTheBorder) {
    const Mesh mesh = quad_grid(5, 4);
    // The interior line y = 2 from (2,2)-(3,2): its loop is the whole line, 5 edges.
    const std::vector<Edge> loop = edge_loop(mesh, edge_between(mesh, 2 * 6 + 2, 2 * 6 + 3));
    EXPECT_EQ(loop.size(), 5u);
    EXPECT_EQ(indices(loop), edges_where(mesh, [](const Vec3& p) { return p.y == 2; }));
    // A border edge follows the border across valence-3 vertices and stops at the corners.
    const std::vector<Edge> side = edge_loop(mesh, edge_between(mesh, 1, 2));
    EXPECT_EQ(indices(side), edges_where(mesh, [](const Vec3& p) { return p.y == 0; }));
}

TEST(EdgeLoop, ClosesAroundATorusBothWays) {
    const Mesh mesh = quad_torus(12, 7);
    const std::vector<Edge> around = edge_loop(mesh, edge_between(mesh, 0, 7));  // i to i+1
    const std::vector<Edge> tube = edge_loop(mesh, edge_between(mesh, 0, 1));    // j to j+1
    EXPECT_EQ(around.size(), 12u);
    EXPECT_EQ(tube.size(), 7u);
    EXPECT_EQ(indices(around).size(), 12u);          // no edge twice
    for (std::size_t k = 0; k < tube.size(); ++k) {  // consecutive edges share a vertex
        const Edge a = tube[k], b = tube[(k + 1) % tube.size()];
        const std::set<std::uint32_t> ends{mesh.vertex(a, 0).idx(), mesh.vertex(a, 1).idx()};
        EXPECT_TRUE(ends.count(mesh.vertex(b, 0).idx()) + ends.count(mesh.vertex(b, 1).idx()) == 1);
    }
}

TEST(EdgeLoop, StopsAtAPole) {
    const Mesh cube = test::quad_cube();  // every vertex has valence 3
    EXPECT_EQ(edge_loop(cube, Edge(0)).size(), 1u);
}

TEST(EdgeRing, CrossesQuadsToTheOppositeEdges) {
    const Mesh mesh = quad_grid(5, 4);
    // The vertical edge (2,1)-(2,2): its ring is every vertical edge of row 1, 6 of them.
    const std::vector<Edge> ring = edge_ring(mesh, edge_between(mesh, 1 * 6 + 2, 2 * 6 + 2));
    std::set<std::uint32_t> row;  // the vertical edges between y = 1 and y = 2
    for (const Edge e : mesh.edges()) {
        const Vec3 p = mesh.position(mesh.vertex(e, 0)), q = mesh.position(mesh.vertex(e, 1));
        if (p.x == q.x && std::min(p.y, q.y) == 1 && std::max(p.y, q.y) == 2) {
            row.insert(e.idx());
        }
    }
    EXPECT_EQ(indices(ring), row);
    EXPECT_EQ(ring.size(), 6u);
    EXPECT_EQ(edge_ring(test::quad_cube(), Edge(0)).size(), 4u);  // closed around the cube
}

TEST(Linked, FloodsOnePieceAndStopsAtCreases) {
    Mesh mesh = quad_grid(3, 3, true);  // two 3 × 3 pieces, faces 0-8 and 9-17
    FaceSet seed(mesh.faces_size());
    seed.insert(Face(4));
    const FaceSet one = linked_faces(mesh, seed);
    EXPECT_EQ(one.count(), 9u);
    for (std::uint32_t f = 0; f < 9; ++f) {
        EXPECT_TRUE(one.contains(Face(f)));
    }
    // Crease the line x = 1 of the first piece: the seed's side is x in [1, 3].
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    for (const Edge e : mesh.edges()) {
        if (mesh.position(mesh.vertex(e, 0)).x == 1 && mesh.position(mesh.vertex(e, 1)).x == 1) {
            crease[e] = 1;
        }
    }
    EXPECT_EQ(linked_faces(mesh, seed, {.stop_at_creases = true}).count(), 6u);
    EXPECT_EQ(linked_faces(mesh, seed, {.stop_at_creases = false}).count(), 9u);
}

TEST(GrowShrink, ByTheVerticesFacesShare) {
    const Mesh mesh = quad_grid(5, 5);
    FaceSet centre(mesh.faces_size());
    centre.insert(Face(2 * 5 + 2));
    const FaceSet nine = grow(mesh, centre);
    EXPECT_EQ(nine.count(), 9u);
    EXPECT_EQ(shrink(mesh, nine), centre);
    FaceSet all = invert(mesh, FaceSet(mesh.faces_size()));
    EXPECT_EQ(all.count(), 25u);
    EXPECT_EQ(shrink(mesh, all).count(), 9u);  // the border ring goes
    EXPECT_EQ(invert(mesh, nine).count(), 16u);
}

TEST(Traits, CountWhatTheGridHas) {
    const Mesh mesh = quad_grid(5, 4);
    EXPECT_EQ(vertices_with(mesh, {.trait = Trait::Boundary}).count(), 18u);
    EXPECT_EQ(vertices_with(mesh, {.trait = Trait::Valence, .k = 4}).count(), 12u);
    EXPECT_EQ(vertices_with(mesh, {.trait = Trait::Valence, .k = 2}).count(), 4u);
    EXPECT_EQ(edges_with(mesh, {.trait = Trait::Boundary}).count(), 18u);
    EXPECT_EQ(faces_with(mesh, {.trait = Trait::Degree, .k = 4}).count(), 20u);
    EXPECT_EQ(faces_with(mesh, {.trait = Trait::Boundary}).count(), 14u);
    const Mesh cube = test::quad_cube();
    // More than 135° from +z: the bottom face only (the sides are at 90°).
    const FaceSet away =
        faces_with(cube, {.trait = Trait::FacingAway, .direction = {0, 0, 1}, .angle_deg = 135.0});
    ASSERT_EQ(away.count(), 1u);
    EXPECT_LT(face_normal(cube, away.elements()[0]).z, 0.0);
}

TEST(Conversions, AsBlenderConvertsModes) {
    const Mesh mesh = quad_grid(3, 3);
    FaceSet one(mesh.faces_size());
    one.insert(Face(4));
    const VertexSet corners = vertices_of_faces(mesh, one);
    EXPECT_EQ(corners.count(), 4u);
    EXPECT_EQ(faces_of_vertices(mesh, corners), one);
    EXPECT_EQ(edges_of_vertices(mesh, corners).count(), 4u);
    EXPECT_EQ(vertices_of_edges(mesh, edges_of_vertices(mesh, corners)), corners);
}

TEST(ShortestPath, AlongEdgesAndAcrossFaces) {
    const Mesh mesh = quad_grid(5, 4, true);
    const auto path = shortest_vertex_path(mesh, Vertex(0), Vertex(4 * 6 + 5));
    ASSERT_TRUE(path);
    EXPECT_EQ(path->size(), 10u);  // 5 + 4 edges
    for (std::size_t k = 0; k + 1 < path->size(); ++k) {
        EXPECT_TRUE(mesh.find_edge((*path)[k], (*path)[k + 1]).is_valid());
    }
    EXPECT_FALSE(shortest_vertex_path(mesh, Vertex(0), Vertex(30)));  // the other piece
    const auto faces = shortest_face_path(mesh, Face(0), Face(19));
    ASSERT_TRUE(faces);
    EXPECT_EQ(faces->size(), 8u);  // (4 + 3) steps
    EXPECT_FALSE(shortest_face_path(mesh, Face(0), Face(20)));
}

}  // namespace
}  // namespace meshedit
