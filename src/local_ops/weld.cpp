/// \file
/// Welding two boundary edges into one interior edge (Scotty3D's weld_edges). Contract
/// (local_ops.h): the predicate is checked first and a refusal leaves the mesh untouched.

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "local_ops/local_op_helpers.h"
#include "meshedit/core/local_ops.h"

namespace meshedit {
namespace {

// The halfedge of boundary edge `e` that has a face.
Halfedge inner(const Mesh& mesh, Edge e) {
    const Halfedge h = Mesh::halfedge(e, 0);
    return mesh.is_boundary(h) ? Mesh::twin(h) : h;
}

// Where a vertex ends up: c becomes b and d becomes a.
struct Renaming {
    Vertex a, b, c, d;
    Vertex operator()(Vertex v) const { return v == c ? b : v == d ? a : v; }
};

// Whether a face around u also holds w (u != w): merged, it would visit them twice.
bool share_a_face(const Mesh& mesh, Vertex u, Vertex w) {
    for (const Face f : mesh.faces(u)) {
        for (const Vertex x : mesh.vertices(f)) {
            if (x == w) {
                return true;
            }
        }
    }
    return false;
}

}  // namespace

OpStatus is_weld_ok(const Mesh& mesh, Edge e1, Edge e2) {
    MESHEDIT_ASSERT(mesh.is_valid(e1) && mesh.is_valid(e2));
    if (mesh.is_deleted(e1) || mesh.is_deleted(e2)) {
        return OpStatus::refused("cannot weld: an edge is deleted");
    }
    if (e1 == e2) {
        return OpStatus::refused("cannot weld: the two edges are the same");
    }
    if (!mesh.is_boundary(e1) || !mesh.is_boundary(e2)) {
        return OpStatus::refused("cannot weld: both edges must be on the boundary");
    }
    const Halfedge h1 = inner(mesh, e1);
    const Halfedge h2 = inner(mesh, e2);
    if (mesh.face(h1) == mesh.face(h2)) {
        return OpStatus::refused("cannot weld: the edges belong to the same face");
    }
    const Renaming rename{mesh.from_vertex(h1), mesh.to_vertex(h1), mesh.from_vertex(h2),
                          mesh.to_vertex(h2)};
    // Every edge at a, b, c or d after the renaming (e2 becomes e1): none may join a vertex
    // to itself, and no two may join the same vertices.
    std::vector<std::pair<std::uint32_t, std::pair<Vertex, Vertex>>> edges;
    for (const Vertex v : {rename.a, rename.b, rename.c, rename.d}) {
        for (const Halfedge h : mesh.halfedges(v)) {
            const Edge e = Mesh::edge(h);
            if (e == e2) {
                continue;
            }
            const Vertex x = rename(mesh.from_vertex(h));
            const Vertex y = rename(mesh.to_vertex(h));
            if (x == y) {
                return OpStatus::refused("cannot weld: an edge would join a vertex to itself");
            }
            edges.push_back({e.idx(), std::minmax(x, y)});
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());  // met from both ends
    std::sort(edges.begin(), edges.end(),
              [](const auto& p, const auto& q) { return p.second < q.second; });
    for (std::size_t i = 1; i < edges.size(); ++i) {
        if (edges[i].second == edges[i - 1].second) {
            return OpStatus::refused("cannot weld: two edges would join the same vertices");
        }
    }
    // Merged vertices not joined by an edge may still share a face (checked after the edges,
    // as every edge has a face: this names the cause).
    if ((rename.c != rename.b && share_a_face(mesh, rename.c, rename.b)) ||
        (rename.d != rename.a && share_a_face(mesh, rename.d, rename.a))) {
        return OpStatus::refused("cannot weld: a face would visit a vertex twice");
    }
    return OpStatus::ok();
}

// e1 = a-b with h1 = a -> b in F1 and g1 = b -> a on the boundary; e2 = c-d with h2 = c -> d
// in F2 and g2 = d -> c on the boundary. The two gaps face each other:
//
//                 F1                                    F1
//          a -----h1----> b                      a -----h1----> b
//    n1 <- a <----g1----- b <- p1                 <----g1-----        g1 now in F2,
//                                       =>           F2               in h2's place
//    p2 -> d -----g2----> c -> n2
//          d <----h2----- c                      (d merged into a, c into b)
//                 F2
//
// c merges into b and d into a (each at the midpoint), g1 takes h2's place in F2, so that F1
// and F2 meet across e1, and e2 goes. The boundary loops are spliced where g1 and g2 were:
// p1 -> n2 (at b) and p2 -> n1 (at a).
//
// When the two edges meet at a vertex (a == d: next(g1) == g2, or b == c: next(g2) == g1)
// they are zipped: only the other splice is made, and the shared vertex leaves the boundary.
OpResult<Edge> weld(Mesh& mesh, Edge e1, Edge e2) {
    if (const OpStatus ok = is_weld_ok(mesh, e1, e2); !ok) {
        return ok;
    }
    const Halfedge h1 = inner(mesh, e1);
    const Halfedge g1 = Mesh::twin(h1);
    const Halfedge h2 = inner(mesh, e2);
    const Halfedge g2 = Mesh::twin(h2);
    const Vertex a = mesh.from_vertex(h1);
    const Vertex b = mesh.to_vertex(h1);
    const Vertex c = mesh.from_vertex(h2);
    const Vertex d = mesh.to_vertex(h2);
    const Face f2 = mesh.face(h2);
    const Halfedge p1 = mesh.prev(g1);
    const Halfedge n1 = mesh.next(g1);
    const Halfedge p2 = mesh.prev(g2);
    const Halfedge n2 = mesh.next(g2);
    const bool zip_at_a = n1 == g2;  // a == d
    const bool zip_at_b = n2 == g1;  // b == c

    // Merge: everything that pointed at c now points at b, at d now at a.
    for (const auto& [from, to] : {std::pair{c, b}, std::pair{d, a}}) {
        if (from == to) {
            continue;
        }
        mesh.position(to) = midpoint(mesh.position(to), mesh.position(from));
        mesh.carry(to, {{to, 0.5}, {from, 0.5}});
        redirect_arrivals(mesh, from, to);
        mesh.set_halfedge(from, Halfedge());
        mesh.mark_deleted(from);
    }

    // g1 takes h2's place in F2, as its corner at d (now a); e1 blends both edges.
    mesh.carry(g1, h2);
    mesh.carry(e1, {{e1, 0.5}, {e2, 0.5}});
    mesh.set_next(mesh.prev(h2), g1);
    mesh.set_next(g1, mesh.next(h2));
    mesh.set_face(g1, f2);
    if (mesh.halfedge(f2) == h2) {
        mesh.set_halfedge(f2, g1);
    }

    // Boundary loops, and the anchors of the merged vertices: n2 leaves b on the boundary and
    // n1 leaves a, unless the zip took that vertex off the boundary.
    if (!zip_at_a) {
        mesh.set_next(p2, n1);
    }
    if (!zip_at_b) {
        mesh.set_next(p1, n2);
    }
    mesh.set_halfedge(a, zip_at_a ? h1 : n1);
    mesh.set_halfedge(b, zip_at_b ? g1 : n2);
    mesh.mark_deleted(e2);
    return e1;
}

}  // namespace meshedit
