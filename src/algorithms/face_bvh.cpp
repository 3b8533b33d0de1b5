// The face BVH (face_bvh.h).
//
// Build: binned SAH (16 bins) on the axis where the triangles' centres spread most, until a
// node holds 4 triangles or fewer; small nodes and pathological spreads (past depth 48, where
// SAH could peel one triangle per level) are halved at the median instead, which bounds the
// depth and so the query's fixed stack. The bins give the children's boxes, and each level
// costs one binning pass and one branch-free scatter over a compact array. Boxes are floats
// rounded outwards from the double positions, so a box never misses a triangle inside it.
//
// Query: depth-first, nearer child first, a node skipped once the best hit is nearer than
// where the ray enters it; the triangle test is Moller-Trumbore in double.

#include "meshedit/core/face_bvh.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "meshedit/core/display_fan.h"

namespace meshedit {
namespace {

constexpr std::uint32_t kLeafSize = 4;
constexpr int kBins = 16;
constexpr std::uint32_t kMaxSahDepth = 48;
constexpr int kStackSize = 128;  // > kMaxSahDepth + log2(2^32 / kLeafSize) + 1

// A float at or below (above) the double d: two float steps out, then rounded to nearest,
// which moves back at most half a step. Branch-free (the direction of the rounding is a coin
// toss a branch would mispredict); the 1e-30 keeps zero inside.
float round_down(double d) {
    return static_cast<float>(d - std::abs(d) * 0x1p-22 - 1e-30);
}

float round_up(double d) {
    return static_cast<float>(d + std::abs(d) * 0x1p-22 + 1e-30);
}

struct Box {
    std::array<float, 3> lo{INFINITY, INFINITY, INFINITY};
    std::array<float, 3> hi{-INFINITY, -INFINITY, -INFINITY};

    void grow(const Box& b) {
        for (std::size_t a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], b.lo[a]);
            hi[a] = std::max(hi[a], b.hi[a]);
        }
    }
    void grow(const std::array<float, 3>& p) {
        for (std::size_t a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], p[a]);
            hi[a] = std::max(hi[a], p[a]);
        }
    }
    double half_area() const {
        const double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
        return x < 0.0 ? 0.0 : x * y + y * z + z * x;
    }
};

/// A triangle while building: its box and its index in face order. Splits sort by twice
/// the box centre (key()), which needs no division.
struct Prim {
    Box box;
    std::uint32_t index = 0;
};

std::array<float, 3> key(const Prim& p) {
    return {p.box.lo[0] + p.box.hi[0], p.box.lo[1] + p.box.hi[1], p.box.lo[2] + p.box.hi[2]};
}

struct Bin {
    Box box;
    std::uint32_t count = 0;
};
using Bins = std::array<Bin, kBins>;
// Big ranges fill several sets of bins in turn: neighbouring triangles often share a bin, and
// one set would make each update wait for the previous one's store.
constexpr std::size_t kBinSets = 4;
// Below this many triangles a median split is as good and costs less than clearing the bins.
constexpr std::uint32_t kSahFrom = 24;

/// A node's split: [begin, mid) and [mid, end), their boxes and their centres' bounds.
struct Split {
    std::uint32_t mid = 0;
    Box left, right, left_c, right_c;
};

std::size_t widest_axis(const Box& b) {
    std::size_t axis = 0;
    for (std::size_t a = 1; a < 3; ++a) {
        if (b.hi[a] - b.lo[a] > b.hi[axis] - b.lo[axis]) {
            axis = a;
        }
    }
    return axis;
}

/// Halves [begin, end) of `prims` in place at the median centre along `axis`.
Split split_median(std::vector<Prim>& prims, std::uint32_t begin, std::uint32_t end,
                   std::size_t axis) {
    Split s;
    s.mid = begin + (end - begin) / 2;
    std::nth_element(prims.begin() + begin, prims.begin() + s.mid, prims.begin() + end,
                     [&](const Prim& x, const Prim& y) { return key(x)[axis] < key(y)[axis]; });
    for (std::uint32_t i = begin; i < end; ++i) {
        (i < s.mid ? s.left : s.right).grow(prims[i].box);
        (i < s.mid ? s.left_c : s.right_c).grow(key(prims[i]));
    }
    return s;
}

