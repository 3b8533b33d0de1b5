// De Casteljau's algorithm: the single evaluation routine for curves and patches. Everything
// here is repeated linear interpolation of a span of points; the Bernstein form exists only
// as an independent reference for tests.

#include "meshedit/bezier/bezier_curve.h"

#include <algorithm>
#include <cmath>

#include "meshedit/core/assert.h"

namespace meshedit {

void de_casteljau_step(std::span<const Vec3> in, double t, std::vector<Vec3>& out) {
    MESHEDIT_ASSERT(in.size() >= 2);
    const std::size_t n = in.size() - 1;
    // Writing out[i] only reads in[i] and in[i+1], so `in` may view `out` itself (in-place
    // reduction); shrinking a vector never reallocates, so the view stays valid.
    if (out.size() < n) {
        out.resize(n);
    }
    for (std::size_t i = 0; i < n; ++i) {
        out[i] = lerp(in[i], in[i + 1], t);
    }
    out.resize(n);
}

Vec3 de_casteljau_reduce(std::vector<Vec3>& points, double t, Vec3* derivative) {
    MESHEDIT_ASSERT(!points.empty());
    const double degree = static_cast<double>(points.size() - 1);
    while (points.size() > 2) {
        de_casteljau_step(points, t, points);
    }
    if (points.size() == 1) {
        if (derivative != nullptr) {
            *derivative = Vec3{};
        }
        return points[0];
    }
    // The last-but-one level (two points) gives the exact tangent: B'(t) = n (Q1 − Q0).
    if (derivative != nullptr) {
        *derivative = degree * (points[1] - points[0]);
    }
    return lerp(points[0], points[1], t);
}

std::vector<std::vector<Vec3>> de_casteljau_levels(std::span<const Vec3> control, double t,
                                                   int max_level) {
    MESHEDIT_ASSERT(!control.empty());
    const std::size_t count =
        max_level < 0 ? control.size()
                      : std::min(control.size(), static_cast<std::size_t>(max_level) + 1);
    std::vector<std::vector<Vec3>> levels;
    levels.reserve(count);
    levels.emplace_back(control.begin(), control.end());
    while (levels.size() < count) {
        std::vector<Vec3> next;
        de_casteljau_step(levels.back(), t, next);
        levels.push_back(std::move(next));
    }
    return levels;
}

double de_casteljau_level_points(std::size_t n_points, int max_level) {
    const double n = static_cast<double>(n_points);
    const double levels =
        max_level < 0 ? n : std::min(n, static_cast<double>(max_level) + 1.0);  // 0 … max
    // Level k holds n − k points: the sum over k < levels.
    return levels * n - levels * (levels - 1.0) / 2.0;
}

Vec3 bernstein_linear(std::span<const Vec3> control, double t) {
    MESHEDIT_ASSERT(!control.empty());
    const std::size_t n = control.size() - 1;
    if (!(t > 0.0)) {  // t = 0 (and NaN, which the callers refuse): exactly the first point
        return control.front();
    }
    if (!(t < 1.0)) {
        return control.back();
    }
    // Weights relative to the largest, B(n, m)(t) at the mode m = floor((n + 1) t), by the
    // ratio B(n, i+1) / B(n, i) = (n − i) / (i + 1) · t / (1 − t) outward from it: every
    // weight is in [0, 1], none is a difference, and past ~40 standard deviations they
    // underflow to 0 and stop the walk. Dividing by their sum normalises away the
    // unnormalised start (C(n, m) tᵐ (1−t)ⁿ⁻ᵐ itself under- or overflows for long curves).
    const double ratio = t / (1.0 - t);
    const std::size_t mode =
        std::min(n, static_cast<std::size_t>(std::floor(static_cast<double>(n + 1) * t)));
    Vec3 sum = control[mode];
    double total = 1.0;
    double w = 1.0;
    for (std::size_t i = mode; i < n && w > 0.0; ++i) {
        w *= static_cast<double>(n - i) / static_cast<double>(i + 1) * ratio;
        sum += w * control[i + 1];
        total += w;
    }
    w = 1.0;
    for (std::size_t i = mode; i > 0 && w > 0.0; --i) {
        w *= static_cast<double>(i) / static_cast<double>(n - i + 1) / ratio;
        sum += w * control[i - 1];
        total += w;
    }
    return sum / total;
}

Vec3 de_casteljau(std::span<const Vec3> control, double t) {
    if (control.size() > kDeCasteljauLongCurve) {
        return bernstein_linear(control, t);
    }
    std::vector<Vec3> points(control.begin(), control.end());
    return de_casteljau_reduce(points, t, nullptr);
}

Vec3 de_casteljau_derivative(std::span<const Vec3> control, double t) {
    MESHEDIT_ASSERT(!control.empty());
    std::vector<Vec3> points(control.begin(), control.end());
    Vec3 derivative;
    de_casteljau_reduce(points, t, &derivative);
    return derivative;
}

Vec3 bernstein(std::span<const Vec3> control, double t) {
    MESHEDIT_ASSERT(!control.empty());
    const int n = static_cast<int>(control.size()) - 1;
    Vec3 sum;
    double binomial = 1.0;  // C(n, i), updated incrementally
    for (int i = 0; i <= n; ++i) {
        sum += binomial * std::pow(t, i) * std::pow(1.0 - t, n - i) * control[i];
        binomial = binomial * (n - i) / (i + 1);
    }
    return sum;
}

std::vector<Vec3> BezierCurve::polyline(int samples) const {
    MESHEDIT_ASSERT(samples >= 1);
    std::vector<Vec3> out;
    out.reserve(samples + 1);
    for (int i = 0; i <= samples; ++i) {
        // i == samples gives exactly t = 1, so the polyline ends on the last control point.
        out.push_back(evaluate(static_cast<double>(i) / samples));
    }
    return out;
}

}  // namespace meshedit
