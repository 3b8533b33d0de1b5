// Catmull-Clark one phase at a time (cc_steps.h), made of the verified local operations
// (poke, split, dissolve_edge) and catmark_rules.h's weights, so that the four phases make
// what quad_subdivide() makes; the tests hold them to it.

#include "meshedit/core/cc_steps.h"

#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/catmark_rules.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/loop_steps.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/validate.h"

namespace meshedit {
namespace {

using Flags = VertexProperty<std::uint8_t>;

bool flagged(const Flags& flags, Vertex v) {
    return flags && flags[v] != 0;
}

// 1. Poke every face: the new vertex sits at the centroid, the face point.
std::size_t poke_faces(Mesh& mesh) {
    std::vector<Face> faces;
    for (const Face f : mesh.faces()) {
        faces.push_back(f);
    }
    auto face_point = mesh.property<Vertex, std::uint8_t>(kCcFacePoint, 0);
    for (const Face f : faces) {
        const OpResult<Vertex> v = poke(mesh, f);
        MESHEDIT_ASSERT(v.ok());
        face_point[*v] = 1;
    }
    return faces.size();
}

// 2. Split every old edge (one joining two old vertices) and move the new vertex to the
//    edge point. Split joins it to the two face points across the edge, as the quads will.
std::size_t split_edges(Mesh& mesh) {
    const Flags face_point = mesh.get_property<Vertex, std::uint8_t>(kCcFacePoint);
    const EdgeProperty<std::uint8_t> crease = loop_rules::crease_property(mesh);
    struct Old {
        Edge e;
        Vec3 point;
    };
    std::vector<Old> old;
    for (const Edge e : mesh.edges()) {
        const Vertex a = mesh.vertex(e, 0), b = mesh.vertex(e, 1);
        if (flagged(face_point, a) || flagged(face_point, b)) {
            continue;
        }
        const bool sharp = loop_rules::is_sharp(mesh.is_boundary(e), crease ? crease[e] : 0);
        // The face points across the edge: the third corners of its two triangles.
        Vec3 f[2];
        for (int side = 0; side < 2; ++side) {
            const Halfedge h = Mesh::halfedge(e, side);
            if (!mesh.is_boundary(h)) {
                f[side] = mesh.position(mesh.to_vertex(mesh.next(h)));
            }
        }
        old.push_back(
            {e, catmark_rules::edge_point(QuadScheme::CatmullClark, sharp, mesh.position(a),
                                          mesh.position(b), f[0], f[1])});
    }
    auto edge_point = mesh.property<Vertex, std::uint8_t>(kCcEdgePoint, 0);
    for (const Old& o : old) {
        const OpResult<Vertex> m = split(mesh, o.e);
        MESHEDIT_ASSERT(m.ok());
        mesh.position(*m) = o.point;
        edge_point[*m] = 1;
    }
    return old.size();
}

// 3. Move every old vertex to its vertex point, all computed before any moves.
std::size_t move_vertices(Mesh& mesh) {
    const Flags face_point = mesh.get_property<Vertex, std::uint8_t>(kCcFacePoint);
    const Flags edge_point = mesh.get_property<Vertex, std::uint8_t>(kCcEdgePoint);
    const EdgeProperty<std::uint8_t> crease = loop_rules::crease_property(mesh);
    std::vector<std::pair<Vertex, Vec3>> moves;
    for (const Vertex v : mesh.vertices()) {
        if (flagged(face_point, v) || flagged(edge_point, v)) {
            continue;
        }
        catmark_rules::Ring ring;
        for (const Halfedge h : mesh.halfedges(v)) {
            const Vertex w = mesh.to_vertex(h);
            if (flagged(face_point, w)) {
                ring.face_point_sum += mesh.position(w);
                continue;
            }
            // An edge point: the old edge's far end is its other old neighbour.
            Vertex far = v;
            for (const Vertex u : mesh.vertices(w)) {
                if (u != v && !flagged(face_point, u) && !flagged(edge_point, u)) {
                    far = u;
                }
            }
            const Vec3 q = mesh.position(far);
            ring.neighbour_sum += q;
            ++ring.valence;
            if (loop_rules::is_sharp(mesh.is_boundary(Mesh::edge(h)),
                                     crease ? crease[Mesh::edge(h)] : 0)) {
                ring.sharp_sum += q;
                ++ring.n_sharp;
            }
        }
        moves.emplace_back(
            v, catmark_rules::vertex_point(QuadScheme::CatmullClark, mesh.position(v), ring));
    }
    for (const auto& [v, p] : moves) {
        mesh.position(v) = p;
    }
    mesh.property<Vertex, std::uint8_t>(kCcMoved, 1);
    return moves.size();
}

// 4. Dissolve every edge from a face point to an old vertex: each pair of triangles beside
//    it becomes one quad (old vertex, edge point, face point, edge point).
std::size_t reconnect(Mesh& mesh) {
    const Flags face_point = mesh.get_property<Vertex, std::uint8_t>(kCcFacePoint);
    const Flags edge_point = mesh.get_property<Vertex, std::uint8_t>(kCcEdgePoint);
    std::vector<Edge> spokes;
    for (const Edge e : mesh.edges()) {
        const Vertex a = mesh.vertex(e, 0), b = mesh.vertex(e, 1);
        const bool a_old = !flagged(face_point, a) && !flagged(edge_point, a);
        const bool b_old = !flagged(face_point, b) && !flagged(edge_point, b);
        if ((flagged(face_point, a) && b_old) || (flagged(face_point, b) && a_old)) {
            spokes.push_back(e);
        }
    }
    for (const Edge e : spokes) {
        const OpResult<Face> f = dissolve_edge(mesh, e);
        MESHEDIT_ASSERT(f.ok());
    }
    for (const char* name : {kCcFacePoint, kCcEdgePoint, kCcMoved}) {
        if (auto p = mesh.get_property<Vertex, std::uint8_t>(name)) {
            mesh.remove_property(p);
        }
    }
    mesh.garbage_collection();  // dissolving left tombstones; the result is dense, as CC's
    return spokes.size();
}

}  // namespace

int next_cc_phase(const Mesh& mesh) {
    if (mesh.has_property<Vertex>(kCcMoved)) {
        return 4;
    }
    if (mesh.has_property<Vertex>(kCcEdgePoint)) {
        return 3;
    }
    if (mesh.has_property<Vertex>(kCcFacePoint)) {
        return 2;
    }
    return 1;
}

OpStatus check_cc_step(const Mesh& mesh) {
    if (next_cc_phase(mesh) != 1) {
        return OpStatus::ok();
    }
    if (next_loop_phase(mesh) != 1) {
        return OpStatus::refused("cannot step Catmull-Clark: a phased Loop is under way");
    }
    if (mesh.n_faces() == 0) {
        return OpStatus::refused("cannot step Catmull-Clark: the mesh has no faces");
    }
    return plan_quad_subdivision(mesh, 1).status;
}

CcStepReport cc_step(Mesh& mesh) {
    MESHEDIT_ASSERT(check_cc_step(mesh));
    CcStepReport report;
    report.phase = next_cc_phase(mesh);
    switch (report.phase) {
        case 1:
            report.count = poke_faces(mesh);
            report.message = "Catmull-Clark 1/4: a face point at the centre of each of " +
                             std::to_string(report.count) + " faces, joined to its corners";
            break;
        case 2:
            report.count = split_edges(mesh);
            report.message = "Catmull-Clark 2/4: split " + std::to_string(report.count) +
                             " edges at their edge points (ends and face points averaged)";
            break;
        case 3:
            report.count = move_vertices(mesh);
            report.message = "Catmull-Clark 3/4: moved " + std::to_string(report.count) +
                             " old vertices to their vertex points";
            break;
        default:
            report.count = reconnect(mesh);
            report.message = "Catmull-Clark 4/4: dissolved " + std::to_string(report.count) +
                             " edges from face points to old vertices: quads";
            break;
    }
    MESHEDIT_ASSERT(!validate(mesh));
    return report;
}

}  // namespace meshedit