/// The binned-SAH split of from[begin, end), whose centres span `centres`, scattered into
/// the same range of `to` (a branch-free copy: a data-dependent branch per triangle would
/// mispredict half the time). Nothing when every centre falls into one bin.
std::optional<Split> split_sah(const std::vector<Prim>& from, std::vector<Prim>& to,
                               std::uint32_t begin, std::uint32_t end, const Box& centres,
                               std::array<Bins, kBinSets>& sets) {
    const std::size_t axis = widest_axis(centres);
    const float extent = centres.hi[axis] - centres.lo[axis];
    if (!(extent > 0.0f)) {
        return std::nullopt;
    }
    const float lo = centres.lo[axis];
    const float scale = static_cast<float>(kBins) / extent;
    const auto bin_of = [&](const Prim& p) {
        const float k = (p.box.lo[axis] + p.box.hi[axis] - lo) * scale;
        // max(0, NaN) is 0: a triangle with a NaN corner still gets a bin.
        return static_cast<std::size_t>(std::min(std::max(0.0f, k), kBins - 1.0f));
    };
    const std::uint32_t count = end - begin;
    const std::size_t n_sets = count >= 1024 ? kBinSets : 2;
    for (std::size_t s = 0; s < n_sets; ++s) {
        sets[s].fill(Bin());
    }
    for (std::uint32_t i = begin; i < end; ++i) {
        Bin& b = sets[i % n_sets][bin_of(from[i])];
        ++b.count;
        b.box.grow(from[i].box);
    }
    Bins& bins = sets[0];
    for (std::size_t s = 1; s < n_sets; ++s) {
        for (std::size_t k = 0; k < kBins; ++k) {
            bins[k].count += sets[s][k].count;
            bins[k].box.grow(sets[s][k].box);
        }
    }
    // Cost of splitting after bin k: area × count on each side.
    std::array<double, kBins> cost{};
    Box acc;
    std::uint32_t below = 0;
    for (std::size_t k = 0; k + 1 < kBins; ++k) {
        acc.grow(bins[k].box);
        below += bins[k].count;
        cost[k] = acc.half_area() * below;
    }
    acc = Box();
    std::uint32_t above = 0;
    std::size_t best = kBins;
    double best_cost = INFINITY;
    for (std::size_t k = kBins - 1; k > 0; --k) {
        acc.grow(bins[k].box);
        above += bins[k].count;
        const double c = cost[k - 1] + acc.half_area() * above;
        if (above > 0 && above < count && c < best_cost) {
            best_cost = c;
            best = k - 1;
        }
    }
    if (best == kBins) {
        return std::nullopt;
    }
    Split s;
    s.mid = begin;
    for (std::size_t k = 0; k < kBins; ++k) {
        (k <= best ? s.left : s.right).grow(bins[k].box);
        s.mid += k <= best ? bins[k].count : 0;
    }
    std::uint32_t l = begin, r = s.mid;
    for (std::uint32_t i = begin; i < end; ++i) {
        const std::uint32_t right = bin_of(from[i]) > best ? 1 : 0;
        to[right != 0 ? r : l] = from[i];
        r += right;
        l += 1 - right;
    }
    // The children's centres lie in their boxes (doubled, as key() doubles), within the
    // parent's centres, on their side of the plane: bounds enough to place the next bins.
    const float plane = lo + static_cast<float>(best + 1) / scale;
    s.left_c = s.left;
    s.right_c = s.right;
    for (std::size_t a = 0; a < 3; ++a) {
        for (Box* c : {&s.left_c, &s.right_c}) {
            c->lo[a] = std::max(2.0f * c->lo[a], centres.lo[a]);
            c->hi[a] = std::min(2.0f * c->hi[a], centres.hi[a]);
        }
    }
    s.left_c.hi[axis] = std::min(s.left_c.hi[axis], plane);
    s.right_c.lo[axis] = std::max(s.right_c.lo[axis], plane);
    return s;
}

}  // namespace

