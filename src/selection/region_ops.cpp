/// \file
/// Extrude and subdivide a region of faces as one. Contract (local_ops.h): the predicate is
/// checked first and a refusal leaves the mesh untouched.

#include "meshedit/selection/region_ops.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "meshedit/core/assert.h"
#include "region_targets.h"

namespace meshedit {
namespace {

// A side of the region: its face is in the region, the face across it is not (or a hole).
bool is_border(const Mesh& mesh, const FaceSet& region, Halfedge h) {
    const Face f = mesh.face(h);
    const Face g = mesh.face(Mesh::twin(h));
    return f.is_valid() && region.contains(f) && (!g.is_valid() || !region.contains(g));
}

// The region's border sides, in increasing halfedge order.
std::vector<Halfedge> border_of(const Mesh& mesh, const FaceSet& region) {
    std::vector<Halfedge> out;
    for (const Face f : region.elements()) {
        for (const Halfedge h : mesh.halfedges(f)) {
            if (is_border(mesh, region, h)) {
                out.push_back(h);
            }
        }
    }
    return out;
}

Vec3 area_normal(const Mesh& mesh, Face f) {  // Newell: twice the area along the normal
    Vec3 n{0, 0, 0};
    for (const Halfedge h : mesh.halfedges(f)) {
        n += cross(mesh.position(mesh.from_vertex(h)), mesh.position(mesh.to_vertex(h)));
    }
    return n;
}

// Each face's piece (faces joined across edges inside the region) and each piece's unit
// normal, area-weighted; a zero normal for a piece without area.
struct Pieces {
    std::unordered_map<std::uint32_t, std::uint32_t> of_face;
    std::vector<Vec3> normal;
};
Pieces pieces_of(const Mesh& mesh, const FaceSet& region) {
    Pieces out;
    for (const Face seed : region.elements()) {
        if (out.of_face.count(seed.idx()) != 0) {
            continue;
        }
        const auto piece = static_cast<std::uint32_t>(out.normal.size());
        Vec3 sum{0, 0, 0};
        std::vector<Face> stack{seed};
        out.of_face[seed.idx()] = piece;
        while (!stack.empty()) {
            const Face f = stack.back();
            stack.pop_back();
            sum += area_normal(mesh, f);
            for (const Halfedge h : mesh.halfedges(f)) {
                const Face g = mesh.face(Mesh::twin(h));
                if (g.is_valid() && region.contains(g) &&
                    out.of_face.emplace(g.idx(), piece).second) {
                    stack.push_back(g);
                }
            }
        }
        const double length = norm(sum);
        out.normal.push_back(length > 0 && std::isfinite(length) ? sum / length : Vec3{0, 0, 0});
    }
    return out;
}

// The region's vertices, each once, with the normal of its piece.
void region_vertices(const Mesh& mesh, const FaceSet& region, const Pieces& pieces,
                     std::vector<Vertex>& vertices, std::vector<Vec3>& normals) {
    std::unordered_map<std::uint32_t, std::size_t> seen;
    for (const Face f : region.elements()) {
        const Vec3 n = pieces.normal[pieces.of_face.at(f.idx())];
        for (const Halfedge h : mesh.halfedges(f)) {
            if (seen.emplace(mesh.to_vertex(h).idx(), vertices.size()).second) {
                vertices.push_back(mesh.to_vertex(h));
                normals.push_back(n);
            }
        }
    }
}

bool all_live(const Mesh& mesh, const FaceSet& region) {
    if (region.size() > mesh.faces_size() || region.empty()) {
        return false;
    }
    for (const Face f : region.elements()) {
        if (mesh.is_deleted(f)) {
            return false;
        }
    }
    return true;
}

}  // namespace

OpStatus is_extrude_region_ok(const Mesh& mesh, const FaceSet& region, double height) {
    if (!all_live(mesh, region)) {
        return OpStatus::refused("cannot extrude the region: select one or more live faces");
    }
    if (!std::isfinite(height)) {
        return OpStatus::refused("cannot extrude the region: the height must be a finite number");
    }
    const std::vector<Halfedge> border = border_of(mesh, region);
    if (border.empty()) {
        return OpStatus::refused(
            "cannot extrude the region: it is a whole closed surface, with no border to extrude "
            "from");
    }
    std::unordered_map<std::uint32_t, int> leaving;
    for (const Halfedge h : border) {
        if (++leaving[mesh.from_vertex(h).idx()] > 1) {
            return OpStatus::composed("cannot extrude the region: it touches itself at vertex " +
                                      std::to_string(mesh.from_vertex(h).idx()) +
                                      " (its faces may meet only across edges)");
        }
    }
    if (height != 0) {
        const Pieces pieces = pieces_of(mesh, region);
        std::vector<Vertex> vertices;
        std::vector<Vec3> normals;
        region_vertices(mesh, region, pieces, vertices, normals);
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            if (sqrnorm(normals[i]) == 0) {
                return OpStatus::refused(
                    "cannot extrude the region: a piece of it has no area, so no normal");
            }
            if (!std::isfinite(sqrnorm(mesh.position(vertices[i]) + height * normals[i]))) {
                return OpStatus::refused(
                    "cannot extrude the region: the height puts corners beyond the range of "
                    "numbers");
            }
        }
    }
    return OpStatus::ok();
}

