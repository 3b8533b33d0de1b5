// Orienting faces coherently, closed parts outward (repair.h, orient_faces()).

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "meshedit/repair/repair.h"
#include "soup_edit.h"

namespace meshedit {
namespace {

using namespace repair_detail;

// One side of a face, by its undirected edge: `forward` when it runs from the smaller
// vertex to the larger.
struct Side {
    std::uint32_t low, high, face;
    bool forward;
};

// Two faces across an edge of exactly two faces; `flip` when their windings disagree there
// (both use it in the same direction), so that one of them must turn over.
struct Link {
    std::uint32_t a, b;
    bool flip;
};

// The faces' links, and which faces have a side that is not shared by exactly two faces
// (a boundary, or a non-manifold edge): their part is not closed.
void link_faces(const PolygonSoup& s, std::vector<Link>& links, std::vector<bool>& open) {
    std::vector<Side> sides;
    sides.reserve(s.indices.size());
    for_each_side(s, [&sides](std::uint32_t a, std::uint32_t b, std::uint32_t f, std::uint32_t) {
        sides.push_back({std::min(a, b), std::max(a, b), f, a < b});
    });
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
        return x.low != y.low     ? x.low < y.low
               : x.high != y.high ? x.high < y.high
                                  : x.face < y.face;
    });
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i + 1;
        while (j < sides.size() && sides[j].low == sides[i].low && sides[j].high == sides[i].high) {
            ++j;
        }
        if (j - i == 2 && sides[i].face != sides[i + 1].face) {
            links.push_back(
                {sides[i].face, sides[i + 1].face, sides[i].forward == sides[i + 1].forward});
        } else {
            for (std::size_t k = i; k < j; ++k) {
                open[sides[k].face] = true;
            }
        }
        i = j;
    }
}

// What the faces enclose (Enclosure), each face taken turned over where `flip` says, about
// `origin` (a corner of the part, for the digits).
Enclosure enclosure(const PolygonSoup& s, const std::vector<std::uint32_t>& faces,
                    const std::vector<bool>& flip, const Vec3& origin) {
    Enclosure out;
    for (const std::uint32_t f : faces) {
        const std::uint32_t begin = s.face_offsets[f];
        const std::uint32_t end = s.face_offsets[f + 1];
        if (end - begin < 3) {
            continue;
        }
        const Vec3 p0 = s.positions[s.indices[begin]] - origin;
        for (std::uint32_t c = begin + 1; c + 1 < end; ++c) {
            const Vec3 p1 = s.positions[s.indices[c]] - origin;
            const Vec3 p2 = s.positions[s.indices[c + 1]] - origin;
            if (flip[f]) {
                out.add(p0, p2, p1);
            } else {
                out.add(p0, p1, p2);
            }
        }
    }
    return out;
}

}  // namespace

RepairResult orient_faces(MeshSoup& soup) {
    check_polygon_soup(soup.soup);
    const PolygonSoup& s = soup.soup;
    const std::size_t n_faces = s.n_faces();
    std::vector<Link> links;
    std::vector<bool> open(n_faces, false);
    link_faces(s, links, open);

    // Each face's links, as offsets into one list.
    std::vector<std::uint32_t> first(n_faces + 1, 0);
    for (const Link& l : links) {
        ++first[l.a + 1];
        ++first[l.b + 1];
    }
    for (std::size_t f = 0; f < n_faces; ++f) {
        first[f + 1] += first[f];
    }
    std::vector<std::pair<std::uint32_t, bool>> neighbours(first.back());
    {
        std::vector<std::uint32_t> at(first.begin(), first.end() - 1);
        for (const Link& l : links) {
            neighbours[at[l.a]++] = {l.b, l.flip};
            neighbours[at[l.b]++] = {l.a, l.flip};
        }
    }

    // Breadth-first over each part: parity 1 means turned relative to the part's first face.
    std::vector<std::int8_t> parity(n_faces, -1);
    std::vector<bool> flip(n_faces, false);
    std::vector<std::uint32_t> part;
    RepairResult result;
    std::size_t outward_parts = 0, outward_faces = 0;
    for (std::uint32_t seed = 0; seed < n_faces; ++seed) {
        if (parity[seed] != -1) {
            continue;
        }
        part.clear();
        part.push_back(seed);
        parity[seed] = 0;
        std::size_t turned = 0;
        bool closed = true;
        for (std::size_t q = 0; q < part.size(); ++q) {
            const std::uint32_t f = part[q];
            closed = closed && !open[f];
            for (std::uint32_t k = first[f]; k < first[f + 1]; ++k) {
                const auto [g, relative] = neighbours[k];
                const std::int8_t expected =
                    static_cast<std::int8_t>(parity[f] ^ (relative ? 1 : 0));
                if (parity[g] == -1) {
                    parity[g] = expected;
                    turned += static_cast<std::size_t>(expected);
                    part.push_back(g);
                } else if (parity[g] != expected && f < g) {
                    ++result.left;  // counted once, from the smaller face
                    closed = false;
                }
            }
        }
        // The winding most of the part's faces have stays (the first face's on a tie).
        const std::int8_t keep = 2 * turned > part.size() ? 1 : 0;
        for (const std::uint32_t f : part) {
            flip[f] = parity[f] != keep;
        }
        if (closed && part.size() > 1 &&
            enclosure(s, part, flip, s.positions[s.indices[s.face_offsets[seed]]]).faces_inward()) {
            ++outward_parts;
            for (const std::uint32_t f : part) {
                flip[f] = !flip[f];
                outward_faces += flip[f] ? 1 : 0;
            }
        }
    }
    for (std::uint32_t f = 0; f < n_faces; ++f) {
        if (flip[f]) {
            reverse_face(soup, f);
            ++result.count;
            note_first(result, f);
        }
    }
    if (result.count > 0) {
        const std::size_t agree = result.count - outward_faces;
        const std::string to_agree =
            agree == 1 ? "to agree with its neighbours" : "to agree with their neighbours";
        const std::string outward =
            "so that " + count_of(outward_parts, "closed part faces", "closed parts face") +
            " outward";
        std::string why;
        if (agree > 0 && outward_faces > 0) {
            why = " (" + std::to_string(agree) + " " + to_agree + ", " +
                  std::to_string(outward_faces) + " " + outward + ")";
        } else {
            why = " " + (agree > 0 ? to_agree : outward);
        }
        result.sentence =
            "turned over " + count_of(result.count, "face", "faces") + why + listed(result);
    }
    if (result.left > 0) {
        result.sentence += std::string(result.sentence.empty() ? "" : "; ") + "left " +
                           count_of(result.left, "edge", "edges") +
                           " whose faces cannot agree (a part that is not orientable, such as a "
                           "Möbius strip; the builder cuts them)";
    }
    return result;
}

}  // namespace meshedit
