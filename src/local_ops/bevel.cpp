/// \file
/// Vertex and edge bevel: the element is replaced by a new face with one corner on each edge
/// that left it, each corner a fraction `t` of the way along its edge. Contract
/// (local_ops.h): the predicate is checked first and a refusal leaves the mesh untouched.

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "meshedit/core/local_ops.h"

namespace meshedit {
namespace {

bool is_amount_ok(double t) {
    return std::isfinite(t) && t >= 0 && t < 1;
}

// What split_fan() will make, from the fan alone (BevelBase, local_ops.h).
BevelBase fan_base(const Mesh& mesh, std::vector<Halfedge> o, const std::vector<Vertex>& reuse,
                   std::vector<Vertex> from) {
    const auto count = static_cast<std::uint32_t>(o.size());
    BevelBase base;
    base.face = Face(static_cast<std::uint32_t>(mesh.faces_size()));
    base.first_edge = static_cast<std::uint32_t>(mesh.edges_size());
    base.w.resize(count);
    base.reused.resize(count);
    base.start.resize(count);
    base.at_start.resize(count);
    base.at_next.resize(count);
    base.kept_w.resize(count);
    base.kept_arriving.resize(count);
    auto next_new = static_cast<std::uint32_t>(mesh.vertices_size());
    for (std::uint32_t i = 0; i < count; ++i) {
        base.reused[i] = reuse[i].is_valid();
        base.w[i] = base.reused[i] ? reuse[i] : Vertex(next_new++);
        base.start[i] = mesh.position(from[i]);
        base.at_start[i] = mesh.prev(o[i]);
        const Halfedge arriving = Mesh::twin(o[(i + 1) % count]);
        base.at_next[i] = mesh.prev(arriving);
        if (base.reused[i]) {
            base.kept_w[i] = mesh.attribute_values(base.w[i]);
        }
        base.kept_arriving[i] = mesh.attribute_values(arriving);
    }
    base.o = std::move(o);
    base.from = std::move(from);
    return base;
}

Halfedge new_halfedge(const BevelBase& base, std::size_t i) {
    return Mesh::halfedge(Edge(base.first_edge + static_cast<std::uint32_t>(i % base.o.size())), 0);
}

// Splits a fan of outgoing halfedges apart into a new face. o[0..N) are counter-clockwise:
// between o[i] and o[i+1] lies the loop of o[i] (a face, or a boundary gap), in which
// twin(o[i+1]) comes just before o[i] (or before the edge being removed, then o[i]). Corner
// w[i] takes o[i]'s tail: a reused vertex, or a new one. In each loop i a new halfedge
// n[i] = w[i+1] -> w[i] comes between twin(o[i+1]) and o[i]; the twins of the n[i] form the
// new face B = w[0] -> w[1] -> ... . On a boundary gap n[i] is a boundary halfedge, so B has
// a side on that hole. Where the corners go and what they carry is place_fan()'s.
//
//                x1                                  x1
//                ^                                   ^
//          f1    | o[1]     f0                 f1    | o[1]     f0
//                |                                   w1
//      x2 <----- v -----> x0        =>     x2 <- w2 /  B  \ w0 -> x0     n[i]: w[i+1] -> w[i]
//          o[2]  |  o[0]                         \  /          o[0]     in loop i (f_i);
//          f2    | o[3]    f3                     w3                    twin(n[i]) in B
//                v                                   | o[3]
//                x3                                  x3
void split_fan(Mesh& mesh, const BevelBase& base) {
    const std::vector<Halfedge>& o = base.o;
    const std::vector<Vertex>& w = base.w;
    const auto count = static_cast<std::uint32_t>(o.size());
    std::vector<Face> loop(count);
    std::uint32_t fresh = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        loop[i] = mesh.face(o[i]);
        fresh += base.reused[i] ? 0 : 1;
    }
    mesh.new_elements(fresh, count, 1);
    const auto n = [&](std::uint32_t i) { return new_halfedge(base, i); };
    for (std::uint32_t i = 0; i < count; ++i) {
        const Halfedge ni = n(i);
        const Halfedge mi = Mesh::twin(ni);
        mesh.set_vertex(Mesh::twin(o[i]), w[i]);
        mesh.set_vertex(ni, w[i]);
        mesh.set_vertex(mi, w[(i + 1) % count]);
        mesh.set_next(Mesh::twin(o[(i + 1) % count]), ni);
        mesh.set_next(ni, o[i]);
        mesh.set_face(ni, loop[i]);
        if (loop[i].is_valid()) {
            mesh.set_halfedge(loop[i], ni);
        }
        mesh.set_next(mi, Mesh::twin(n(i + 1)));
        mesh.set_face(mi, base.face);
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        // w[i] leaves along o[i] and along n[i-1]; the latter is its boundary halfedge when
        // the loop before o[i] is a gap (when o[i]'s own loop is, o[i] is).
        const Halfedge before = n(i + count - 1);
        mesh.set_halfedge(w[i], mesh.is_boundary(before) ? before : o[i]);
    }
    mesh.set_halfedge(base.face, Mesh::twin(n(0)));
}

// Each w[i] goes to start[i] + t (head of o[i] - start[i]), and the carry uses the weights of
// the positions: w[i] lies at t along from[i] -> to_vertex(o[i]), and so do its corners: n[i]
// in loop i, and twin(o[i+1]), now loop i's corner at w[i+1], blends towards
// to_vertex(o[i+1]). B's corners copy the loops' n[i]; B is a part of the first face around.
// New vertices first: a reused one is a source of the others.
void place_fan(Mesh& mesh, const BevelBase& base, double t) {
    const std::vector<Halfedge>& o = base.o;
    const auto count = static_cast<std::uint32_t>(o.size());
    for (std::uint32_t i = 0; i < count; ++i) {
        const Vec3 rail_end = mesh.position(mesh.to_vertex(o[i]));
        mesh.position(base.w[i]) = base.start[i] + t * (rail_end - base.start[i]);
    }
    for (const bool reused : {false, true}) {
        for (std::uint32_t i = 0; i < count; ++i) {
            if (base.reused[i] == reused) {
                mesh.carry(base.w[i], {{base.from[i], 1.0 - t}, {mesh.to_vertex(o[i]), t}});
            }
        }
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        mesh.carry(new_halfedge(base, i), {{base.at_start[i], 1.0 - t}, {o[i], t}});
        mesh.carry_default(Edge(base.first_edge + i));
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        const Halfedge arriving = Mesh::twin(o[(i + 1) % count]);
        mesh.carry(arriving, {{arriving, 1.0 - t}, {base.at_next[i], t}});
        mesh.carry(Mesh::twin(new_halfedge(base, i)), new_halfedge(base, i + 1));
    }
    Face around;
    for (const Halfedge h : o) {
        around = around.is_valid() ? around : mesh.face(h);
    }
    if (around.is_valid()) {
        mesh.carry(base.face, around);
    } else {
        mesh.carry_default(base.face);
    }
}

}  // namespace