void FaceBvh::append_fan(const Mesh& mesh, Face f, std::vector<Triangle>& out) {
    for_each_fan_triangle(mesh, f, [&](std::size_t i, Vertex c0, Halfedge h) {
        out.push_back({f.idx(),
                       static_cast<std::uint32_t>(i),
                       {c0.idx(), mesh.from_vertex(h).idx(), mesh.to_vertex(h).idx()}});
    });
}

void FaceBvh::build(const Mesh& mesh) {
    nodes_.clear();
    overflow_.clear();
    stale_ = 0;
    faces_known_ = mesh.faces_size();
    std::vector<Triangle> tris;
    tris.reserve(mesh.n_faces());
    face_first_.assign(faces_known_ + 1, 0);
    for (std::uint32_t f = 0; f < faces_known_; ++f) {
        face_first_[f] = static_cast<std::uint32_t>(tris.size());
        if (!mesh.is_deleted(Face(f))) {
            append_fan(mesh, Face(f), tris);
        }
    }
    face_first_[faces_known_] = static_cast<std::uint32_t>(tris.size());
    const auto n = static_cast<std::uint32_t>(tris.size());

    std::vector<Prim> prims(n);
    Box root, root_keys;
    for (std::uint32_t i = 0; i < n; ++i) {
        const auto& c = tris[i].c;
        const Vec3& a = mesh.position(Vertex(c[0]));
        const Vec3& b = mesh.position(Vertex(c[1]));
        const Vec3& d = mesh.position(Vertex(c[2]));
        Prim& p = prims[i];
        bool finite = true;
        for (int k = 0; k < 3; ++k) {
            const auto z = static_cast<std::size_t>(k);
            p.box.lo[z] = round_down(std::min(a[k], std::min(b[k], d[k])));
            p.box.hi[z] = round_up(std::max(a[k], std::max(b[k], d[k])));
            finite = finite && std::isfinite(a[k] + b[k] + d[k]);
        }
        if (!finite) {
            // Never hit (the triangle test meets a NaN); a point box keeps NaN out of the
            // bins and the median's comparisons.
            p.box.lo = p.box.hi = {0.0f, 0.0f, 0.0f};
        }
        p.index = i;
        root.grow(p.box);
        root_keys.grow(key(p));
    }

    if (n > 0) {
        nodes_.reserve(2 * (n / 2 + 1));  // trimmed below: about 0.6 n are used
        nodes_.push_back({root.lo, 0, root.hi, 0});
        // A SAH split moves its range between prims and spare; leaves copy theirs back.
        std::vector<Prim> spare(n);
        std::array<Bins, kBinSets> sets;
        struct Task {
            std::uint32_t node, begin, end, depth;
            bool in_spare;
            Box centres;
        };
        std::vector<Task> tasks{{0, 0, n, 0, false, root_keys}};
        while (!tasks.empty()) {
            const Task task = tasks.back();
            tasks.pop_back();
            std::vector<Prim>& from = task.in_spare ? spare : prims;
            std::vector<Prim>& to = task.in_spare ? prims : spare;
            const std::uint32_t count = task.end - task.begin;
            if (count <= kLeafSize) {
                std::copy(from.begin() + task.begin, from.begin() + task.end,
                          prims.begin() + task.begin);
                nodes_[task.node].first = task.begin;
                nodes_[task.node].count = count;
                continue;
            }
            std::optional<Split> split;
            if (count >= kSahFrom && task.depth < kMaxSahDepth) {
                split = split_sah(from, to, task.begin, task.end, task.centres, sets);
            }
            const bool moved = split.has_value();
            if (!split) {
                split = split_median(from, task.begin, task.end, widest_axis(task.centres));
            }
            const bool child_in_spare = task.in_spare != moved;
            const auto child = static_cast<std::uint32_t>(nodes_.size());
            nodes_[task.node].first = child;
            nodes_.push_back({split->left.lo, 0, split->left.hi, 0});
            nodes_.push_back({split->right.lo, 0, split->right.hi, 0});
            tasks.push_back(
                {child, task.begin, split->mid, task.depth + 1, child_in_spare, split->left_c});
            tasks.push_back(
                {child + 1, split->mid, task.end, task.depth + 1, child_in_spare, split->right_c});
        }
    }

    nodes_.shrink_to_fit();
    tris_.resize(n);
    slots_.resize(n);
    for (std::uint32_t p = 0; p < n; ++p) {
        tris_[p] = tris[prims[p].index];
        slots_[prims[p].index] = p;
    }
}

