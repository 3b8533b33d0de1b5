// Stitching T-junctions: a boundary vertex that lies on another boundary edge becomes a
// corner of that edge's face (repair.h, stitch_borders()).
//
// A CAD exporter tessellates each surface patch on its own, so two patches that meet along a
// curve have different vertices along it: the curve's vertices of one side lie on the edges
// of the other (a T-junction), and the merge cannot join what has no partner vertex. As
// Unreal's FMeshResolveTJunctions and MeshLab's "snap mismatched borders" do, the edge is
// split at the vertex instead, then the merge joins the pieces:
//
//        c                 c
//       / \               /|\     faces (a v c) and (v b c),
//      /   \     ──▶     / | \    corners at v blended from a and b
//     a─────b           a──v──b
//       v   (v on the other side of the crack)

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "meshedit/repair/repair.h"
#include "soup_edit.h"

namespace meshedit {
namespace {

using namespace repair_detail;

// One side of a face, by its undirected edge (as in orient.cpp); `corner` is the global
// index of its first corner, so it runs from low to high when indices[corner] is low. 12
// bytes: a 10M-triangle soup has 30M of them.
struct Side {
    std::uint32_t low, high, corner;
};

// A boundary side (used by one face only) from a to b; its face's corners are
// indices[begin, begin + n).
struct Border {
    std::uint32_t a, b, corner, begin, n;
};

// The border sides; `sides` gets every side, sorted by undirected edge.
std::vector<Border> border_sides(const PolygonSoup& s, std::vector<Side>& sides) {
    sides.clear();
    sides.reserve(s.indices.size());
    for_each_side(s, [&sides](std::uint32_t a, std::uint32_t b, std::uint32_t, std::uint32_t c) {
        sides.push_back({std::min(a, b), std::max(a, b), c});
    });
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
        return std::tie(x.low, x.high) < std::tie(y.low, y.high);
    });
    std::vector<Border> borders;
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i + 1;
        while (j < sides.size() && sides[j].low == sides[i].low && sides[j].high == sides[i].high) {
            ++j;
        }
        if (j == i + 1) {
            const Side& x = sides[i];
            const std::uint32_t f = static_cast<std::uint32_t>(
                std::upper_bound(s.face_offsets.begin(), s.face_offsets.end(), x.corner) -
                s.face_offsets.begin() - 1);
            const std::uint32_t begin = s.face_offsets[f];
            const std::uint32_t n = s.face_offsets[f + 1] - begin;
            const std::uint32_t a = s.indices[x.corner];
            borders.push_back({a, a == x.low ? x.high : x.low, x.corner, begin, n});
        }
        i = j;
    }
    return borders;
}

// Where boundary vertex `vertex` goes: into border side `side` (kGone: nowhere), at
// parameter t along it.
struct Insert {
    std::uint32_t vertex = kGone;
    std::uint32_t side = kGone;
    double t = 0.0;
    double distance = std::numeric_limits<double>::infinity();  // relative to the side's length
};

struct CellKey {
    std::int64_t x, y, z;
    auto operator<=>(const CellKey&) const = default;
};

// How far off a side a vertex may be, against its distance along the side from the nearer
// end: a tessellation's chord turns from its curve by at most about this (14°; a circle in 12
// chords turns 15° at each end).
constexpr double kMaxTurn = 0.25;
// The cosine between sides that run against each other at least (37°).
constexpr double kAgainst = 0.8;