RegionExtrude extrude_region_base(const Mesh& mesh, const FaceSet& region) {
    RegionExtrude r;
    region_vertices(mesh, region, pieces_of(mesh, region), r.moved, r.normal);
    const std::vector<Halfedge> border = border_of(mesh, region);
    std::unordered_map<std::uint32_t, std::uint32_t> copy;  // border vertex -> its copy
    for (std::uint32_t i = 0; i < border.size(); ++i) {
        copy[mesh.from_vertex(border[i]).idx()] =
            static_cast<std::uint32_t>(mesh.vertices_size()) + i;
        r.sides.push_back(Face(static_cast<std::uint32_t>(mesh.faces_size()) + i));
    }
    for (Vertex& v : r.moved) {
        r.base.push_back(mesh.position(v));
        if (const auto it = copy.find(v.idx()); it != copy.end()) {
            v = Vertex(it->second);
        }
    }
    return r;
}

// The border sides h[i] run a -> b with face F in the region. New per side: the copy a' of
// a (q[i]), the rung up[i] = a -> a' (twin down[i]), the top side k[i] = a' -> b' (twin
// kt[i]) and the quad Q[i]. h[i] leaves F for Q[i]; k[i] takes its place in F; the region's
// halfedges that pointed at a border vertex (between its two border sides) point at the
// copy. j is the side leaving b.
//
//          a' --k[i]--> b'                a' <--kt[i]-- b'
//        (top: F, the region)              |    Q[i]    ^
//                                  down[i] v            | up[j]
//                                          a --h[i]---> b
//      a ------h[i]------> b      =>      (below: the face across, unchanged)
//         F (the region)
//
// Carry: a' copies a; k[i] copies h[i] (F's corner at b), kt[i] and down[i] copy F's corner
// at a (prev(h[i]) before), up[j] copies h[i]; the top side k[i]'s edge copies h[i]'s, the
// rungs take defaults; Q[i] copies F.
OpResult<Face> extrude_region(Mesh& mesh, const FaceSet& region, double height,
                              RegionExtrude* made) {
    if (const OpStatus ok = is_extrude_region_ok(mesh, region, height); !ok) {
        return ok;
    }
    const RegionExtrude base = extrude_region_base(mesh, region);
    const std::vector<Halfedge> h = border_of(mesh, region);
    const auto n = static_cast<std::uint32_t>(h.size());
    std::unordered_map<std::uint32_t, std::uint32_t> side_of;     // border vertex a -> i
    std::unordered_map<std::uint32_t, std::uint32_t> side_index;  // h[i] -> i
    std::vector<Halfedge> before(n), after(n), corner_a(n);
    std::vector<Vertex> a(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        a[i] = mesh.from_vertex(h[i]);
        side_of[a[i].idx()] = i;
        side_index[h[i].idx()] = i;
        before[i] = mesh.prev(h[i]);
        after[i] = mesh.next(h[i]);
        corner_a[i] = before[i];
    }
    // The region's halfedges into each border vertex a, other than the border side into it:
    // turning from h[i] across the region's inner edges.
    std::vector<Halfedge> into_copy;
    for (std::uint32_t i = 0; i < n; ++i) {
        Halfedge x = h[i];
        for (std::size_t guard = 0; guard < mesh.edges_size(); ++guard) {
            const Halfedge in = mesh.prev(x);
            if (is_border(mesh, region, in)) {
                break;
            }
            into_copy.push_back(in);
            x = Mesh::twin(in);
        }
    }
    const auto first_v = static_cast<std::uint32_t>(mesh.vertices_size());
    const auto first_e = static_cast<std::uint32_t>(mesh.edges_size());
    const auto first_f = static_cast<std::uint32_t>(mesh.faces_size());
    mesh.new_elements(n, 2 * n, n);
    const auto q = [&](std::uint32_t i) { return Vertex(first_v + i); };
    const auto up = [&](std::uint32_t i) { return Mesh::halfedge(Edge(first_e + i), 0); };
    const auto k = [&](std::uint32_t i) { return Mesh::halfedge(Edge(first_e + n + i), 0); };
    const auto copy_of = [&](Vertex v) { return q(side_of.at(v.idx())); };
    const auto top = [&](Halfedge x) {  // x, or its top side if x is a border side
        const auto it = side_index.find(x.idx());
        return it != side_index.end() ? k(it->second) : x;
    };

    for (std::uint32_t i = 0; i < n; ++i) {
        const Vertex b = mesh.to_vertex(h[i]);
        mesh.position(q(i)) = mesh.position(a[i]);
        mesh.set_vertex(up(i), q(i));
        mesh.set_vertex(Mesh::twin(up(i)), a[i]);
        mesh.set_vertex(k(i), copy_of(b));
        mesh.set_vertex(Mesh::twin(k(i)), q(i));
    }
    for (const Halfedge in : into_copy) {
        mesh.set_vertex(in, copy_of(mesh.to_vertex(in)));
    }
    // The top: k[i] in F where h[i] was (links in from the side before, out to the side after).
    for (std::uint32_t i = 0; i < n; ++i) {
        const Face f = mesh.face(h[i]);
        mesh.set_next(top(before[i]), k(i));
        mesh.set_next(k(i), top(after[i]));
        mesh.set_face(k(i), f);
        if (mesh.halfedge(f) == h[i]) {
            mesh.set_halfedge(f, k(i));
        }
    }
    // The sides: Q[i] = h[i] -> up[j] -> kt[i] -> down[i].
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = side_of.at(mesh.to_vertex(h[i]).idx());
        const Face g(first_f + i);
        const Halfedge kt = Mesh::twin(k(i));
        const Halfedge down = Mesh::twin(up(i));
        mesh.set_next(h[i], up(j));
        mesh.set_next(up(j), kt);
        mesh.set_next(kt, down);
        mesh.set_next(down, h[i]);
        for (const Halfedge x : {h[i], up(j), kt, down}) {
            mesh.set_face(x, g);
        }
        mesh.set_halfedge(g, h[i]);
        mesh.set_halfedge(q(i), k(i));
        if (!mesh.is_boundary(a[i])) {
            mesh.set_halfedge(a[i], h[i]);  // its old anchor may now leave the copy
        }
    }
    // Carry (the rule above the diagram).
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = side_of.at(mesh.to_vertex(h[i]).idx());
        mesh.carry(q(i), a[i]);
        mesh.carry(k(i), h[i]);
        mesh.carry(Mesh::twin(k(i)), corner_a[i]);
        mesh.carry(Mesh::twin(up(i)), corner_a[i]);
        mesh.carry(up(j), h[i]);
        mesh.carry(Edge(first_e + n + i), Mesh::edge(h[i]));
        mesh.carry_default(Edge(first_e + i));
        mesh.carry(Face(first_f + i), mesh.face(k(i)));
    }
    extrude_region_positions(mesh, base, height);
    if (made != nullptr) {
        *made = base;
    }
    return region.elements().front();
}

