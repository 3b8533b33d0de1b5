// The triangles that cover a hole (hole_triangles.h): Liepa's minimum-weight triangulation,
// ear clipping, and the edge flips that turn a fan into either.

#include "hole_triangles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <set>
#include <tuple>
#include <unordered_map>

namespace meshedit::repair_detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Vec3 unit_or_zero(const Vec3& v) {
    const double l = norm(v);
    return l > 0.0 ? v / l : Vec3{};
}

// Liepa's weight of a set of triangles: the largest dihedral angle first, then the area. The
// angle is kept as its negated cosine, `fold` (−1 flat, 1 folded back), which orders the same
// without an arccosine in the O(n³) loop.
struct Weight {
    double fold = kInf;
    double area = kInf;
    bool operator<(const Weight& o) const {
        return fold < o.fold || (fold == o.fold && area < o.area);
    }
};

// A corner in the hole's mean plane.
struct Plane2 {
    double x = 0.0, y = 0.0;
};

double turn(const Plane2& a, const Plane2& b, const Plane2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The corners in the plane through the origin with unit `normal`, turning counter-clockwise
// when the loop turns about the normal; empty when the normal is zero.
std::vector<Plane2> projected(const std::vector<Vec3>& p, const Vec3& normal) {
    if (sqrnorm(normal) == 0.0) {
        return {};
    }
    const Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = unit_or_zero(cross(helper, normal));
    const Vec3 v = cross(normal, u);
    std::vector<Plane2> out(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        out[i] = {dot(p[i], u), dot(p[i], v)};
    }
    return out;
}

// Whether segments ab and cd cross or touch (collinear overlaps included).
bool segments_meet(const Plane2& a, const Plane2& b, const Plane2& c, const Plane2& d) {
    const double d1 = turn(c, d, a), d2 = turn(c, d, b), d3 = turn(a, b, c), d4 = turn(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
        return true;
    }
    const auto on = [](const Plane2& p, const Plane2& q, const Plane2& r, double t) {
        return t == 0.0 && std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) &&
               std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
    };
    return on(c, d, a, d1) || on(c, d, b, d2) || on(a, b, c, d3) || on(a, b, d, d4);
}

// Whether the closed outline has no two sides that meet but at their shared corner. O(n²).
bool is_simple(const std::vector<Plane2>& q) {
    const std::size_t n = q.size();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = i + 2; k < n; ++k) {
            if (i == 0 && k == n - 1) {
                continue;  // neighbours through corner 0
            }
            if (segments_meet(q[i], q[(i + 1) % n], q[k], q[(k + 1) % n])) {
                return false;
            }
        }
    }
    return true;
}

// Whether no corner left on the outline (after b, through `next`, up to a) lies in or on
// the triangle a, c, b (counter-clockwise), so that clipping it leaves a simple outline.
bool empty_ear(const std::vector<Plane2>& q, std::uint32_t a, std::uint32_t c, std::uint32_t b,
               const std::vector<std::uint32_t>& next) {
    for (std::uint32_t x = next[b]; x != a; x = next[x]) {
        if (turn(q[a], q[c], q[x]) >= 0.0 && turn(q[c], q[b], q[x]) >= 0.0 &&
            turn(q[b], q[a], q[x]) >= 0.0) {
            return false;
        }
    }
    return true;
}

}  // namespace

