/// \file
/// Edge collapse. Refusals follow the link condition (Dey, Edelsbrunner et al.): on a surface
/// with boundary, think of every boundary loop as coned to a virtual vertex; the collapse
/// keeps a manifold exactly when the endpoints share no neighbour and no link edge other
/// than those of the edge's own (possibly virtual) triangles.

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

// v0 (smaller index) survives at the midpoint; v1, e, f0, f1, edge(h1) and edge(t2) are
// deleted. h2 takes the place of o1 = twin(h1), t1 that of q2 = twin(t2). On a boundary edge
// one side is a boundary gap instead of f0 or f1, and is closed.
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

    // Everything that pointed at v1 now points at v0 (the walk reads only next/prev).
    const Halfedge start = mesh.halfedge(v1);
    Halfedge h = start;
    do {
        mesh.set_vertex(Mesh::twin(h), v0);
        h = mesh.ccw_rotated(h);
    } while (h != start);

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
        mesh.mark_deleted(Mesh::edge(h1));
        mesh.mark_deleted(f0);
    }
    if (triangle1) {
        const Vertex d = mesh.to_vertex(t1);
        replace(mesh, Mesh::twin(t2), t1);
        if (mesh.halfedge(d) == t2) {
            mesh.set_halfedge(d, Mesh::twin(t1));
        }
        mesh.mark_deleted(Mesh::edge(t2));
        mesh.mark_deleted(f1);
    }

    // Anchor v0 at an outgoing boundary halfedge if it has one (boundary-anchor rule).
    // Any live halfedge leaving v0: twin(h2) = v0 -> a beside a triangle; after p0 in a
    // polygon f0 (h1 itself may be gone, taken by a triangle f1 beside it); t1 after a gap.
    const Halfedge first = triangle0 ? Mesh::twin(h2) : f0.is_valid() ? mesh.next(p0) : t1;
    Halfedge anchor = first;
    h = first;
    do {
        if (mesh.is_boundary(h)) {
            anchor = h;
            break;
        }
        h = mesh.ccw_rotated(h);
    } while (h != first);
    mesh.set_halfedge(v0, anchor);
    mesh.position(v0) = midpoint(mesh.position(v0), mesh.position(v1));

    mesh.mark_deleted(e);
    mesh.mark_deleted(v1);
    return v0;
}

}  // namespace meshedit