// Finds, for each boundary vertex with one border side in and one out, the border side it
// lies on: at most `ratio` of the side's length and kMaxTurn of its distance from the nearer
// end off the side, farther than `merge` from either end (nearer, it is the merge's), and
// with a side of its own border running against the side within kAgainst (the other side of
// a crack runs the other way). Each vertex goes into the side it is nearest relative to that
// side's length.
std::vector<Insert> find_inserts(const PolygonSoup& s, const std::vector<Border>& borders,
                                 double ratio, double merge) {
    // Border vertices by a dense number i (their own arrays, not the soup's: a 10M-vertex
    // soup with one hole needs a few of them).
    std::vector<std::uint32_t> vertex;
    vertex.reserve(2 * borders.size());
    for (const Border& e : borders) {
        vertex.push_back(e.a);
        vertex.push_back(e.b);
    }
    std::sort(vertex.begin(), vertex.end());
    vertex.erase(std::unique(vertex.begin(), vertex.end()), vertex.end());
    const auto number = [&vertex](std::uint32_t v) {
        return static_cast<std::uint32_t>(std::lower_bound(vertex.begin(), vertex.end(), v) -
                                          vertex.begin());
    };
    const std::size_t nb = vertex.size();
    std::vector<std::uint32_t> next(nb, kGone), prev(nb, kGone), ends(nb, 0);
    double total = 0.0;
    for (const Border& e : borders) {
        const std::uint32_t a = number(e.a), b = number(e.b);
        next[a] = e.b;
        prev[b] = e.a;
        ++ends[a];
        ++ends[b];
        total += norm(s.positions[e.b] - s.positions[e.a]);
    }
    std::vector<Insert> inserts(nb);
    for (std::size_t i = 0; i < nb; ++i) {
        inserts[i].vertex = vertex[i];
    }
    if (borders.empty() || total == 0.0) {
        return inserts;
    }
    const double cell = std::max(total / static_cast<double>(borders.size()), merge);
    // Clamped, so that a position far from the others (1e300 against edges of 1e-10) makes
    // an extreme cell rather than an overflowing conversion.
    const auto coordinate = [cell](double x) {
        const double q = std::floor(x / cell);
        return std::isnan(q) ? 0 : static_cast<std::int64_t>(std::clamp(q, -4e18, 4e18));
    };
    const auto key = [&coordinate](const Vec3& p) {
        return CellKey{coordinate(p.x), coordinate(p.y), coordinate(p.z)};
    };
    std::vector<std::pair<CellKey, std::uint32_t>> grid;  // every border vertex, by i
    grid.reserve(nb);
    for (std::uint32_t i = 0; i < nb; ++i) {
        grid.push_back({key(s.positions[vertex[i]]), i});
    }
    std::sort(grid.begin(), grid.end());
    // The vertices that go in: simple border vertices without another border vertex within
    // the merge distance. Such a twin is one the merge kept apart or the builder split off
    // at a pinch; stitching one of them would only move the pinch (and a second repair would
    // find the other).
    std::vector<bool> candidate(nb, false);
    for (std::uint32_t i = 0; i < nb; ++i) {
        candidate[i] = ends[i] == 2 && next[i] != kGone && prev[i] != kGone;
    }
    for (const auto& [c, i] : grid) {
        const Vec3 p = s.positions[vertex[i]];
        for (std::int64_t x = c.x - 1; x <= c.x + 1 && candidate[i]; ++x) {
            for (std::int64_t y = c.y - 1; y <= c.y + 1 && candidate[i]; ++y) {
                auto it = std::lower_bound(grid.begin(), grid.end(),
                                           std::pair{CellKey{x, y, c.z - 1}, 0u});
                for (; it != grid.end() && it->first.x == x && it->first.y == y &&
                       it->first.z <= c.z + 1;
                     ++it) {
                    if (it->second != i && norm(s.positions[vertex[it->second]] - p) <= merge) {
                        candidate[i] = false;
                        break;
                    }
                }
            }
        }
    }

    const auto try_vertex = [&](std::uint32_t side, const Border& e, std::uint32_t i) {
        const std::uint32_t v = vertex[i];
        if (!candidate[i]) {
            return;
        }
        const auto corners = s.indices.begin() + e.begin;
        if (std::find(corners, corners + e.n, v) != corners + e.n) {
            return;  // a corner of the face already: it would pinch
        }
        const Vec3 pa = s.positions[e.a];
        const Vec3 ab = s.positions[e.b] - pa;
        const double length2 = dot(ab, ab);
        const double t = dot(s.positions[v] - pa, ab) / length2;
        const double length = std::sqrt(length2);
        const double along = std::min(t, 1.0 - t) * length;  // from the nearer end
        if (!(along > merge)) {
            return;
        }
        const double off = norm(pa + t * ab - s.positions[v]);
        const double distance = off / length;
        if (distance > ratio || off > kMaxTurn * along || distance >= inserts[i].distance) {
            return;
        }
        // One of v's border sides runs against this one (within 37°): the other side of a
        // crack, or its end where the border turns away. Else a flap folded onto it.
        const Vec3 p = s.positions[v];
        const double in = dot(p - s.positions[prev[i]], ab) / norm(p - s.positions[prev[i]]);
        const double out = dot(s.positions[next[i]] - p, ab) / norm(s.positions[next[i]] - p);
        if (!(std::min(in, out) <= -kAgainst * length)) {
            return;
        }
        inserts[i] = {v, side, t, distance};
    };
    for (std::uint32_t side = 0; side < borders.size(); ++side) {
        const Border& e = borders[side];
        const Vec3 pa = s.positions[e.a];
        const Vec3 pb = s.positions[e.b];
        const double reach = ratio * norm(pb - pa);
        if (!(reach > 0.0 && std::isfinite(reach))) {
            continue;  // no length, or past the largest double (nothing lies on it here)
        }
        const Vec3 pad{reach, reach, reach};
        const Vec3 low{std::min(pa.x, pb.x), std::min(pa.y, pb.y), std::min(pa.z, pb.z)};
        const Vec3 high{std::max(pa.x, pb.x), std::max(pa.y, pb.y), std::max(pa.z, pb.z)};
        const CellKey lo = key(low - pad);
        const CellKey hi = key(high + pad);
        const double cells =
            double(hi.x - lo.x + 1) * double(hi.y - lo.y + 1) * double(hi.z - lo.z + 1);
        if (cells > 4.0 * static_cast<double>(grid.size())) {
            for (std::uint32_t i = 0; i < nb; ++i) {  // a side longer than most: scan them all
                try_vertex(side, e, i);
            }
            continue;
        }
        for (std::int64_t x = lo.x; x <= hi.x; ++x) {
            for (std::int64_t y = lo.y; y <= hi.y; ++y) {
                const auto first =
                    std::lower_bound(grid.begin(), grid.end(), std::pair{CellKey{x, y, lo.z}, 0u});
                for (auto it = first; it != grid.end() && it->first.x == x && it->first.y == y &&
                                      it->first.z <= hi.z;
                     ++it) {
                    try_vertex(side, e, it->second);
                }
            }
        }
    }
    return inserts;
}

