/// \file
/// Edge collapse. Refusals follow the link condition (Dey, Edelsbrunner et al.): on a surface
/// with boundary, think of every boundary loop as coned to a virtual vertex; the collapse
/// keeps a manifold exactly when the endpoints share no neighbour and no link edge other
/// than those of the edge's own (possibly virtual) triangles.

#include <algorithm>
#include <string_view>
#include <utility>
#include <vector>

#include "local_ops/local_op_helpers.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"

namespace meshedit {
namespace {

// e's halfedge leaving the survivor, the endpoint with the smaller index.
Halfedge from_survivor(const Mesh& mesh, Edge e) {
    const Halfedge h = Mesh::halfedge(e, 0);
    return mesh.from_vertex(h) < mesh.to_vertex(h) ? h : Mesh::twin(h);
}

// Whether `h` lies in a triangle (not a polygon, not a boundary gap): the sides of e that
// disappear in a collapse, taking one of their two other edges with them.
bool in_triangle(const Mesh& mesh, Halfedge h) {
    return !mesh.is_boundary(h) && mesh.is_triangle(mesh.face(h));
}

// The corner opposite `h` in its triangle; invalid for a boundary halfedge or a polygon,
// which only loses a corner and so may share no neighbour of both ends.
Vertex opposite(const Mesh& mesh, Halfedge h) {
    return in_triangle(mesh, h) ? mesh.to_vertex(mesh.next(h)) : Vertex();
}

// Takes `h` out of its loop (a polygon losing a corner, or a boundary gap closing).
void unlink(Mesh& mesh, Halfedge h) {
    const Face f = mesh.face(h);
    mesh.set_next(mesh.prev(h), mesh.next(h));
    if (f.is_valid() && mesh.halfedge(f) == h) {
        mesh.set_halfedge(f, mesh.next(h));
    }
}

// Puts `h` in the place of `old` in old's loop (a face or a boundary loop).
void replace(Mesh& mesh, Halfedge old, Halfedge h) {
    const Face g = mesh.face(old);
    mesh.set_next(mesh.prev(old), h);
    mesh.set_next(h, mesh.next(old));
    mesh.set_face(h, g);
    if (g.is_valid() && mesh.halfedge(g) == old) {
        mesh.set_halfedge(g, h);
    }
}

}  // namespace

OpStatus is_collapse_ok(const Mesh& mesh, Edge e) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    if (mesh.is_deleted(e)) {
        return OpStatus::refused("cannot collapse: the edge is deleted");
    }
    const Halfedge h0 = from_survivor(mesh, e);
    const Halfedge t0 = Mesh::twin(h0);
    const Face f0 = mesh.face(h0);
    const Face f1 = mesh.face(t0);
    const Vertex v0 = mesh.from_vertex(h0);
    const Vertex v1 = mesh.to_vertex(h0);
    // Both virtual cone vertices would be common neighbours: the surface would be pinched.
    if (!mesh.is_boundary(e) && mesh.is_boundary(v0) && mesh.is_boundary(v1)) {
        return OpStatus::refused(
            "cannot collapse: an interior edge joining two boundary vertices would pinch the "
            "surface");
    }
    const Vertex a = opposite(mesh, h0);
    const Vertex d = opposite(mesh, t0);
    if (a.is_valid() && a == d) {  // both faces are the same three vertices: a pillow
        return OpStatus::refused("cannot collapse: the mesh would degenerate");
    }
    // Vertex part of the link condition: common neighbours are exactly a and d. A second
    // edge v0-v1 would become a self-loop (valid meshes have none; this keeps the op safe on
    // a mesh built by hand that has one).
    std::size_t edges_to_v0 = 0;
    for (const Vertex w : mesh.vertices(v1)) {
        if (w == v0 && ++edges_to_v0 > 1) {
            return OpStatus::refused("cannot collapse: another edge joins the same two vertices");
        }
        if (w != v0 && w != a && w != d && mesh.find_halfedge(v0, w).is_valid()) {
            return OpStatus::refused("cannot collapse: the link condition fails");
        }
    }
    // A polygon around v1 that also holds v0 would repeat a corner.
    for (const Face g : mesh.faces(v1)) {
        if (g != f0 && g != f1 && !mesh.is_triangle(g)) {
            for (const Vertex w : mesh.vertices(g)) {
                if (w == v0) {
                    return OpStatus::refused("cannot collapse: the link condition fails");
                }
            }
        }
    }
    // Edge part: a link edge shared by v0 and v1. Both faces present: triangles (v0,a,d) and
    // (v1,a,d) close a tetrahedron. One face: its other two edges on the boundary make an
    // isolated triangle (the virtual triangles (v0,a,*) and (v1,a,*)).
    if (a.is_valid() && d.is_valid()) {
        const Halfedge ha = mesh.find_halfedge(a, d);
        if (ha.is_valid()) {
            const Vertex x = opposite(mesh, ha);
            const Vertex y = opposite(mesh, Mesh::twin(ha));
            if ((x == v0 && y == v1) || (x == v1 && y == v0)) {
                return OpStatus::refused("cannot collapse: the mesh would degenerate");
            }
        }
    } else if (mesh.is_boundary(e) && (a.is_valid() || d.is_valid())) {
        const Halfedge h = f0.is_valid() ? h0 : t0;
        if (mesh.is_boundary(Mesh::twin(mesh.next(h))) &&
            mesh.is_boundary(Mesh::twin(mesh.prev(h)))) {
            return OpStatus::refused("cannot collapse: the mesh would degenerate");
        }
    }
    return OpStatus::ok();
}

