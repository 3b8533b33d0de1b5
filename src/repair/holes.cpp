// Filling small holes of a built mesh with the local operation fill_hole() (repair.h,
// fill_holes()).

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/topology.h"
#include "meshedit/repair/repair.h"
#include "soup_edit.h"

namespace meshedit {
namespace {

using namespace repair_detail;

struct Hole {
    Halfedge h;             // a boundary halfedge of it
    std::size_t edges = 0;  // its sides
    bool flat = false;      // its outline encloses no area: a fill would be degenerate
};

// Every boundary loop once, in the order of its first halfedge.
std::vector<Hole> find_holes(const Mesh& mesh) {
    std::vector<Hole> holes;
    std::vector<bool> seen(mesh.halfedges_size(), false);
    for (const Halfedge h : mesh.halfedges()) {
        if (seen[h.idx()] || !mesh.is_boundary(h)) {
            continue;
        }
        Hole hole{h};
        // Twice the area vector of the outline (Newell, about its first corner) against its
        // longest side, as remove_degenerate_faces() judges a face.
        const Vec3 origin = mesh.position(mesh.from_vertex(h));
        Vec3 area;
        double longest = 0.0;
        Halfedge x = h;
        do {
            seen[x.idx()] = true;
            ++hole.edges;
            const Vec3 a = mesh.position(mesh.from_vertex(x)) - origin;
            const Vec3 b = mesh.position(mesh.to_vertex(x)) - origin;
            area += cross(a, b);
            longest = std::max(longest, sqrnorm(b - a));
            x = mesh.next(x);
        } while (x != h);
        hole.flat = 0.5 * norm(area) <= 1e-12 * longest;
        holes.push_back(hole);
    }
    return holes;
}

// Whether the triangle a, b, c has zero area as remove_degenerate_faces() judges a face.
bool is_flat(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double longest = std::max({sqrnorm(b - a), sqrnorm(c - b), sqrnorm(a - c)});
    return 0.5 * norm(cross(b - a, c - a)) <= 1e-12 * longest;
}

// The smallest angle of triangle a, b, c (0 when it is flat).
double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const auto angle = [](const Vec3& u, const Vec3& v) {
        return std::atan2(norm(cross(u, v)), dot(u, v));
    };
    return std::min({angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c)});
}

// How a hole of a triangle mesh is covered: fill_hole() from `start`, then triangulate(),
// which fans from start's tail (no diagonal of that fan is an edge of the mesh already), then
// the edge flips `flips` (each an edge by its ends) that make its smallest angles larger
// (Lawson's flips), so that no triangle is flat where a better one exists.
struct TrianglePlan {
    Halfedge start;
    std::vector<std::pair<Vertex, Vertex>> flips;
};

