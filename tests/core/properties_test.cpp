// Named, typed properties: lifetime, type safety, growth with elements, deep copies.
#include <gtest/gtest.h>

#include <stdexcept>

#include "meshedit/core/mesh.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

TEST(Properties, AddGetRemove) {
    Mesh mesh = test::two_triangles();
    auto weight = mesh.add_property<Vertex, double>("v:weight", 2.5);
    ASSERT_TRUE(weight);
    EXPECT_EQ(weight.vector().size(), 4u);
    EXPECT_EQ(weight[Vertex(3)], 2.5);
    weight[Vertex(1)] = 7.0;
    EXPECT_EQ((mesh.get_property<Vertex, double>("v:weight")[Vertex(1)]), 7.0);
    EXPECT_TRUE(mesh.has_property<Vertex>("v:weight"));
    EXPECT_FALSE(mesh.has_property<Edge>("v:weight"));

    mesh.remove_property(weight);
    EXPECT_FALSE(weight);
    EXPECT_FALSE(mesh.has_property<Vertex>("v:weight"));
}

TEST(Properties, WrongTypeIsNullAndDuplicateNameThrows) {
    Mesh mesh = test::two_triangles();
    mesh.add_property<Edge, std::uint8_t>("e:crease");
    EXPECT_FALSE((mesh.get_property<Edge, double>("e:crease")));
    EXPECT_FALSE((mesh.get_property<Edge, std::uint8_t>("e:missing")));
    EXPECT_THROW((mesh.add_property<Edge, std::uint8_t>("e:crease")), std::logic_error);
    EXPECT_THROW((mesh.property<Edge, int>("e:crease")), std::logic_error);
    EXPECT_TRUE((mesh.property<Edge, std::uint8_t>("e:crease")));
}

TEST(Properties, GrowWithElements) {
    Mesh mesh;
    auto label = mesh.add_property<Vertex, int>("v:label", -1);
    mesh.new_vertex({0, 0, 0});
    mesh.new_vertex({1, 0, 0});
    ASSERT_EQ(label.vector().size(), 2u);
    EXPECT_EQ(label[Vertex(1)], -1);
}

TEST(Properties, PushBackNAppendsDefaultsToEveryArray) {
    PropertyContainer c;
    auto* label = c.add<int>("label", -1);
    auto* point = c.add<Vec3>("point");
    c.push_back_n(3);
    c.push_back_n(0);
    EXPECT_EQ(c.size(), 3u);
    EXPECT_EQ(label->vector(), (memory::Array<int>{-1, -1, -1}));
    EXPECT_EQ(point->vector(), memory::Array<Vec3>(3));
}

// new_elements() gives the same arrays as the one-at-a-time calls in the documented order
// (vertices, then edges, then faces), user properties included.
TEST(Properties, AddElementsEqualsOneAtATime) {
    Mesh bulk = test::two_triangles();
    bulk.add_property<Edge, std::uint8_t>("e:crease", 0);
    bulk.add_property<Halfedge, int>("h:label", 7);
    Mesh single = bulk;
    bulk.new_elements(1, 3, 2);
    single.new_vertex({});
    for (int i = 0; i < 3; ++i) {
        single.new_edge(Vertex(), Vertex());
    }
    single.new_face();
    single.new_face();
    EXPECT_TRUE(test::identical(bulk, single));
    EXPECT_EQ(bulk.vertices_size(), 5u);
    EXPECT_EQ(bulk.edges_size(), 8u);
    EXPECT_EQ(bulk.faces_size(), 4u);
    EXPECT_EQ(bulk.n_vertices(), 5u);  // new elements are live
    EXPECT_EQ((bulk.get_property<Halfedge, int>("h:label").vector()),
              (single.get_property<Halfedge, int>("h:label").vector()));
    EXPECT_FALSE(bulk.halfedge(Vertex(4)).is_valid());
    EXPECT_FALSE(bulk.next(Halfedge(15)).is_valid());
    EXPECT_FALSE(bulk.to_vertex(Halfedge(15)).is_valid());
}

TEST(Properties, ScopedPropertyIsRemovedEvenOnException) {
    Mesh mesh = test::two_triangles();
    {
        ScopedProperty<Face, int> scratch(mesh, "f:scratch", 3);
        EXPECT_EQ(scratch[Face(1)], 3);
        EXPECT_TRUE(mesh.has_property<Face>("f:scratch"));
    }
    EXPECT_FALSE(mesh.has_property<Face>("f:scratch"));
    try {
        ScopedProperty<Face, int> scratch(mesh, "f:scratch");
        throw std::runtime_error("algorithm failed");
    } catch (const std::runtime_error&) {
    }
    EXPECT_FALSE(mesh.has_property<Face>("f:scratch"));
}

TEST(Properties, CopyIsDeepAndMoveKeepsViews) {
    Mesh mesh = test::two_triangles();
    auto label = mesh.add_property<Vertex, int>("v:label", 1);
    Mesh copy = mesh;
    copy.position(Vertex(0)) = {9, 9, 9};
    copy.get_property<Vertex, int>("v:label")[Vertex(0)] = 5;
    EXPECT_EQ(mesh.position(Vertex(0)), (Vec3{0, 0, 0}));
    EXPECT_EQ(label[Vertex(0)], 1);

    Mesh moved = std::move(mesh);
    EXPECT_EQ(label[Vertex(0)], 1);  // the array moved with its owner, the view is intact
    EXPECT_EQ(moved.n_faces(), 2u);
    EXPECT_EQ(moved.position(Vertex(2)), (Vec3{1, 1, 0}));
    EXPECT_EQ(mesh.n_vertices(), 0u);  // NOLINT: the moved-from mesh is a valid empty mesh
    mesh.new_vertex({1, 2, 3});
    EXPECT_EQ(mesh.n_vertices(), 1u);
}

}  // namespace
}  // namespace meshedit
