// Merging vertices by distance through a uniform grid (repair.h, merge_vertices()).

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshedit/core/hash.h"
#include "meshedit/repair/repair.h"
#include "soup_edit.h"

namespace meshedit {
namespace {

using repair_detail::kGone;

struct Cell {
    std::int64_t x, y, z;
    bool operator==(const Cell&) const = default;
};

// Cell → number, open addressing in one array (a node per cell in std::unordered_map made
// the lookups of a 10M-triangle merge cache misses twice over). Never holds kGone.
class CellTable {
public:
    // The number at `c`, or kGone.
    std::uint32_t find(const Cell& c) const {
        if (slots_.empty()) {
            return kGone;
        }
        for (std::size_t i = slot_of(c);; i = (i + 1) & (slots_.size() - 1)) {
            if (slots_[i].value == kGone || slots_[i].cell == c) {
                return slots_[i].value;
            }
        }
    }
    // The number at `c`, set to `value` first if there was none.
    std::uint32_t& at_or_set(const Cell& c, std::uint32_t value) {
        if (2 * (used_ + 1) > slots_.size()) {
            grow();
        }
        std::size_t i = slot_of(c);
        while (slots_[i].value != kGone && slots_[i].cell != c) {
            i = (i + 1) & (slots_.size() - 1);
        }
        if (slots_[i].value == kGone) {
            slots_[i] = {c, value};
            ++used_;
        }
        return slots_[i].value;
    }

private:
    struct Slot {
        Cell cell{};
        std::uint32_t value = kGone;
    };
    std::size_t slot_of(const Cell& c) const {
        return splitmix64(static_cast<std::uint64_t>(c.x) ^
                          splitmix64(static_cast<std::uint64_t>(c.y) ^
                                     splitmix64(static_cast<std::uint64_t>(c.z)))) &
               (slots_.size() - 1);
    }
    void grow() {
        std::vector<Slot> old = std::move(slots_);
        slots_.assign(std::max<std::size_t>(64, 2 * old.size()), Slot{});
        used_ = 0;
        for (const Slot& s : old) {
            if (s.value != kGone) {
                at_or_set(s.cell, s.value);
            }
        }
    }
    std::vector<Slot> slots_;
    std::size_t used_ = 0;
};

// The same key for 0 and -0, so equal positions meet.
Vec3 without_negative_zero(Vec3 p) {
    for (int i = 0; i < 3; ++i) {
        if (p[i] == 0.0) {
            p[i] = 0.0;
        }
    }
    return p;
}

// Kept vertices by grid cell; a vertex joins the lowest-numbered kept vertex within the
// distance among the cells its ball of that radius touches, or is kept itself. Cells are four
// distances wide, so the ball mostly lies in one cell (27 lookups a vertex, every one a hash
// miss, were two thirds of a 10M-triangle repair).
class Grid {
public:
    Grid(const BoundingBox& box, double distance) : origin_(box.min), distance_(distance) {
        // Cells at least `distance` wide, so neighbours within it are in the 27 cells around;
        // wider when the box holds more than 2^40 of them a side (a tiny absolute distance on
        // a large mesh), which keeps the cell numbers exact and changes nothing else.
        double largest = 0.0;
        for (int i = 0; i < 3; ++i) {
            largest = std::max(largest, box.max[i] * 0.5 - box.min[i] * 0.5);
        }
        cell_ = std::max(4.0 * distance, largest / std::ldexp(1.0, 39));
    }

    // The kept vertex (an index into `kept`) that `p` merges into, or kGone.
    std::uint32_t find(const Vec3& p, const std::vector<Vec3>& kept) const {
        const Cell lo = cell_of(p, -distance_);
        const Cell hi = cell_of(p, distance_);
        std::uint32_t best = kGone;
        for (std::int64_t x = lo.x; x <= hi.x; ++x) {
            for (std::int64_t y = lo.y; y <= hi.y; ++y) {
                for (std::int64_t z = lo.z; z <= hi.z; ++z) {
                    for (std::uint32_t k = heads_.find({x, y, z}); k != kGone; k = next_[k]) {
                        if (k < best && distance(kept[k], p) <= distance_) {
                            best = k;
                        }
                    }
                }
            }
        }
        return best;
    }

