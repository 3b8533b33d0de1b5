// The face steps: degenerate faces, duplicate faces, small components (repair.h).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "meshedit/repair/repair.h"
#include "soup_edit.h"

namespace meshedit {
namespace {

using namespace repair_detail;

// Twice the area vector of the polygon through `corners` (Newell's formula, about the first
// corner so that a face far from the origin keeps its digits).
template <class Corners>
Vec3 area_vector(const std::vector<Vec3>& positions, const Corners& corners) {
    Vec3 sum;
    const Vec3 origin = positions[corners[0]];
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
        sum += cross(positions[corners[i]] - origin, positions[corners[i + 1]] - origin);
    }
    return sum;
}

double face_area(const PolygonSoup& s, std::size_t f) {
    const std::span<const std::uint32_t> corners(s.indices.data() + s.face_offsets[f],
                                                 s.face_offsets[f + 1] - s.face_offsets[f]);
    return corners.size() < 3 ? 0.0 : 0.5 * norm(area_vector(s.positions, corners));
}

// Vertex groups joined by faces (union by size, path halving).
class Components {
public:
    explicit Components(std::size_t n) : parent_(n), size_(n, 1) {
        std::iota(parent_.begin(), parent_.end(), 0u);
    }
    std::uint32_t find(std::uint32_t v) {
        while (parent_[v] != v) {
            parent_[v] = parent_[parent_[v]];
            v = parent_[v];
        }
        return v;
    }
    void join(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) {
            return;
        }
        if (size_[a] < size_[b]) {
            std::swap(a, b);
        }
        parent_[b] = a;
        size_[a] += size_[b];
    }

private:
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint32_t> size_;
};

}  // namespace

RepairResult remove_degenerate_faces(MeshSoup& soup) {
    check_polygon_soup(soup.soup);
    PolygonSoup& s = soup.soup;
    const std::vector<bool> used_before = used_vertices(s);
    std::vector<bool> keep_corner(s.indices.size(), false);
    std::vector<bool> keep_face(s.n_faces(), true);
    std::size_t few = 0, pinched = 0, flat = 0, corner_faces = 0;
    std::vector<std::uint32_t> corner_face_list;
    RepairResult result;
    std::vector<std::uint32_t> corners;  // the corner slots kept, then their vertices
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        corners.clear();
        for (std::uint32_t c = s.face_offsets[f]; c < s.face_offsets[f + 1]; ++c) {
            if (corners.empty() || s.indices[corners.back()] != s.indices[c]) {
                corners.push_back(c);
            }
        }
        while (corners.size() > 1 && s.indices[corners.front()] == s.indices[corners.back()]) {
            corners.pop_back();
        }
        for (const std::uint32_t c : corners) {
            keep_corner[c] = true;
        }
        const std::size_t dropped = s.face_offsets[f + 1] - s.face_offsets[f] - corners.size();
        for (std::uint32_t& c : corners) {
            c = s.indices[c];
        }
        const Degenerate kind = degenerate(s.positions, corners);
        few += kind == Degenerate::Few ? 1 : 0;
        pinched += kind == Degenerate::Pinched ? 1 : 0;
        flat += kind == Degenerate::Flat ? 1 : 0;
        if (kind != Degenerate::None) {
            keep_face[f] = false;
            ++result.count;
            note_first(result, static_cast<std::uint32_t>(f));
        } else if (dropped > 0) {
            result.corners += dropped;
            ++corner_faces;
            if (corner_face_list.size() < kRepairShown) {
                corner_face_list.push_back(static_cast<std::uint32_t>(f));
            }
        }
    }
    if (!result.changed()) {
        return result;
    }
    keep_corners(soup, keep_corner);
    keep_faces(soup, keep_face);
    std::size_t creases = 0;
    result.removed_vertices = remove_unused_vertices(soup, used_before, creases);

    std::vector<std::string> parts;
    if (result.count > 0) {
        std::vector<std::string> why;
        if (few > 0) {
            why.push_back(std::to_string(few) + " with fewer than 3 distinct corners");
        }
        if (pinched > 0) {
            why.push_back(std::to_string(pinched) + " with a corner repeated");
        }
        if (flat > 0) {
            why.push_back(std::to_string(flat) + " of zero area");
        }
        std::string reasons;
        for (std::size_t i = 0; i < why.size(); ++i) {
            reasons += (i == 0 ? "" : ", ") + why[i];
        }
        parts.push_back("removed " + count_of(result.count, "degenerate face", "degenerate faces") +
                        " (" + reasons + ")" + listed(result) +
                        also_removed(result.removed_vertices, creases));
    }
    if (result.corners > 0) {
        RepairResult faces;
        faces.count = corner_faces;
        faces.first = corner_face_list;
        parts.push_back("dropped " +
                        count_of(result.corners, "repeated corner", "repeated corners") + " from " +
                        count_of(corner_faces, "face", "faces") + listed(faces));
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
        result.sentence += (i == 0 ? "" : "; ") + parts[i];
    }
    return result;
}