namespace {

// Two edges become one: the one kept blends both (a crease if either was: a feature line
// survives a collapse beside it, as it survives a split).
void merge_edges(Mesh& mesh, Edge kept, Edge merged) {
    mesh.carry(kept, {{kept, 0.5}, {merged, 0.5}});
}

}  // namespace

// v0 (smaller index) survives at the midpoint; v1, e, f0, f1, edge(h1) and edge(t2) are
// deleted. h2 takes the place of o1 = twin(h1), t1 that of q2 = twin(t2), each keeping a
// crease of either. On a boundary edge one side is a boundary gap instead of f0 or f1, and
// is closed.
//
//             a                          a
//           /   ^                       | ^
//         h2  f0  h1                 h2 | | o2
//         v         \                   v |
//       v0 --h0--> v1       =>          v0
//         \ <--t0--  ^                  | ^
//         t1  f1   t2                t1 | | q1
//           v     /                     v |
//             d                          d
OpResult<Vertex> collapse(Mesh& mesh, Edge e) {
    if (const OpStatus ok = is_collapse_ok(mesh, e); !ok) {
        return ok;
    }
    // Collect.
    const Halfedge h0 = from_survivor(mesh, e);
    const Halfedge t0 = Mesh::twin(h0);
    const Vertex v0 = mesh.from_vertex(h0);
    const Vertex v1 = mesh.to_vertex(h0);
    const Face f0 = mesh.face(h0);
    const Face f1 = mesh.face(t0);
    const Halfedge h1 = mesh.next(h0);
    const Halfedge h2 = mesh.next(h1);
    const Halfedge t1 = mesh.next(t0);
    const Halfedge t2 = mesh.next(t1);
    const Halfedge p0 = mesh.prev(h0);  // ends at v0; never deleted
    const bool triangle0 = in_triangle(mesh, h0);
    const bool triangle1 = in_triangle(mesh, t0);

    // Everything that pointed at v1 now points at v0.
    redirect_arrivals(mesh, v1, v0);

    // Relink. Each step reads its neighbours when it runs, so the steps compose even where
    // they touch the same loop (an ear, a valence-3 v1).
    if (!triangle0) {
        unlink(mesh, h0);
    }
    if (!triangle1) {
        unlink(mesh, t0);
    }
    if (triangle0) {
        const Vertex a = mesh.to_vertex(h1);
        const Halfedge o1 = Mesh::twin(h1);
        replace(mesh, o1, h2);
        if (mesh.halfedge(a) == o1) {
            mesh.set_halfedge(a, h2);
        }
        merge_edges(mesh, Mesh::edge(h2), Mesh::edge(h1));
        mesh.carry(h2, o1);  // the corner at v1 of the face across h1
        mesh.mark_deleted(Mesh::edge(h1));
        mesh.mark_deleted(f0);
    }
    if (triangle1) {
        const Vertex d = mesh.to_vertex(t1);
        replace(mesh, Mesh::twin(t2), t1);
        if (mesh.halfedge(d) == t2) {
            mesh.set_halfedge(d, Mesh::twin(t1));
        }
        merge_edges(mesh, Mesh::edge(t1), Mesh::edge(t2));
        mesh.carry(t1, Mesh::twin(t2));  // the corner at d of the face across t2
        mesh.mark_deleted(Mesh::edge(t2));
        mesh.mark_deleted(f1);
    }

    // Anchor v0 at an outgoing boundary halfedge if it has one (boundary-anchor rule).
    // Any live halfedge leaving v0: twin(h2) = v0 -> a beside a triangle; after p0 in a
    // polygon f0 (h1 itself may be gone, taken by a triangle f1 beside it); t1 after a gap.
    const Halfedge first = triangle0 ? Mesh::twin(h2) : f0.is_valid() ? mesh.next(p0) : t1;
    Halfedge anchor = first;
    Halfedge h = first;
    do {
        if (mesh.is_boundary(h)) {
            anchor = h;
            break;
        }
        h = mesh.ccw_rotated(h);
    } while (h != first);
    mesh.set_halfedge(v0, anchor);
    mesh.position(v0) = midpoint(mesh.position(v0), mesh.position(v1));
    mesh.carry(v0, {{v0, 0.5}, {v1, 0.5}});

    mesh.mark_deleted(e);
    mesh.mark_deleted(v1);
    return v0;
}

