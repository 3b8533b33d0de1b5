/// \file
/// Removing elements and filling holes: make_boundary (a face becomes a hole), dissolve_edge
/// (two faces merge), dissolve_vertex (the faces around a vertex merge) and fill_hole (a
/// boundary loop becomes a face). Each predicate says exactly when the result would break an
/// invariant of docs/halfedge.md; the operation checks it first and a refusal changes
/// nothing.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"

namespace meshedit {
namespace {

// The sides of `f` in order.
std::vector<Halfedge> sides_of(const Mesh& mesh, Face f) {
    std::vector<Halfedge> sides;
    for (const Halfedge h : mesh.halfedges(f)) {
        sides.push_back(h);
    }
    return sides;
}

// The outgoing halfedges of `v`, counter-clockwise from halfedge(v) (on the boundary the
// first is the outgoing boundary halfedge).
std::vector<Halfedge> outgoing(const Mesh& mesh, Vertex v) {
    std::vector<Halfedge> out;
    for (const Halfedge h : mesh.halfedges(v)) {
        out.push_back(h);
    }
    return out;
}

// Whether removing face `f` would put a corner on two holes: a corner already on the
// boundary whose gap is not beside f (neither of f's sides at it is a boundary edge).
bool corner_would_touch_two_holes(const Mesh& mesh, Face f) {
    for (const Halfedge h : mesh.halfedges(f)) {
        const Vertex v = mesh.to_vertex(h);
        if (mesh.is_boundary(v) && !mesh.is_boundary(Mesh::twin(h)) &&
            !mesh.is_boundary(Mesh::twin(mesh.next(h)))) {
            return true;
        }
    }
    return false;
}

// The corners the faces around v make when merged without v: the heads of every halfedge of
// those faces except the two at v in each (outs[first...]: the outgoing halfedges whose faces
// merge). Sorted, so that a repeated corner sits next to its twin.
std::vector<Vertex> merged_corners(const Mesh& mesh, const std::vector<Halfedge>& outs,
                                   std::size_t first) {
    std::vector<Vertex> corners;
    for (std::size_t i = first; i < outs.size(); ++i) {
        const Halfedge stop = mesh.prev(outs[i]);
        for (Halfedge h = mesh.next(outs[i]); h != stop; h = mesh.next(h)) {
            corners.push_back(mesh.to_vertex(h));
        }
    }
    std::sort(corners.begin(), corners.end());
    return corners;
}

bool has_repeat(const std::vector<Vertex>& sorted) {
    return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

}  // namespace

// ------------------------------------------------------------------ make_boundary

OpStatus is_make_boundary_ok(const Mesh& mesh, Face f) {
    MESHEDIT_ASSERT(mesh.is_valid(f));
    if (mesh.is_deleted(f)) {
        return OpStatus::refused("cannot make boundary: the face is deleted");
    }
    if (corner_would_touch_two_holes(mesh, f)) {
        return OpStatus::refused("cannot make boundary: a corner would touch two holes");
    }
    return OpStatus::ok();
}

// f's sides s[i] run into corner v[i] = to_vertex(s[i]), and s[i+1] leaves it. Every side
// becomes a boundary halfedge; a side whose twin t was on the boundary already has gaps on
// both sides and goes, its two boundary loops spliced where it was:
//
//    hole above             ---> u <-- t -- v <---           ---> u        v <---
//                                 \           ^                    \      ^
//    f (now a gap)               s[i-1] -s[i]->  s[i+1]     =>      (loops joined:
//                                                                    prev(s) -> next(t),
//                                                                    prev(t) -> next(s))
//
// A corner whose two sides both go had no other edge: it goes too. Otherwise its anchor is
// its outgoing side if that stays (now a boundary halfedge), else the halfedge after its
// incoming side, which the splice made the boundary halfedge leaving it.
OpResult<Halfedge> make_boundary(Mesh& mesh, Face f) {
    if (const OpStatus ok = is_make_boundary_ok(mesh, f); !ok) {
        return ok;
    }
    const std::vector<Halfedge> s = sides_of(mesh, f);
    const std::size_t n = s.size();
    std::vector<char> goes(n);
    for (std::size_t i = 0; i < n; ++i) {
        goes[i] = mesh.is_boundary(Mesh::twin(s[i])) ? 1 : 0;
    }
    for (const Halfedge h : s) {
        mesh.set_face(h, Face());
    }
    mesh.mark_deleted(f);
    for (std::size_t i = 0; i < n; ++i) {
        if (goes[i] != 0) {
            const Halfedge h = s[i];
            const Halfedge t = Mesh::twin(h);
            const Halfedge h_prev = mesh.prev(h);
            const Halfedge t_prev = mesh.prev(t);
            mesh.set_next(h_prev, mesh.next(t));
            mesh.set_next(t_prev, mesh.next(h));
            mesh.mark_deleted(Mesh::edge(h));
        }
    }
    Halfedge kept;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        const Vertex v = mesh.to_vertex(s[i]);
        if (goes[i] != 0 && goes[j] != 0) {
            mesh.set_halfedge(v, Halfedge());
            mesh.mark_deleted(v);
        } else if (goes[j] == 0) {
            mesh.set_halfedge(v, s[j]);
        } else {
            mesh.set_halfedge(v, mesh.next(s[i]));
        }
        if (goes[i] == 0 && !kept.is_valid()) {
            kept = s[i];
        }
    }
    return kept;
}

// ------------------------------------------------------------------ fill_hole

OpStatus is_fill_hole_ok(const Mesh& mesh, Halfedge h) {
    MESHEDIT_ASSERT(mesh.is_valid(h));
    if (mesh.is_deleted(h)) {
        return OpStatus::refused("cannot fill: the edge is deleted");
    }
    if (!mesh.is_boundary(h)) {
        return OpStatus::refused("cannot fill: not a boundary edge");
    }
    if (mesh.next(mesh.next(h)) == h) {
        return OpStatus::refused("cannot fill: the hole has fewer than 3 sides");
    }
    return OpStatus::ok();
}

// The loop through h gets a new face g; its vertices keep their anchors (outgoing halfedges
// of this loop), which stay valid as they are no longer on a boundary: a vertex of a
// manifold mesh is on one boundary loop at most.
OpResult<Face> fill_hole(Mesh& mesh, Halfedge h) {
    if (const OpStatus ok = is_fill_hole_ok(mesh, h); !ok) {
        return ok;
    }
    // Carry: nothing old describes g; each corner of it takes the values of the corner at
    // the same vertex across its next side, so a filled hole shows no seam.
    const Face g = mesh.new_face();
    mesh.carry_default(g);
    for (Halfedge x = h;;) {
        mesh.carry(x, Mesh::twin(mesh.next(x)));
        mesh.set_face(x, g);
        x = mesh.next(x);
        if (x == h) {
            break;
        }
    }
    mesh.set_halfedge(g, h);
    return g;
}

// ------------------------------------------------------------------ dissolve_edge

OpStatus is_dissolve_edge_ok(const Mesh& mesh, Edge e) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    if (mesh.is_deleted(e)) {
        return OpStatus::refused("cannot dissolve: the edge is deleted");
    }
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge t0 = Mesh::halfedge(e, 1);
    if (mesh.is_boundary(e)) {
        const Face f = mesh.face(mesh.is_boundary(h0) ? t0 : h0);
        if (corner_would_touch_two_holes(mesh, f)) {
            return OpStatus::refused("cannot dissolve: a corner would touch two holes");
        }
        return OpStatus::ok();
    }
    // The merged face holds both faces' corners once each: they may share only e's ends.
    std::vector<Vertex> corners;
    for (const Halfedge side : {h0, t0}) {
        for (Halfedge h = mesh.next(side); mesh.next(h) != side; h = mesh.next(h)) {
            corners.push_back(mesh.to_vertex(h));
        }
    }
    std::sort(corners.begin(), corners.end());
    if (has_repeat(corners)) {
        return OpStatus::refused("cannot dissolve: the merged face would visit a vertex twice");
    }
    return OpStatus::ok();
}

