// The whole-mesh refinements' attribute carry (src/algorithms/refine_carry.h): it takes the
// halfedge, edge and face attributes out of the mesh before refining, so a refinement that
// refuses before it begins must give them back.

#include <gtest/gtest.h>

#include <stdexcept>

#include "algorithms/refine_carry.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/validate.h"
#include "support/mesh_compare.h"
#include "support/textured_torus.h"

namespace meshedit {
namespace {

TEST(RefineCarry, ARefinementRefusedBeforeItBeginsLeavesEveryAttribute) {
    Mesh mesh = test::uv_torus(12, 8);
    test::add_colors(mesh);
    auto material = mesh.add_property<Face, std::uint32_t>(kMaterialProperty);
    auto tag = mesh.add_property<Edge, double>("e:tag");
    for (const Face f : mesh.faces()) {
        material[f] = f.idx() % 3;
    }
    for (const Edge e : mesh.edges()) {
        tag[e] = 0.5 * e.idx();
    }
    const Mesh before = mesh;
    const refine::FaceVaryingRules rules{refine::Scheme::Loop};
    EXPECT_THROW(refine::refine_carrying(mesh, rules,
                                         [](Mesh&, refine::ChannelGroups&) {
                                             throw std::length_error("too big to index");
                                         }),
                 std::length_error);
    EXPECT_TRUE(test::identical(mesh, before));
    EXPECT_FALSE(validate(mesh));
    const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const auto uv_before = before.get_property<Halfedge, Vec2>(kTexCoordProperty);
    for (const Halfedge h : mesh.halfedges()) {
        ASSERT_EQ(uv[h], uv_before[h]) << h.idx();
    }
    const auto colour = mesh.get_property<Vertex, Vec4>(kColorProperty);
    const auto colour_before = before.get_property<Vertex, Vec4>(kColorProperty);
    for (const Vertex v : mesh.vertices()) {
        ASSERT_EQ(colour[v], colour_before[v]) << v.idx();
    }
    for (const Face f : mesh.faces()) {
        ASSERT_EQ(material[f], f.idx() % 3) << f.idx();
    }
    for (const Edge e : mesh.edges()) {
        ASSERT_EQ(tag[e], 0.5 * e.idx()) << e.idx();
    }
}

}  // namespace
}  // namespace meshedit
