// Tensor-product patches: evaluation, exact partials, normals at poles, and tessellation into
// a welded, consistently oriented mesh.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/topology.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

// Independent reference: Bernstein basis value B(n, i)(t) from factorials.
double basis(int n, int i, double t) {
    return std::tgamma(n + 1) / (std::tgamma(i + 1) * std::tgamma(n - i + 1)) * std::pow(t, i) *
           std::pow(1.0 - t, n - i);
}

// S, ∂S/∂u and ∂S/∂v as double sums over the control net (u runs along columns).
PatchPoint closed_form(const BezierPatch& p, double u, double v) {
    const int m = p.rows - 1, n = p.cols - 1;
    PatchPoint out;
    for (int r = 0; r <= m; ++r) {
        for (int c = 0; c <= n; ++c) {
            out.position += basis(m, r, v) * basis(n, c, u) * p.cp(r, c);
            if (c < n) {
                out.du += n * basis(m, r, v) * basis(n - 1, c, u) * (p.cp(r, c + 1) - p.cp(r, c));
            }
            if (r < m) {
                out.dv += m * basis(m - 1, r, v) * basis(n, c, u) * (p.cp(r + 1, c) - p.cp(r, c));
            }
        }
    }
    return out;
}

BezierPatch random_patch(int rows, int cols, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    BezierPatch p{rows, cols, {}};
    for (int i = 0; i < rows * cols; ++i) {
        p.control_points.push_back({coord(rng), coord(rng), coord(rng)});
    }
    return p;
}

// A quarter of a dome whose row 0 collapses to the apex (0,0,1): a pole at v = 0. Row 1
// lies level with the apex, so the surface is smooth there with tangent plane z = 1.
BezierPatch pole_patch() {
    BezierPatch p{4, 4, {}};
    const double height[4] = {1.0, 1.0, 0.6, 0.0};
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            const double a = c * (std::numbers::pi / 2.0) / 3.0, s = r / 3.0;
            p.control_points.push_back({s * std::cos(a), s * std::sin(a), height[r]});
        }
    }
    return p;
}

// Bicubic patches over a (3a+1) × (3b+1) control net of a height field, patch (i, j) using
// net rows 3i..3i+3 and columns 3j..3j+3, so neighbours share their boundary control points.
std::vector<BezierPatch> height_field_patches(int a, int b) {
    auto net = [&](int r, int c) {
        return Vec3(c, r, 0.3 * std::sin(0.7 * c + 1.3 * r) + 0.1 * r);
    };
    std::vector<BezierPatch> out;
    for (int i = 0; i < a; ++i) {
        for (int j = 0; j < b; ++j) {
            BezierPatch p{4, 4, {}};
            for (int r = 0; r < 4; ++r) {
                for (int c = 0; c < 4; ++c) {
                    p.control_points.push_back(net(3 * i + r, 3 * j + c));
                }
            }
            out.push_back(p);
        }
    }
    return out;
}

// The same surface traversed with u and v swapped: its normal points the other way.
BezierPatch transposed(const BezierPatch& p) {
    BezierPatch t{p.cols, p.rows, {}};
    for (int c = 0; c < p.cols; ++c) {
        for (int r = 0; r < p.rows; ++r) {
            t.control_points.push_back(p.cp(r, c));
        }
    }
    return t;
}

// A flat bicubic patch on a side of the cube [-1,1]^3: corner + u·e1 + v·e2 spread evenly.
BezierPatch flat_patch(const Vec3& corner, const Vec3& e1, const Vec3& e2) {
    BezierPatch p{4, 4, {}};
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            p.control_points.push_back(corner + (c / 3.0) * e1 + (r / 3.0) * e2);
        }
    }
    return p;
}