void FaceBvh::update(const Mesh& mesh, std::span<const Face> touched) {
    std::vector<std::uint32_t> changed;
    for (const Face f : touched) {
        if (f.idx() < std::max(faces_known_, mesh.faces_size())) {
            changed.push_back(f.idx());
        }
    }
    // Appended since, or (an undone creation) gone past the end: changed either way.
    for (std::size_t f = std::min(faces_known_, mesh.faces_size());
         f < std::max(faces_known_, mesh.faces_size()); ++f) {
        changed.push_back(static_cast<std::uint32_t>(f));
    }
    faces_known_ = mesh.faces_size();
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());

    const std::size_t in_tree = face_first_.empty() ? 0 : face_first_.size() - 1;
    for (const std::uint32_t f : changed) {
        if (f >= in_tree) {
            continue;
        }
        for (std::uint32_t s = face_first_[f]; s < face_first_[f + 1]; ++s) {
            Triangle& tri = tris_[slots_[s]];
            if (tri.face != kInvalidIndex) {
                tri.face = kInvalidIndex;
                ++stale_;
            }
        }
    }
    std::erase_if(overflow_, [&](const Triangle& tri) {
        return std::binary_search(changed.begin(), changed.end(), tri.face);
    });
    for (const std::uint32_t f : changed) {
        if (f < mesh.faces_size() && !mesh.is_deleted(Face(f))) {
            append_fan(mesh, Face(f), overflow_);
        }
    }
    // Stale triangles only cost a skipped test each, so a big tree tolerates more of them.
    if (overflow_.size() > kUpdateLimit || stale_ > std::max(kUpdateLimit, tris_.size() / 4)) {
        build(mesh);
        ++rebuilds_;
    }
}

std::optional<std::array<double, 4>> FaceBvh::line_plane(const Vec3& a, const Vec3& b,
                                                         const Vec3& c, const Vec3& origin,
                                                         const Vec3& direction) {
    // Moller-Trumbore without the range checks.
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 p = cross(direction, e2);
    const double det = dot(e1, p);
    if (det == 0.0 || !std::isfinite(det)) {
        return std::nullopt;
    }
    const double inv = 1.0 / det;
    const Vec3 s = origin - a;
    const double u = dot(s, p) * inv;
    const Vec3 q = cross(s, e1);
    const double v = dot(direction, q) * inv;
    return std::array<double, 4>{dot(e2, q) * inv, 1.0 - u - v, u, v};
}

void FaceBvh::test(const Mesh& mesh, const Triangle& tri, const Ray& ray, Sides sides,
                   double& best_t, const Triangle*& best, std::array<double, 3>& best_b,
                   bool& best_front) const {
    if (tri.face == kInvalidIndex) {
        return;
    }
    const std::size_t nv = mesh.vertices_size();
    if (tri.c[0] >= nv || tri.c[1] >= nv || tri.c[2] >= nv) {
        return;  // a mesh this tree was not built for: never read outside it
    }
    const Vec3& a = mesh.position(Vertex(tri.c[0]));
    const Vec3 e1 = mesh.position(Vertex(tri.c[1])) - a;
    const Vec3 e2 = mesh.position(Vertex(tri.c[2])) - a;
    const Vec3 p = cross(ray.direction, e2);
    const double det = dot(e1, p);
    // det > 0: the ray runs against the normal e1 × e2, i.e. meets the front side.
    if (det == 0.0 || (sides == Sides::FrontOnly && det < 0.0)) {
        return;
    }
    const double inv = 1.0 / det;
    const Vec3 s = ray.origin - a;
    const double u = dot(s, p) * inv;
    if (!(u >= 0.0 && u <= 1.0)) {
        return;
    }
    const Vec3 q = cross(s, e1);
    const double v = dot(ray.direction, q) * inv;
    if (!(v >= 0.0 && u + v <= 1.0)) {
        return;
    }
    const double t = dot(e2, q) * inv;
    if (t >= ray.t_min && t < best_t) {
        best_t = t;
        best = &tri;
        best_b = {1.0 - u - v, u, v};
        best_front = det > 0.0;
    }
}