OpStatus extrude_region_positions(Mesh& mesh, const RegionExtrude& made, double height) {
    if (!std::isfinite(height)) {
        return OpStatus::refused("cannot extrude the region: the height must be a finite number");
    }
    for (std::size_t m = 0; m < made.moved.size(); ++m) {
        if (height != 0 && sqrnorm(made.normal[m]) == 0) {
            return OpStatus::refused(
                "cannot extrude the region: a piece of it has no area, so no normal");
        }
        if (!std::isfinite(sqrnorm(made.base[m] + height * made.normal[m]))) {
            return OpStatus::refused(
                "cannot extrude the region: the height puts corners beyond the range of numbers");
        }
    }
    for (std::size_t m = 0; m < made.moved.size(); ++m) {
        mesh.position(made.moved[m]) = made.base[m] + height * made.normal[m];
    }
    return OpStatus::ok();
}

// ------------------------------------------------------------------ inset

// The border sides h[i] = a -> b (face F in the region) as extrude_region() names them; the
// copy a' = q[i] of a moves into the region from where a is:
//
//        ----h[j]----> a ----h[i]----> b          into[j], into[i]: each side's direction
//        F_j      into[j]^   ^into[i]   F_i        into its face (n_F x (b - a)), unit;
//                        \ | /                     d = into[j] + into[i], unit;
//                          a'  = a + t d / (d . into[i])
//
// so that the ring is t wide along both sides (even thickness). Carry: extrude_region()'s at
// height 0; moving a' changes no attribute (the top keeps its texture coordinates, squeezed
// into the smaller top, as Blender's inset without Correct UVs).
RegionInset inset_region_base(const Mesh& mesh, const FaceSet& region) {
    RegionInset r;
    const std::vector<Halfedge> h = border_of(mesh, region);
    std::unordered_map<std::uint32_t, std::uint32_t> side_into;  // b -> the side h[j] into it
    for (std::uint32_t i = 0; i < h.size(); ++i) {
        side_into[mesh.to_vertex(h[i]).idx()] = i;
    }
    const auto into = [&](Halfedge side) {
        const Vec3 along =
            mesh.position(mesh.to_vertex(side)) - mesh.position(mesh.from_vertex(side));
        const Vec3 across = cross(area_normal(mesh, mesh.face(side)), along);
        const double length = norm(across);
        return length > 0.0 ? across / length : Vec3{};
    };
    for (std::uint32_t i = 0; i < h.size(); ++i) {
        const Vertex a = mesh.from_vertex(h[i]);
        const Vec3 out_side = into(h[i]);
        const Vec3 in_side = into(h[side_into.at(a.idx())]);
        Vec3 d = out_side + in_side;
        const double length = norm(d);
        d = length > 1e-12 ? d / length : out_side;             // a side folded back on the other
        const double along = std::max(dot(d, out_side), 0.25);  // at most 4 t at a spike
        r.border.push_back(Vertex(static_cast<std::uint32_t>(mesh.vertices_size()) + i));
        r.base.push_back(mesh.position(a));
        r.inward.push_back(d / along);
    }
    return r;
}