HoleTriangles minimum_weight_triangles(const HoleLoop& hole) {
    const std::size_t n = hole.points.size();
    HoleTriangles out;
    if (n < 3) {
        out.why = "it has fewer than 3 sides";
        return out;
    }
    const auto& p = hole.points;
    double longest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        longest = std::max(longest, sqrnorm(p[(i + 1) % n] - p[i]));
    }
    // W[i * n + k]: the best triangulation of corners i..k (i < k) closed by the side or
    // diagonal i–k, mirrored at W[k * n + i] so that the loop below reads both of its
    // operands along a row (a column's stride missed the cache; 300 corners: 1.4 MB); L
    // the middle corner of its triangle on i–k.
    std::vector<Weight> w(n * n);
    std::vector<std::uint32_t> lambda(n * n, 0);
    // The unit normal across i–k inside the patch: the outside face for a side, else the
    // sub-solution's triangle on i–k, kept so that the O(n³) loop below reads it instead of
    // making it again for every middle corner; mirrored as W.
    std::vector<Vec3> normal(n * n);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        w[i * n + i + 1] = w[(i + 1) * n + i] = {-1.0, 0.0};  // no triangle, no angle
        // across a side: the face outside
        normal[i * n + i + 1] = normal[(i + 1) * n + i] = hole.outside_normals[i];
    }
    for (std::size_t len = 2; len < n; ++len) {
        for (std::size_t i = 0; i + len < n; ++i) {
            const std::size_t k = i + len;
            const bool side = (i == 0 && k == n - 1);
            if (!side && hole.forbidden(i, k)) {
                continue;  // i–k is an edge the mesh has already
            }
            Weight best;
            std::uint32_t best_m = 0;
            const auto consider = [&](std::size_t m) {
                const Weight& a = w[i * n + m];
                const Weight& b = w[k * n + m];
                if (a.fold == kInf || b.fold == kInf) {
                    return;
                }
                // The largest angle only grows as triangles join: a candidate already past
                // the best cannot win, so it is dropped before its cross product. Equal
                // angles go on, to compare areas.
                double fold = std::max(a.fold, b.fold);
                if (fold > best.fold) {
                    return;
                }
                const Vec3 c = cross(p[m] - p[i], p[k] - p[i]);
                const double area = 0.5 * norm(c);
                if (area <= 1e-12 * longest) {
                    return;  // a flat triangle
                }
                const Vec3 nt = c / (2.0 * area);
                fold = std::max({fold, -dot(nt, normal[i * n + m]), -dot(nt, normal[k * n + m])});
                if (side) {
                    fold = std::max(fold, -dot(nt, hole.outside_normals[n - 1]));
                }
                const Weight total{fold, a.area + b.area + area};
                // Ties go to the smallest m, so the order tried does not change the result.
                if (total < best || (!(best < total) && m < best_m)) {
                    best = total;
                    best_m = static_cast<std::uint32_t>(m);
                }
            };
            // The middle corner that won for i..k−1 first: it is often near the best here,
            // and a good bound early drops most of the others before their cross products.
            const std::size_t hint = len > 2 ? lambda[i * n + k - 1] : 0;
            if (hint > i && hint < k) {
                consider(hint);
            }
            for (std::size_t m = i + 1; m < k; ++m) {
                if (m != hint) {
                    consider(m);
                }
            }
            w[i * n + k] = w[k * n + i] = best;
            lambda[i * n + k] = best_m;
            if (best.fold != kInf) {
                normal[i * n + k] = normal[k * n + i] =
                    unit_or_zero(cross(p[best_m] - p[i], p[k] - p[i]));
            }
        }
    }
    if (w[n - 1].fold == kInf) {
        out.why = "every triangulation has a flat triangle or an edge the mesh already has";
        return out;
    }
    std::vector<std::pair<std::size_t, std::size_t>> todo{{0, n - 1}};
    while (!todo.empty()) {
        const auto [i, k] = todo.back();
        todo.pop_back();
        if (k <= i + 1) {
            continue;
        }
        const std::size_t m = lambda[i * n + k];
        out.triangles.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(m),
                                 static_cast<std::uint32_t>(k)});
        todo.emplace_back(i, m);
        todo.emplace_back(m, k);
    }
    return out;
}

