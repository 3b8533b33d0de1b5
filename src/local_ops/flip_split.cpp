/// \file
/// Edge flip and edge split. Both are O(1) relinkings of a fixed set of halfedges, drawn
/// above each op with the variable names as labels. Contract (local_ops.h): the predicate is
/// checked first and a refusal leaves the mesh untouched.

#include <cstdint>

#include "mesh/mesh_arrays.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"

namespace meshedit {

namespace {

// Whether the loop through `h` has three halfedges: on a valid mesh (prev is the inverse of
// next) the same as is_triangle(face(h)), but from a halfedge the caller holds rather than
// halfedge(face(h)), and with two dependent reads instead of three (next(next(h)) against
// prev(h), which is read at the same time as next(h)). On a large mesh each is a cache miss.
bool is_triangle_loop(const Mesh& mesh, Halfedge h) {
    return mesh.next(mesh.next(h)) == mesh.prev(h);
}

// Whether a halfedge a -> v exists, given a's two outgoing halfedges `ab` and `ac = ccw(ab)`
// (the sides of a triangle at a). find_halfedge() rotates once around a from halfedge(a);
// this walks clockwise from `ab` and counter-clockwise from `ac` at the same time until the
// two meet, so on a large mesh the two chains of cache misses overlap and each is half as
// long.
bool has_outgoing_to(const Mesh& mesh, Halfedge ab, Halfedge ac, Vertex v) {
    Halfedge cw = ab;
    Halfedge ccw = ac;
    for (;;) {
        if (mesh.to_vertex(cw) == v || mesh.to_vertex(ccw) == v) {
            return true;
        }
        const Halfedge ccw_next = mesh.ccw_rotated(ccw);
        if (ccw_next == cw) {
            return false;  // every outgoing halfedge checked
        }
        const Halfedge cw_next = mesh.cw_rotated(cw);
        if (cw_next == ccw_next) {
            return mesh.to_vertex(cw_next) == v;  // the last one
        }
        cw = cw_next;
        ccw = ccw_next;
    }
}

// is_deleted(e) without reading the flag when nothing is deleted (one cache miss fewer).
bool edge_is_deleted(const Mesh& mesh, Edge e) {
    return mesh.n_edges() != mesh.edges_size() && mesh.is_deleted(e);
}

// What a flip or split of live edge e = (h0, t0) reads and writes around it, asked for
// before the predicate walks anything so that the misses overlap (MeshArrays::prefetch). Only the
// links the op touches: every line asked for takes one of the few miss slots a core has.
// h1 = next(h0), h2 = prev(h0), t1 = next(t0), t2 = prev(t0); b = to(t0), c = to(h0).
struct EdgeFrameLinks {
    unsigned h1, h2, t1, t2;
    bool positions;  // of b and c
};
// flip: reads a, d and the ring at a (from h2 and twin(h1)); relinks all four.
constexpr EdgeFrameLinks kFlipLinks{
    MeshArrays::kAllLinks, MeshArrays::kNext | MeshArrays::kPrev | MeshArrays::kVertex,
    MeshArrays::kAllLinks, MeshArrays::kNext | MeshArrays::kPrev, false};
// split: reads next(h1), a, next(t1), d; writes next(h1), next/prev/face(h2),
// next/prev/face(t1), prev(t2); the midpoint needs b and c.
constexpr EdgeFrameLinks kSplitLinks{MeshArrays::kNext | MeshArrays::kVertex,
                                     MeshArrays::kNext | MeshArrays::kPrev | MeshArrays::kFace,
                                     MeshArrays::kAllLinks, MeshArrays::kPrev, true};

void prefetch_edge_frame(const Mesh& mesh, Edge e, const EdgeFrameLinks& links) {
    if (edge_is_deleted(mesh, e)) {
        return;  // its links may be stale
    }
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge t0 = Mesh::halfedge(e, 1);
    MeshArrays::prefetch(mesh, mesh.next(h0), links.h1);
    MeshArrays::prefetch(mesh, mesh.prev(h0), links.h2);
    MeshArrays::prefetch(mesh, mesh.next(t0), links.t1);
    MeshArrays::prefetch(mesh, mesh.prev(t0), links.t2);
    MeshArrays::prefetch(mesh, mesh.to_vertex(h0), links.positions);
    MeshArrays::prefetch(mesh, mesh.to_vertex(t0), links.positions);
    if (mesh.face(h0).is_valid()) {
        MeshArrays::prefetch(mesh, mesh.face(h0));
    }
    if (mesh.face(t0).is_valid()) {
        MeshArrays::prefetch(mesh, mesh.face(t0));
    }
}

// is_flip_ok() beside a polygon (e interior, a face of more than three sides beside it):
// f0 trades corner c for d and f1 trades b for a. A corner already there would be visited
// twice (this covers an endpoint of valence 2, whose two faces share its other edge too).
// Kept out of line: flips between triangles, the hot path, stay as short as they were.
[[gnu::noinline, gnu::cold]] OpStatus is_polygon_flip_ok(const Mesh& mesh, Halfedge h0,
                                                         Halfedge t0) {
    const Vertex a = mesh.to_vertex(mesh.next(h0));
    const Vertex d = mesh.to_vertex(mesh.next(t0));
    if (a == d) {
        return OpStatus::refused("cannot flip: the new edge already exists");
    }
    for (const Halfedge h : mesh.loop(h0)) {
        if (mesh.to_vertex(h) == d) {
            return OpStatus::refused("cannot flip: a face would visit a vertex twice");
        }
    }
    for (const Halfedge h : mesh.loop(t0)) {
        if (mesh.to_vertex(h) == a) {
            return OpStatus::refused("cannot flip: a face would visit a vertex twice");
        }
    }
    if (mesh.find_halfedge(a, d).is_valid()) {
        return OpStatus::refused("cannot flip: the new edge already exists");
    }
    return OpStatus::ok();
}

// The relinking of flip() (drawn above flip(), below): f0 = t1 -> h0 -> h3 ... h2 -> t1 and
// f1 = h1 -> t0 -> t3 ... t2 -> h1, with h3 = next(h1) and t3 = next(t1); between triangles
// h3 = h2 and t3 = t2 (f0 = h0 -> h2 -> t1, f1 = t0 -> t2 -> h1). Inlined in both callers so
// that the triangle path compiles to exactly the triangle relinking.
[[gnu::always_inline]] inline void relink_flip(Mesh& mesh, Edge e, Halfedge h1, Halfedge h2,
                                               Halfedge h3, Halfedge t1, Halfedge t2, Halfedge t3) {
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge t0 = Mesh::twin(h0);
    const Vertex a = mesh.to_vertex(h1);
    const Vertex b = mesh.to_vertex(t0);
    const Vertex c = mesh.to_vertex(h0);
    const Vertex d = mesh.to_vertex(t1);
    const Face f0 = mesh.face(h0);
    const Face f1 = mesh.face(t0);

    // Carry: h0 becomes f0's corner at a, which h1 was; t0 f1's corner at d, which t1 was.
    // h1 and t1 change faces and keep their values; the edge keeps its own.
    mesh.carry(h0, h1);
    mesh.carry(t0, t1);
    mesh.set_vertex(h0, a);
    mesh.set_vertex(t0, d);
    mesh.set_next(h0, h3);
    mesh.set_next(h2, t1);
    mesh.set_next(t1, h0);
    mesh.set_next(t0, t3);
    mesh.set_next(t2, h1);
    mesh.set_next(h1, t0);
    mesh.set_face(t1, f0);
    mesh.set_face(h1, f1);

    // Anchors. b and c lose e; as e is interior, a boundary anchor is never h0 or t0.
    mesh.set_halfedge(f0, h0);
    mesh.set_halfedge(f1, t0);
    if (mesh.halfedge(b) == h0) {
        mesh.set_halfedge(b, t1);
    }
    if (mesh.halfedge(c) == t0) {
        mesh.set_halfedge(c, h1);
    }
}

// flip() beside a polygon, after its predicate. Out of line, as is_polygon_flip_ok().
[[gnu::noinline, gnu::cold]] Edge flip_polygons(Mesh& mesh, Edge e) {
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge t0 = Mesh::twin(h0);
    const Halfedge h1 = mesh.next(h0);
    const Halfedge t1 = mesh.next(t0);
    relink_flip(mesh, e, h1, mesh.prev(h0), mesh.next(h1), t1, mesh.prev(t0), mesh.next(t1));
    return e;
}

// Whether the loop of `h` is a triangle or a boundary gap: the sides split() divides as
// drawn below.
bool is_triangle_or_gap(const Mesh& mesh, Halfedge h) {
    return mesh.is_boundary(h) || is_triangle_loop(mesh, h);
}

// Cuts the face of `hu` and `hv` by a new edge from u = to_vertex(hu) to v = to_vertex(hv),
// two corners of it that are not neighbours. The part from u to v (next(hu) ... hv) keeps
// the face, closed by n1 = v -> u; the part from v to u (next(hv) ... hu) becomes the new
// face g, closed by n0 = u -> v. \return n0.
//
//        v <--hv-- .                v <--hv-- .
//        |         ^                | ^  n1   ^
//        |    f    |       =>       |  n0 \ f |
//        v         |                v  g   v  |
//        . --hu--> u                . --hu--> u
Halfedge cut(Mesh& mesh, Halfedge hu, Halfedge hv) {
    const Face f = mesh.face(hu);
    const Halfedge u_out = mesh.next(hu);
    const Halfedge v_out = mesh.next(hv);
    const Halfedge n0 = mesh.new_edge(mesh.to_vertex(hu), mesh.to_vertex(hv));
    const Halfedge n1 = Mesh::twin(n0);
    const Face g = mesh.new_face();
    mesh.set_next(hv, n1);
    mesh.set_next(n1, u_out);
    mesh.set_next(hu, n0);
    mesh.set_next(n0, v_out);
    mesh.set_face(n1, f);
    for (Halfedge h = n0; mesh.face(h) != g; h = mesh.next(h)) {
        mesh.set_face(h, g);
    }
    mesh.set_halfedge(f, n1);
    mesh.set_halfedge(g, n0);
    // Carry: g is a part of f; n0 is g's corner at v as hv is f's, n1 f's corner at u as hu
    // is g's; the new edge is new.
    mesh.carry(g, f);
    mesh.carry(n0, hv);
    mesh.carry(n1, hu);
    mesh.carry_default(Mesh::edge(n0));
    return n0;
}

// split() when a face beside e is not a triangle: bisect e, then cut each side that was a
// triangle, now the quad (b, m, c, a), from m to its third corner; a polygon side keeps m
// as one more corner. The sides of m - c are halfedge(e, 0) and halfedge(e, 1) (bisect keeps
// e as that half): the one leaving m is followed by c -> a, the one arriving at m by m -> b
// and then b -> d.
OpResult<Vertex> split_beside_polygon(Mesh& mesh, Edge e) {
    bool divide[2];
    for (unsigned k = 0; k < 2; ++k) {
        const Halfedge h = Mesh::halfedge(e, k);
        divide[k] = !mesh.is_boundary(h) && is_triangle_loop(mesh, h);
    }
    const Vertex m = *bisect(mesh, e);
    for (unsigned k = 0; k < 2; ++k) {
        if (!divide[k]) {
            continue;
        }
        const Halfedge h = Mesh::halfedge(e, k);
        if (mesh.from_vertex(h) == m) {
            cut(mesh, mesh.prev(h), mesh.next(h));
        } else {
            cut(mesh, h, mesh.next(mesh.next(h)));
        }
    }
    return m;
}

// is_flip_ok(), also saying whether both faces are triangles (flip() then reads nothing more).
OpStatus flip_status(const Mesh& mesh, Edge e, bool& triangles) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    triangles = false;
    if (edge_is_deleted(mesh, e)) {
        return OpStatus::refused("cannot flip: the edge is deleted");
    }
    if (mesh.is_boundary(e)) {
        return OpStatus::refused("cannot flip: boundary edge");
    }
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge t0 = Mesh::halfedge(e, 1);
    if (!is_triangle_loop(mesh, h0) || !is_triangle_loop(mesh, t0)) {
        return is_polygon_flip_ok(mesh, h0, t0);
    }
    triangles = true;
    const Halfedge h1 = mesh.next(h0);  // c -> a
    const Halfedge h2 = mesh.prev(h0);  // a -> b
    const Vertex a = mesh.to_vertex(h1);
    const Vertex d = mesh.to_vertex(mesh.next(t0));
    // a == d happens on a two-triangle "pillow"; an existing a-d edge would be doubled (this
    // also covers an endpoint of valence 3, whose third face already holds a-d).
    if (a == d || has_outgoing_to(mesh, h2, Mesh::twin(h1), d)) {
        return OpStatus::refused("cannot flip: the new edge already exists");
    }
    return OpStatus::ok();
}

}  // namespace