OpStatus is_inset_region_ok(const Mesh& mesh, const FaceSet& region, double thickness) {
    if (!(std::isfinite(thickness) && thickness >= 0.0)) {
        return OpStatus::refused(
            "cannot inset the region: the thickness must be a finite number of at least 0");
    }
    if (const OpStatus ok = is_extrude_region_ok(mesh, region, 0.0); !ok) {
        // Its reasons are the extrude's ("cannot extrude the region: …"): said as an inset's.
        const std::string why = ok.text();
        return OpStatus::composed("cannot inset the region" + why.substr(why.find(':')));
    }
    const RegionInset base = inset_region_base(mesh, region);
    for (std::size_t i = 0; i < base.border.size(); ++i) {
        if (!std::isfinite(sqrnorm(base.base[i] + thickness * base.inward[i]))) {
            return OpStatus::refused(
                "cannot inset the region: the thickness puts corners beyond the range of numbers");
        }
    }
    return OpStatus::ok();
}

OpResult<Face> inset_region(Mesh& mesh, const FaceSet& region, double thickness,
                            RegionInset* made) {
    if (const OpStatus ok = is_inset_region_ok(mesh, region, thickness); !ok) {
        return ok;
    }
    const RegionInset base = inset_region_base(mesh, region);
    const OpResult<Face> top = extrude_region(mesh, region, 0.0);
    MESHEDIT_ASSERT(top.ok());  // the predicate allowed the extrude at height 0
    [[maybe_unused]] const OpStatus moved = inset_region_positions(mesh, base, thickness);
    MESHEDIT_ASSERT(static_cast<bool>(moved));  // and the move
    if (made != nullptr) {
        *made = base;
    }
    return top;
}