// Pairwise distances are all above the weld distance: no duplicate vertices survive.
::testing::AssertionResult no_duplicates(const Mesh& mesh, double tol) {
    const auto& p = mesh.position_vector();
    for (std::size_t i = 0; i < p.size(); ++i) {
        for (std::size_t j = i + 1; j < p.size(); ++j) {
            if (distance(p[i], p[j]) <= tol) {
                return ::testing::AssertionFailure() << "vertices " << i << " and " << j;
            }
        }
    }
    return ::testing::AssertionSuccess();
}

double weld_distance(const Mesh& mesh, const TessellationOptions& options = {}) {
    return options.weld_tolerance * mesh.bounds().diagonal();
}

TEST(BezierPatch, MatchesTensorProductBernstein) {
    for (const BezierPatch& p : {random_patch(4, 4, 1), random_patch(3, 5, 2)}) {
        for (int i = 0; i <= 10; ++i) {
            for (int j = 0; j <= 10; ++j) {
                const double u = i / 10.0, v = j / 10.0;
                const Vec3 expected = closed_form(p, u, v).position;
                EXPECT_LT(norm(p.evaluate(u, v) - expected), 1e-12) << u << " " << v;
                EXPECT_LT(norm(p.evaluate_bernstein(u, v) - expected), 1e-12);
            }
        }
    }
}

TEST(BezierPatch, InterpolatesCornersExactly) {
    const BezierPatch p = random_patch(3, 5, 3);
    EXPECT_EQ(p.evaluate(0, 0), p.cp(0, 0));
    EXPECT_EQ(p.evaluate(1, 0), p.cp(0, 4));
    EXPECT_EQ(p.evaluate(0, 1), p.cp(2, 0));
    EXPECT_EQ(p.evaluate(1, 1), p.cp(2, 4));
}

TEST(BezierPatch, PartialDerivativesAreExact) {
    for (const BezierPatch& p : {random_patch(4, 4, 4), random_patch(3, 5, 5)}) {
        for (int i = 0; i <= 10; ++i) {
            for (int j = 0; j <= 10; ++j) {
                const double u = i / 10.0, v = j / 10.0;
                const PatchPoint got = p.evaluate_with_derivatives(u, v);
                const PatchPoint want = closed_form(p, u, v);
                EXPECT_LT(norm(got.position - want.position), 1e-12);
                EXPECT_LT(norm(got.du - want.du), 1e-11) << u << " " << v;
                EXPECT_LT(norm(got.dv - want.dv), 1e-11) << u << " " << v;
                EXPECT_LT(norm(got.normal - normalize(cross(want.du, want.dv))), 1e-9);
            }
        }
    }
}

