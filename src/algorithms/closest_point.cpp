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

double box_distance_squared(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    const double dx = std::max({lo.x - p.x, 0.0, p.x - hi.x});
    const double dy = std::max({lo.y - p.y, 0.0, p.y - hi.y});
    const double dz = std::max({lo.z - p.z, 0.0, p.z - hi.z});
    return dx * dx + dy * dy + dz * dz;
}

double length_squared(const Vec3& v) {
    return dot(v, v);
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
        build_range(0, static_cast<std::uint32_t>(triangles_.size()), centre);
    }
}

// Builds the node of order_[begin, end) (and its subtree) and returns its index.
std::uint32_t TriangleTree::build_range(std::uint32_t begin, std::uint32_t end,
                                        std::vector<Vec3>& centre) {
    const auto self = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    Vec3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
    Vec3 clo = lo, chi = hi;
    for (std::uint32_t i = begin; i < end; ++i) {
        for (const std::uint32_t v : triangles_[order_[i]]) {
            const Vec3& p = points_[v];
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        }
        const Vec3& c = centre[order_[i]];
        clo = {std::min(clo.x, c.x), std::min(clo.y, c.y), std::min(clo.z, c.z)};
        chi = {std::max(chi.x, c.x), std::max(chi.y, c.y), std::max(chi.z, c.z)};
    }
    if (end - begin <= kLeafSize) {
        nodes_[self] = {lo, hi, begin, 0, end - begin};
        return self;
    }
    const Vec3 extent = chi - clo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto key = [&](std::uint32_t t) {
        const Vec3& c = centre[t];
        return axis == 0 ? c.x : (axis == 1 ? c.y : c.z);
    };
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](std::uint32_t x, std::uint32_t y) { return key(x) < key(y); });
    const std::uint32_t left = build_range(begin, mid, centre);
    const std::uint32_t right = build_range(mid, end, centre);
    nodes_[self] = {lo, hi, left, right, 0};
    return self;
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
    // Each node with its box's distance, measured once, when its parent is opened.
    struct Pending {
        std::uint32_t node;
        double distance_squared;
    };
    Pending stack[64];
    int top = 0;
    stack[top++] = {0, box_distance_squared(p, nodes_[0].min, nodes_[0].max)};
    while (top > 0) {
        const Pending next = stack[--top];
        if (next.distance_squared >= best.distance_squared) {
            continue;
        }
        const Node& node = nodes_[next.node];
        if (node.count > 0) {
            for (std::uint32_t i = node.a; i < node.a + node.count; ++i) {
                const auto& tri = triangles_[order_[i]];
                const Vec3 q =
                    closest_point_on_triangle(p, points_[tri[0]], points_[tri[1]], points_[tri[2]]);
                const double d = length_squared(p - q);
                if (d < best.distance_squared) {
                    best = {q, d, order_[i]};
                }
            }
            continue;
        }
        const std::uint32_t a = node.a;
        const std::uint32_t b = node.b;
        const double da = box_distance_squared(p, nodes_[a].min, nodes_[a].max);
        const double db = box_distance_squared(p, nodes_[b].min, nodes_[b].max);
        // Push the farther first so the nearer is searched first.
        if (da <= db) {
            stack[top++] = {b, db};
            stack[top++] = {a, da};
        } else {
            stack[top++] = {a, da};
            stack[top++] = {b, db};
        }
    }
    return best;
}

}  // namespace meshedit
