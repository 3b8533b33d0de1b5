// De Casteljau curves against the closed Bernstein form, level structure and derivatives.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "meshedit/bezier/bezier_curve.h"

namespace meshedit {
namespace {

std::vector<Vec3> random_points(std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::vector<Vec3> p(count);
    for (Vec3& q : p) {
        q = {coord(rng), coord(rng), coord(rng)};
    }
    return p;
}

double parameter(int k) {
    return k / 100.0;
}  // 101 values, 0 and 1 exact

TEST(DeCasteljau, HandComputedQuadratic) {
    // Midpoints (0.5,1,0) and (1.5,1,0), then their midpoint.
    const std::vector<Vec3> p{{0, 0, 0}, {1, 2, 0}, {2, 0, 0}};
    EXPECT_EQ(de_casteljau(p, 0.5), Vec3(1, 1, 0));
    EXPECT_EQ(de_casteljau_derivative(p, 0.5), Vec3(2, 0, 0));
    EXPECT_EQ(de_casteljau_derivative(p, 0.0), Vec3(2, 4, 0));  // 2 (P1 − P0)
}

TEST(DeCasteljau, MatchesBernsteinForDegreesOneToTen) {
    std::mt19937_64 rng(20240501);
    for (int degree = 1; degree <= 10; ++degree) {
        const std::vector<Vec3> p = random_points(rng, degree + 1);
        for (int k = 0; k <= 100; ++k) {
            const double t = parameter(k);
            EXPECT_LT(norm(de_casteljau(p, t) - bernstein(p, t)), 1e-12)
                << "degree " << degree << " t " << t;
        }
    }
}

TEST(DeCasteljau, InterpolatesEndpointsExactly) {
    std::mt19937_64 rng(7);
    for (int degree = 0; degree <= 10; ++degree) {
        const std::vector<Vec3> p = random_points(rng, degree + 1);
        EXPECT_EQ(de_casteljau(p, 0.0), p.front()) << degree;
        EXPECT_EQ(de_casteljau(p, 1.0), p.back()) << degree;
    }
}

TEST(DeCasteljau, LevelsShrinkByOneAndAreLerps) {
    std::mt19937_64 rng(11);
    for (int degree = 0; degree <= 10; ++degree) {
        const std::vector<Vec3> p = random_points(rng, degree + 1);
        for (double t : {0.0, 0.3, 0.5, 1.0}) {
            const auto levels = de_casteljau_levels(p, t);
            ASSERT_EQ(levels.size(), p.size());
            EXPECT_EQ(levels.front(), p);
            for (std::size_t k = 1; k < levels.size(); ++k) {
                ASSERT_EQ(levels[k].size(), levels[k - 1].size() - 1);
                for (std::size_t i = 0; i < levels[k].size(); ++i) {
                    EXPECT_EQ(levels[k][i], lerp(levels[k - 1][i], levels[k - 1][i + 1], t));
                }
            }
            ASSERT_EQ(levels.back().size(), 1u);
            EXPECT_EQ(levels.back()[0], de_casteljau(p, t));
        }
    }
}

TEST(DeCasteljau, OnlyTheLevelsAskedForAreComputed) {
    std::mt19937_64 rng(12);
    const std::vector<Vec3> p = random_points(rng, 8);
    const auto all = de_casteljau_levels(p, 0.3);
    for (int max_level : {0, 1, 3, 7, 8, 100}) {
        const auto some = de_casteljau_levels(p, 0.3, max_level);
        ASSERT_EQ(some.size(), std::min<std::size_t>(static_cast<std::size_t>(max_level) + 1, 8));
        for (std::size_t k = 0; k < some.size(); ++k) {
            EXPECT_EQ(some[k], all[k]) << max_level << " " << k;
        }
    }
    // A curve of a million points: its first two levels, not the 5·10¹¹ points of all of them
    // (which took the renderer to std::bad_alloc on a 390 KB file).
    const std::vector<Vec3> long_curve = random_points(rng, 1'000'000);
    const auto first = de_casteljau_levels(long_curve, 0.5, 1);
    ASSERT_EQ(first.size(), 2u);
    EXPECT_EQ(first[1].size(), 999'999u);
}

TEST(DeCasteljau, StepWorksInPlace) {
    std::vector<Vec3> p{{0, 0, 0}, {2, 0, 0}, {2, 4, 0}};
    de_casteljau_step(p, 0.25, p);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0], Vec3(0.5, 0, 0));
    EXPECT_EQ(p[1], Vec3(2, 1, 0));
}

TEST(DeCasteljau, DerivativeMatchesClosedFormAndFiniteDifference) {
    std::mt19937_64 rng(99);
    for (int degree = 1; degree <= 10; ++degree) {
        const std::vector<Vec3> p = random_points(rng, degree + 1);
        // Closed form: n · Bernstein of the forward differences.
        std::vector<Vec3> diff;
        for (int i = 0; i < degree; ++i) {
            diff.push_back(degree * (p[i + 1] - p[i]));
        }
        for (int k = 0; k <= 100; ++k) {
            const double t = parameter(k);
            const Vec3 d = de_casteljau_derivative(p, t);
            EXPECT_LT(norm(d - bernstein(diff, t)), 1e-11) << degree << " " << t;
            // Central difference (one-sided at the ends), O(h²) resp. O(h) accurate.
            const double h = 1e-6;
            const double t0 = std::max(0.0, t - h), t1 = std::min(1.0, t + h);
            const Vec3 fd = (de_casteljau(p, t1) - de_casteljau(p, t0)) / (t1 - t0);
            EXPECT_LT(norm(d - fd), 1e-3 * std::max(1.0, norm(d))) << degree << " " << t;
        }
    }
    EXPECT_EQ(de_casteljau_derivative(std::vector<Vec3>{{1, 2, 3}}, 0.5), Vec3());
}

TEST(DeCasteljau, ReduceReturnsValueAndTangentTogether) {
    std::mt19937_64 rng(5);
    const std::vector<Vec3> p = random_points(rng, 6);
    std::vector<Vec3> buffer = p;
    Vec3 tangent;
    const Vec3 value = de_casteljau_reduce(buffer, 0.4, &tangent);
    EXPECT_EQ(value, de_casteljau(p, 0.4));
    EXPECT_EQ(tangent, de_casteljau_derivative(p, 0.4));
}

// The linear-time form against repeated lerps on curves just past the switch, where both are
// affordable: the same polynomial, to 1e-12 of the curve's size.
TEST(DeCasteljau, LinearFormMatchesLerpsOnLongCurves) {
    std::mt19937_64 rng(39);
    for (const int count : {2, 7, 300, static_cast<int>(kDeCasteljauLongCurve) + 1, 5000}) {
        const std::vector<Vec3> p = random_points(rng, count);
        for (const double t : {0.0, 1e-300, 1e-9, 0.013, 0.25, 0.5, 0.77, 1.0 - 1e-12, 1.0}) {
            std::vector<Vec3> buffer = p;
            const Vec3 lerps = de_casteljau_reduce(buffer, t);
            EXPECT_LT(norm(bernstein_linear(p, t) - lerps), 1e-12) << count << " " << t;
            EXPECT_LT(norm(de_casteljau(p, t) - lerps), 1e-12) << count << " " << t;
        }
        EXPECT_EQ(bernstein_linear(p, 0.0), p.front());
        EXPECT_EQ(bernstein_linear(p, 1.0), p.back());
    }
}

// A curve of a million points, evaluated in a moment (n²/2 lerps took minutes): with Pᵢ =
// (i/n, (i/n)²) the sum is exactly (t, t² + t(1−t)/n) and (7, 7, 7) stays (7, 7, 7).
TEST(DeCasteljau, MillionPointCurveIsEvaluatedInLinearTime) {
    const std::size_t n = 1'000'000;
    std::vector<Vec3> p(n + 1);
    std::vector<Vec3> flat(n + 1, Vec3(7, 7, 7));
    for (std::size_t i = 0; i <= n; ++i) {
        const double x = static_cast<double>(i) / n;
        p[i] = {x, x * x, 0.0};
    }
    const BezierCurve curve{p};
    for (const double t : {0.0, 1e-7, 0.1, 0.5, 0.999999, 1.0}) {
        const Vec3 b = curve.evaluate(t);
        EXPECT_NEAR(b.x, t, 1e-12) << t;
        EXPECT_NEAR(b.y, t * t + t * (1.0 - t) / n, 1e-12) << t;
        EXPECT_LT(norm(de_casteljau(flat, t) - Vec3(7, 7, 7)), 1e-12) << t;
    }
    const std::vector<Vec3> line = curve.polyline(200);
    ASSERT_EQ(line.size(), 201u);
    EXPECT_EQ(line.back(), p.back());
    EXPECT_NEAR(line[100].x, 0.5, 1e-12);
}

TEST(BezierCurve, PolylineSamplesUniformly) {
    const BezierCurve curve{{{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 0, 0}}};
    EXPECT_EQ(curve.degree(), 3);
    const std::vector<Vec3> line = curve.polyline(8);
    ASSERT_EQ(line.size(), 9u);
    EXPECT_EQ(line.front(), curve.control_points.front());
    EXPECT_EQ(line.back(), curve.control_points.back());
    for (int i = 0; i <= 8; ++i) {
        EXPECT_EQ(line[i], curve.evaluate(i / 8.0));
    }
    EXPECT_EQ(curve.levels(0.5).size(), 4u);
}

}  // namespace
}  // namespace meshedit