std::optional<FaceBvh::Hit> FaceBvh::intersect(const Mesh& mesh, const Ray& ray,
                                               Sides sides) const {
    double best_t = ray.t_max;
    const Triangle* best = nullptr;
    std::array<double, 3> best_b{};
    bool best_front = true;

    // Entry t of the ray into a node's box within [t_min, best_t], or nothing.
    const auto enter = [&](const Node& node) -> std::optional<double> {
        double t0 = ray.t_min, t1 = best_t;
        for (int a = 0; a < 3; ++a) {
            const double o = ray.origin[a], d = ray.direction[a];
            const double lo = node.lo[static_cast<std::size_t>(a)];
            const double hi = node.hi[static_cast<std::size_t>(a)];
            if (d == 0.0) {
                if (o < lo || o > hi) {
                    return std::nullopt;
                }
                continue;
            }
            double ta = (lo - o) / d, tb = (hi - o) / d;
            if (ta > tb) {
                std::swap(ta, tb);
            }
            t0 = std::max(t0, ta);
            t1 = std::min(t1, tb);
            if (!(t0 <= t1)) {
                return std::nullopt;
            }
        }
        return t0;
    };

    if (!nodes_.empty()) {
        std::array<std::pair<std::uint32_t, double>, kStackSize> stack;
        int top = 0;
        if (const auto t = enter(nodes_[0])) {
            stack[static_cast<std::size_t>(top++)] = {0, *t};
        }
        while (top > 0) {
            const auto [index, t_enter] = stack[static_cast<std::size_t>(--top)];
            if (t_enter >= best_t) {
                continue;  // a nearer hit was found since it was pushed
            }
            const Node& node = nodes_[index];
            if (node.count > 0) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                    test(mesh, tris_[i], ray, sides, best_t, best, best_b, best_front);
                }
                continue;
            }
            const auto ta = enter(nodes_[node.first]);
            const auto tb = enter(nodes_[node.first + 1]);
            // The nearer child goes on top, to be searched first.
            if (ta && tb) {
                const bool a_first = *ta <= *tb;
                stack[static_cast<std::size_t>(top++)] =
                    a_first ? std::pair{node.first + 1, *tb} : std::pair{node.first, *ta};
                stack[static_cast<std::size_t>(top++)] =
                    a_first ? std::pair{node.first, *ta} : std::pair{node.first + 1, *tb};
            } else if (ta) {
                stack[static_cast<std::size_t>(top++)] = {node.first, *ta};
            } else if (tb) {
                stack[static_cast<std::size_t>(top++)] = {node.first + 1, *tb};
            }
        }
    }
    for (const Triangle& tri : overflow_) {
        test(mesh, tri, ray, sides, best_t, best, best_b, best_front);
    }
    if (best == nullptr) {
        return std::nullopt;
    }

    Hit hit;
    const Face f(best->face);
    hit.face = f;
    hit.corners = {Vertex(best->c[0]), Vertex(best->c[1]), Vertex(best->c[2])};
    // The sides as MeshRenderer::upload() names them: only the fan's outer sides are edges.
    const Halfedge h0 = mesh.halfedge(f);
    Halfedge h = h0;
    for (std::uint32_t i = 0; i < best->fan; ++i) {
        h = mesh.next(h);
    }
    const std::size_t n = mesh.valence(f);
    hit.sides = {best->fan == 1 ? h0 : Halfedge(), h,
                 best->fan + 2 == n ? mesh.next(h) : Halfedge()};
    hit.barycentric = best_b;
    hit.t = best_t;
    hit.front = best_front;
    return hit;
}

}  // namespace meshedit