    void add(const Vec3& p, std::uint32_t k) {
        next_.resize(k + 1, kGone);
        std::uint32_t& head = heads_.at_or_set(cell_of(p, 0.0), k);
        if (head != k) {
            next_[k] = head;
            head = k;
        }
    }

private:
    // The cell of p shifted by `by` along every axis (halved first, so no sum overflows).
    Cell cell_of(const Vec3& p, double by) const {
        const auto axis = [&](int i) {
            return static_cast<std::int64_t>(
                std::floor((p[i] * 0.5 - origin_[i] * 0.5 + by * 0.5) / cell_ * 2.0));
        };
        return {axis(0), axis(1), axis(2)};
    }

    Vec3 origin_;
    double distance_;
    double cell_ = 1.0;
    CellTable heads_;
    std::vector<std::uint32_t> next_;  // the next kept vertex in the same cell
};

// The leader of each vertex's group: the lowest-numbered used vertex within `distance` that
// is a leader itself (vertices are taken in order), or the vertex itself. Unused and
// non-finite vertices lead themselves.
std::vector<std::uint32_t> group_leaders(const std::vector<Vec3>& positions,
                                         const std::vector<bool>& used, const BoundingBox& box,
                                         double distance) {
    std::vector<std::uint32_t> leader(positions.size());
    std::vector<Vec3> kept;                 // the leaders' positions, in order
    std::vector<std::uint32_t> kept_index;  // and their vertex indices
    if (distance > 0.0) {
        Grid grid(box, distance);
        for (std::uint32_t v = 0; v < positions.size(); ++v) {
            leader[v] = v;
            if (!used[v] || !is_finite(positions[v])) {
                continue;
            }
            const std::uint32_t k = grid.find(positions[v], kept);
            if (k != kGone) {
                leader[v] = kept_index[k];
                continue;
            }
            grid.add(positions[v], static_cast<std::uint32_t>(kept.size()));
            kept.push_back(positions[v]);
            kept_index.push_back(v);
        }
        return leader;
    }
    // Equal positions only: a hash of the exact coordinates.
    CellTable seen;
    for (std::uint32_t v = 0; v < positions.size(); ++v) {
        leader[v] = v;
        const Vec3 p = without_negative_zero(positions[v]);
        if (used[v] && is_finite(p)) {
            const Cell key{std::bit_cast<std::int64_t>(p.x), std::bit_cast<std::int64_t>(p.y),
                           std::bit_cast<std::int64_t>(p.z)};
            leader[v] = seen.at_or_set(key, v);
        }
    }
    return leader;
}

// Where each corner goes once the groups merge, so that no merge makes a vertex whose faces
// touch only there: the corners at a group fall into fans, joined through the edges of
// exactly two faces they share once merged (the builder cuts an edge of three faces and would
// split the vertex again), and each fan becomes one vertex, its lowest-numbered member.
// Faces that the later steps remove take no part, so that they do not hold fans apart: a
// face left degenerate sends its corners to their groups' leaders, a face on the same groups
// as an earlier one (a duplicate) sends them where that face's go. Returns the old vertex
// index for each corner, and counts the groups' fans beyond the first in `apart`.
std::vector<std::uint32_t> corners_by_fan(const PolygonSoup& s,
                                          const std::vector<std::uint32_t>& leader,
                                          std::size_t& apart) {
    using repair_detail::Degenerate;
    std::vector<std::uint32_t> members(leader.size(), 0);
    for (std::size_t v = 0; v < leader.size(); ++v) {
        ++members[leader[v]];
    }
    const auto merged = [&](std::uint32_t g) { return members[g] >= 2; };
    const auto edge_key = [](std::uint32_t a, std::uint32_t b) {
        return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    };
    constexpr std::uint32_t kTakesPart = kGone;
    // Per face: kTakesPart, kGone - 1 (degenerate once merged) or the earlier face it repeats.
    constexpr std::uint32_t kDegenerate = kGone - 1;
    std::vector<std::uint32_t> role(s.n_faces(), kTakesPart);
    std::unordered_multimap<std::uint64_t, std::uint32_t> by_groups;
    std::vector<std::uint32_t> groups, sorted, other;
    for (std::uint32_t f = 0; f < s.n_faces(); ++f) {
        groups.assign(s.indices.begin() + s.face_offsets[f],
                      s.indices.begin() + s.face_offsets[f + 1]);
        bool touched = false;
        for (std::uint32_t& v : groups) {
            touched = touched || merged(leader[v]);
            v = leader[v];
        }
        if (!touched) {
            continue;  // as it was: the other steps judge it
        }
        repair_detail::drop_repeated_corners(groups);
        if (repair_detail::degenerate(s.positions, groups) != Degenerate::None) {
            role[f] = kDegenerate;
            continue;
        }
        sorted = groups;
        std::sort(sorted.begin(), sorted.end());
        std::uint64_t hash = 0xcbf29ce484222325ull;
        for (const std::uint32_t g : sorted) {
            hash = (hash ^ g) * 0x100000001b3ull;
        }
        const auto [first, last] = by_groups.equal_range(hash);
        for (auto at = first; at != last && role[f] == kTakesPart; ++at) {
            other.assign(s.indices.begin() + s.face_offsets[at->second],
                         s.indices.begin() + s.face_offsets[at->second + 1]);
            for (std::uint32_t& v : other) {
                v = leader[v];
            }
            repair_detail::drop_repeated_corners(other);
            std::sort(other.begin(), other.end());
            if (other == sorted) {
                role[f] = at->second;
            }
        }
        if (role[f] == kTakesPart) {
            by_groups.emplace(hash, f);
        }
    }
    // How many sides of the faces that take part each edge at a merged group will have.
    std::unordered_map<std::uint64_t, std::uint32_t> sides;
    for (std::uint32_t f = 0; f < s.n_faces(); ++f) {
        const std::uint32_t begin = s.face_offsets[f];
        const std::uint32_t n = s.face_offsets[f + 1] - begin;
        for (std::uint32_t i = 0; i < n && role[f] == kTakesPart; ++i) {
            const std::uint32_t a = leader[s.indices[begin + i]];
            const std::uint32_t b = leader[s.indices[begin + (i + 1) % n]];
            if (a != b && (merged(a) || merged(b))) {
                ++sides[edge_key(a, b)];
            }
        }
    }
    // Their corners at merged groups, joined when they share such an edge (leader, other
    // end's leader).
    std::vector<std::uint32_t> parent(s.indices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&parent](std::uint32_t c) {
        while (parent[c] != c) {
            parent[c] = parent[parent[c]];
            c = parent[c];
        }
        return c;
    };
    std::unordered_map<std::uint64_t, std::uint32_t> corner_of_edge;
    for (std::uint32_t f = 0; f < s.n_faces(); ++f) {
        const std::uint32_t begin = s.face_offsets[f];
        const std::uint32_t n = s.face_offsets[f + 1] - begin;
        for (std::uint32_t i = 0; i < n && role[f] == kTakesPart; ++i) {
            const std::uint32_t c = begin + i;
            const std::uint32_t g = leader[s.indices[c]];
            if (!merged(g)) {
                continue;
            }
            for (const std::uint32_t next : {begin + (i + 1) % n, begin + (i + n - 1) % n}) {
                const std::uint32_t w = leader[s.indices[next]];
                if (w == g) {
                    parent[find(c)] = find(next);  // a side that merges away: one corner
                    continue;
                }
                if (sides[edge_key(g, w)] != 2) {
                    continue;  // an edge the builder cuts
                }
                const std::uint64_t key = (static_cast<std::uint64_t>(g) << 32) | w;
                const auto [at, added] = corner_of_edge.try_emplace(key, c);
                if (!added) {
                    parent[find(c)] = find(at->second);
                }
            }
        }
    }
    // Each fan's lowest-numbered member, found at the fan's root corner.
    std::unordered_map<std::uint32_t, std::uint32_t> lowest;
    for (std::uint32_t f = 0; f < s.n_faces(); ++f) {
        for (std::uint32_t c = s.face_offsets[f]; c < s.face_offsets[f + 1]; ++c) {
            if (role[f] == kTakesPart && merged(leader[s.indices[c]])) {
                const auto at = lowest.try_emplace(find(c), s.indices[c]).first;
                at->second = std::min(at->second, s.indices[c]);
            }
        }
    }
    std::unordered_map<std::uint32_t, std::uint32_t> fans_of_group;
    for (const auto& [root, vertex] : lowest) {
        ++fans_of_group[leader[vertex]];
    }
    apart = 0;
    for (const auto& [group, fans] : fans_of_group) {
        apart += fans - 1;
    }
    std::vector<std::uint32_t> target(s.indices.begin(), s.indices.end());
    for (std::uint32_t f = 0; f < s.n_faces(); ++f) {
        for (std::uint32_t c = s.face_offsets[f]; c < s.face_offsets[f + 1]; ++c) {
            const std::uint32_t g = leader[s.indices[c]];
            if (role[f] == kTakesPart) {
                target[c] = merged(g) ? lowest[find(c)] : s.indices[c];
            } else if (role[f] == kDegenerate) {
                target[c] = g;
            }
        }
    }
    // A duplicate's corners go where the corners of the face it repeats went (that face is
    // earlier, so its targets are set).
    for (std::uint32_t f = 0; f < s.n_faces(); ++f) {
        if (role[f] == kTakesPart || role[f] == kDegenerate) {
            continue;
        }
        const std::uint32_t o = role[f];
        for (std::uint32_t c = s.face_offsets[f]; c < s.face_offsets[f + 1]; ++c) {
            for (std::uint32_t d = s.face_offsets[o]; d < s.face_offsets[o + 1]; ++d) {
                if (leader[s.indices[d]] == leader[s.indices[c]]) {
                    target[c] = target[d];
                    break;
                }
            }
        }
    }
    return target;
}

}  // namespace

RepairResult merge_vertices(MeshSoup& soup, const MergeTolerance& tolerance) {
    using namespace repair_detail;
    if (!std::isfinite(tolerance.value) || tolerance.value < 0.0) {
        throw std::invalid_argument(
            "the merge distance must be a finite number of at least 0, not " +
            number(tolerance.value));
    }
    check_polygon_soup(soup.soup);
    PolygonSoup& s = soup.soup;
    const std::vector<bool> used = used_vertices(s);
    BoundingBox box;
    for (std::size_t v = 0; v < s.positions.size(); ++v) {
        if (used[v]) {
            box.add(s.positions[v]);
        }
    }
    const double distance =
        tolerance.relative ? fraction_of_diagonal(box, tolerance.value) : tolerance.value;
    const std::vector<std::uint32_t> leader = group_leaders(s.positions, used, box, distance);
    std::size_t apart = 0;
    const std::vector<std::uint32_t> target = corners_by_fan(s, leader, apart);

    RepairResult result;
    result.left = apart;
    std::vector<bool> still_used(s.positions.size(), false);
    for (const std::uint32_t v : target) {
        still_used[v] = true;
    }
    // Where a crease's ends go: a merged vertex to where its corners went, others stay.
    std::vector<std::uint32_t> into(s.positions.size());
    std::iota(into.begin(), into.end(), 0u);
    for (std::size_t c = 0; c < target.size(); ++c) {
        if (!still_used[s.indices[c]]) {
            into[s.indices[c]] = target[c];
        }
    }
    for (std::uint32_t v = 0; v < s.positions.size(); ++v) {
        if (used[v] && !still_used[v]) {
            ++result.count;
            note_first(result, v);
        }
    }
    const std::size_t before = s.positions.size();
    std::size_t creases = 0;
    if (result.count > 0) {
        s.indices.assign(target.begin(), target.end());
        std::size_t out = 0;
        for (auto [a, b] : soup.creases) {
            a = a < into.size() ? into[a] : a;
            b = b < into.size() ? into[b] : b;
            if (a == b) {
                ++creases;
            } else {
                soup.creases[out++] = {a, b};
            }
        }
        soup.creases.resize(out);
        remove_unused_vertices(soup, used, creases);  // the merged ones: the count itself
    }

    std::string within = "within " + number(distance);
    if (tolerance.relative) {
        within += " (" + number(tolerance.value) + " of the bounding-box diagonal)";
    }
    if (result.count > 0) {
        result.sentence = "merged " + count_of(result.count, "vertex", "vertices") +
                          " into others " + within + ", " + std::to_string(before) + " → " +
                          count_of(s.positions.size(), "vertex", "vertices") + listed(result);
        if (creases > 0) {
            result.sentence += "; dropped " + count_of(creases, "crease mark", "crease marks") +
                               " whose ends merged";
        }
    }
    if (apart > 0) {
        result.sentence += std::string(result.sentence.empty() ? "" : "; ") + "kept " +
                           count_of(apart, "vertex", "vertices") + " " + within +
                           " of another apart, as their faces would touch only there";
    }
    return result;
}

}  // namespace meshedit