OpStatus is_flip_ok(const Mesh& mesh, Edge e) {
    bool triangles;
    return flip_status(mesh, e, triangles);
}

// Before: e = b-c between f0 = (a,b,c) and f1 = (c,b,d). After: e = d-a between
// f0 = (a,b,d) and f1 = (a,d,c); h0 keeps its index and runs d -> a, t0 runs a -> d.
//
//            a                                a
//          /   ^                            / ^| ^
//      h2 v  f0 \ h1                    h2 v  ||  \ h1
//        b --h0--> c          =>          b f0 || f1 c
//      t1 \ <-t0-- ^ t2                  t1 \  ||  ^ t2
//          v  f1  /                         v |v  /
//            d                                d
//                                         (h0 up, t0 down)
//
// Polygons (Scotty3D's rule): the edge turns to join the corners that follow its ends, d
// after b in f1 and a after c in f0, and each face keeps its number of sides. With
// h3 = next(h1) and t3 = next(t1), f0 = t1 -> h0 -> h3 ... h2 and f1 = h1 -> t0 -> t3 ... t2;
// for triangles h3 = h2 and t3 = t2, which is the relinking above. Two quads:
//
//        p <--h3-- a                 p <--h3-- a
//        |   f0    ^                 |  f0   / ^
//     h2 v         | h1           h2 v   h0/   | h1
//        b --h0--> c       =>        b    /    c       f0 = (b,c,a,p) -> (b,d,a,p)
//        | <--t0-- ^                 |   /t0   ^       f1 = (c,b,d,r) -> (c,a,d,r)
//     t1 v   f1    | t2           t1 v  /  f1  | t2
//        d --t3--> r                 d --t3--> r
//
OpResult<Edge> flip(Mesh& mesh, Edge e) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    prefetch_edge_frame(mesh, e, kFlipLinks);
    bool triangles;
    if (const OpStatus ok = flip_status(mesh, e, triangles); !ok) {
        return ok;
    }
    if (!triangles) {
        return flip_polygons(mesh, e);
    }
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge t0 = Mesh::twin(h0);
    const Halfedge h2 = mesh.prev(h0);
    const Halfedge t2 = mesh.prev(t0);
    relink_flip(mesh, e, mesh.next(h0), h2, h2, mesh.next(t0), t2, t2);
    return e;
}