// ------------------------------------------------------------------ collapse_face

namespace {

// What collapse_face() reads of f before changing anything: corner c[i], side s[i] = c[i] ->
// c[i+1], its twin r[i] and the loop across it, g[i] = face(r[i]) (invalid: a boundary gap).
struct FaceFrame {
    std::vector<Vertex> c;
    std::vector<Halfedge> s;
    std::vector<Vertex> sorted;  // c, sorted, for membership
    bool has(Vertex v) const { return std::binary_search(sorted.begin(), sorted.end(), v); }
    Halfedge r(std::size_t i) const { return Mesh::twin(s[i % s.size()]); }
};

FaceFrame frame_of(const Mesh& mesh, Face f) {
    FaceFrame fr;
    for (const Halfedge h : mesh.halfedges(f)) {
        fr.s.push_back(h);
        fr.c.push_back(mesh.from_vertex(h));
    }
    fr.sorted = fr.c;
    std::sort(fr.sorted.begin(), fr.sorted.end());
    return fr;
}

// Whether the loop across side i disappears: a triangle, which keeps one corner off f and
// becomes a 2-gon whose two other edges merge.
bool degenerates(const Mesh& mesh, const FaceFrame& fr, std::size_t i) {
    const Halfedge r = fr.r(i);
    return !mesh.is_boundary(r) && mesh.is_triangle(mesh.face(r));
}

// Faces other than f: each keeps f's corners as one run joined by twins of f's sides (that
// run becomes the one corner w) and at least three corners, or is a triangle across one side.
// \return the refusal, or empty.
std::string_view faces_stay_simple(const Mesh& mesh, Face f, const FaceFrame& fr) {
    std::vector<Face> seen;
    for (const Vertex v : fr.c) {
        for (const Face g : mesh.faces(v)) {
            if (g == f || std::find(seen.begin(), seen.end(), g) != seen.end()) {
                continue;
            }
            seen.push_back(g);
            std::size_t size = 0, on_f = 0, runs = 0;
            bool joined_by_sides = true;
            for (const Halfedge h : mesh.halfedges(g)) {
                ++size;
                const bool here = fr.has(mesh.to_vertex(h));
                const bool before = fr.has(mesh.from_vertex(h));
                on_f += here ? 1 : 0;
                runs += here && !before ? 1 : 0;
                if (here && before && mesh.face(Mesh::twin(h)) != f) {
                    joined_by_sides = false;  // a chord of f, or an edge off f between corners
                }
            }
            if (on_f < 2) {
                continue;
            }
            if (runs != 1 || !joined_by_sides) {
                return "cannot collapse face: a face would visit the new vertex twice";
            }
            const std::size_t left = size - on_f + 1;
            if (left < 2 || (left == 2 && on_f != 2)) {
                return "cannot collapse face: a face would shrink below three corners";
            }
        }
    }
    return {};
}

// Edges off f: none between two corners (it would become a loop at w), and no vertex joined
// to two corners except the third corner of a triangle across a side (those two edges merge).
bool edges_stay_simple(const Mesh& mesh, const FaceFrame& fr) {
    std::vector<std::pair<Vertex, std::size_t>> ends;  // (far end, corner index)
    for (std::size_t i = 0; i < fr.c.size(); ++i) {
        for (const Halfedge h : mesh.halfedges(fr.c[i])) {
            const Vertex x = mesh.to_vertex(h);
            if (fr.has(x)) {
                const Face f = mesh.face(fr.s[i]);
                if (mesh.face(h) != f && mesh.face(Mesh::twin(h)) != f) {
                    return false;  // a chord: joins two corners, not a side of f
                }
                continue;
            }
            ends.emplace_back(x, i);
        }
    }
    std::sort(ends.begin(), ends.end());
    const std::size_t n = fr.c.size();
    for (std::size_t k = 0; k < ends.size();) {
        std::size_t m = k;
        while (m < ends.size() && ends[m].first == ends[k].first) {
            ++m;
        }
        if (m - k > 2) {
            return false;
        }
        if (m - k == 2) {
            // Allowed only as (c[i+1], c[i], x) across side i.
            const std::size_t i = ends[k].second, j = ends[k + 1].second;
            const std::size_t side = (j == (i + 1) % n) ? i : (i == (j + 1) % n) ? j : n;
            if (side == n || !degenerates(mesh, fr, side) ||
                mesh.to_vertex(mesh.next(fr.r(side))) != ends[k].first) {
                return false;
            }
        }
        k = m;
    }
    return true;
}

// The wedges around w after the collapse, in order: around each corner c[i] from r[i-1]
// counter-clockwise up to (not including) the wedge across side i, which the next corner
// starts with. A triangle across a side disappears, and the edges beside it merge: both
// neighbours of it being gaps would leave that edge without a face. At most one run of gaps
// (w on one hole at most), and at least one face left.
bool fan_stays_manifold(const Mesh& mesh, const FaceFrame& fr) {
    struct Wedge {
        bool gap;
        bool goes;  // a triangle across a side
    };
    std::vector<Wedge> fan;
    const std::size_t n = fr.c.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Halfedge stop = fr.s[i];
        Halfedge u = fr.r(i + n - 1);
        for (std::size_t k = 0; mesh.ccw_rotated(u) != stop; ++k, u = mesh.ccw_rotated(u)) {
            fan.push_back({mesh.is_boundary(u), k == 0 && degenerates(mesh, fr, i + n - 1)});
        }
    }
    std::vector<Wedge> kept;
    for (std::size_t k = 0; k < fan.size(); ++k) {
        if (!fan[k].goes) {
            kept.push_back(fan[k]);
        } else if (fan[(k + fan.size() - 1) % fan.size()].gap && fan[(k + 1) % fan.size()].gap) {
            return false;
        }
    }
    std::size_t gap_runs = 0, faces = 0;
    for (std::size_t k = 0; k < kept.size(); ++k) {
        faces += kept[k].gap ? 0 : 1;
        gap_runs += kept[k].gap && !kept[(k + kept.size() - 1) % kept.size()].gap ? 1 : 0;
    }
    return faces > 0 && gap_runs <= 1;
}

}  // namespace