// Interior e = b-c: f0 (left of h0) and f1 (left of t0) become one loop, f0; e and f1 go.
//
//        . <------ c <----- .              . <------ c <----- .
//        |  f0   ^ |        ^              |         ^        ^
//        v    h0 | | t0  f1 |      =>      v   f0             |
//        . -----> b ------> .              . -----> b ------> .
//
//   prev(h0) -> next(t0) and prev(t0) -> next(h0); b and c re-anchored off h0 and t0.
OpResult<Face> dissolve_edge(Mesh& mesh, Edge e) {
    if (const OpStatus ok = is_dissolve_edge_ok(mesh, e); !ok) {
        return ok;
    }
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge t0 = Mesh::halfedge(e, 1);
    if (mesh.is_boundary(e)) {
        make_boundary(mesh, mesh.face(mesh.is_boundary(h0) ? t0 : h0));
        return Face();
    }
    const Face f0 = mesh.face(h0);
    const Face f1 = mesh.face(t0);
    const Vertex b = mesh.from_vertex(h0);
    const Vertex c = mesh.to_vertex(h0);
    const Halfedge h_next = mesh.next(h0);
    const Halfedge t_next = mesh.next(t0);
    mesh.set_next(mesh.prev(h0), t_next);
    mesh.set_next(mesh.prev(t0), h_next);
    for (Halfedge h = t_next; mesh.face(h) != f0; h = mesh.next(h)) {
        mesh.set_face(h, f0);
    }
    mesh.set_halfedge(f0, h_next);
    if (mesh.halfedge(b) == h0) {
        mesh.set_halfedge(b, t_next);
    }
    if (mesh.halfedge(c) == t0) {
        mesh.set_halfedge(c, h_next);
    }
    mesh.mark_deleted(e);
    mesh.mark_deleted(f1);
    return f0;
}