TEST(BezierPatch, FlatPatchIsTheParameterPlane) {
    // Evenly spread control points reproduce the bilinear map (linear precision).
    const BezierPatch p = flat_patch({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    const PatchPoint q = p.evaluate_with_derivatives(0.25, 0.6);
    EXPECT_LT(norm(q.position - Vec3(0.25, 0.6, 0)), 1e-15);
    EXPECT_LT(norm(q.du - Vec3(1, 0, 0)), 1e-14);
    EXPECT_LT(norm(q.dv - Vec3(0, 1, 0)), 1e-14);
    EXPECT_LT(norm(q.normal - Vec3(0, 0, 1)), 1e-14);
}

TEST(BezierPatch, NormalAtPoleIsTheLimit) {
    const BezierPatch p = pole_patch();
    for (double u : {0.0, 0.3, 0.5, 1.0}) {
        const PatchPoint pole = p.evaluate_with_derivatives(u, 0.0);
        EXPECT_EQ(pole.du, Vec3());  // the collapsed row has no u-extent
        EXPECT_NEAR(norm(pole.normal), 1.0, 1e-12);
        const PatchPoint near = p.evaluate_with_derivatives(u, 1e-3);
        EXPECT_GT(dot(pole.normal, near.normal), 0.999) << u;
    }
    // The apex is smooth with a horizontal tangent plane: the normal is the axis, and the
    // same from every direction u (up or down, as du × dv of the nearby points says).
    const double z = p.evaluate_with_derivatives(0.5, 1e-2).normal.z > 0.0 ? 1.0 : -1.0;
    for (double u : {0.0, 0.3, 0.5, 1.0}) {
        EXPECT_LT(norm(p.evaluate_with_derivatives(u, 0.0).normal - Vec3(0, 0, z)), 1e-5) << u;
    }
}

TEST(Tessellate, TwoByTwoPatchesWeldIntoOneGrid) {
    const std::vector<BezierPatch> patches = height_field_patches(2, 2);
    for (int d : {1, 4, 8}) {
        SCOPED_TRACE(d);
        const TessellationOptions options{d, 1e-7};
        const Mesh mesh = tessellate(patches, options);
        ASSERT_VALID(mesh);
        EXPECT_EQ(mesh.n_vertices(), std::size_t(2 * d + 1) * (2 * d + 1));
        EXPECT_EQ(mesh.n_faces(), std::size_t(8 * d * d));
        EXPECT_EQ(count_boundary_loops(mesh), 1u);
        EXPECT_EQ(euler_characteristic(mesh), 1);
        EXPECT_TRUE(no_duplicates(mesh, weld_distance(mesh, options)));
        // Columns run along +x (u) and rows along +y (v): du × dv faces up.
        for (Face f : mesh.faces()) {
            EXPECT_GT(face_normal(mesh, f).z, 0.0);
        }
    }
}

TEST(Tessellate, OrientsMixedPatchesConsistently) {
    // One patch of four traversed the other way round: the seam must not become a boundary.
    std::vector<BezierPatch> patches = height_field_patches(2, 2);
    patches[3] = transposed(patches[3]);
    const Mesh mesh = tessellate(patches, {4, 1e-7});
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.n_vertices(), 81u);
    EXPECT_EQ(mesh.n_faces(), 128u);
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
    for (Face f : mesh.faces()) {
        EXPECT_GT(face_normal(mesh, f).z, 0.0);  // the majority's orientation
    }
}

TEST(Tessellate, PoleTrianglesAreDropped) {
    // Row 0 welds into a single apex vertex; the d triangles touching it from the first row
    // of quads collapse and are dropped.
    const BezierPatch pole = pole_patch();
    for (int d : {2, 4, 7}) {
        SCOPED_TRACE(d);
        const TessellationOptions options{d, 1e-7};
        const Mesh mesh = tessellate(std::span(&pole, 1), options);
        ASSERT_VALID(mesh);
        EXPECT_EQ(mesh.n_vertices(), std::size_t(d * d + d + 1));
        EXPECT_EQ(mesh.n_faces(), std::size_t(2 * d * d - d));
        EXPECT_EQ(count_boundary_loops(mesh), 1u);
        EXPECT_TRUE(no_duplicates(mesh, weld_distance(mesh, options)));
    }
}

TEST(Tessellate, ClosedPatchCubeIsOutward) {
    // Six flat sides, three listed inside-out: the result is closed and outward.
    const std::vector<BezierPatch> sides{
        flat_patch({-1, -1, -1}, {0, 2, 0}, {0, 0, 2}),  // -x, inward
        flat_patch({1, -1, -1}, {0, 2, 0}, {0, 0, 2}),   // +x, outward
        flat_patch({-1, -1, -1}, {0, 0, 2}, {2, 0, 0}),  // -y, inward
        flat_patch({-1, 1, -1}, {2, 0, 0}, {0, 0, 2}),   // +y, inward
        flat_patch({-1, -1, -1}, {0, 2, 0}, {2, 0, 0}),  // -z, outward
        flat_patch({-1, -1, 1}, {2, 0, 0}, {0, 2, 0}),   // +z, outward
    };
    const int d = 3;
    const TessellationOptions options{d, 1e-7};
    const Mesh mesh = tessellate(sides, options);
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.n_vertices(), std::size_t(6 * d * d + 2));
    EXPECT_EQ(mesh.n_faces(), std::size_t(12 * d * d));
    EXPECT_EQ(count_boundary_loops(mesh), 0u);
    EXPECT_EQ(euler_characteristic(mesh), 2);
    EXPECT_NEAR(signed_volume(mesh), 8.0, 1e-12);
    EXPECT_TRUE(no_duplicates(mesh, weld_distance(mesh, options)));
}

