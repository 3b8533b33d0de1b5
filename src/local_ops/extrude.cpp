/// \file
/// Inset and extrude: a ring of quads around a face, whose inner copy shrinks towards its
/// centre and (extrude) moves along its normal. Contract (local_ops.h): the predicate is
/// checked first and a refusal leaves the mesh untouched.

#include <cmath>
#include <cstdint>
#include <vector>

#include "meshedit/core/local_ops.h"

namespace meshedit {
namespace {

// The unit normal of polygon `corners` by Newell's formula (an area-weighted average of its
// triangles' normals, right for non-planar polygons too); zero for a face without area.
Vec3 newell_normal(const std::vector<Vec3>& corners, const Vec3& centre) {
    Vec3 n{0, 0, 0};
    for (std::size_t i = 0; i < corners.size(); ++i) {
        n += cross(corners[i] - centre, corners[(i + 1) % corners.size()] - centre);
    }
    const double length = norm(n);
    return length > 0 && std::isfinite(length) ? n / length : Vec3{0, 0, 0};
}

// The inner corner q[i] (the formula above extrude_face()).
Vec3 inner_corner(const ExtrudeBase& r, std::size_t i, double shrink, const Vec3& lift) {
    return r.corners[i] + shrink * (r.centre - r.corners[i]) + lift;
}

// Every inner corner and its squared length are finite: huge amounts (a height of 1e308, a
// shrink of -1e300) would leave corners whose normals and areas overflow.
bool inner_corners_in_range(const ExtrudeBase& r, double shrink, const Vec3& lift) {
    for (std::size_t i = 0; i < r.corners.size(); ++i) {
        if (!std::isfinite(sqrnorm(inner_corner(r, i, shrink, lift)))) {
            return false;
        }
    }
    return true;
}

// The attribute carry of extrude_face(), with its names: q[i] blends the corners with the
// weights of its position's shrink towards the centre (the lift is not an attribute's);
// f's corner at q[i] (k[i-1]) and quad i-1's (up[i]) and quad i's (kt[i]) blend f's old
// corners the same way, down[i] is quad i's corner at p[i] as h[i-1] was f's; the quads are
// parts of f, the inner sides copies of the old sides, the rungs new.
void carry_extruded(Mesh& mesh, const ExtrudeBase& r, double shrink) {
    const Face f = r.f;
    const std::uint32_t first_v = r.first_vertex, first_e = r.first_edge, first_f = r.first_face;
    const std::vector<Halfedge>& h = r.sides;
    const auto n = static_cast<std::uint32_t>(h.size());
    std::vector<Vertex> p(n);
    std::vector<Halfedge> corner(n);  // f's old corner at p[i]: h[i-1]
    for (std::uint32_t i = 0; i < n; ++i) {
        p[i] = mesh.from_vertex(h[i]);
        corner[i] = h[(i + n - 1) % n];
    }
    std::vector<double> w(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const Halfedge up = Mesh::halfedge(Edge(first_e + i), 0);
        const Halfedge k_prev = Mesh::halfedge(Edge(first_e + n + (i + n - 1) % n), 0);
        const Halfedge kt = Mesh::halfedge(Edge(first_e + n + i), 1);
        for (std::uint32_t m = 0; m < n; ++m) {
            w[m] = shrink / n + (m == i ? 1.0 - shrink : 0.0);
        }
        mesh.carry(Vertex(first_v + i), p.data(), w.data(), n);
        for (const Halfedge at_q : {up, k_prev, kt}) {
            mesh.carry(at_q, corner.data(), w.data(), n);
        }
        mesh.carry(Mesh::twin(up), corner[i]);
        mesh.carry_default(Mesh::edge(up));
        mesh.carry(Edge(first_e + n + i), Mesh::edge(h[i]));
        mesh.carry(Face(first_f + i), f);
    }
}

// The lift of the inner corners: `height` along the unit Newell normal (none at height 0, so
// a face without area can be inset).
Vec3 lift_of(const ExtrudeBase& r, double height) {
    return height == 0 ? Vec3{0, 0, 0} : height * newell_normal(r.corners, r.centre);
}

// The inner corners' places and what they carry: the one code extrude_face() and an
// interactive extrude's later moves (extrude_positions()) run. \pre the amounts were checked.
void place_corners(Mesh& mesh, const ExtrudeBase& r, double height, double shrink) {
    const Vec3 lift = lift_of(r, height);
    for (std::uint32_t i = 0; i < r.corners.size(); ++i) {
        mesh.position(Vertex(r.first_vertex + i)) = inner_corner(r, i, shrink, lift);
    }
    carry_extruded(mesh, r, shrink);
}

OpStatus is_extrude_face_live(const Mesh& mesh, Face f) {
    MESHEDIT_ASSERT(mesh.is_valid(f));
    if (mesh.is_deleted(f)) {
        return OpStatus::refused("cannot extrude: the face is deleted");
    }
    return OpStatus::ok();
}

}  // namespace

ExtrudeBase extrude_base(const Mesh& mesh, Face f) {
    ExtrudeBase r;
    r.f = f;
    const std::size_t n = mesh.valence(f);
    r.sides.reserve(n);
    r.corners.reserve(n);
    for (const Halfedge side : mesh.halfedges(f)) {
        r.sides.push_back(side);
        r.corners.push_back(mesh.position(mesh.from_vertex(side)));
    }
    for (const Vec3& x : r.corners) {
        r.centre += x / static_cast<double>(r.corners.size());
    }
    r.first_vertex = static_cast<std::uint32_t>(mesh.vertices_size());
    r.first_edge = static_cast<std::uint32_t>(mesh.edges_size());
    r.first_face = static_cast<std::uint32_t>(mesh.faces_size());
    return r;
}

OpStatus is_extrude_positions_ok(const ExtrudeBase& r, double height, double shrink) {
    if (!std::isfinite(height) || !std::isfinite(shrink)) {
        return OpStatus::refused("cannot extrude: the amounts must be finite numbers");
    }
    if (shrink >= 1) {
        return OpStatus::refused("cannot extrude: shrink must be below 1 (1 is a point)");
    }
    if (height != 0 && norm(newell_normal(r.corners, r.centre)) == 0) {
        return OpStatus::refused("cannot extrude: the face has no area, so no normal");
    }
    if (!inner_corners_in_range(r, shrink, lift_of(r, height))) {
        return OpStatus::refused(
            "cannot extrude: the amounts put corners beyond the range of "
            "numbers");
    }
    return OpStatus::ok();
}

OpStatus extrude_positions(Mesh& mesh, const ExtrudeBase& r, double height, double shrink) {
    if (const OpStatus ok = is_extrude_positions_ok(r, height, shrink); !ok) {
        return ok;
    }
    place_corners(mesh, r, height, shrink);
    return OpStatus::ok();
}

OpStatus is_extrude_ok(const Mesh& mesh, Face f, double height, double shrink) {
    if (const OpStatus ok = is_extrude_face_live(mesh, f); !ok) {
        return ok;
    }
    return is_extrude_positions_ok(extrude_base(mesh, f), height, shrink);
}

OpStatus is_inset_ok(const Mesh& mesh, Face f, double shrink) {
    MESHEDIT_ASSERT(mesh.is_valid(f));
    if (mesh.is_deleted(f)) {
        return OpStatus::refused("cannot inset: the face is deleted");
    }
    if (!std::isfinite(shrink)) {
        return OpStatus::refused("cannot inset: the amount must be a finite number");
    }
    if (shrink >= 1) {
        return OpStatus::refused("cannot inset: shrink must be below 1 (1 is a point)");
    }
    if (!inner_corners_in_range(extrude_base(mesh, f), shrink, Vec3{0, 0, 0})) {
        return OpStatus::refused(
            "cannot inset: the amount puts corners beyond the range of "
            "numbers");
    }
    return OpStatus::ok();
}

// f's sides h[i] run p[i] -> p[i+1]. New: inner corners q[i], rungs up[i] = p[i] -> q[i]
// (twin down[i]), inner sides k[i] = q[i] -> q[i+1] (twin kt[i]) and quads Q[i]. f keeps its
// handle and becomes the inner face k[0] -> k[1] -> ...; quad i is
// h[i] -> up[i+1] -> kt[i] -> down[i].
//
//      p3 --------h2-------- p2          p3 ----------------- p2
//       |                    ^            | \      Q2       / ^
//       |                    |            |  q3 <--k2--- q2   |
//       h3        f         h1    =>      Q3  |    f     ^   Q1
//       |                    |            |   v          |    |
//       v                    |            |  q0 ---k0--> q1   |
//      p0 --------h0-------> p1           | /      Q0       \ |
//                                        p0 -------h0------> p1
//
// q[i] = p[i] + shrink (c - p[i]) + height n, with c the average of the corners and n the
// unit Newell normal of the face (area-weighted, exact for a planar polygon).
OpResult<Face> extrude_face(Mesh& mesh, Face f, double height, double shrink) {
    // is_extrude_ok(), with the base it takes kept for the operation.
    if (const OpStatus ok = is_extrude_face_live(mesh, f); !ok) {
        return ok;
    }
    const ExtrudeBase base = extrude_base(mesh, f);
    if (const OpStatus ok = is_extrude_positions_ok(base, height, shrink); !ok) {
        return ok;
    }
    const std::vector<Halfedge>& h = base.sides;
    const auto n = static_cast<std::uint32_t>(h.size());
    const std::uint32_t first_v = base.first_vertex, first_e = base.first_edge,
                        first_f = base.first_face;
    mesh.new_elements(n, 2 * n, n);
    const auto q = [&](std::uint32_t i) { return Vertex(first_v + i % n); };
    const auto up = [&](std::uint32_t i) { return Mesh::halfedge(Edge(first_e + i % n), 0); };
    const auto k = [&](std::uint32_t i) { return Mesh::halfedge(Edge(first_e + n + i % n), 0); };
    const auto quad = [&](std::uint32_t i) { return Face(first_f + i); };

    for (std::uint32_t i = 0; i < n; ++i) {
        mesh.set_vertex(up(i), q(i));
        mesh.set_vertex(Mesh::twin(up(i)), mesh.from_vertex(h[i]));
        mesh.set_vertex(k(i), q(i + 1));
        mesh.set_vertex(Mesh::twin(k(i)), q(i));
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        const Face g = quad(i);
        const Halfedge down = Mesh::twin(up(i));
        const Halfedge kt = Mesh::twin(k(i));
        mesh.set_next(h[i], up(i + 1));
        mesh.set_next(up(i + 1), kt);
        mesh.set_next(kt, down);
        mesh.set_next(down, h[i]);
        for (const Halfedge x : {h[i], up(i + 1), kt, down}) {
            mesh.set_face(x, g);
        }
        mesh.set_halfedge(g, h[i]);
        mesh.set_next(k(i), k(i + 1));
        mesh.set_face(k(i), f);
        mesh.set_halfedge(q(i), k(i));
    }
    mesh.set_halfedge(f, k(0));
    place_corners(mesh, base, height, shrink);  // checked above, by is_extrude_ok()
    return f;
}

OpResult<Face> inset_face(Mesh& mesh, Face f, double shrink) {
    if (const OpStatus ok = is_inset_ok(mesh, f, shrink); !ok) {
        return ok;
    }
    return extrude_face(mesh, f, 0.0, shrink);
}

}  // namespace meshedit