// Plans the triangles of the hole through `h`, or returns nothing when every triangulation
// this finds keeps a flat triangle (a later repair would remove it) or needs an edge the mesh
// has. The flips are planned on the loop's own corners, so the plan costs O(n²) per round
// of flips for a hole of n sides.
std::optional<TrianglePlan> plan_triangles(const Mesh& mesh, Halfedge h) {
    std::vector<Halfedge> sides;
    for (Halfedge x = h;;) {
        sides.push_back(x);
        x = mesh.next(x);
        if (x == h) {
            break;
        }
    }
    const std::size_t n = sides.size();
    std::vector<Vertex> corner(n);
    for (std::size_t i = 0; i < n; ++i) {
        corner[i] = mesh.from_vertex(sides[i]);
    }
    const auto joined = [&](std::size_t i, std::size_t j) {
        return mesh.find_edge(corner[i], corner[j]).is_valid();
    };
    // The first corner whose fan needs no edge the mesh has: the fan triangulate() makes.
    std::size_t apex = n;
    for (std::size_t i = 0; i < n && apex == n; ++i) {
        bool free = true;
        for (std::size_t k = 2; free && k + 1 < n; ++k) {
            free = !joined(i, (i + k) % n);
        }
        apex = free ? i : n;
    }
    if (apex == n) {
        return std::nullopt;
    }
    using Triangle = std::array<std::size_t, 3>;
    std::vector<Triangle> triangles;
    for (std::size_t k = 1; k + 1 < n; ++k) {
        triangles.push_back({apex, (apex + k) % n, (apex + k + 1) % n});
    }
    const auto at = [&](std::size_t i) { return mesh.position(corner[i]); };
    const auto quality = [&](const Triangle& t) {
        return smallest_angle(at(t[0]), at(t[1]), at(t[2]));
    };
    // Which triangle holds each directed side, as a * n + b.
    std::unordered_map<std::size_t, std::size_t> holder;
    const auto hold = [&](std::size_t t) {
        for (int k = 0; k < 3; ++k) {
            holder[triangles[t][k] * n + triangles[t][(k + 1) % 3]] = t;
        }
    };
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        hold(t);
    }
    TrianglePlan plan{sides[apex], {}};
    // Lawson's flips over the diagonals: each flip raises the smaller of the two triangles'
    // smallest angles, so the rounds end; a bound stops them anyway.
    for (std::size_t round = 0, flipped = 1; flipped > 0 && round < 4 * n + 8; ++round) {
        flipped = 0;
        for (std::size_t s = 0; s < triangles.size(); ++s) {
            for (int e = 0; e < 3; ++e) {
                const std::size_t a = triangles[s][e], b = triangles[s][(e + 1) % 3];
                const std::size_t c = triangles[s][(e + 2) % 3];
                const auto other = holder.find(b * n + a);
                if (other == holder.end()) {
                    continue;  // a side of the hole
                }
                const std::size_t t = other->second;
                std::size_t d = 0;
                for (int k = 0; k < 3; ++k) {
                    if (triangles[t][k] == b) {
                        d = triangles[t][(k + 2) % 3];
                    }
                }
                if (joined(c, d)) {
                    continue;
                }
                const Triangle s_new{c, a, d}, t_new{d, b, c};
                const double before = std::min(quality(triangles[s]), quality(triangles[t]));
                const double after = std::min(quality(s_new), quality(t_new));
                if (after > before + 1e-12) {
                    plan.flips.emplace_back(corner[a], corner[b]);
                    holder.erase(a * n + b);
                    holder.erase(b * n + a);
                    triangles[s] = s_new;
                    triangles[t] = t_new;
                    hold(s);
                    hold(t);
                    ++flipped;
                    break;
                }
            }
        }
    }
    for (const Triangle& t : triangles) {
        if (is_flat(at(t[0]), at(t[1]), at(t[2]))) {
            return std::nullopt;
        }
    }
    return plan;
}

// Whether a face on the hole's first corner has the hole's corners (a triangle whose two
// sides the builder cut apart leaves such a hole): filling it would make a duplicate face.
bool fill_repeats_a_face(const Mesh& mesh, Halfedge h) {
    std::vector<std::uint32_t> hole;
    for (Halfedge x = h;;) {
        hole.push_back(mesh.to_vertex(x).idx());
        x = mesh.next(x);
        if (x == h) {
            break;
        }
    }
    std::sort(hole.begin(), hole.end());
    std::vector<std::uint32_t> corners;
    for (const Face f : mesh.faces(mesh.from_vertex(h))) {
        if (!f.is_valid() || mesh.valence(f) != hole.size()) {
            continue;
        }
        corners.clear();
        for (const Vertex v : mesh.vertices(f)) {
            corners.push_back(v.idx());
        }
        std::sort(corners.begin(), corners.end());
        if (corners == hole) {
            return true;
        }
    }
    return false;
}

}  // namespace

