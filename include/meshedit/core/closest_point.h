#pragma once
/// \file
/// Closest points on a triangle surface: a bounding-volume hierarchy over its triangles
/// (built once, then read-only and safe to query from several threads). Remeshing projects
/// onto its input with it, and the benchmarks' Hausdorff sampler measures with it.

#include <array>
#include <cstdint>
#include <vector>

#include "meshedit/core/math.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

/// The point of triangle (a, b, c) closest to p (Ericson, Real-Time Collision Detection 5.1.5:
/// by the Voronoi region of p: a corner, a side, or the inside).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class TriangleTree {
public:
    /// The triangles of `mesh` as it is now (polygons cut into fans as the renderer cuts them).
    explicit TriangleTree(const Mesh& mesh);
    /// `triangles` index `points`.
    TriangleTree(std::vector<Vec3> points, std::vector<std::array<std::uint32_t, 3>> triangles);

    struct Hit {
        Vec3 point;
        double distance_squared = 0.0;
        std::uint32_t triangle = 0;  ///< index into the triangles given (or the fans' order)
    };
    /// The closest point of the surface to p. \pre !empty(). A `hint` triangle (one near p,
    /// such as the last answer for a point that moved a little) bounds the search from the
    /// start; any index works, kInvalidIndex means none.
    Hit closest(const Vec3& p, std::uint32_t hint = kInvalidIndex) const;

    bool empty() const { return triangles_.empty(); }
    const std::vector<Vec3>& points() const { return points_; }
    const std::vector<std::array<std::uint32_t, 3>>& triangles() const { return triangles_; }

private:
    struct Node {
        Vec3 min, max;
        std::uint32_t a = 0;      ///< leaf: first of `count` triangles in order_; inner: left
                                  ///< child (the right one is a + 1)
        std::uint32_t count = 0;  ///< 0 for an inner node
    };
    void build();
    void build_range(std::uint32_t self, std::uint32_t begin, std::uint32_t end,
                     std::vector<Vec3>& centre);

    std::vector<Vec3> points_;
    std::vector<std::array<std::uint32_t, 3>> triangles_;
    std::vector<std::uint32_t> order_;          // triangle indices, grouped by leaf
    std::vector<std::array<Vec3, 3>> corners_;  // order_'s triangles' corners, in its order
    std::vector<Node> nodes_;                   // nodes_[0] is the root
};

}  // namespace meshedit