OpStatus is_bevel_vertex_ok(const Mesh& mesh, Vertex v, double t) {
    MESHEDIT_ASSERT(mesh.is_valid(v));
    if (mesh.is_deleted(v)) {
        return OpStatus::refused("cannot bevel: the vertex is deleted");
    }
    if (!is_amount_ok(t)) {
        return OpStatus::refused("cannot bevel: the amount must be at least 0 and below 1");
    }
    if (mesh.is_isolated(v) || mesh.valence(v) < 3) {
        return OpStatus::refused("cannot bevel: the new face would have fewer than 3 corners");
    }
    return OpStatus::ok();
}

// The fan is every outgoing halfedge of v; v itself becomes the corner on halfedge(v).
BevelBase bevel_vertex_base(const Mesh& mesh, Vertex v) {
    std::vector<Halfedge> o;
    for (const Halfedge h : mesh.halfedges(v)) {
        o.push_back(h);
    }
    std::vector<Vertex> reuse(o.size());
    reuse[0] = v;
    std::vector<Vertex> from(o.size(), v);
    return fan_base(mesh, std::move(o), reuse, std::move(from));
}

OpResult<Face> bevel_vertex(Mesh& mesh, Vertex v, double t) {
    if (const OpStatus ok = is_bevel_vertex_ok(mesh, v, t); !ok) {
        return ok;
    }
    const BevelBase base = bevel_vertex_base(mesh, v);
    split_fan(mesh, base);
    place_fan(mesh, base, t);
    return base.face;
}