// The sides of the undirected edge u-v.
std::span<const Side> sides_of(const std::vector<Side>& sides, std::uint32_t u, std::uint32_t v) {
    const Side key{std::min(u, v), std::max(u, v), 0};
    const auto [first, last] =
        std::equal_range(sides.begin(), sides.end(), key, [](const Side& x, const Side& y) {
            return std::tie(x.low, x.high) < std::tie(y.low, y.high);
        });
    return {first, last};
}

// Whether a new side from u to v keeps its edge manifold and oriented: the edge has no side
// yet, or one running from v to u.
bool joins(const PolygonSoup& s, const std::vector<Side>& sides, std::uint32_t u, std::uint32_t v) {
    const std::span<const Side> old = sides_of(sides, u, v);
    return old.empty() || (old.size() == 1 && s.indices[old[0].corner] == v);
}

// Drops the inserts of a side whose pieces would give an edge a third face or two sides
// running the same way: a piece a-v or v-b (or v-w between two inserts) that is already an
// edge of two faces or of one running as it would, or, in a triangle, a fan edge v-c that is
// already an edge at all (a vertex beside the side, not on a crack).
void drop_unsafe(const PolygonSoup& s, const std::vector<Side>& sides,
                 const std::vector<Border>& borders, std::vector<Insert>& inserts) {
    std::vector<std::vector<std::pair<double, std::uint32_t>>> on(borders.size());
    for (std::uint32_t i = 0; i < inserts.size(); ++i) {
        if (inserts[i].side != kGone) {
            on[inserts[i].side].push_back({inserts[i].t, i});
        }
    }
    for (std::size_t side = 0; side < borders.size(); ++side) {
        if (on[side].empty()) {
            continue;
        }
        std::sort(on[side].begin(), on[side].end());
        const Border& e = borders[side];
        const std::uint32_t c = s.indices[e.begin + (e.corner - e.begin + 2) % e.n];
        bool safe = true;
        std::uint32_t from = e.a;
        for (std::size_t k = 0; k <= on[side].size() && safe; ++k) {
            const std::uint32_t to = k < on[side].size() ? inserts[on[side][k].second].vertex : e.b;
            safe = joins(s, sides, from, to) &&
                   (e.n != 3 || to == e.b || sides_of(sides, to, c).empty());
            from = to;
        }
        if (!safe) {
            for (const auto& [t, i] : on[side]) {
                inserts[i].side = kGone;
            }
        }
    }
}