// ------------------------------------------------------------------ dissolve_vertex

OpStatus is_dissolve_vertex_ok(const Mesh& mesh, Vertex v) {
    MESHEDIT_ASSERT(mesh.is_valid(v));
    if (mesh.is_deleted(v)) {
        return OpStatus::refused("cannot dissolve: the vertex is deleted");
    }
    if (mesh.is_isolated(v)) {
        return OpStatus::refused("cannot dissolve: the vertex has no edges");
    }
    const std::vector<Halfedge> outs = outgoing(mesh, v);
    const bool boundary = mesh.is_boundary(outs[0]);
    std::vector<Vertex> corners = merged_corners(mesh, outs, boundary ? 1 : 0);
    if (boundary) {
        // The new edge x0 -> x1 closes the merged face and adds x1 as a corner.
        const Vertex x0 = mesh.to_vertex(outs[0]);
        const Vertex x1 = mesh.to_vertex(outs[1]);
        corners.insert(std::lower_bound(corners.begin(), corners.end(), x1), x1);
        if (corners.size() >= 3 && mesh.find_edge(x0, x1).is_valid()) {
            return OpStatus::refused("cannot dissolve: the new edge already exists");
        }
    }
    if (corners.size() < 3) {
        return OpStatus::refused(
            "cannot dissolve: the merged face would have fewer than 3 corners");
    }
    if (has_repeat(corners)) {
        return OpStatus::refused("cannot dissolve: the merged face would visit a vertex twice");
    }
    return OpStatus::ok();
}