OpStatus is_split_ok(const Mesh& mesh, Edge e) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    if (edge_is_deleted(mesh, e)) {
        return OpStatus::refused("cannot split: the edge is deleted");
    }
    const Face f0 = mesh.face(e, 0);
    const Face f1 = mesh.face(e, 1);
    if (!f0.is_valid() && !f1.is_valid()) {
        return OpStatus::refused("cannot split: the edge has no face");
    }
    // Two triangles on the same three corners (a "pillow"): the spokes m-a and m-d coincide.
    // (A polygon beside e is not divided, so only two triangles can make two spokes.)
    if (f0.is_valid() && f1.is_valid() && is_triangle_loop(mesh, Mesh::halfedge(e, 0)) &&
        is_triangle_loop(mesh, Mesh::halfedge(e, 1)) &&
        mesh.to_vertex(mesh.next(Mesh::halfedge(e, 0))) ==
            mesh.to_vertex(mesh.next(Mesh::halfedge(e, 1)))) {
        return OpStatus::refused("cannot split: the new edges would coincide");
    }
    return OpStatus::ok();
}

// h0 is halfedge(e, 1) if that one is on the boundary, else halfedge(e, 0), so t0 always
// has a face and only the top (f0) may be missing. e is kept as the m-c half with h0 now
// running m -> c: halfedge(m) = h0. New: vertex m, edges s (b-m), u (m-a) and w (m-d),
// faces f2 and f3. On the boundary the top is a gap: only s (s0 on the boundary) and f3.
//
//            a                                  a
//          /   ^                              / ^ ^
//      h2 v  f0 \ h1                      h2 v f2 u f0 \ h1
//        b --h0--> c          =>            b -s0-> m -h0-> c
//      t1 \ <-t0-- ^ t2                    t1 \ <-s1- <-t0- ^ t2
//          v  f1  /                             v f3 w f1 /
//            d                                  d
//
// u0 = m -> a, u1 = a -> m; w0 = m -> d, w1 = d -> m; s0 = b -> m, s1 = m -> b.
OpResult<Vertex> split(Mesh& mesh, Edge e) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    prefetch_edge_frame(mesh, e, kSplitLinks);
    if (const OpStatus ok = is_split_ok(mesh, e); !ok) {
        return ok;
    }
    if (!is_triangle_or_gap(mesh, Mesh::halfedge(e, 0)) ||
        !is_triangle_or_gap(mesh, Mesh::halfedge(e, 1))) {
        return split_beside_polygon(mesh, e);
    }
    // Collect every value first: on a large mesh these reads are cache misses at random
    // places, and issued together, before any write or allocation, they overlap.
    const unsigned i = mesh.is_boundary(Mesh::halfedge(e, 1)) ? 1 : 0;
    const Halfedge h0 = Mesh::halfedge(e, i);
    const Halfedge t0 = Mesh::twin(h0);
    const Halfedge t1 = mesh.next(t0);
    const Halfedge t2 = mesh.prev(t0);
    const Halfedge h1 = mesh.next(h0);    // unused on the boundary
    const Halfedge h2 = mesh.prev(h0);    // on the boundary: the boundary halfedge before h0
    const Vertex a = mesh.to_vertex(h1);  // unused on the boundary
    const Vertex b = mesh.to_vertex(t0);
    const Vertex c = mesh.to_vertex(h0);
    const Vertex d = mesh.to_vertex(t1);
    const Face f0 = mesh.face(h0);
    const Face f1 = mesh.face(t0);
    const bool top = f0.is_valid();
    const Vec3 midpoint = meshedit::midpoint(mesh.position(b), mesh.position(c));
    const bool b_anchored_at_h0 = mesh.halfedge(b) == h0;

    // Allocate, in one step per element kind: m; edges s, w (and u with a top face); faces
    // f3 (and f2).
    const auto first_v = static_cast<std::uint32_t>(mesh.vertices_size());
    const auto first_e = static_cast<std::uint32_t>(mesh.edges_size());
    const auto first_f = static_cast<std::uint32_t>(mesh.faces_size());
    mesh.new_elements(1, top ? 3 : 2, top ? 2 : 1);
    const Vertex m(first_v);
    const Halfedge s0 = Mesh::halfedge(Edge(first_e), 0);
    const Halfedge s1 = Mesh::twin(s0);
    const Halfedge w0 = Mesh::halfedge(Edge(first_e + 1), 0);
    const Halfedge w1 = Mesh::twin(w0);
    const Face f3(first_f);
    mesh.position(m) = midpoint;
    mesh.set_vertex(s0, m);
    mesh.set_vertex(s1, b);
    mesh.set_vertex(w0, d);
    mesh.set_vertex(w1, m);
    // Carry (a halfedge holds its face's corner at its head): m is the midpoint of b and c;
    // s is a half of e (both halves of a crease stay creases: Loop relies on it); u and w
    // cross old faces; f2 and f3 are parts of f0 and f1. Corners at m blend those at b and c
    // of the same face; t0 moves from b to m, so the copies of it come first.
    mesh.carry(m, {{b, 0.5}, {c, 0.5}});
    mesh.carry(Mesh::edge(s0), e);
    mesh.carry_default(Mesh::edge(w0));
    mesh.carry(f3, f1);
    mesh.carry(s1, t0);
    mesh.carry(w0, t1);
    mesh.carry(w1, {{t0, 0.5}, {t2, 0.5}});
    mesh.carry(t0, {{t0, 0.5}, {t2, 0.5}});
    if (top) {
        const Halfedge u0 = Mesh::halfedge(Edge(first_e + 2), 0);
        mesh.carry_default(Mesh::edge(u0));
        mesh.carry(Face(first_f + 1), f0);
        mesh.carry(u0, h1);
        mesh.carry(Mesh::twin(u0), {{h2, 0.5}, {h0, 0.5}});
    }
    mesh.carry(s0, {{h2, 0.5}, {h0, 0.5}});

    // Relink the bottom: f1 = t0 -> w0 -> t2, f3 = s1 -> t1 -> w1.
    mesh.set_vertex(t0, m);
    mesh.set_next(t0, w0);
    mesh.set_next(w0, t2);
    mesh.set_next(s1, t1);
    mesh.set_next(t1, w1);
    mesh.set_next(w1, s1);
    mesh.set_face(w0, f1);
    mesh.set_face(s1, f3);
    mesh.set_face(t1, f3);
    mesh.set_face(w1, f3);
    mesh.set_halfedge(f1, t0);
    mesh.set_halfedge(f3, s1);

    // Relink the top: a boundary loop gains s0 before h0, a face splits into f0 and f2.
    if (!top) {
        mesh.set_next(h2, s0);
        mesh.set_next(s0, h0);  // face(s0) stays unset: a boundary halfedge
    } else {
        const Halfedge u0 = Mesh::halfedge(Edge(first_e + 2), 0);
        const Halfedge u1 = Mesh::twin(u0);
        const Face f2(first_f + 1);
        mesh.set_vertex(u0, a);
        mesh.set_vertex(u1, m);
        // f0 = h0 -> h1 -> u1, f2 = s0 -> u0 -> h2.
        mesh.set_next(h1, u1);
        mesh.set_next(u1, h0);
        mesh.set_next(s0, u0);
        mesh.set_next(u0, h2);
        mesh.set_next(h2, s0);
        mesh.set_face(u1, f0);
        mesh.set_face(s0, f2);
        mesh.set_face(u0, f2);
        mesh.set_face(h2, f2);
        mesh.set_halfedge(f0, h0);
        mesh.set_halfedge(f2, s0);
    }

    // Anchors: h0 now leaves m (on a boundary split it is m's outgoing boundary halfedge);
    // if b was anchored at h0, s0 replaces it and is a boundary halfedge exactly when h0 is.
    mesh.set_halfedge(m, h0);
    if (b_anchored_at_h0) {
        mesh.set_halfedge(b, s0);
    }
    return m;
}