// Rebuilds the faces with each vertex of `inserts` a corner of its side's face. A triangle
// split on one side becomes a fan from its third corner; any other face keeps the new corners
// as a polygon. \return how many vertices went in.
std::size_t insert_corners(MeshSoup& soup, const std::vector<Border>& borders,
                           const std::vector<Insert>& inserts, RepairResult& result) {
    PolygonSoup& s = soup.soup;
    // (corner of the side, t, vertex), sorted by corner then t.
    std::vector<std::tuple<std::uint32_t, double, std::uint32_t>> at;
    for (const Insert& in : inserts) {
        if (in.side != kGone) {
            at.emplace_back(borders[in.side].corner, in.t, in.vertex);
        }
    }
    if (at.empty()) {
        return 0;
    }
    std::sort(at.begin(), at.end());
    for (const auto& [corner, t, v] : at) {
        note_first(result, v);
    }

    std::vector<NewCorner> corners;
    std::vector<std::uint32_t> offsets{0}, source;
    corners.reserve(s.indices.size() + 3 * at.size());
    const auto corner = [&corners](std::uint32_t v, std::uint32_t c, std::uint32_t d, double t) {
        corners.push_back({v, c, d, t});
    };
    const auto close_face = [&](std::size_t f) {
        offsets.push_back(static_cast<std::uint32_t>(corners.size()));
        source.push_back(static_cast<std::uint32_t>(f));
    };

    std::size_t next = 0;  // into `at`
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const std::uint32_t begin = s.face_offsets[f];
        const std::uint32_t n = s.face_offsets[f + 1] - begin;
        const std::size_t first = next;
        while (next < at.size() && std::get<0>(at[next]) < begin + n) {
            ++next;
        }
        const bool one_side = first < next && std::get<0>(at[first]) == std::get<0>(at[next - 1]);
        if (n == 3 && one_side) {
            // a = the side's first corner, b the next, c the third: a fan from c.
            const std::uint32_t ca = std::get<0>(at[first]);
            const std::uint32_t cb = begin + (ca - begin + 1) % 3;
            const std::uint32_t cc = begin + (ca - begin + 2) % 3;
            std::uint32_t from_v = s.indices[ca];
            double from_t = 0.0;
            for (std::size_t k = first; k <= next; ++k) {
                const bool last = k == next;
                const std::uint32_t to_v = last ? s.indices[cb] : std::get<2>(at[k]);
                const double to_t = last ? 1.0 : std::get<1>(at[k]);
                corner(from_v, ca, cb, from_t);
                corner(to_v, ca, cb, to_t);
                corner(s.indices[cc], cc, cc, 0.0);
                close_face(f);
                from_v = to_v;
                from_t = to_t;
            }
            continue;
        }
        std::size_t k = first;
        for (std::uint32_t c = begin; c < begin + n; ++c) {
            corner(s.indices[c], c, c, 0.0);
            const std::uint32_t d = begin + (c - begin + 1) % n;
            for (; k < next && std::get<0>(at[k]) == c; ++k) {
                corner(std::get<2>(at[k]), c, d, std::get<1>(at[k]));
            }
        }
        close_face(f);
    }

    // A crease along a split side follows its pieces, in order.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> creases;
    for (const auto& [a, b] : soup.creases) {
        std::vector<std::uint32_t> chain;  // the vertices put into the crease's side
        bool reversed = false;
        for (const auto& [c, t, v] : at) {
            const std::uint32_t f = static_cast<std::uint32_t>(
                std::upper_bound(s.face_offsets.begin(), s.face_offsets.end(), c) -
                s.face_offsets.begin() - 1);
            const std::uint32_t begin = s.face_offsets[f];
            const std::uint32_t n = s.face_offsets[f + 1] - begin;
            const std::uint32_t x = s.indices[c];
            const std::uint32_t y = s.indices[begin + (c - begin + 1) % n];
            if ((a == x && b == y) || (a == y && b == x)) {
                chain.push_back(v);  // `at` runs from x to y
                reversed = a == y;
            }
        }
        if (reversed) {
            std::reverse(chain.begin(), chain.end());
        }
        std::uint32_t from = a;
        for (const std::uint32_t v : chain) {
            creases.push_back({from, v});
            from = v;
        }
        creases.push_back({from, b});
    }

    rebuild_faces(soup, corners, offsets, source);
    soup.creases = std::move(creases);
    return at.size();
}

}  // namespace

