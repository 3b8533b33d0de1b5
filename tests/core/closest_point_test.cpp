// Closest points: every Voronoi region of a triangle by hand, degenerate triangles, and the
// tree against a brute-force search over every triangle.

#include <gtest/gtest.h>

#include <random>

#include "meshedit/core/closest_point.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

TEST(ClosestPointOnTriangle, EveryRegion) {
    const Vec3 a{0, 0, 0}, b{2, 0, 0}, c{0, 2, 0};
    const auto at = [&](Vec3 p) { return closest_point_on_triangle(p, a, b, c); };
    EXPECT_EQ(at({-1, -1, 3}), a);                       // corner a
    EXPECT_EQ(at({3, -1, 0}), b);                        // corner b
    EXPECT_EQ(at({-1, 3, -2}), c);                       // corner c
    EXPECT_EQ(at({1, -5, 1}), (Vec3{1, 0, 0}));          // side ab
    EXPECT_EQ(at({-5, 1, 1}), (Vec3{0, 1, 0}));          // side ac
    EXPECT_EQ(at({2, 2, 7}), (Vec3{1, 1, 0}));           // side bc
    EXPECT_EQ(at({0.5, 0.5, -4}), (Vec3{0.5, 0.5, 0}));  // inside
    // A degenerate triangle (all on a line): the closest point of the segment.
    EXPECT_EQ(closest_point_on_triangle({1, 1, 0}, a, b, {1, 0, 0}), (Vec3{1, 0, 0}));
}

TEST(TriangleTree, AgreesWithBruteForce) {
    const Mesh torus = shapes::torus(40, 20);
    const TriangleTree tree(torus);
    ASSERT_EQ(tree.triangles().size(), torus.n_faces());
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p{u(rng), u(rng), 0.5 * u(rng)};
        double brute = 1e300;
        for (const auto& t : tree.triangles()) {
            const Vec3 q = closest_point_on_triangle(p, tree.points()[t[0]], tree.points()[t[1]],
                                                     tree.points()[t[2]]);
            brute = std::min(brute, dot(p - q, p - q));
        }
        const TriangleTree::Hit hit = tree.closest(p);
        EXPECT_DOUBLE_EQ(hit.distance_squared, brute) << i;
        const auto& t = tree.triangles()[hit.triangle];
        const Vec3 q = closest_point_on_triangle(p, tree.points()[t[0]], tree.points()[t[1]],
                                                 tree.points()[t[2]]);
        EXPECT_EQ(q, hit.point);
        // Any hint, near or far, only bounds the search: the answer is the same.
        const auto hint = static_cast<std::uint32_t>((i * 7919) % tree.triangles().size());
        EXPECT_DOUBLE_EQ(tree.closest(p, hint).distance_squared, brute) << i;
        EXPECT_DOUBLE_EQ(tree.closest(p, hit.triangle).distance_squared, brute) << i;
    }
}

}  // namespace
}  // namespace meshedit
