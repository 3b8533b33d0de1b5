// Patch tessellation into one welded, consistently oriented core mesh. Order of work:
// sample, weld (spatial hash), triangulate dropping collapsed triangles, orient per connected
// component, compact, build_mesh(). Orientation must happen before build_mesh(), which would
// otherwise cut every inconsistently oriented seam into two boundaries.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/build.h"

namespace meshedit {
namespace {

using Index = std::uint32_t;
using Triangle = std::array<Index, 3>;

// Maps every sample to a representative: a sample joins the first representative within
// min(its tolerance, the representative's), otherwise it becomes one. Tolerances are relative
// to each patch's size, so a patch a long way off (or a huge one) cannot weld a small one
// away. Representatives live in one grid per tolerance scale (powers of 16), each grid's cells
// at least as wide as its tolerances: a representative that can join a sample lies within its
// own tolerance of it, so the 27 cells around the sample in each grid hold every candidate.
class Welder {
public:
    /// `extent` bounds |coordinate|; cells never get so small that their indices overflow.
    explicit Welder(double extent) : min_cell_(extent * 0x1p-50) {}

    Index add(const Vec3& p, double tol) {
        for (Grid& g : grids_) {
            const std::array<std::int64_t, 3> c = g.cell(p);
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
                for (std::int64_t dy = -1; dy <= 1; ++dy) {
                    for (std::int64_t dz = -1; dz <= 1; ++dz) {
                        const auto it = g.cells.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
                        if (it == g.cells.end()) {
                            continue;
                        }
                        for (Index r : it->second) {
                            if (distance(points_[r], p) <= std::min(tol, tols_[r])) {
                                return r;
                            }
                        }
                    }
                }
            }
        }
        const Index r = static_cast<Index>(points_.size());
        points_.push_back(p);
        tols_.push_back(tol);
        Grid& g = grid_for(tol);
        g.cells[key(g.cell(p))].push_back(r);
        return r;
    }

    const std::vector<Vec3>& points() const { return points_; }

private:
    struct Grid {
        int scale;  // cells are 16^scale wide (or min_cell_, whichever is larger)
        double inv_cell;
        std::unordered_map<std::uint64_t, std::vector<Index>> cells;

        std::array<std::int64_t, 3> cell(const Vec3& p) const {
            return {static_cast<std::int64_t>(std::floor(p.x * inv_cell)),
                    static_cast<std::int64_t>(std::floor(p.y * inv_cell)),
                    static_cast<std::int64_t>(std::floor(p.z * inv_cell))};
        }
    };

    Grid& grid_for(double tol) {
        int exponent = 0;
        std::frexp(tol, &exponent);
        const int scale = tol > 0.0 ? (exponent + 3) / 4 : -1000;  // 16^scale >= tol
        for (Grid& g : grids_) {
            if (g.scale == scale) {
                return g;
            }
        }
        const double cell = std::max(tol > 0.0 ? std::ldexp(1.0, 4 * scale) : 0.0, min_cell_);
        grids_.push_back({scale, cell > 0.0 ? 1.0 / cell : 0.0, {}});
        return grids_.back();
    }

    static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
        // Mixing hash; collisions only cost a few extra distance tests.
        std::uint64_t h = 0x9e3779b97f4a7c15ull;
        for (std::int64_t v : c) {
            h ^= static_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        }
        return h;
    }

    double min_cell_;
    std::vector<Vec3> points_;
    std::vector<double> tols_;
    std::vector<Grid> grids_;
};

