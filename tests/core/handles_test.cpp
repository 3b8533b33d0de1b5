// Handles are distinct 4-byte value types; twins and edges are index arithmetic.
#include <gtest/gtest.h>

#include <type_traits>
#include <unordered_set>

#include "meshedit/core/mesh.h"

namespace meshedit {
namespace {

static_assert(sizeof(Vertex) == 4 && sizeof(Halfedge) == 4 && sizeof(Edge) == 4 &&
              sizeof(Face) == 4);
static_assert(std::is_trivially_copyable_v<Vertex> && std::is_trivially_copyable_v<Face>);
// A vertex can never be passed where a face or halfedge is expected.
static_assert(!std::is_convertible_v<Vertex, Face>);
static_assert(!std::is_convertible_v<Halfedge, Edge>);
static_assert(!std::is_convertible_v<std::uint32_t, Vertex>);

TEST(Handles, DefaultIsInvalid) {
    EXPECT_FALSE(Vertex().is_valid());
    EXPECT_EQ(Vertex().idx(), kInvalidIndex);
    EXPECT_TRUE(Vertex(0).is_valid());
}

TEST(Handles, OrderedAndHashable) {
    EXPECT_LT(Vertex(1), Vertex(2));
    EXPECT_EQ(Face(7), Face(7));
    EXPECT_NE(Face(7), Face(8));
    std::unordered_set<Edge> set{Edge(3), Edge(5), Edge(3)};
    EXPECT_EQ(set.size(), 2u);
}

TEST(Handles, TwinsAreImplicitPairs) {
    EXPECT_EQ(Mesh::twin(Halfedge(6)), Halfedge(7));
    EXPECT_EQ(Mesh::twin(Halfedge(7)), Halfedge(6));
    EXPECT_EQ(Mesh::edge(Halfedge(7)), Edge(3));
    EXPECT_EQ(Mesh::halfedge(Edge(3), 0), Halfedge(6));
    EXPECT_EQ(Mesh::halfedge(Edge(3), 1), Halfedge(7));
}

TEST(Handles, NewEdgeSetsBothEndpoints) {
    Mesh mesh;
    const Vertex a = mesh.new_vertex({0, 0, 0});
    const Vertex b = mesh.new_vertex({1, 0, 0});
    const Halfedge h = mesh.new_edge(a, b);
    EXPECT_EQ(h, Halfedge(0));
    EXPECT_EQ(mesh.to_vertex(h), b);
    EXPECT_EQ(mesh.from_vertex(h), a);
    EXPECT_EQ(mesh.n_edges(), 1u);
    EXPECT_EQ(mesh.n_halfedges(), 2u);
}

}  // namespace
}  // namespace meshedit