RepairResult remove_duplicate_faces(MeshSoup& soup) {
    check_polygon_soup(soup.soup);
    PolygonSoup& s = soup.soup;
    // Each face's sorted corners, side by side in the same layout as the indices.
    std::vector<std::uint32_t> sorted = s.indices;
    // (hash of the sorted corners, face), sorted: equal faces end up side by side, earliest
    // first (a multimap of 10M nodes was a fifth of a repair).
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(s.n_faces());
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const auto begin = sorted.begin() + s.face_offsets[f];
        const auto end = sorted.begin() + s.face_offsets[f + 1];
        std::sort(begin, end);
        std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a over the sorted corners
        for (auto it = begin; it != end; ++it) {
            hash = (hash ^ *it) * 0x100000001b3ull;
        }
        keys[f] = {hash, static_cast<std::uint32_t>(f)};
    }
    std::sort(keys.begin(), keys.end());
    const auto corners_of = [&](std::uint32_t f) {
        return std::span<const std::uint32_t>(sorted.data() + s.face_offsets[f],
                                              s.face_offsets[f + 1] - s.face_offsets[f]);
    };
    std::vector<bool> keep(s.n_faces(), true);
    RepairResult result;
    for (std::size_t run = 0; run < keys.size();) {
        std::size_t end = run + 1;
        while (end < keys.size() && keys[end].first == keys[run].first) {
            ++end;
        }
        // Within a run of one hash (nearly always one face): a face equal to an earlier kept
        // face of the run is a duplicate.
        for (std::size_t i = run + 1; i < end; ++i) {
            const std::span<const std::uint32_t> a = corners_of(keys[i].second);
            for (std::size_t j = run; j < i; ++j) {
                const std::span<const std::uint32_t> b = corners_of(keys[j].second);
                if (keep[keys[j].second] && std::equal(a.begin(), a.end(), b.begin(), b.end())) {
                    keep[keys[i].second] = false;
                    ++result.count;
                    break;
                }
            }
        }
        run = end;
    }
    for (std::uint32_t f = 0; f < s.n_faces() && result.first.size() < kRepairShown; ++f) {
        if (!keep[f]) {
            note_first(result, f);  // the first few, in face order as before
        }
    }
    if (result.count == 0) {
        return result;
    }
    // A duplicate's vertices are its original's: none is left unused.
    keep_faces(soup, keep);
    result.sentence = "removed " + count_of(result.count, "duplicate face", "duplicate faces") +
                      " (the same vertices as an earlier face)" + listed(result);
    return result;
}

RepairResult remove_small_components(MeshSoup& soup, const ComponentBounds& bounds) {
    if (!(bounds.min_area >= 0.0) || !std::isfinite(bounds.min_area)) {
        throw std::invalid_argument(
            "the smallest component area must be a finite number of at "
            "least 0, not " +
            number(bounds.min_area));
    }
    check_polygon_soup(soup.soup);
    PolygonSoup& s = soup.soup;
    RepairResult result;
    if ((bounds.min_faces == 0 && bounds.min_area == 0.0) || s.n_faces() == 0) {
        return result;
    }
    Components components(s.positions.size());
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        for (std::uint32_t c = s.face_offsets[f] + 1; c < s.face_offsets[f + 1]; ++c) {
            components.join(s.indices[s.face_offsets[f]], s.indices[c]);
        }
    }
    // Per component, in the order of their first faces: faces, area, first face.
    struct Part {
        std::size_t faces = 0;
        double area = 0.0;
        std::uint32_t first_face = 0;
    };
    std::vector<Part> parts;
    std::unordered_map<std::uint32_t, std::uint32_t> part_of_root;
    std::vector<std::uint32_t> part_of_face(s.n_faces(), kGone);
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        if (s.face_offsets[f] == s.face_offsets[f + 1]) {
            continue;  // a face without corners belongs to no component; the builder drops it
        }
        const std::uint32_t root = components.find(s.indices[s.face_offsets[f]]);
        const auto [at, added] =
            part_of_root.try_emplace(root, static_cast<std::uint32_t>(parts.size()));
        if (added) {
            parts.push_back({0, 0.0, static_cast<std::uint32_t>(f)});
        }
        part_of_face[f] = at->second;
        parts[at->second].faces += 1;
        parts[at->second].area += face_area(s, f);
    }
    const auto small = [&](const Part& p) {
        return (bounds.min_faces > 0 && p.faces < bounds.min_faces) ||
               (bounds.min_area > 0.0 && p.area < bounds.min_area);
    };
    std::vector<bool> remove(parts.size(), false);
    std::size_t kept_largest = kGone;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        remove[i] = small(parts[i]);
    }
    if (std::all_of(remove.begin(), remove.end(), [](bool r) { return r; })) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < parts.size(); ++i) {
            if (parts[i].faces > parts[best].faces ||
                (parts[i].faces == parts[best].faces && parts[i].area > parts[best].area)) {
                best = i;
            }
        }
        remove[best] = false;
        kept_largest = best;
    }
    std::size_t faces_removed = 0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (remove[i]) {
            ++result.count;
            faces_removed += parts[i].faces;
            note_first(result, parts[i].first_face);
        }
    }
    if (result.count == 0) {
        return result;
    }
    const std::vector<bool> used_before = used_vertices(s);
    std::vector<bool> keep(s.n_faces(), true);
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        keep[f] = part_of_face[f] == kGone || !remove[part_of_face[f]];
    }
    keep_faces(soup, keep);
    std::size_t creases = 0;
    result.removed_vertices = remove_unused_vertices(soup, used_before, creases);

    std::string bound;
    if (bounds.min_faces > 0) {
        bound = "fewer than " + count_of(bounds.min_faces, "face", "faces");
    }
    if (bounds.min_area > 0.0) {
        bound += (bound.empty() ? "" : " or ") + std::string("less than ") +
                 number(bounds.min_area) + " in area";
    }
    result.sentence = "removed " + count_of(result.count, "component", "components") + " of " +
                      bound + " (" + count_of(faces_removed, "face", "faces") +
                      " in all; the first face of each" + listed(result) + ")" +
                      also_removed(result.removed_vertices, creases);
    if (kept_largest != kGone) {
        result.sentence += "; kept the largest (" +
                           count_of(parts[kept_largest].faces, "face", "faces") + ", from face " +
                           std::to_string(parts[kept_largest].first_face) +
                           ") as every component is below the bound";
    }
    return result;
}

}  // namespace meshedit