// Flips triangles so that neighbours across every manifold edge agree, then orients each
// connected component: positive signed volume about its centroid for closed-ish parts, the
// area-weighted majority of the input orientation for open sheets.
void orient(std::vector<Triangle>& tris, const std::vector<Vec3>& points) {
    struct EdgeUse {
        std::uint64_t key;
        Index tri;
        bool forward;  // runs from the smaller to the larger vertex index
    };
    std::vector<EdgeUse> uses;
    uses.reserve(3 * tris.size());
    for (Index t = 0; t < tris.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const Index a = tris[t][k], b = tris[t][(k + 1) % 3];
            const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
            uses.push_back({key, t, a < b});
        }
    }
    std::sort(uses.begin(), uses.end(),
              [](const EdgeUse& x, const EdgeUse& y) { return x.key < y.key; });

    // Adjacency across manifold edges only; `same` means both use the edge in one direction,
    // so exactly one of the two must flip. Edges with 3+ uses are left to build_mesh().
    struct Link {
        Index other;
        bool same;
    };
    std::vector<std::vector<Link>> adjacent(tris.size());
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i;
        while (j < uses.size() && uses[j].key == uses[i].key) {
            ++j;
        }
        if (j - i == 2 && uses[i].tri != uses[i + 1].tri) {
            const bool same = uses[i].forward == uses[i + 1].forward;
            adjacent[uses[i].tri].push_back({uses[i + 1].tri, same});
            adjacent[uses[i + 1].tri].push_back({uses[i].tri, same});
        }
        i = j;
    }

    constexpr std::uint8_t kUnseen = 2;
    std::vector<std::uint8_t> flip(tris.size(), kUnseen);
    std::vector<Index> component;
    for (Index seed = 0; seed < tris.size(); ++seed) {
        if (flip[seed] != kUnseen) {
            continue;
        }
        // Breadth-first over the component; a conflict (a Möbius-like part) keeps the first
        // assignment and the seam becomes a boundary in build_mesh().
        component.clear();
        component.push_back(seed);
        flip[seed] = 0;
        for (std::size_t q = 0; q < component.size(); ++q) {
            const Index t = component[q];
            for (const Link& l : adjacent[t]) {
                if (flip[l.other] == kUnseen) {
                    flip[l.other] = static_cast<std::uint8_t>(flip[t] ^ (l.same ? 1 : 0));
                    component.push_back(l.other);
                }
            }
        }
        for (Index t : component) {
            if (flip[t]) {
                std::swap(tris[t][1], tris[t][2]);
            }
        }

        // Closed-ish parts (their face area vectors nearly cancel: a teapot body with its
        // open top) take the orientation of positive signed volume about their centroid.
        // Open sheets, whose volume sign means nothing, keep the area-weighted majority of
        // the input orientation.
        Vec3 centroid;
        Vec3 area_sum;
        double area_total = 0.0, area_flipped = 0.0;
        for (Index t : component) {
            const Vec3& a = points[tris[t][0]];
            const Vec3& b = points[tris[t][1]];
            const Vec3& c = points[tris[t][2]];
            centroid += a + b + c;
            const Vec3 area = cross(b - a, c - a);
            area_sum += area;
            area_total += norm(area);
            area_flipped += flip[t] ? norm(area) : 0.0;
        }
        centroid /= 3.0 * static_cast<double>(component.size());
        double volume = 0.0;  // six times the signed volume of the cone from the centroid
        for (Index t : component) {
            const Vec3 a = points[tris[t][0]] - centroid;
            const Vec3 b = points[tris[t][1]] - centroid;
            const Vec3 c = points[tris[t][2]] - centroid;
            volume += dot(a, cross(b, c));
        }
        const bool closed_ish = norm(area_sum) <= 0.5 * area_total && volume != 0.0;
        const bool reverse = closed_ish ? volume < 0.0 : 2.0 * area_flipped > area_total;
        if (reverse) {
            for (Index t : component) {
                std::swap(tris[t][1], tris[t][2]);
            }
        }
    }
}

}  // namespace

Mesh tessellate(std::span<const BezierPatch> patches, const TessellationOptions& options) {
    const int d = std::max(options.density, 1);
    const std::size_t side = std::size_t(d) + 1;
    // About 240 bytes per triangle were measured at the peak (samples, welding hash, edge
    // uses and adjacency for orienting), then the soup and the mesh.
    const double samples_n = static_cast<double>(patches.size() * side * side);
    const double triangles = 2.0 * static_cast<double>(patches.size()) * d * d;
    check_budget(240.0 * triangles + build_bytes(samples_n, 3.0 * triangles, triangles),
                 "tessellating " + std::to_string(patches.size()) + " patches at density " +
                     std::to_string(d));

    std::vector<Vec3> samples;
    samples.reserve(patches.size() * side * side);
    std::vector<double> patch_tolerance;
    patch_tolerance.reserve(patches.size());
    double extent = 0.0;
    for (const BezierPatch& patch : patches) {
        BoundingBox box;
        for (int j = 0; j <= d; ++j) {
            for (int i = 0; i <= d; ++i) {
                // i / d and j / d are exact at 0 and 1, so patch corners hit control points.
                const Vec3 p = patch.evaluate(double(i) / d, double(j) / d);
                samples.push_back(p);
                box.add(p);
            }
        }
        patch_tolerance.push_back(options.weld_tolerance * box.diagonal());
        for (int i = 0; i < 3; ++i) {
            extent = std::max({extent, std::abs(box.min[i]), std::abs(box.max[i])});
        }
    }
    Welder welder(extent);
    std::vector<Index> welded(samples.size());
    for (std::size_t s = 0; s < samples.size(); ++s) {
        welded[s] = welder.add(samples[s], patch_tolerance[s / (side * side)]);
    }

    std::vector<Triangle> tris;
    tris.reserve(2 * patches.size() * d * d);
    auto add = [&](Index a, Index b, Index c) {
        // Triangles with a repeated welded corner are the slivers of a collapsed row (a pole).
        if (a != b && b != c && c != a) {
            tris.push_back({a, b, c});
        }
    };
    for (std::size_t k = 0; k < patches.size(); ++k) {
        const std::size_t base = k * side * side;
        for (int j = 0; j < d; ++j) {
            for (int i = 0; i < d; ++i) {
                const std::size_t s = base + j * side + i;
                const Index a = welded[s], b = welded[s + 1];
                const Index c = welded[s + side + 1], e = welded[s + side];
                if (a == c) {
                    // A diagonal whose ends weld together would lose the whole quad: use the
                    // other one.
                    add(a, b, e);
                    add(b, c, e);
                } else {
                    add(a, b, c);
                    add(a, c, e);
                }
            }
        }
    }

    orient(tris, welder.points());

    // Compact: keep only representatives that some triangle uses, in first-use order.
    constexpr Index kUnused = ~Index{0};
    std::vector<Index> remap(welder.points().size(), kUnused);
    PolygonSoup soup;
    for (Triangle& t : tris) {
        for (Index& v : t) {
            if (remap[v] == kUnused) {
                remap[v] = static_cast<Index>(soup.positions.size());
                soup.positions.push_back(welder.points()[v]);
            }
            v = remap[v];
        }
        soup.add_face_range(t);
    }
    return build_mesh(soup);
}

}  // namespace meshedit
