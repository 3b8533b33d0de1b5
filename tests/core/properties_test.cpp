// Named, typed properties: lifetime, type safety, growth with elements, deep copies.
#include <gtest/gtest.h>

#include <stdexcept>

#include "meshedit/core/mesh.h"
#include "support/fixtures.h"

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
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, 0, 0});
    ASSERT_EQ(label.vector().size(), 2u);
    EXPECT_EQ(label[Vertex(1)], -1);
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
    mesh.add_vertex({1, 2, 3});
    EXPECT_EQ(mesh.n_vertices(), 1u);
}

}  // namespace
}  // namespace meshedit