// The faces around v, f[i] = face(o[i]) for its outgoing halfedges o[i] = v -> x[i], each
// run from x[i] to x[i+1] (first[i] = next(o[i]) ... last[i] = prev(prev(o[i]))). Without v
// the runs join end to start into one loop, which keeps f[0]; v, its edges and the other
// faces go.
//
//        x2 ------- x1                 x2 ------- x1
//        |  \  f1  / |                 |           |
//        | f2  \ /  f0|       =>       |    f0     |
//        |     v     |                 |           |
//        |  /  f3  \ |                 |           |
//        x3 ------- x0                 x3 ------- x0
//
// On the boundary o[0] is v's outgoing boundary halfedge and the faces are f[1..k]; their
// runs go from x1 to x0, and edge(o[0]) is turned into the edge that closes them: twin(o[0])
// runs x0 -> x1 in the merged face (f[1]) and o[0] runs x1 -> x0 on the boundary, so the hole
// keeps its side and is not swallowed.
//
//        x2 ------ x1                  x2 ------ x1
//        |  \ f1  /                    |        / <- o[0] (boundary, x1 -> x0)
//        | f2  \ /  (hole)    =>       |  f1  /
//        |      v                      |    /  twin(o[0]): x0 -> x1
//        |   /                         |  /
//        x0                            x0
OpResult<Face> dissolve_vertex(Mesh& mesh, Vertex v) {
    if (const OpStatus ok = is_dissolve_vertex_ok(mesh, v); !ok) {
        return ok;
    }
    const std::vector<Halfedge> o = outgoing(mesh, v);
    const std::size_t n = o.size();
    const bool boundary = mesh.is_boundary(o[0]);
    const std::size_t first_face = boundary ? 1 : 0;
    std::vector<Halfedge> first(n), last(n);
    std::vector<Face> f(n);
    for (std::size_t i = first_face; i < n; ++i) {
        first[i] = mesh.next(o[i]);
        last[i] = mesh.prev(mesh.prev(o[i]));
        f[i] = mesh.face(o[i]);
    }
    // Anchors: a neighbour anchored at its halfedge into v moves to the one leaving it along
    // the next face. On the boundary x1 is anchored at the boundary halfedge twin(o[1]), and
    // o[0], now x1 -> x0 on the boundary, takes its place; x0 is anchored away from v.
    for (std::size_t i = first_face; i < n; ++i) {
        const Vertex x = mesh.to_vertex(o[i]);
        if (mesh.halfedge(x) == Mesh::twin(o[i])) {
            mesh.set_halfedge(x, boundary && i == 1 ? o[0] : first[i]);
        }
    }
    Halfedge start;
    if (!boundary) {
        for (std::size_t i = 0; i < n; ++i) {
            mesh.set_next(last[i], first[(i + 1) % n]);
        }
        start = first[0];
    } else {
        const Halfedge closing = Mesh::twin(o[0]);             // x0 -> v, becomes x0 -> x1
        const Halfedge into_x1 = mesh.prev(Mesh::twin(o[1]));  // boundary, arrives at x1
        mesh.set_vertex(closing, mesh.to_vertex(o[1]));
        mesh.set_next(into_x1, o[0]);
        for (std::size_t i = 1; i + 1 < n; ++i) {
            mesh.set_next(last[i], first[i + 1]);
        }
        mesh.set_next(closing, first[1]);  // last[n-1] -> closing is linked already
        // Carry: the closing edge is new in all but its index (not a crease); its halfedge is
        // now the merged face's corner at x1, which o[1] was in f[1].
        mesh.carry_default(Mesh::edge(closing));
        mesh.carry(closing, o[1]);
        start = closing;
    }
    const Face merged = f[first_face];
    for (Halfedge h = start;;) {
        mesh.set_face(h, merged);
        h = mesh.next(h);
        if (h == start) {
            break;
        }
    }
    mesh.set_halfedge(merged, start);
    for (std::size_t i = first_face; i < n; ++i) {
        mesh.mark_deleted(Mesh::edge(o[i]));
        if (i > first_face) {
            mesh.mark_deleted(f[i]);
        }
    }
    mesh.set_halfedge(v, Halfedge());
    mesh.mark_deleted(v);
    return merged;
}

}  // namespace meshedit
