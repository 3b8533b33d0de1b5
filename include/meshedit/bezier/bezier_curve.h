#pragma once
/// \file
/// De Casteljau evaluation, the one routine behind curves of any degree and patches.
///
/// A Bezier curve of degree n has n+1 control points P0…Pn and is defined for t in [0, 1]
/// (values outside extrapolate the same polynomial). De Casteljau's algorithm repeatedly
/// linearly interpolates neighbouring points at t; level 0 is the control polygon, level k
/// has n+1−k points, and the single point of level n is B(t). Curves in the viewer are 2D:
/// they use z = 0.

#include <span>
#include <vector>

#include "meshedit/core/math.h"

namespace meshedit {

/// One de Casteljau step: `out[i] = lerp(in[i], in[i+1], t)`; `out` gets in.size()−1 points.
/// `in` may view `out` itself (an in-place step). \pre in.size() >= 2.
void de_casteljau_step(std::span<const Vec3> in, double t, std::vector<Vec3>& out);

/// The core routine: reduces `points` in place by de Casteljau steps and returns B(t); the
/// buffer is consumed (callers reuse its capacity). If `derivative` is given it receives
/// B'(t) = n · (Q1 − Q0) from the last-but-one level {Q0, Q1} (zero for degree 0).
/// \pre !points.empty().
Vec3 de_casteljau_reduce(std::vector<Vec3>& points, double t, Vec3* derivative = nullptr);

/// Levels 0 … `max_level` of de Casteljau's algorithm at `t` (`max_level` < 0 or past the
/// last: every level): `levels[0]` are the control points, `levels[k]` has one point fewer
/// than `levels[k-1]`; with every level, `levels.back()` is the single point B(t). Only the
/// levels asked for are computed (a long curve's all levels hold n(n+1)/2 points).
/// \pre control.size() >= 1.
std::vector<std::vector<Vec3>> de_casteljau_levels(std::span<const Vec3> control, double t,
                                                   int max_level = -1);

/// How many points levels 0 … `max_level` of a curve of `n_points` control points hold
/// together (`max_level` < 0: all, n(n+1)/2): the size every caller that shows or prints
/// levels checks against the memory budget (core/budget.h) first, as it grows with n².
double de_casteljau_level_points(std::size_t n_points, int max_level = -1);

/// Past this many control points de_casteljau() evaluates by bernstein_linear(): repeated
/// lerps cost n²/2 (a curve of 300,000 points took 30 s to evaluate at one t).
inline constexpr std::size_t kDeCasteljauLongCurve = 2048;

/// B(t) in time linear in n: the Bernstein sum, each weight from its neighbour's by the
/// ratio of consecutive Bernstein polynomials, walking out from the largest and normalised
/// by their sum (stable: positive weights, no cancellation, no overflow of C(n, i)).
/// Exactly P0 at t = 0 and Pn at t = 1. \pre control.size() >= 1.
Vec3 bernstein_linear(std::span<const Vec3> control, double t);

/// B(t): by de Casteljau (repeated lerp) up to kDeCasteljauLongCurve points, so short curves
/// give exactly the lerps' values, by bernstein_linear() past it. \pre control.size() >= 1.
Vec3 de_casteljau(std::span<const Vec3> control, double t);

/// Derivative B'(t) = n · Σ (P(i+1) − P(i)) B(n-1,i)(t), taken from the last-but-one de
/// Casteljau level as n · (Q1 − Q0) (the same polynomial). Zero for a single point.
Vec3 de_casteljau_derivative(std::span<const Vec3> control, double t);

/// B(t) by the closed Bernstein form Σ C(n,i) tⁱ (1−t)ⁿ⁻ⁱ Pᵢ; tests compare against it.
Vec3 bernstein(std::span<const Vec3> control, double t);

/// A Bezier curve: control points plus conveniences.
struct BezierCurve {
    std::vector<Vec3> control_points;

    int degree() const { return static_cast<int>(control_points.size()) - 1; }
    Vec3 evaluate(double t) const { return de_casteljau(control_points, t); }
    std::vector<std::vector<Vec3>> levels(double t) const {
        return de_casteljau_levels(control_points, t);
    }
    /// `samples + 1` points at t = i / samples.
    std::vector<Vec3> polyline(int samples) const;
};

}  // namespace meshedit