OpStatus inset_region_positions(Mesh& mesh, const RegionInset& made, double thickness) {
    if (!(std::isfinite(thickness) && thickness >= 0.0)) {
        return OpStatus::refused(
            "cannot inset the region: the thickness must be a finite number of at least 0");
    }
    for (std::size_t i = 0; i < made.border.size(); ++i) {
        if (!std::isfinite(sqrnorm(made.base[i] + thickness * made.inward[i]))) {
            return OpStatus::refused(
                "cannot inset the region: the thickness puts corners beyond the range of numbers");
        }
    }
    for (std::size_t i = 0; i < made.border.size(); ++i) {
        mesh.position(made.border[i]) = made.base[i] + thickness * made.inward[i];
    }
    return OpStatus::ok();
}

// ------------------------------------------------------------------ dissolve

namespace {

// The dissolves themselves, without checks: the region's inner vertices (every face around
// them in the region, none of their halfedges on a hole), in index order, then the edges
// left between two of its faces. False as soon as one is refused.
bool dissolve_inside(Mesh& mesh, const FaceSet& region) {
    std::vector<Vertex> inner;
    std::vector<Edge> edges;
    {
        VertexSet seen(mesh.vertices_size());
        for (const Face f : region.elements()) {
            for (const Halfedge h : mesh.halfedges(f)) {
                const Vertex v = mesh.to_vertex(h);
                if (seen.contains(v)) {
                    continue;
                }
                seen.insert(v);
                bool all_inside = true;
                for (const Halfedge o : mesh.halfedges(v)) {
                    const Face g = mesh.face(o);
                    all_inside = all_inside && g.is_valid() && region.contains(g);
                }
                if (all_inside) {
                    inner.push_back(v);
                }
            }
        }
    }
    for (const Vertex v : inner) {
        if (!dissolve_vertex(mesh, v).ok()) {
            return false;
        }
    }
    // What is left inside: edges whose two sides are (what remains of) region faces.
    for (std::uint32_t e = 0; e < mesh.edges_size(); ++e) {
        const Edge edge(e);
        if (mesh.is_deleted(edge) || mesh.is_boundary(edge)) {
            continue;
        }
        const Face a = mesh.face(edge, 0), b = mesh.face(edge, 1);
        if (a != b && region.contains(a) && region.contains(b)) {
            edges.push_back(edge);
        }
    }
    for (const Edge e : edges) {
        if (!mesh.is_deleted(e) && !dissolve_edge(mesh, e).ok()) {
            return false;
        }
    }
    return true;
}

}  // namespace

OpStatus is_dissolve_region_ok(const Mesh& mesh, const FaceSet& region) {
    if (!all_live(mesh, region)) {
        return OpStatus::refused("cannot dissolve the region: select one or more live faces");
    }
    if (border_of(mesh, region).empty()) {
        return OpStatus::refused(
            "cannot dissolve the region: it is a whole closed surface, which no one face can "
            "replace");
    }
    if (region.count() < 2) {
        return OpStatus::refused("cannot dissolve the region: one face is merged already");
    }
    std::unordered_map<std::uint32_t, int> leaving;
    for (const Halfedge h : border_of(mesh, region)) {
        if (++leaving[mesh.from_vertex(h).idx()] > 1) {
            return OpStatus::composed("cannot dissolve the region: it touches itself at vertex " +
                                      std::to_string(mesh.from_vertex(h).idx()) +
                                      " (the merged face would visit it twice)");
        }
    }
    Mesh trial = mesh;  // the dissolves themselves decide the rest (a piece with a hole in it)
    FaceSet same = region;
    if (!dissolve_inside(trial, same)) {
        return OpStatus::refused(
            "cannot dissolve the region: a piece of it is not a disk (it has a hole, or its "
            "faces meet only at a corner)");
    }
    return OpStatus::ok();
}