namespace repair_detail {

// Turns over each part that a fill closed (no boundary left) and that encloses a negative
// volume, as orient_faces() turns closed parts outward: flip_orientation() on one part,
// through the mesh's setters. \return how many parts; their faces are added to `faces`.
std::size_t turn_closed_parts_outward(Mesh& mesh, const std::vector<Face>& filled,
                                      std::size_t& faces) {
    // The parts by vertex components (a union-find over the edges, in index order: a walk
    // from face to face took 80 ms on a 1.2M-face scan, its reads all over memory). A closed
    // part is one component either way: where two face-parts share a vertex, each has a
    // border there.
    const std::vector<std::uint32_t> root = component_roots(mesh);
    struct Part {
        Vec3 origin;  // of the volume: the first filled face's first corner, as flip's tests
        Enclosure inside;
        bool open = false;
        std::size_t faces = 0;
    };
    std::vector<Part> touched;
    std::vector<std::int32_t> slot(mesh.vertices_size(), -1);  // by root: its Part
    const auto part_of = [&](Face f) { return slot[root[mesh.to_vertex(mesh.halfedge(f)).idx()]]; };
    for (const Face seed : filled) {
        const std::uint32_t r = root[mesh.to_vertex(mesh.halfedge(seed)).idx()];
        if (slot[r] < 0) {
            slot[r] = static_cast<std::int32_t>(touched.size());
            touched.push_back({mesh.position(mesh.to_vertex(mesh.halfedge(seed)))});
        }
    }
    for (const Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h)) {
            if (const std::int32_t k = slot[root[mesh.to_vertex(h).idx()]]; k >= 0) {
                touched[static_cast<std::size_t>(k)].open = true;
            }
        }
    }
    if (std::all_of(touched.begin(), touched.end(), [](const Part& p) { return p.open; })) {
        return 0;
    }
    // Each face a fan from its first corner, from_vertex of its halfedge.
    for (const Face f : mesh.faces()) {
        const std::int32_t k = part_of(f);
        if (k < 0 || touched[static_cast<std::size_t>(k)].open) {
            continue;
        }
        Part& part = touched[static_cast<std::size_t>(k)];
        ++part.faces;
        const Halfedge h0 = mesh.halfedge(f);
        const Vec3 p0 = mesh.position(mesh.from_vertex(h0)) - part.origin;
        for (Halfedge h = h0; mesh.next(mesh.next(h)) != h0; h = mesh.next(h)) {
            part.inside.add(p0, mesh.position(mesh.to_vertex(h)) - part.origin,
                            mesh.position(mesh.to_vertex(mesh.next(h))) - part.origin);
        }
    }
    std::vector<Halfedge> turn;  // the halfedges of the parts to turn over
    std::size_t parts = 0;
    for (const Part& part : touched) {
        if (!part.open && part.inside.faces_inward()) {
            ++parts;
            faces += part.faces;
        }
    }
    if (parts > 0) {
        for (const Face f : mesh.faces()) {
            const std::int32_t k = part_of(f);
            if (k >= 0 && !touched[static_cast<std::size_t>(k)].open &&
                touched[static_cast<std::size_t>(k)].inside.faces_inward()) {
                for (const Halfedge h : mesh.halfedges(f)) {
                    turn.push_back(h);
                }
            }
        }
    }
    if (turn.empty()) {
        return 0;
    }
    // As flip_orientation(): each halfedge takes its old prev as next and its old tail as
    // head, and its corner values from its old prev; each vertex is anchored at the old prev
    // of its anchor.
    std::vector<std::uint32_t> source(mesh.halfedges_size());
    for (std::size_t h = 0; h < source.size(); ++h) {
        source[h] = static_cast<std::uint32_t>(h);
    }
    std::vector<Halfedge> old_prev(turn.size());
    std::vector<Vertex> old_tail(turn.size());
    for (std::size_t i = 0; i < turn.size(); ++i) {
        old_prev[i] = mesh.prev(turn[i]);
        old_tail[i] = mesh.from_vertex(turn[i]);
        source[turn[i].idx()] = old_prev[i].idx();
    }
    std::vector<std::pair<Vertex, Halfedge>> anchors;
    for (const Halfedge h : turn) {
        const Vertex v = mesh.to_vertex(h);
        if (mesh.halfedge(v) == mesh.next(h)) {  // v's anchor leaves v after h
            anchors.emplace_back(v, h);
        }
    }
    mesh.permute_attributes<Halfedge>(source);
    for (std::size_t i = 0; i < turn.size(); ++i) {
        mesh.set_vertex(turn[i], old_tail[i]);
    }
    for (std::size_t i = 0; i < turn.size(); ++i) {
        mesh.set_next(turn[i], old_prev[i]);
    }
    for (const auto& [v, h] : anchors) {
        mesh.set_halfedge(v, h);
    }
    return parts;
}

std::string turned_outward(std::size_t faces, std::size_t parts) {
    return "turned over " + count_of(faces, "face", "faces") + " so that " +
           count_of(parts, "part", "parts") + " the fills closed " +
           (parts == 1 ? "faces" : "face") + " outward";
}

}  // namespace repair_detail

