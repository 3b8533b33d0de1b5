/// \file
/// Edge flip and edge split. Both are O(1) relinkings of a fixed set of halfedges, drawn
/// above each op with the variable names as labels. Contract (local_ops.h): the predicate is
/// checked first and a refusal leaves the mesh untouched.

#include <cstdint>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/subdivision.h"

namespace meshedit {

OpStatus is_flip_ok(const Mesh& mesh, Edge e) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    if (mesh.is_deleted(e)) {
        return OpStatus::refused("edge is deleted");
    }
    if (mesh.is_boundary(e)) {
        return OpStatus::refused("cannot flip a boundary edge");
    }
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge t0 = Mesh::halfedge(e, 1);
    if (!mesh.is_triangle(mesh.face(h0)) || !mesh.is_triangle(mesh.face(t0))) {
        return OpStatus::refused("cannot flip: an adjacent face is not a triangle");
    }
    const Vertex a = mesh.to_vertex(mesh.next(h0));
    const Vertex d = mesh.to_vertex(mesh.next(t0));
    // a == d happens on a two-triangle "pillow"; an existing a-d edge would be doubled (this
    // also covers an endpoint of valence 3, whose third face already holds a-d).
    if (a == d || mesh.find_halfedge(a, d).is_valid()) {
        return OpStatus::refused("cannot flip: the new edge already exists");
    }
    return OpStatus::ok();
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
OpResult<Edge> flip(Mesh& mesh, Edge e) {
    if (const OpStatus ok = is_flip_ok(mesh, e); !ok) {
        return ok;
    }
    // Collect.
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge h1 = mesh.next(h0);
    const Halfedge h2 = mesh.next(h1);
    const Halfedge t0 = Mesh::twin(h0);
    const Halfedge t1 = mesh.next(t0);
    const Halfedge t2 = mesh.next(t1);
    const Vertex a = mesh.to_vertex(h1);
    const Vertex b = mesh.to_vertex(t0);
    const Vertex c = mesh.to_vertex(h0);
    const Vertex d = mesh.to_vertex(t1);
    const Face f0 = mesh.face(h0);
    const Face f1 = mesh.face(t0);

    // Relink: f0 = h0 -> h2 -> t1, f1 = t0 -> t2 -> h1.
    mesh.set_vertex(h0, a);
    mesh.set_vertex(t0, d);
    mesh.set_next(h0, h2);
    mesh.set_next(h2, t1);
    mesh.set_next(t1, h0);
    mesh.set_next(t0, t2);
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
    return e;
}

OpStatus is_split_ok(const Mesh& mesh, Edge e) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    if (mesh.is_deleted(e)) {
        return OpStatus::refused("edge is deleted");
    }
    const Face f0 = mesh.face(e, 0);
    const Face f1 = mesh.face(e, 1);
    if (!f0.is_valid() && !f1.is_valid()) {
        return OpStatus::refused("cannot split: the edge has no face");
    }
    if ((f0.is_valid() && !mesh.is_triangle(f0)) || (f1.is_valid() && !mesh.is_triangle(f1))) {
        return OpStatus::refused("cannot split: an adjacent face is not a triangle");
    }
    // Two triangles on the same three corners (a "pillow"): the spokes m-a and m-d coincide.
    if (f0.is_valid() && f1.is_valid() &&
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
    if (const OpStatus ok = is_split_ok(mesh, e); !ok) {
        return ok;
    }
    // Collect.
    const unsigned i = mesh.is_boundary(Mesh::halfedge(e, 1)) ? 1 : 0;
    const Halfedge h0 = Mesh::halfedge(e, i);
    const Halfedge t0 = Mesh::twin(h0);
    const Halfedge t1 = mesh.next(t0);
    const Halfedge t2 = mesh.next(t1);
    const Vertex b = mesh.to_vertex(t0);
    const Vertex c = mesh.to_vertex(h0);
    const Vertex d = mesh.to_vertex(t1);
    const Face f0 = mesh.face(h0);
    const Face f1 = mesh.face(t0);

    // Allocate.
    const Vertex m = mesh.add_vertex(0.5 * (mesh.position(b) + mesh.position(c)));
    const Halfedge s0 = mesh.new_edge(b, m);
    const Halfedge s1 = Mesh::twin(s0);
    const Halfedge w0 = mesh.new_edge(m, d);
    const Halfedge w1 = Mesh::twin(w0);
    const Face f3 = mesh.new_face();
    // Both halves of a crease stay creases (Loop subdivision relies on it).
    if (auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty)) {
        crease[Mesh::edge(s0)] = crease[e];
    }

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
    if (!f0.is_valid()) {
        mesh.set_next(mesh.prev(h0), s0);
        mesh.set_next(s0, h0);
        mesh.set_face(s0, Face());
    } else {
        const Halfedge h1 = mesh.next(h0);
        const Halfedge h2 = mesh.next(h1);
        const Vertex a = mesh.to_vertex(h1);
        const Halfedge u0 = mesh.new_edge(m, a);
        const Halfedge u1 = Mesh::twin(u0);
        const Face f2 = mesh.new_face();
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
    if (mesh.halfedge(b) == h0) {
        mesh.set_halfedge(b, s0);
    }
    return m;
}

}  // namespace meshedit
