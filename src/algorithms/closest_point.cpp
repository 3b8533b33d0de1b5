// Closest points on triangles and the bounding-volume hierarchy that finds them.
//
// The tree splits at the median centroid along the longest axis of the centroids' box until a
// node holds 4 triangles or fewer; children are stored next to each other, so an inner node
// only needs its first child's index. A query walks down the nearer child first and skips any
// node whose box is farther than the best distance found so far.

#include "meshedit/core/closest_point.h"

#include <algorithm>
#include <limits>

#include "meshedit/core/display_fan.h"

namespace meshedit {
namespace {

constexpr std::uint32_t kLeafSize = 4;

// Inlined: a query measures two boxes at every node it opens.
inline double box_distance_squared(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    const double dx = std::max(std::max(lo.x - p.x, 0.0), p.x - hi.x);
    const double dy = std::max(std::max(lo.y - p.y, 0.0), p.y - hi.y);
    const double dz = std::max(std::max(lo.z - p.z, 0.0), p.z - hi.z);
    return dx * dx + dy * dy + dz * dz;
}

double length_squared(const Vec3& v) {
    return dot(v, v);
}

// Component by component.
Vec3 lower(const Vec3& a, const Vec3& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
Vec3 upper(const Vec3& a, const Vec3& b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}

}  // namespace

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) {
        return a;
    }
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) {
        return b;
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        return a + ab * (d1 / (d1 - d3));
    }
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) {
        return c;
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        return a + ac * (d2 / (d2 - d6));
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) {
        // A degenerate triangle: the closest of its three sides' closest points.
        Vec3 best = a;
        for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
            const Vec3 uv = v - u;
            const double len = dot(uv, uv);
            const double t = len > 0.0 ? std::clamp(dot(p - u, uv) / len, 0.0, 1.0) : 0.0;
            const Vec3 q = u + uv * t;
            if (length_squared(p - q) < length_squared(p - best)) {
                best = q;
            }
        }
        return best;
    }
    const double v = vb / sum, w = vc / sum;
    return a + ab * v + ac * w;
}

TriangleTree::TriangleTree(const Mesh& mesh) {
    std::vector<std::uint32_t> index(mesh.vertices_size(), 0);
    for (Vertex v : mesh.vertices()) {
        index[v.idx()] = static_cast<std::uint32_t>(points_.size());
        points_.push_back(mesh.position(v));
    }
    for (Face f : mesh.faces()) {
        for_each_fan_triangle(mesh, f, [&](std::size_t, Vertex c0, Halfedge h) {
            triangles_.push_back({index[c0.idx()], index[mesh.from_vertex(h).idx()],
                                  index[mesh.to_vertex(h).idx()]});
        });
    }
    build();
}

TriangleTree::TriangleTree(std::vector<Vec3> points,
                           std::vector<std::array<std::uint32_t, 3>> triangles)
    : points_(std::move(points)), triangles_(std::move(triangles)) {
    build();
}

void TriangleTree::build() {
    order_.resize(triangles_.size());
    std::vector<Vec3> centre(triangles_.size());
    for (std::uint32_t t = 0; t < triangles_.size(); ++t) {
        order_[t] = t;
        const auto& tri = triangles_[t];
        centre[t] = (points_[tri[0]] + points_[tri[1]] + points_[tri[2]]) * (1.0 / 3.0);
    }
    nodes_.clear();
    nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
    if (!triangles_.empty()) {
        nodes_.emplace_back();
        build_range(0, 0, static_cast<std::uint32_t>(triangles_.size()), centre);
    }
    // The leaves' corners in the leaves' order: a query reads them in a row, not through two
    // indices into the points.
    corners_.resize(triangles_.size());
    for (std::size_t i = 0; i < order_.size(); ++i) {
        const auto& tri = triangles_[order_[i]];
        corners_[i] = {points_[tri[0]], points_[tri[1]], points_[tri[2]]};
    }
}

// Fills node `self` with order_[begin, end) and builds its subtree. A node's box is the union
// of its children's (the same box as over its triangles, without reading them again).
void TriangleTree::build_range(std::uint32_t self, std::uint32_t begin, std::uint32_t end,
                               std::vector<Vec3>& centre) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    Vec3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
    if (end - begin <= kLeafSize) {
        for (std::uint32_t i = begin; i < end; ++i) {
            for (const std::uint32_t v : triangles_[order_[i]]) {
                lo = lower(lo, points_[v]);
                hi = upper(hi, points_[v]);
            }
        }
        nodes_[self] = {lo, hi, begin, end - begin};
        return;
    }
    for (std::uint32_t i = begin; i < end; ++i) {
        lo = lower(lo, centre[order_[i]]);
        hi = upper(hi, centre[order_[i]]);
    }
    const Vec3 extent = hi - lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto key = [&](std::uint32_t t) {
        const Vec3& c = centre[t];
        return axis == 0 ? c.x : (axis == 1 ? c.y : c.z);
    };
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](std::uint32_t x, std::uint32_t y) { return key(x) < key(y); });
    // The two children side by side, so a query that opens this node reads one stretch.
    const auto first = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    nodes_.emplace_back();
    build_range(first, begin, mid, centre);
    build_range(first + 1, mid, end, centre);
    const Node& left = nodes_[first];
    const Node& right = nodes_[first + 1];
    nodes_[self] = {lower(left.min, right.min), upper(left.max, right.max), first, 0};
}

TriangleTree::Hit TriangleTree::closest(const Vec3& p, std::uint32_t hint) const {
    Hit best;
    best.distance_squared = std::numeric_limits<double>::infinity();
    if (hint < triangles_.size()) {
        const auto& tri = triangles_[hint];
        const Vec3 q =
            closest_point_on_triangle(p, points_[tri[0]], points_[tri[1]], points_[tri[2]]);
        best = {q, length_squared(p - q), hint};
    }
    // The nodes still to open, each with its box's distance, measured when its parent was
    // opened. The walk goes on into the nearer child at once and keeps the farther here.
    struct Pending {
        std::uint32_t node;
        double distance_squared;
    };
    Pending stack[64];
    int top = 0;
    stack[top++] = {0, box_distance_squared(p, nodes_[0].min, nodes_[0].max)};
    while (top > 0) {
        Pending next = stack[--top];
        while (next.distance_squared < best.distance_squared) {
            const Node& node = nodes_[next.node];
            if (node.count > 0) {
                for (std::uint32_t i = node.a; i < node.a + node.count; ++i) {
                    const auto& tri = corners_[i];
                    const Vec3 q = closest_point_on_triangle(p, tri[0], tri[1], tri[2]);
                    const double d = length_squared(p - q);
                    if (d < best.distance_squared) {
                        best = {q, d, order_[i]};
                    }
                }
                break;
            }
            const std::uint32_t a = node.a;
            const double da = box_distance_squared(p, nodes_[a].min, nodes_[a].max);
            const double db = box_distance_squared(p, nodes_[a + 1].min, nodes_[a + 1].max);
            const Pending near = da <= db ? Pending{a, da} : Pending{a + 1, db};
            const Pending far = da <= db ? Pending{a + 1, db} : Pending{a, da};
            if (far.distance_squared < best.distance_squared) {
                stack[top++] = far;
            }
            next = near;
        }
    }
    return best;
}

}  // namespace meshedit
