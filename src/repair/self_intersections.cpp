// Faces that pass through each other (problems.h, self_intersections()). Broad phase: each
// triangle of each face's fan goes into the cells of a uniform grid its bounding box covers;
// a pair is tested once, in the first cell both boxes share. Narrow phase: two triangles
// pass through each other when an edge of one crosses the other's inside (strictly, so
// faces that only touch are not counted).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "meshedit/repair/problems.h"

namespace meshedit {
namespace {

struct Tri {
    std::array<Vec3, 3> p;
    Face face;
    std::array<std::int64_t, 3> lo, hi;  // the cells its box covers
    Vec3 box_lo, box_hi;
};

bool boxes_overlap(const Tri& a, const Tri& b) {
    return a.box_lo.x <= b.box_hi.x && b.box_lo.x <= a.box_hi.x && a.box_lo.y <= b.box_hi.y &&
           b.box_lo.y <= a.box_hi.y && a.box_lo.z <= b.box_hi.z && b.box_lo.z <= a.box_hi.z;
}

// Whether every corner of `b` lies strictly on one side of `a`'s plane (then they cannot
// pass through each other): Moller's early rejection, which most neighbours in a cell meet.
bool one_side(const Tri& a, const Tri& b) {
    const Vec3 n = cross(a.p[1] - a.p[0], a.p[2] - a.p[0]);
    const double d0 = dot(n, b.p[0] - a.p[0]);
    const double d1 = dot(n, b.p[1] - a.p[0]);
    const double d2 = dot(n, b.p[2] - a.p[0]);
    return (d0 > 0 && d1 > 0 && d2 > 0) || (d0 < 0 && d1 < 0 && d2 < 0);
}

// Whether segment a–b crosses the inside of triangle t (Möller–Trumbore, strict bounds).
bool crosses(const Vec3& a, const Vec3& b, const std::array<Vec3, 3>& t) {
    constexpr double kEps = 1e-10;
    const Vec3 d = b - a;
    const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
    const Vec3 q = cross(d, e2);
    const double det = dot(e1, q);
    const double scale = norm(d) * norm(e1) * norm(e2);
    if (std::abs(det) <= kEps * scale) {
        return false;  // parallel or coplanar: touching, not passing through
    }
    const Vec3 s = a - t[0];
    const double u = dot(s, q) / det;
    const Vec3 r = cross(s, e1);
    const double v = dot(d, r) / det;
    const double w = dot(e2, r) / det;  // along the segment, 0 at a and 1 at b
    return u > kEps && v > kEps && u + v < 1 - kEps && w > kEps && w < 1 - kEps;
}

bool pass_through(const Tri& x, const Tri& y) {
    for (int i = 0; i < 3; ++i) {
        if (crosses(x.p[i], x.p[(i + 1) % 3], y.p) || crosses(y.p[i], y.p[(i + 1) % 3], x.p)) {
            return true;
        }
    }
    return false;
}

bool share_a_vertex(const Mesh& mesh, Face f, Face g) {
    for (const Vertex a : mesh.vertices(f)) {
        for (const Vertex b : mesh.vertices(g)) {
            if (a == b) {
                return true;
            }
        }
    }
    return false;
}

}  // namespace

std::vector<std::pair<Face, Face>> self_intersections(const Mesh& mesh) {
    std::vector<Tri> tris;
    double length = 0.0;
    std::size_t edges = 0;
    for (const Face f : mesh.faces()) {
        const Halfedge h0 = mesh.halfedge(f);
        const Vec3 p0 = mesh.position(mesh.from_vertex(h0));
        for (Halfedge h = mesh.next(h0); mesh.next(h) != h0; h = mesh.next(h)) {
            Tri t{{p0, mesh.position(mesh.from_vertex(h)), mesh.position(mesh.to_vertex(h))},
                  f,
                  {},
                  {},
                  {},
                  {}};
            t.box_lo = {std::min({t.p[0].x, t.p[1].x, t.p[2].x}),
                        std::min({t.p[0].y, t.p[1].y, t.p[2].y}),
                        std::min({t.p[0].z, t.p[1].z, t.p[2].z})};
            t.box_hi = {std::max({t.p[0].x, t.p[1].x, t.p[2].x}),
                        std::max({t.p[0].y, t.p[1].y, t.p[2].y}),
                        std::max({t.p[0].z, t.p[1].z, t.p[2].z})};
            for (int i = 0; i < 3; ++i) {
                length += norm(t.p[(i + 1) % 3] - t.p[i]);
            }
            edges += 3;
            tris.push_back(t);
        }
    }
    std::vector<std::pair<Face, Face>> found;
    if (tris.size() < 2 || !(length > 0.0) || !std::isfinite(length)) {
        return found;
    }
    const double cell = 2.0 * length / static_cast<double>(edges);
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
    const auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
        const auto m = [](std::int64_t v) { return static_cast<std::uint64_t>(v) & 0x1fffff; };
        return m(x) | (m(y) << 21) | (m(z) << 42);
    };
    std::vector<std::uint32_t> huge;  // triangles covering too many cells: tested with all
    std::vector<bool> is_huge(tris.size(), false);
    for (std::uint32_t i = 0; i < tris.size(); ++i) {
        Tri& t = tris[i];
        std::int64_t cells = 1;
        for (int k = 0; k < 3; ++k) {
            const auto coord = [k](const Vec3& p) { return k == 0 ? p.x : k == 1 ? p.y : p.z; };
            const double lo = std::min({coord(t.p[0]), coord(t.p[1]), coord(t.p[2])});
            const double hi = std::max({coord(t.p[0]), coord(t.p[1]), coord(t.p[2])});
            t.lo[k] = static_cast<std::int64_t>(std::floor(lo / cell));
            t.hi[k] = static_cast<std::int64_t>(std::floor(hi / cell));
            cells *= std::min<std::int64_t>(t.hi[k] - t.lo[k] + 1, 1 << 20);
        }
        if (cells > 512) {
            huge.push_back(i);
            is_huge[i] = true;
            continue;
        }
        for (std::int64_t x = t.lo[0]; x <= t.hi[0]; ++x) {
            for (std::int64_t y = t.lo[1]; y <= t.hi[1]; ++y) {
                for (std::int64_t z = t.lo[2]; z <= t.hi[2]; ++z) {
                    grid[key(x, y, z)].push_back(i);
                }
            }
        }
    }
    const auto test = [&](const Tri& a, const Tri& b) {
        if (a.face != b.face && boxes_overlap(a, b) && !one_side(a, b) && !one_side(b, a) &&
            !share_a_vertex(mesh, a.face, b.face) && pass_through(a, b)) {
            found.emplace_back(std::min(a.face, b.face), std::max(a.face, b.face));
        }
    };
    for (const auto& [cell_key, members] : grid) {
        for (std::size_t i = 0; i < members.size(); ++i) {
            for (std::size_t j = i + 1; j < members.size(); ++j) {
                const Tri& a = tris[members[i]];
                const Tri& b = tris[members[j]];
                // Once per pair: in the first cell both boxes share.
                const std::uint64_t first =
                    key(std::max(a.lo[0], b.lo[0]), std::max(a.lo[1], b.lo[1]),
                        std::max(a.lo[2], b.lo[2]));
                bool apart = false;
                for (int k = 0; k < 3; ++k) {
                    apart = apart || a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k];
                }
                if (!apart && first == cell_key) {
                    test(a, b);
                }
            }
        }
    }
    for (const std::uint32_t h : huge) {
        for (std::uint32_t i = 0; i < tris.size(); ++i) {
            // A pair of two huge triangles once.
            if (i != h && !(is_huge[i] && i < h)) {
                test(tris[h], tris[i]);
            }
        }
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
}

}  // namespace meshedit