RepairResult fill_holes(Mesh& mesh, std::size_t max_edges) {
    RepairResult result;
    if (max_edges == 0) {
        return result;
    }
    const bool triangles = mesh.is_triangle_mesh();
    std::size_t filled_edges = 0, large = 0, largest = 0, flat = 0, no_fan = 0, repeats = 0,
                polygons = 0;
    Vertex largest_at;
    std::vector<std::size_t> large_sizes;
    std::vector<Face> filled;
    // The fan's flips are planned in O(n²) a round: a border of 100,000 edges did not finish
    // in 150 s (measured), so holes past this are left, named (fill_holes_fair takes them).
    constexpr std::size_t kMaxPlainEdges = 5'000;
    std::size_t huge = 0;
    for (const Hole& hole : find_holes(mesh)) {
        if (hole.edges <= max_edges && hole.edges > kMaxPlainEdges) {
            ++huge;
            continue;
        }
        if (hole.edges > max_edges) {
            ++large;
            large_sizes.push_back(hole.edges);
            if (hole.edges > largest) {
                largest = hole.edges;
                largest_at = mesh.from_vertex(hole.h);
            }
            continue;
        }
        if (hole.flat || !is_fill_hole_ok(mesh, hole.h)) {
            ++flat;  // fewer than 3 sides is flat too
            continue;
        }
        if (fill_repeats_a_face(mesh, hole.h)) {
            ++repeats;
            continue;
        }
        std::optional<TrianglePlan> plan;
        if (triangles) {
            plan = plan_triangles(mesh, hole.h);
            if (!plan) {
                ++no_fan;
                continue;
            }
        }
        const Halfedge start = plan ? plan->start : hole.h;
        const Vertex at = mesh.from_vertex(start);
        const OpResult<Face> face = fill_hole(mesh, start);
        if (!face) {
            ++flat;
            continue;
        }
        if (plan && !mesh.is_triangle(*face)) {
            if (!triangulate(mesh, *face)) {
                ++polygons;
            } else {
                for (const auto& [a, b] : plan->flips) {
                    // The plan's flips fit the triangles triangulate() made; were one
                    // refused, the patch would stay valid, only less even.
                    const Edge e = mesh.find_edge(a, b);
                    if (!e.is_valid() || !flip(mesh, e)) {
                        break;
                    }
                }
            }
        }
        filled.push_back(*face);
        ++result.count;
        filled_edges += hole.edges;
        note_first(result, at.idx());
    }
    result.left = large + flat + no_fan + repeats + huge;
    std::size_t turned_faces = 0;
    const std::size_t turned = turn_closed_parts_outward(mesh, filled, turned_faces);
    std::vector<std::string> parts;
    if (result.count > 0) {
        RepairResult at = result;
        parts.push_back("filled " + count_of(result.count, "hole", "holes") + " of at most " +
                        count_of(max_edges, "edge", "edges") + " (" +
                        count_of(filled_edges, "edge", "edges") + " in all" +
                        (triangles ? ", with triangles" : "") + "; a vertex of each" + listed(at) +
                        ")");
    }
    if (turned > 0) {
        parts.push_back(turned_outward(turned_faces, turned));
    }
    if (polygons > 0) {
        parts.push_back(count_of(polygons, "filled hole stays one polygon",
                                 "filled holes stay one polygon each") +
                        " (no triangulation without an edge the mesh has)");
    }
    if (large > 0) {
        // Their sizes, largest first: "40, 10 edges".
        std::sort(large_sizes.rbegin(), large_sizes.rend());
        std::string sizes;
        for (std::size_t i = 0; i < large_sizes.size() && i < kRepairShown; ++i) {
            sizes += (i == 0 ? "" : ", ") + std::to_string(large_sizes[i]);
        }
        sizes += large_sizes.size() > kRepairShown ? ", … edges" : " edges";
        parts.push_back("left " + count_of(large, "hole", "holes") + " of more than " +
                        count_of(max_edges, "edge", "edges") + " (" + sizes +
                        "; the largest at vertex " + std::to_string(largest_at.idx()) + ")");
    }
    if (huge > 0) {
        parts.push_back("left " + count_of(huge, "hole", "holes") + " of more than " +
                        count_of(kMaxPlainEdges, "edge", "edges") +
                        ", too large for this fill (fill_holes_fair, repair --fair, takes them)");
    }
    if (flat > 0) {
        parts.push_back("left " + count_of(flat, "hole", "holes") +
                        " whose outline encloses no area (a fill would be a degenerate face)");
    }
    if (no_fan > 0) {
        parts.push_back("left " + count_of(no_fan, "hole", "holes") +
                        " that no triangulation found here fills without a flat triangle or an "
                        "edge the mesh already has");
    }
    if (repeats > 0) {
        parts.push_back("left " + count_of(repeats, "hole", "holes") +
                        " whose fill would repeat a face the mesh has");
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
        result.sentence += (i == 0 ? "" : "; ") + parts[i];
    }
    return result;
}

}  // namespace meshedit