OpStatus is_bevel_edge_ok(const Mesh& mesh, Edge e, double t) {
    MESHEDIT_ASSERT(mesh.is_valid(e));
    if (mesh.is_deleted(e)) {
        return OpStatus::refused("cannot bevel: the edge is deleted");
    }
    if (!is_amount_ok(t)) {
        return OpStatus::refused("cannot bevel: the amount must be at least 0 and below 1");
    }
    if (mesh.valence(mesh.vertex(e, 0)) + mesh.valence(mesh.vertex(e, 1)) < 5) {
        return OpStatus::refused("cannot bevel: the new face would have fewer than 3 corners");
    }
    return OpStatus::ok();
}

// e = a-b, h = a -> b, t = b -> a. The fan is a's outgoing halfedges after h (counter-
// clockwise, up to the one before h), then b's after t: the fan of the vertex a and b would
// be if e were collapsed. e goes; a and b become the corners on ccw(h) and ccw(t).
//
//      x ------ a ------ y              x --- wa1       wam --- y
//               |                             |  \     /  |
//          f    h ^ t   g       =>        f   |    B      |   g      (B between a's and
//               v |                           |  /     \  |           b's corners)
//      z ------ b ------ u              z --- wb       wbk --- u
BevelBase bevel_edge_base(const Mesh& mesh, Edge e) {
    const Halfedge h = Mesh::halfedge(e, 0);
    const Halfedge t = Mesh::twin(h);
    const Vertex a = mesh.from_vertex(h);
    const Vertex b = mesh.to_vertex(h);
    std::vector<Halfedge> o;
    std::vector<Vertex> reuse;
    std::vector<Vertex> from;
    for (const auto& [around, end] : {std::pair{h, a}, std::pair{t, b}}) {
        for (Halfedge x = mesh.ccw_rotated(around); x != around; x = mesh.ccw_rotated(x)) {
            reuse.push_back(x == mesh.ccw_rotated(around) ? end : Vertex());
            o.push_back(x);
            from.push_back(end);
        }
    }
    return fan_base(mesh, std::move(o), reuse, std::move(from));
}

OpResult<Face> bevel_edge(Mesh& mesh, Edge e, double amount) {
    if (const OpStatus ok = is_bevel_edge_ok(mesh, e, amount); !ok) {
        return ok;
    }
    const BevelBase base = bevel_edge_base(mesh, e);
    split_fan(mesh, base);
    place_fan(mesh, base, amount);
    mesh.mark_deleted(e);
    return base.face;
}

OpStatus is_bevel_positions_ok(const BevelBase&, double t) {
    if (!is_amount_ok(t)) {
        return OpStatus::refused("cannot bevel: the amount must be at least 0 and below 1");
    }
    return OpStatus::ok();
}

// The carry blended the reused corners and the faces' corners at the old corners in place:
// their values from before come back first, so the blends start from what the bevel saw.
OpStatus bevel_positions(Mesh& mesh, const BevelBase& base, double t) {
    if (const OpStatus ok = is_bevel_positions_ok(base, t); !ok) {
        return ok;
    }
    const std::size_t count = base.o.size();
    for (std::size_t i = 0; i < count; ++i) {
        if (base.reused[i]) {
            mesh.set_attribute_values(base.w[i], base.kept_w[i]);
        }
        mesh.set_attribute_values(Mesh::twin(base.o[(i + 1) % count]), base.kept_arriving[i]);
    }
    place_fan(mesh, base, t);
    return OpStatus::ok();
}

}  // namespace meshedit