OpResult<Face> dissolve_region(Mesh& mesh, const FaceSet& region, std::vector<Face>* merged) {
    if (const OpStatus ok = is_dissolve_region_ok(mesh, region); !ok) {
        return ok;
    }
    [[maybe_unused]] const bool done = dissolve_inside(mesh, region);  // as the trial ran
    MESHEDIT_ASSERT(done);
    std::vector<Face> left;
    for (const Face f : region.elements()) {
        if (!mesh.is_deleted(f)) {
            left.push_back(f);
        }
    }
    const Face first = left.front();
    if (merged != nullptr) {
        *merged = std::move(left);
    }
    return first;
}

// ------------------------------------------------------------------ subdivide

namespace {

// Cuts face g = face(x) along a new edge u from a = to_vertex(x) to b = to_vertex(y), two
// corners of g that do not follow each other. g keeps x; the new face g2 takes the corners
// after a up to b.
//
//        x1 -> ... -> y                  x1 -> ... -> y
//       /       g      \                /      g2     v
//      a                b      =>      a <----ut----- b
//       ^              /                ^----u---->  /
//        x <- ... <- y1                  x <- ... <- y1   (g)
//
// Carry: u (g's corner at b) copies y, ut (g2's corner at a) copies x; the edge takes
// defaults (it crosses a face), g2 copies g.
Face connect_corners(Mesh& mesh, Halfedge x, Halfedge y) {
    const Face g = mesh.face(x);
    const Halfedge x1 = mesh.next(x);
    const Halfedge y1 = mesh.next(y);
    MESHEDIT_ASSERT(x != y && x1 != y && y1 != x && mesh.face(y) == g);
    const auto first_e = static_cast<std::uint32_t>(mesh.edges_size());
    const auto first_f = static_cast<std::uint32_t>(mesh.faces_size());
    mesh.new_elements(0, 1, 1);
    const Halfedge u = Mesh::halfedge(Edge(first_e), 0);
    const Halfedge ut = Mesh::twin(u);
    const Face g2(first_f);
    mesh.set_vertex(u, mesh.to_vertex(y));
    mesh.set_vertex(ut, mesh.to_vertex(x));
    for (Halfedge z = x1;; z = mesh.next(z)) {
        mesh.set_face(z, g2);
        if (z == y) {
            break;
        }
    }
    mesh.set_next(x, u);
    mesh.set_next(u, y1);
    mesh.set_next(y, ut);
    mesh.set_next(ut, x1);
    mesh.set_face(u, g);
    mesh.set_face(ut, g2);
    mesh.set_halfedge(g, x);
    mesh.set_halfedge(g2, ut);
    mesh.carry(u, y);
    mesh.carry(ut, x);
    mesh.carry_default(Edge(first_e));
    mesh.carry(g2, g);
    return g2;
}

// The halfedge of face `f` into vertex `v`.
Halfedge into(const Mesh& mesh, Face f, Vertex v) {
    for (const Halfedge h : mesh.halfedges(f)) {
        if (mesh.to_vertex(h) == v) {
            return h;
        }
    }
    MESHEDIT_ASSERT(false);
    return {};
}

}  // namespace

OpStatus is_subdivide_region_ok(const Mesh& mesh, const FaceSet& region, RegionScheme scheme) {
    if (!all_live(mesh, region)) {
        return OpStatus::refused("cannot subdivide the region: select one or more live faces");
    }
    if (scheme == RegionScheme::Loop) {
        for (const Face f : region.elements()) {
            if (mesh.valence(f) != 3) {
                return OpStatus::composed(
                    "cannot subdivide the region with Loop: face " + std::to_string(f.idx()) +
                    " has " + std::to_string(mesh.valence(f)) +
                    " corners (Loop takes triangles; Catmull-Clark takes any face)");
            }
        }
    }
    return OpStatus::ok();
}

