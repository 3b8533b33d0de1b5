#pragma once
// What the subdivision tests (Loop, Catmull-Clark and linear, OpenSubdiv equality) share:
// crease marks, point comparisons, the creased cube, and the fast == classic comparison.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/shapes.h"
#include "support/mesh_compare.h"

namespace meshedit::test {

using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

inline constexpr double kTol = 1e-12;

// Crease edges as sorted vertex pairs.
inline Pairs crease_pairs(const Mesh& mesh) {
    Pairs out;
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    if (!crease) {
        return out;
    }
    for (Edge e : mesh.edges()) {
        if (crease[e] != 0) {
            const std::uint32_t a = mesh.vertex(e, 0).idx();
            const std::uint32_t b = mesh.vertex(e, 1).idx();
            out.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

inline void mark_crease(Mesh& mesh, std::uint32_t a, std::uint32_t b) {
    const Edge e = mesh.find_edge(Vertex(a), Vertex(b));
    ASSERT_TRUE(e.is_valid()) << a << "-" << b;
    mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0)[e] = 1;
}

inline bool is_crease(const Mesh& mesh, std::uint32_t a, std::uint32_t b) {
    const Edge e = mesh.find_edge(Vertex(a), Vertex(b));
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    return e.is_valid() && crease && crease[e] != 0;
}

inline ::testing::AssertionResult near(const Vec3& actual, const Vec3& expected,
                                       double tol = kTol) {
    if (distance(actual, expected) <= tol) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
           << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") != expected ("
           << expected.x << ", " << expected.y << ", " << expected.z << ")";
}

// The fast path and the classic reference agree: same faces by vertex index, same positions
// per index, same crease edges.
inline void expect_same_result(const Mesh& fast, const Mesh& classic) {
    ASSERT_EQ(fast.n_vertices(), classic.n_vertices());
    ASSERT_EQ(fast.n_edges(), classic.n_edges());
    ASSERT_EQ(fast.n_faces(), classic.n_faces());
    EXPECT_EQ(canonical_faces(fast), canonical_faces(classic));
    for (Vertex v : fast.vertices()) {
        ASSERT_TRUE(near(fast.position(v), classic.position(v))) << "vertex " << v.idx();
    }
    EXPECT_EQ(crease_pairs(fast), crease_pairs(classic));
    EXPECT_EQ(fast.has_property<Edge>(kCreaseProperty),
              classic.has_property<Edge>(kCreaseProperty));
}

// Marks the bottom square (z = -1: 0-1-3-2) and the three cube edges at vertex 7 of
// shapes::cube() as creases. Vertex i sits at ((i&1) ? 1 : -1, (i&2) ? 1 : -1, (i&4) ? 1 : -1):
//
//          6 ------- 7*         * corner (3 creases: 7-3, 7-5, 7-6)
//         /|        /|          0, 1, 2: on exactly 2 creases (bottom loop)
//        4 ------- 5 |          3: corner (1-3, 3-2, 3-7)
//        | 2 ======|=3*         5, 6: darts (1 crease); 4: no crease
//        |//       |//
//        0 ======= 1            (= and // : bottom-loop creases)
inline Mesh creased_cube() {
    Mesh mesh = shapes::cube();
    for (auto [a, b] : Pairs{{0, 1}, {1, 3}, {3, 2}, {2, 0}, {7, 3}, {7, 5}, {7, 6}}) {
        mark_crease(mesh, a, b);
    }
    return mesh;
}

}  // namespace meshedit::test