OpStatus is_collapse_face_ok(const Mesh& mesh, Face f) {
    MESHEDIT_ASSERT(mesh.is_valid(f));
    if (mesh.is_deleted(f)) {
        return OpStatus::refused("cannot collapse face: the face is deleted");
    }
    // From the most particular cause to the most general: a face folding onto the new
    // vertex also leaves its fan broken, and would be reported as such.
    const FaceFrame fr = frame_of(mesh, f);
    if (const std::string_view reason = faces_stay_simple(mesh, f, fr); !reason.empty()) {
        return OpStatus::refused(reason);
    }
    if (!edges_stay_simple(mesh, fr)) {
        return OpStatus::refused("cannot collapse face: two edges would join the same vertices");
    }
    if (!fan_stays_manifold(mesh, fr)) {
        return OpStatus::refused(
            "cannot collapse face: the new vertex would not be manifold (two holes, or no face "
            "left)");
    }
    return OpStatus::ok();
}

// f's corners merge into w, the corner with the smallest index, at their average. Across
// side i: a polygon loses r[i] (one corner fewer); a boundary gap closes over it; a triangle
// (c[i+1], c[i], x) goes, its edge q = x -> c[i+1] merged into p = c[i] -> x (p takes the
// place of twin(q), as in collapse()).
//
//         x                        x
//        / ^                       | ^
//     p v   \ q                  p | | twin(p)
//     c[i] <-r[i]- c[i+1]   =>      v |
//     c[i] -s[i]-> c[i+1]           w        (f, its sides and every corner but w go)
//        (f below)
OpResult<Vertex> collapse_face(Mesh& mesh, Face f) {
    if (const OpStatus ok = is_collapse_face_ok(mesh, f); !ok) {
        return ok;
    }
    const FaceFrame fr = frame_of(mesh, f);
    const std::size_t n = fr.c.size();
    const Vertex w = fr.sorted.front();
    Vec3 centre{0, 0, 0};
    std::vector<Halfedge> around;  // halfedges leaving the corners, off f
    std::vector<char> triangle(n);
    for (std::size_t i = 0; i < n; ++i) {
        centre += mesh.position(fr.c[i]) / static_cast<double>(n);
        triangle[i] = degenerates(mesh, fr, i) ? 1 : 0;
        for (const Halfedge h : mesh.halfedges(fr.c[i])) {
            if (h != fr.s[i] && Mesh::twin(h) != fr.s[(i + n - 1) % n]) {
                around.push_back(h);
            }
        }
    }
    for (const Halfedge h : around) {
        mesh.set_vertex(Mesh::twin(h), w);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const Halfedge r = fr.r(i);
        if (!triangle[i]) {
            unlink(mesh, r);
            continue;
        }
        const Face g = mesh.face(r);
        const Halfedge p = mesh.next(r);  // c[i] -> x
        const Halfedge q = mesh.prev(r);  // x -> c[i+1]
        const Vertex x = mesh.to_vertex(p);
        replace(mesh, Mesh::twin(q), p);
        if (mesh.halfedge(x) == q) {
            mesh.set_halfedge(x, Mesh::twin(p));
        }
        merge_edges(mesh, Mesh::edge(p), Mesh::edge(q));
        mesh.carry(p, Mesh::twin(q));  // the corner at x of the face across q
        mesh.mark_deleted(Mesh::edge(q));
        mesh.mark_deleted(g);
    }
    for (std::size_t i = 0; i < n; ++i) {
        mesh.mark_deleted(Mesh::edge(fr.s[i]));
        if (fr.c[i] != w) {
            mesh.set_halfedge(fr.c[i], Halfedge());
            mesh.mark_deleted(fr.c[i]);
        }
    }
    mesh.mark_deleted(f);
    // Anchor w at a live outgoing boundary halfedge if it has one, else any live one.
    Halfedge anchor;
    for (const Halfedge h : around) {
        if (mesh.is_deleted(h)) {
            continue;  // the merged edge of a triangle across a side
        }
        if (mesh.is_boundary(h)) {
            anchor = h;
            break;
        }
        if (!anchor.is_valid()) {
            anchor = h;
        }
    }
    mesh.set_halfedge(w, anchor);
    mesh.position(w) = centre;
    const std::vector<double> weights(n, 1.0 / static_cast<double>(n));
    mesh.carry(w, fr.c.data(), weights.data(), n);
    return w;
}

}  // namespace meshedit