HoleTriangles clipped_ears(const HoleLoop& hole, bool strict) {
    const std::size_t n = hole.points.size();
    HoleTriangles out;
    const auto& p = hole.points;
    // The hole's mean plane (Newell): corners turn about it; an ear's angle is measured in it.
    Vec3 normal;
    for (std::size_t i = 0; i < n; ++i) {
        normal += cross(p[i], p[(i + 1) % n]);
    }
    normal = unit_or_zero(normal);
    // Strict: the corners in the mean plane, and the outline there must be simple.
    std::vector<Plane2> flat;
    if (strict) {
        flat = projected(p, normal);
        if (flat.empty() || !is_simple(flat)) {
            out.why = "its outline is not a simple polygon in its mean plane";
            return out;
        }
    }
    std::vector<std::uint32_t> prev(n), next(n), version(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        prev[i] = static_cast<std::uint32_t>((i + n - 1) % n);
        next[i] = static_cast<std::uint32_t>((i + 1) % n);
    }
    std::set<std::pair<std::uint32_t, std::uint32_t>> made;  // diagonals so far
    const auto ordered = [](std::uint32_t a, std::uint32_t b) {
        return std::make_pair(std::min(a, b), std::max(a, b));
    };
    // The inside angle at c (smaller first: the sharpest convex corner is clipped first).
    const auto inside_angle = [&](std::uint32_t c) {
        const Vec3 u = p[c] - p[prev[c]];
        const Vec3 v = p[next[c]] - p[c];
        return std::numbers::pi - std::atan2(dot(normal, cross(u, v)), dot(u, v));
    };
    using Entry = std::tuple<double, std::uint32_t, std::uint32_t>;  // angle, corner, version
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::uint32_t c = 0; c < n; ++c) {
        queue.emplace(inside_angle(c), c, 0);
    }
    std::size_t left = n;
    std::vector<Entry> blocked;
    // Strict: the corners tested against ears so far. Blocked corners are tried again after
    // every clip, each test O(left): an outline with many reflex corners (a comb) could
    // take O(n³); past this bound the strict clipping gives up, and the caller falls back.
    std::size_t tested = 0;
    constexpr std::size_t kMostTested = 50'000'000;
    while (left > 3 && !queue.empty()) {
        const auto [angle, c, ver] = queue.top();
        queue.pop();
        if (ver != version[c]) {
            continue;
        }
        if (strict && (tested += left) > kMostTested) {
            out.triangles.clear();
            out.why = "clipping its ears in its plane took too long (a comb-like outline)";
            return out;
        }
        const std::uint32_t a = prev[c], b = next[c];
        const bool thin = norm(cross(p[c] - p[a], p[b] - p[a])) <=
                          1e-12 * std::max(sqrnorm(p[c] - p[a]), sqrnorm(p[b] - p[a]));
        const bool not_an_ear =
            strict && (angle >= std::numbers::pi || !empty_ear(flat, a, c, b, next));
        if (hole.forbidden(a, b) || made.count(ordered(a, b)) > 0 || thin || not_an_ear) {
            blocked.emplace_back(angle, c, ver);  // may become an ear when a neighbour goes
            continue;
        }
        out.triangles.push_back({a, c, b});
        made.insert(ordered(a, b));
        next[a] = b;
        prev[b] = a;
        version[c] = UINT32_MAX;
        --left;
        for (const std::uint32_t x : {a, b}) {
            ++version[x];
            queue.emplace(inside_angle(x), x, version[x]);
        }
        for (const Entry& e : blocked) {
            queue.push(e);  // their neighbours may have changed: try again
        }
        blocked.clear();
    }
    if (left > 3) {
        out.triangles.clear();
        out.why = "every ear left has a flat triangle or an edge the mesh already has";
        return out;
    }
    std::uint32_t a = 0;
    while (version[a] == UINT32_MAX) {
        ++a;
    }
    const std::uint32_t c = next[a], b = next[c];
    out.triangles.push_back({a, c, b});  // its sides are the loop's: sides or diagonals made
    out.clipped = true;
    return out;
}

HoleTriangles hole_triangles(const HoleLoop& hole) {
    const std::size_t n = hole.points.size();
    if (n <= kMinEarSides) {
        return minimum_weight_triangles(hole);
    }
    if (n <= kMaxStrictEarSides) {
        HoleTriangles ears = clipped_ears(hole, true);
        if (!ears.triangles.empty()) {
            return ears;
        }
    }
    return n <= kMaxDynamicSides ? minimum_weight_triangles(hole) : clipped_ears(hole, false);
}

std::vector<FanFlip> flips_from_fan(const std::vector<HoleTriangle>& triangles, std::size_t n,
                                    std::uint32_t apex) {
    // Walks the triangulation to the fan around `apex`, one flip at a time (each gives the
    // apex one more diagonal, so at most n − 3 of them); the way back from the fan is the
    // same flips undone in reverse order.
    std::vector<HoleTriangle> t = triangles;
    std::unordered_map<std::uint64_t, std::uint32_t> holder;  // directed edge → triangle
    const auto key = [n](std::uint32_t x, std::uint32_t y) {
        return static_cast<std::uint64_t>(x) * n + y;
    };
    const auto hold = [&](std::uint32_t i, bool on) {
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t e = key(t[i][k], t[i][(k + 1) % 3]);
            if (on) {
                holder[e] = i;
            } else {
                holder.erase(e);
            }
        }
    };
    std::vector<std::uint32_t> todo;
    for (std::uint32_t i = 0; i < t.size(); ++i) {
        hold(i, true);
        if (std::find(t[i].begin(), t[i].end(), apex) != t[i].end()) {
            todo.push_back(i);
        }
    }
    std::vector<FanFlip> walk;
    while (!todo.empty()) {
        const std::uint32_t i = todo.back();
        todo.pop_back();
        const auto at = std::find(t[i].begin(), t[i].end(), apex) - t[i].begin();
        const std::uint32_t x = t[i][(at + 1) % 3], y = t[i][(at + 2) % 3];
        const auto other = holder.find(key(y, x));
        if (y == (x + 1) % n || other == holder.end()) {
            continue;  // x–y is a side of the hole
        }
        const std::uint32_t j = other->second;
        const auto kx = std::find(t[j].begin(), t[j].end(), x) - t[j].begin();
        const std::uint32_t z = t[j][(kx + 1) % 3];
        hold(i, false);
        hold(j, false);
        t[i] = {apex, x, z};
        t[j] = {apex, z, y};
        hold(i, true);
        hold(j, true);
        walk.push_back({x, y, z});
        todo.push_back(i);
        todo.push_back(j);
    }
    std::reverse(walk.begin(), walk.end());
    return walk;
}

}  // namespace meshedit::repair_detail