TEST(Tessellate, WeldsAcrossTheToleranceOnly) {
    // Two side-by-side flat patches whose shared edge is off by 1e-9 (welded at the default
    // tolerance of 1e-7 × diagonal) or by 1e-3 (kept apart).
    for (double gap : {1e-9, 1e-3}) {
        const std::vector<BezierPatch> patches{flat_patch({0, 0, 0}, {1, 0, 0}, {0, 1, 0}),
                                               flat_patch({1 + gap, 0, 0}, {1, 0, 0}, {0, 1, 0})};
        const Mesh mesh = tessellate(patches, {2, 1e-7});
        ASSERT_VALID(mesh);
        EXPECT_EQ(mesh.n_vertices(), gap < 1e-6 ? 15u : 18u) << gap;
        EXPECT_EQ(count_boundary_loops(mesh), gap < 1e-6 ? 1u : 2u) << gap;
    }
}

// Tolerances are relative to each patch: a patch a long way off (or a huge one) once made
// the bounding box so big that the tolerance welded every other patch into nothing.
TEST(Tessellate, AFarOrHugePatchDoesNotWeldTheOthersAway) {
    const int d = 4;
    const std::vector<BezierPatch> grid = height_field_patches(2, 2);
    for (const BezierPatch& extra : {flat_patch({1e10, 0, 0}, {1, 0, 0}, {0, 1, 0}),
                                     flat_patch({5, 5, 5}, {1e10, 0, 0}, {0, 1e10, 0})}) {
        std::vector<BezierPatch> patches = grid;
        patches.push_back(extra);
        const Mesh mesh = tessellate(patches, {d, 1e-7});
        ASSERT_VALID(mesh);
        EXPECT_EQ(mesh.n_vertices(), std::size_t((2 * d + 1) * (2 * d + 1) + (d + 1) * (d + 1)));
        EXPECT_EQ(mesh.n_faces(), std::size_t(8 * d * d + 2 * d * d));
        EXPECT_EQ(count_boundary_loops(mesh), 2u);
    }
}

TEST(Tessellate, NoPatchesGiveAnEmptyMesh) {
    const Mesh mesh = tessellate({});
    ASSERT_VALID(mesh);
    EXPECT_TRUE(mesh.is_empty());
}

// A wavy bicubic patch scaled to 1e200, 1e-200 and ±1.7e308: du × dv overflowed (a NaN
// normal) or underflowed (a zero one). Scaled evaluation gives the unit patch's normal and
// its position times the scale.
TEST(BezierPatch, HugeAndTinyPatchesEvaluateLikeTheUnitOne) {
    BezierPatch unit;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            unit.control_points.push_back({c / 1.5 - 1.0, r / 1.5 - 1.0, 0.3 * ((r * c) % 3 - 1)});
        }
    }
    for (const double scale : {1e200, 1e-200, 1.7e308}) {
        SCOPED_TRACE(scale);
        BezierPatch big = unit;
        for (Vec3& p : big.control_points) {
            p = scale * p;
        }
        for (const auto& [u, v] : {std::pair{0.5, 0.5}, {0.3, 0.6}, {0.0, 1.0}}) {
            const PatchPoint a = unit.evaluate_with_derivatives(u, v);
            const PatchPoint b = big.evaluate_with_derivatives(u, v);
            EXPECT_LT(norm(b.normal - a.normal), 1e-12) << u << " " << v;
            EXPECT_LT(norm(b.position / scale - a.position), 1e-12) << u << " " << v;
            EXPECT_LT(norm(big.evaluate(u, v) / scale - a.position), 1e-12) << u << " " << v;
        }
    }
}

}  // namespace
}  // namespace meshedit
