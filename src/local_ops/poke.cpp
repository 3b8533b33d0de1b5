/// \file
/// Face poke (Scotty3D's inset_vertex): a centre vertex joined to every corner. Contract
/// (local_ops.h): the predicate is checked first and a refusal leaves the mesh untouched.

#include <cstdint>
#include <vector>

#include "meshedit/core/local_ops.h"

namespace meshedit {

OpStatus is_poke_ok(const Mesh& mesh, Face f) {
    MESHEDIT_ASSERT(mesh.is_valid(f));
    if (mesh.is_deleted(f)) {
        return OpStatus::refused("cannot poke: the face is deleted");
    }
    return OpStatus::ok();
}

// f's sides h[i] run p[i] -> p[i+1] (h[0] = halfedge(f)). Spoke i is a new edge whose
// halfedge o[i] runs c -> p[i] and whose twin runs p[i] -> c. Triangle i is
// h[i] -> twin(o[i+1]) -> o[i]; triangle 0 keeps f, the others are new faces.
//
//      p3 ------h2------ p2               p3 -------------- p2
//       |                 ^                | ^  tri 2     / ^
//       |                 |                |  \o3      /    |
//       h3       f       h1     =>         |  tri 3 c   tri 1
//       |                 |                |  /o0      \o1  |
//       v                 |                v /   tri 0   \  |
//      p0 ------h0-----> p1               p0 -----h0-----> p1
OpResult<Vertex> poke(Mesh& mesh, Face f) {
    MESHEDIT_ASSERT(mesh.is_valid(f));
    if (const OpStatus ok = is_poke_ok(mesh, f); !ok) {
        return ok;
    }
    std::vector<Halfedge> h;
    for (const Halfedge side : mesh.halfedges(f)) {
        h.push_back(side);
    }
    const auto n = static_cast<std::uint32_t>(h.size());
    // The average of the corners, each divided by n first so that no sum can overflow.
    Vec3 centre{0, 0, 0};
    for (const Halfedge side : h) {
        centre += mesh.position(mesh.from_vertex(side)) / static_cast<double>(n);
    }

    const auto first_e = static_cast<std::uint32_t>(mesh.edges_size());
    const auto first_f = static_cast<std::uint32_t>(mesh.faces_size());
    const Vertex c = mesh.new_vertex(centre);
    mesh.new_elements(0, n, n - 1);
    const auto o = [first_e, n](std::uint32_t i) {
        return Mesh::halfedge(Edge(first_e + i % n), 0);
    };
    const auto triangle = [&](std::uint32_t i) { return i == 0 ? f : Face(first_f + i - 1); };

    for (std::uint32_t i = 0; i < n; ++i) {
        mesh.set_vertex(o(i), mesh.from_vertex(h[i]));
        mesh.set_vertex(Mesh::twin(o(i)), c);
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        const Halfedge in = Mesh::twin(o(i + 1));  // p[i+1] -> c
        const Face t = triangle(i);
        mesh.set_next(h[i], in);
        mesh.set_next(in, o(i));
        mesh.set_next(o(i), h[i]);
        mesh.set_face(h[i], t);
        mesh.set_face(in, t);
        mesh.set_face(o(i), t);
        mesh.set_halfedge(t, h[i]);
    }
    // The corners keep their anchors: each still leaves along its old side, and boundary
    // halfedges are not touched.
    mesh.set_halfedge(c, o(0));
    // Carry: c blends the corners with the centre's weights, and f's corners blend into the
    // corner at c of every triangle; o(i) is triangle i's corner at p[i], which h[i-1] was;
    // the triangles are parts of f; the spokes are new.
    std::vector<Vertex> corners;
    std::vector<double> weights(n, 1.0 / n);
    for (const Halfedge side : h) {
        corners.push_back(mesh.from_vertex(side));
    }
    mesh.carry(c, corners.data(), weights.data(), n);
    for (std::uint32_t i = 0; i < n; ++i) {
        mesh.carry(Mesh::twin(o(i + 1)), h.data(), weights.data(), n);
        mesh.carry(o(i), h[(i + n - 1) % n]);
        mesh.carry_default(Mesh::edge(o(i)));
        if (i > 0) {
            mesh.carry(triangle(i), f);
        }
    }
    return c;
}

}  // namespace meshedit