RepairResult stitch_borders(MeshSoup& soup, const StitchOptions& options,
                            const MergeTolerance& tolerance) {
    if (!std::isfinite(options.ratio) || options.ratio <= 0.0 || options.ratio >= 0.5) {
        throw std::invalid_argument(
            "the stitch ratio must be more than 0 and less than 0.5 of an edge's length, not " +
            number(options.ratio));
    }
    RepairResult result;
    const std::size_t faces_before = soup.soup.n_faces();
    std::size_t merged = 0, removed = 0, rounds = 0;
    std::size_t left = 0;
    for (; rounds < options.max_rounds; ++rounds) {
        std::vector<Side> sides;
        const std::vector<Border> borders = border_sides(soup.soup, sides);
        if (borders.empty()) {
            break;  // closed: nothing to stitch
        }
        std::vector<Insert> inserts =
            find_inserts(soup.soup, borders, options.ratio, merge_distance(soup.soup, tolerance));
        drop_unsafe(soup.soup, sides, borders, inserts);
        const std::size_t added = insert_corners(soup, borders, inserts, result);
        if (added == 0) {
            break;
        }
        result.count += added;
        // Vertices the merge kept apart (their faces touched only there) may now share the
        // new edges; what the joins flatten or repeat goes as the first steps would remove it.
        const RepairResult merge = merge_vertices(soup, tolerance);
        merged += merge.count;
        left = merge.left;
        removed += remove_degenerate_faces(soup).count;
        removed += remove_duplicate_faces(soup).count;
    }
    if (result.count == 0) {
        return result;
    }
    result.left = left;
    result.sentence = "stitched " + count_of(result.count, "boundary vertex", "boundary vertices") +
                      " into the boundary edges they lie on (T-junctions, at most " +
                      number(options.ratio) + " of the edge's length off it), " +
                      std::to_string(faces_before) + " → " +
                      count_of(soup.soup.n_faces(), "face", "faces") + listed(result);
    if (merged > 0) {
        result.sentence +=
            "; then merged " + count_of(merged, "vertex", "vertices") + " that now share edges";
    }
    if (removed > 0) {
        result.sentence += " and removed " + count_of(removed, "face", "faces") +
                           " the merge made degenerate or duplicate";
    }
    if (rounds == options.max_rounds) {
        result.sentence += "; stopped after " + std::to_string(rounds) + " rounds";
    }
    return result;
}

}  // namespace meshedit
