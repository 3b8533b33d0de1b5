// Remeshing carries attributes by projection onto its input (issue 32, item 6): texture
// coordinate seams and material borders stay as features, and each corner, vertex colour and
// face material is taken from the closest input triangle of its own chart.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/validate.h"
#include "support/fixtures.h"
#include "support/textured_torus.h"

namespace meshedit {
namespace {

RemeshOptions length(double target) {
    RemeshOptions options;
    options.target_length = target;
    return options;
}

// The box map of a flat-sided cube: on the face whose normal is ±axis k, the two other
// coordinates (an affine function of the position on each face, a chart per face).
int axis_of(const Vec3& normal) {
    const double a[3] = {std::abs(normal.x), std::abs(normal.y), std::abs(normal.z)};
    return a[0] >= a[1] && a[0] >= a[2] ? 0 : a[1] >= a[2] ? 1 : 2;
}
Vec2 box_uv(const Vec3& p, const Vec3& normal) {
    const double c[3] = {p.x, p.y, p.z};
    const int k = axis_of(normal);
    const double sign = (k == 0 ? normal.x : k == 1 ? normal.y : normal.z) > 0 ? 1.0 : -1.0;
    return {c[(k + 1) % 3] + 3.0 * sign, c[(k + 2) % 3] + 5.0 * k};
}

// Colours an affine function of the position: exact wherever a point lies on the input.
Vec4 affine_color(const Vec3& p) {
    return {0.5 + 0.1 * p.x, 0.5 - 0.2 * p.y, 0.25 + 0.3 * p.z, 1.0};
}

// `cube` remeshed to edges of 0.1: valid, and with enough splits and collapses to mean it.
Mesh remeshed(const Mesh& cube) {
    Mesh out = cube;
    const RemeshReport report = remesh(out, length(0.1));
    EXPECT_FALSE(validate(out));
    EXPECT_GT(report.splits + report.collapses, 100u);
    return out;
}

// How many of the flat-sided cube's planes p lies on (0: it left the cube).
int cube_planes(const Vec3& p) {
    const double s = 1.0 / std::sqrt(3.0);
    int on_planes = 0;
    for (const double c : {p.x, p.y, p.z}) {
        on_planes += std::abs(std::abs(c) - s) < 1e-12;
    }
    return on_planes;
}

// A box-mapped cube: every cube edge is a seam (the faces' charts meet there) and no edge is
// creased, so only the seams keep the cube sharp; every corner's texture coordinates come
// out as its face's box map of its vertex, to rounding.
TEST(RemeshAttributes, SeamsStayAndCornersAreProjectedInTheirChart) {
    Mesh cube = test::flat_sided_cube();
    auto uv = cube.add_property<Halfedge, Vec2>(kTexCoordProperty);
    auto color = cube.add_property<Vertex, Vec4>(kColorProperty);
    for (const Face f : cube.faces()) {
        const Vec3 n = face_normal(cube, f);
        for (const Halfedge h : cube.halfedges(f)) {
            uv[h] = box_uv(cube.position(cube.to_vertex(h)), n);
        }
    }
    for (const Vertex v : cube.vertices()) {
        color[v] = affine_color(cube.position(v));
    }
    const Mesh out = remeshed(cube);
    const auto out_uv = out.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const auto out_color = out.get_property<Vertex, Vec4>(kColorProperty);
    ASSERT_TRUE(out_uv && out_color);
    int corners = 0;
    for (const Vertex v : out.vertices()) {
        const Vec3& p = out.position(v);
        const int on_planes = cube_planes(p);
        ASSERT_GE(on_planes, 1) << "vertex " << v.idx() << " left the cube: the seams did not hold";
        corners += on_planes == 3;
        const Vec4 want = affine_color(p), got = out_color[v];
        EXPECT_NEAR(got.x, want.x, 1e-12);
        EXPECT_NEAR(got.y, want.y, 1e-12);
        EXPECT_NEAR(got.z, want.z, 1e-12);
    }
    EXPECT_EQ(corners, 8);
    for (const Face f : out.faces()) {
        const Vec3 n = face_normal(out, f);
        for (const Halfedge h : out.halfedges(f)) {
            const Vec2 want = box_uv(out.position(out.to_vertex(h)), n);
            ASSERT_NEAR(out_uv[h].x, want.x, 1e-12) << "face " << f.idx();
            ASSERT_NEAR(out_uv[h].y, want.y, 1e-12) << "face " << f.idx();
        }
    }
}

// The second texture coordinate set alone box-maps the cube (the first is seamless, an affine
// function of the position): its seams alone keep the cube sharp, and each set's corners are
// projected in their own chart.
TEST(RemeshAttributes, SecondSetSeamsHoldAndItsCornersAreProjected) {
    Mesh cube = test::flat_sided_cube();
    auto uv0 = cube.add_property<Halfedge, Vec2>(kTexCoordProperty);
    auto uv1 = cube.add_property<Halfedge, Vec2>(kTexCoord1Property);
    const auto seamless = [](const Vec3& p) { return Vec2{p.x + 0.5 * p.z, p.y - p.z}; };
    for (const Face f : cube.faces()) {
        const Vec3 n = face_normal(cube, f);
        for (const Halfedge h : cube.halfedges(f)) {
            uv0[h] = seamless(cube.position(cube.to_vertex(h)));
            uv1[h] = box_uv(cube.position(cube.to_vertex(h)), n);
        }
    }
    const Mesh out = remeshed(cube);
    const auto out0 = out.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const auto out1 = out.get_property<Halfedge, Vec2>(kTexCoord1Property);
    ASSERT_TRUE(out0 && out1);
    for (const Vertex v : out.vertices()) {
        ASSERT_GE(cube_planes(out.position(v)), 1)
            << "vertex " << v.idx() << " left the cube: the seams did not hold";
    }
    for (const Face f : out.faces()) {
        const Vec3 n = face_normal(out, f);
        for (const Halfedge h : out.halfedges(f)) {
            const Vec3& p = out.position(out.to_vertex(h));
            const Vec2 want0 = seamless(p), want1 = box_uv(p, n);
            ASSERT_NEAR(out0[h].x, want0.x, 1e-12) << "face " << f.idx();
            ASSERT_NEAR(out0[h].y, want0.y, 1e-12) << "face " << f.idx();
            ASSERT_NEAR(out1[h].x, want1.x, 1e-12) << "face " << f.idx();
            ASSERT_NEAR(out1[h].y, want1.y, 1e-12) << "face " << f.idx();
        }
    }
}

// A torus (no seam in its colours) remeshed finer: every vertex ends on the input surface, so
// an affine colour is exact there; carried alone, the smoothing steps left it behind.
TEST(RemeshAttributes, VertexColoursFollowTheSurface) {
    Mesh torus = shapes::torus(40, 20);
    auto color = torus.add_property<Vertex, Vec4>(kColorProperty);
    for (const Vertex v : torus.vertices()) {
        color[v] = affine_color(torus.position(v));
    }
    remesh(torus, length(0.08));
    const auto out = torus.get_property<Vertex, Vec4>(kColorProperty);
    double worst = 0.0;
    for (const Vertex v : torus.vertices()) {
        const Vec4 want = affine_color(torus.position(v));
        worst = std::max({worst, std::abs(out[v].x - want.x), std::abs(out[v].y - want.y),
                          std::abs(out[v].z - want.z)});
    }
    EXPECT_LT(worst, 1e-12);
}

// Two materials on a flat grid, the border at x = 0.5: it stays a straight feature line, and
// every face takes the material of the side it lies on.
TEST(RemeshAttributes, MaterialBordersStayAndFacesKeepTheirSide) {
    Mesh grid = shapes::grid(12, 12);  // [0, 1]², triangles
    grid.materials().resize(2);
    auto material = grid.add_property<Face, std::uint32_t>(kMaterialProperty, 0);
    for (const Face f : grid.faces()) {
        Vec3 c;
        for (const Vertex v : grid.vertices(f)) {
            c += grid.position(v);
        }
        material[f] = c.x / 3.0 < 0.5 ? 0 : 1;
    }
    remesh(grid, length(0.03));
    ASSERT_FALSE(validate(grid));
    const auto out = grid.get_property<Face, std::uint32_t>(kMaterialProperty);
    std::size_t border = 0;
    for (const Face f : grid.faces()) {
        Vec3 c;
        for (const Vertex v : grid.vertices(f)) {
            c += grid.position(v);
        }
        EXPECT_EQ(out[f], c.x / 3.0 < 0.5 ? 0u : 1u) << "face " << f.idx();
    }
    for (const Edge e : grid.edges()) {
        if (!grid.is_boundary(e) && out[grid.face(e, 0)] != out[grid.face(e, 1)]) {
            ++border;
            for (int i = 0; i < 2; ++i) {
                EXPECT_EQ(grid.position(grid.vertex(e, i)).x, 0.5);
            }
        }
    }
    EXPECT_GE(border, 20u);  // a border of length 1 at edges of about 0.03
}

// The UV torus (two seam loops where the angles wrap): after remeshing no face spans a seam
// (its corners' u and v each within a quarter turn: a corner took the far side's values
// would be most of a turn away) and the seams are still there.
TEST(RemeshAttributes, TorusSeamsStayLoops) {
    Mesh torus = test::uv_torus(48, 24);
    remesh(torus, length(0.12));
    ASSERT_FALSE(validate(torus));
    const auto uv = torus.get_property<Halfedge, Vec2>(kTexCoordProperty);
    std::size_t seams = 0;
    for (const Face f : torus.faces()) {
        double lo_u = 9, hi_u = -9, lo_v = 9, hi_v = -9;
        for (const Halfedge h : torus.halfedges(f)) {
            lo_u = std::min(lo_u, uv[h].x), hi_u = std::max(hi_u, uv[h].x);
            lo_v = std::min(lo_v, uv[h].y), hi_v = std::max(hi_v, uv[h].y);
        }
        EXPECT_LT(hi_u - lo_u, 0.25) << "face " << f.idx() << " spans the u seam";
        EXPECT_LT(hi_v - lo_v, 0.25) << "face " << f.idx() << " spans the v seam";
    }
    for (const Edge e : torus.edges()) {
        const Halfedge h = torus.halfedge(e, 0), t = torus.halfedge(e, 1);
        seams += !(uv[h] == uv[torus.prev(t)]);
    }
    EXPECT_GT(seams, 50u);
}

}  // namespace
}  // namespace meshedit
