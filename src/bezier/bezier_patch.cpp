// Tensor-product patch evaluation: every row is reduced in u with the curve routine, then the
// resulting column is reduced in v. Derivatives come from the same reductions.

#include "meshedit/bezier/bezier_patch.h"

#include <algorithm>
#include <cmath>

#include "meshedit/bezier/bezier_curve.h"
#include "meshedit/core/assert.h"

namespace meshedit {
namespace {

// Value and u-derivative of every row at u, then value and both partials from the columns.
// `normal` is left unset.
PatchPoint evaluate_partials(const BezierPatch& patch, double u, double v) {
    MESHEDIT_ASSERT(patch.rows >= 1 && patch.cols >= 1);
    MESHEDIT_ASSERT(patch.control_points.size() == std::size_t(patch.rows) * patch.cols);
    std::vector<Vec3> row;
    std::vector<Vec3> column(patch.rows);
    std::vector<Vec3> column_du(patch.rows);
    for (int r = 0; r < patch.rows; ++r) {
        const auto first = patch.control_points.begin() + std::ptrdiff_t(r) * patch.cols;
        row.assign(first, first + patch.cols);
        column[r] = de_casteljau_reduce(row, u, &column_du[r]);
    }
    PatchPoint p;
    // ∂S/∂u is the v-curve through the rows' u-derivatives (differentiation commutes with
    // the tensor product).
    p.du = de_casteljau_reduce(column_du, v);
    p.position = de_casteljau_reduce(column, v, &p.dv);
    return p;
}

// du × dv vanishes (or loses all precision) where a row or column of control points
// collapses to a point, as at the poles of a patch-built sphere or the teapot lid's tip.
bool is_degenerate(const Vec3& du, const Vec3& dv, const Vec3& n) {
    const double scale = std::max(sqrnorm(du), sqrnorm(dv));
    return !(norm(n) > 1e-12 * scale) || scale == 0.0;
}

// The exponent e of the largest control coordinate (in [2^(e−1), 2^e)) when it is far from
// 1, else 0. Past 2^256 the cross product du × dv overflows long before the coordinates do,
// and near 1.7e308 a lerp's difference b − a itself overflows (a ±1.7e308 patch evaluated to
// 1e292 at its centre, with a zero normal); below 2^−256 the cross product underflows. Such
// a patch is evaluated scaled by 2^−e, exactly (a power of two), and its results scaled back.
int far_exponent(const BezierPatch& patch) {
    double largest = 0.0;
    for (const Vec3& p : patch.control_points) {
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    int exponent = 0;
    if (largest > 0.0 && std::isfinite(largest)) {
        std::frexp(largest, &exponent);
    }
    return std::abs(exponent) > 256 ? exponent : 0;
}

BezierPatch scaled(const BezierPatch& patch, int exponent) {
    BezierPatch out = patch;
    for (Vec3& p : out.control_points) {
        p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent)};
    }
    return out;
}

Vec3 unscaled(const Vec3& p, int exponent) {
    return {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent)};
}

}  // namespace

Vec3 BezierPatch::evaluate(double u, double v) const {
    MESHEDIT_ASSERT(control_points.size() == std::size_t(rows) * cols);
    if (const int exponent = far_exponent(*this); exponent != 0) {
        return unscaled(scaled(*this, -exponent).evaluate(u, v), exponent);
    }
    std::vector<Vec3> row;
    std::vector<Vec3> column(rows);
    for (int r = 0; r < rows; ++r) {
        const auto first = control_points.begin() + std::ptrdiff_t(r) * cols;
        row.assign(first, first + cols);
        column[r] = de_casteljau_reduce(row, u);
    }
    return de_casteljau_reduce(column, v);
}

PatchPoint BezierPatch::evaluate_with_derivatives(double u, double v) const {
    if (const int exponent = far_exponent(*this); exponent != 0) {
        PatchPoint p = scaled(*this, -exponent).evaluate_with_derivatives(u, v);
        p.position = unscaled(p.position, exponent);
        p.du = unscaled(p.du, exponent);
        p.dv = unscaled(p.dv, exponent);
        return p;  // the unit normal does not change with the scale
    }
    PatchPoint p = evaluate_partials(*this, u, v);
    Vec3 n = cross(p.du, p.dv);
    // At a degenerate point take the normal slightly inside the patch: as the inset shrinks
    // it converges to the limit normal (at a pole, the direction of ∂²S/∂u∂v × ∂S/∂v), and
    // the inset direction makes the sign agree with the neighbouring regular points.
    if (is_degenerate(p.du, p.dv, n)) {
        for (double delta = 1e-6; delta < 0.5; delta *= 100.0) {
            const double ui = u + (u < 0.5 ? delta : -delta);
            const double vi = v + (v < 0.5 ? delta : -delta);
            const PatchPoint q = evaluate_partials(*this, ui, vi);
            n = cross(q.du, q.dv);
            if (!is_degenerate(q.du, q.dv, n)) {
                break;
            }
        }
    }
    p.normal = normalize(n);
    return p;
}

Vec3 BezierPatch::evaluate_bernstein(double u, double v) const {
    MESHEDIT_ASSERT(control_points.size() == std::size_t(rows) * cols);
    // Σ_r B(rows-1, r)(v) · Σ_c B(cols-1, c)(u) · P(r, c), each sum by bernstein().
    std::vector<Vec3> column(rows);
    for (int r = 0; r < rows; ++r) {
        column[r] = bernstein(
            std::span<const Vec3>(control_points).subspan(std::size_t(r) * cols, std::size_t(cols)),
            u);
    }
    return bernstein(column, v);
}

}  // namespace meshedit