OpStatus is_bisect_ok(const Mesh& mesh, Edge e) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    if (mesh.is_deleted(e)) {
        return OpStatus::refused("cannot bisect: the edge is deleted");
    }
    return OpStatus::ok();
}

// As split, h0 is the boundary side if e has one. e is kept as the m-c half; the new edge s
// is the b-m half. No face is divided: the loops of h0 and t0 each gain a corner m.
//
//        (loop of h0: f0, or a boundary gap)           (loop of h0)
//      h2                    h1                  h2                      h1
//    ---> b ------h0------> c --->      =>     ---> b --s0--> m --h0--> c --->
//    <--- b <-----t0------- c <---             <--- b <--s1-- m <--t0-- c <---
//      t1                    t2                  t1                      t2
//        (loop of t0: f1, or a boundary gap)           (loop of t0)
OpResult<Vertex> bisect(Mesh& mesh, Edge e) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    if (const OpStatus ok = is_bisect_ok(mesh, e); !ok) {
        return ok;
    }
    const unsigned i = mesh.is_boundary(Mesh::halfedge(e, 1)) ? 1 : 0;
    const Halfedge h0 = Mesh::halfedge(e, i);
    const Halfedge t0 = Mesh::twin(h0);
    const Halfedge h2 = mesh.prev(h0);
    const Halfedge t1 = mesh.next(t0);
    const Vertex b = mesh.to_vertex(t0);
    const Vertex c = mesh.to_vertex(h0);
    const Vec3 midpoint = meshedit::midpoint(mesh.position(b), mesh.position(c));

    const auto first_e = static_cast<std::uint32_t>(mesh.edges_size());
    const Vertex m = mesh.new_vertex(midpoint);
    mesh.new_elements(0, 1, 0);
    const Halfedge s0 = Mesh::halfedge(Edge(first_e), 0);
    const Halfedge s1 = Mesh::twin(s0);
    // Carry, as in split(): m is the midpoint, s a half of e; t0's corner moves from b to m.
    const Halfedge t2 = mesh.prev(t0);
    mesh.carry(m, {{b, 0.5}, {c, 0.5}});
    mesh.carry(Mesh::edge(s0), e);
    mesh.carry(s0, {{h2, 0.5}, {h0, 0.5}});
    mesh.carry(s1, t0);
    mesh.carry(t0, {{t0, 0.5}, {t2, 0.5}});

    // Loop of h0: h2 -> s0 -> h0; loop of t0: t0 -> s1 -> t1.
    mesh.set_vertex(s0, m);
    mesh.set_vertex(s1, b);
    mesh.set_vertex(t0, m);
    mesh.set_next(h2, s0);
    mesh.set_next(s0, h0);
    mesh.set_next(t0, s1);
    mesh.set_next(s1, t1);
    mesh.set_face(s0, mesh.face(h0));
    mesh.set_face(s1, mesh.face(t0));

    // Anchors: h0 now leaves m (a boundary halfedge if e was on the boundary); s0 takes h0's
    // place at b and is a boundary halfedge exactly when h0 is.
    mesh.set_halfedge(m, h0);
    if (mesh.halfedge(b) == h0) {
        mesh.set_halfedge(b, s0);
    }
    return m;
}

}  // namespace meshedit
