// Vertex colours (kColorProperty, attributes.h): kept through edits by the attribute carry
// like positions.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "io/formats_test_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

constexpr Vec4 kRed{1, 0, 0, 1};
constexpr Vec4 kBlue{0, 0, 1, 1};

// A colour that is an affine function of the position: every blend with weights summing to
// one (a split, Loop's stencils) gives the colour of the blended position back.
Vec4 color_at(const Vec3& p) {
    return {0.5 + 0.25 * p.x, 0.5 - 0.25 * p.y, 0.5 + 0.125 * (p.x + p.z), 1.0};
}

// The midpoint of an edge between a red and a blue vertex is their mean.
TEST(ColorAttributes, SplitBlendsTheEndsColours) {
    Mesh mesh = shapes::tetrahedron();
    auto color = mesh.property<Vertex, Vec4>(kColorProperty);
    for (const Vertex v : mesh.vertices()) {
        color[v] = v.idx() == 0 ? kRed : kBlue;
    }
    const Vertex m = *split(mesh, mesh.find_edge(Vertex(0), Vertex(1)));
    color = mesh.get_property<Vertex, Vec4>(kColorProperty);
    EXPECT_EQ(color[m], (Vec4{0.5, 0, 0.5, 1}));
    EXPECT_EQ(color[Vertex(0)], kRed);
    EXPECT_EQ(color[Vertex(1)], kBlue);
}

// Loop gives every vertex its colour by the positions' weights: an affine colour stays the
// same function of the new positions, and stays in [0, 1] (the weights are positive).
TEST(ColorAttributes, LoopKeepsColoursOnThePositionsWeights) {
    Mesh mesh = shapes::icosahedron();
    auto color = mesh.property<Vertex, Vec4>(kColorProperty);
    for (const Vertex v : mesh.vertices()) {
        color[v] = color_at(mesh.position(v));
    }
    loop_subdivide(mesh);
    loop_subdivide(mesh);
    color = mesh.get_property<Vertex, Vec4>(kColorProperty);
    ASSERT_TRUE(color);
    ASSERT_EQ(mesh.n_vertices(), 162u);
    for (const Vertex v : mesh.vertices()) {
        const Vec4 want = color_at(mesh.position(v));
        const Vec4 got = color[v];
        EXPECT_NEAR(got.x, want.x, 1e-12) << v.idx();
        EXPECT_NEAR(got.y, want.y, 1e-12) << v.idx();
        EXPECT_NEAR(got.z, want.z, 1e-12) << v.idx();
        EXPECT_EQ(got.w, 1.0) << v.idx();
        for (const double c : {got.x, got.y, got.z}) {
            EXPECT_TRUE(c >= 0.0 && c <= 1.0) << v.idx();
        }
    }
}

}  // namespace
}  // namespace meshedit