// Each edge of the region is bisected (bisect(): midpoint m, carried as its halves). Then,
// with p the old corners and m the midpoints of a face in the region (p0 m0 p1 m1 p2 m2 ...):
//
//   a triangle:   connect m2-m0, m0-m1, m1-m2       any other face: poke (centre c), then
//        p2                                         dissolve the spokes c-p[i]
//       /  \                                          p3 --m2-- p2
//     m2----m1                                         |    |    |
//     / \  / \                                        m3 -- c -- m1
//   p0---m0---p1                                       |    |    |
//                                                     p0 --m0-- p1
//
// A face beside the region with midpoints m on its sides is cut by connect_corners() from its
// first midpoint to every corner not beside it (a fan). The carry is that of bisect, poke,
// dissolve and connect_corners().
OpResult<Face> subdivide_region(Mesh& mesh, const FaceSet& region, std::vector<Face>* inside,
                                RegionScheme scheme) {
    if (const OpStatus ok = is_subdivide_region_ok(mesh, region, scheme); !ok) {
        return ok;
    }
    const std::vector<Face> faces = region.elements();
    std::vector<std::vector<Vertex>> corners(faces.size());
    std::vector<Edge> edges;
    std::vector<Face> beside;
    {
        EdgeSet seen(mesh.edges_size());
        FaceSet near(mesh.faces_size());
        for (std::size_t i = 0; i < faces.size(); ++i) {
            for (const Halfedge h : mesh.halfedges(faces[i])) {
                corners[i].push_back(mesh.to_vertex(h));
                if (!seen.contains(Mesh::edge(h))) {
                    seen.insert(Mesh::edge(h));
                    edges.push_back(Mesh::edge(h));
                }
                const Face g = mesh.face(Mesh::twin(h));
                if (g.is_valid() && !region.contains(g) && !near.contains(g)) {
                    near.insert(g);
                    beside.push_back(g);
                }
            }
        }
    }
    const region_detail::RegionTargets targets =
        scheme == RegionScheme::Linear ? region_detail::RegionTargets{}
                                       : region_detail::smooth_targets(mesh, region, edges, scheme);
    const auto first_mid = static_cast<std::uint32_t>(mesh.vertices_size());
    for (const Edge e : edges) {
        [[maybe_unused]] const bool ok = bisect(mesh, e).ok();  // a live edge always bisects
        MESHEDIT_ASSERT(ok);
    }
    const auto first_f = static_cast<std::uint32_t>(mesh.faces_size());
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const Face f = faces[i];
        if (corners[i].size() == 3 && scheme != RegionScheme::CatmullClark) {
            for (const Vertex p : corners[i]) {  // f keeps the middle triangle
                const Halfedge to_p = into(mesh, f, p);
                const Halfedge before = mesh.prev(to_p);  // into the midpoint before p
                connect_corners(mesh, before, mesh.next(to_p));
            }
            continue;
        }
        const Vertex c = *poke(mesh, f);
        for (const Vertex p : corners[i]) {
            // Two triangles of the poke on distinct corners: always dissolvable.
            [[maybe_unused]] const bool ok = dissolve_edge(mesh, mesh.find_edge(c, p)).ok();
            MESHEDIT_ASSERT(ok);
        }
    }
    const auto last_f = static_cast<std::uint32_t>(mesh.faces_size());
    // The transition ring: a fan from each neighbour's first midpoint.
    for (const Face g : beside) {
        Halfedge x{};
        for (const Halfedge h : mesh.halfedges(g)) {
            if (mesh.to_vertex(h).idx() >= first_mid) {
                x = h;
                break;
            }
        }
        while (mesh.valence(mesh.face(x)) > 3) {
            connect_corners(mesh, x, mesh.next(mesh.next(x)));
        }
    }
    // The smooth scheme's places (computed on the mesh before it was cut); the topology and
    // what each element carries are the linear pattern's.
    for (std::size_t i = 0; i < targets.edge_points.size(); ++i) {
        if (targets.edge_points[i].first) {
            mesh.position(Vertex(first_mid + static_cast<std::uint32_t>(i))) =
                targets.edge_points[i].second;
        }
    }
    for (const auto& [v, p] : targets.vertices) {
        mesh.position(v) = p;
    }
    std::vector<Face> made;
    for (const Face f : faces) {
        if (!mesh.is_deleted(f)) {  // a dissolve may have merged it into a new face
            made.push_back(f);
        }
    }
    for (std::uint32_t f = first_f; f < last_f; ++f) {
        if (!mesh.is_deleted(Face(f))) {
            made.push_back(Face(f));
        }
    }
    const Face first = made.front();
    if (inside != nullptr) {
        *inside = std::move(made);
    }
    return first;
}

}  // namespace meshedit
