// Mesh <-> student::HalfedgeMesh. The student's mesh numbers elements as the Mesh does, so a
// handle a student holds names the same element on both sides; boundary loops are extra
// faces after the Mesh's, since the course gives every halfedge a face.

#include "grade_bridge.h"

#include <stdexcept>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"

namespace meshedit::cli::grade {
namespace {

st::Vector3D to_student(const Vec3& p) {
    return {p.x, p.y, p.z};
}

template <class T>
bool usable(st::HalfedgeMesh& m, const st::ElementIter<T>& it) {
    return it.isSet() && static_cast<std::size_t>(it.index()) < m.list<T>().size() &&
           !m.list<T>()[static_cast<std::size_t>(it.index())].deleted;
}

template <class T>
const char* state(st::HalfedgeMesh& m, const st::ElementIter<T>& it) {
    if (!it.isSet()) {
        return "unset";
    }
    return static_cast<std::size_t>(it.index()) < m.list<T>().size() ? "deleted" : "out of range";
}

BridgeError error(const char* invariant, std::string message) {
    return {invariant, std::move(message)};
}

std::string hname(int i) {
    return i < 0 ? std::string("unset") : "halfedge " + std::to_string(i);
}

// The rules the write-back needs, in the course's terms; the first broken one.
BridgeError check(st::HalfedgeMesh& m, std::size_t old_edges) {
    for (std::size_t i = 0; i < m.halfedges.size(); ++i) {
        st::Halfedge& h = m.halfedges[i];
        if (h.deleted) {
            continue;
        }
        const std::string name = hname(static_cast<int>(i));
        if (!usable(m, h.twin())) {
            return error("twin", name + "'s twin is " + state(m, h.twin()));
        }
        if (h.twin()->twin().index() != static_cast<int>(i)) {
            return error("twin", name + "'s twin is " + hname(h.twin().index()) +
                                     ", whose twin is " + hname(h.twin()->twin().index()) +
                                     ", not " + name);
        }
        if (!usable(m, h.next())) {
            return error("next", name + "'s next is " + state(m, h.next()));
        }
        if (!usable(m, h.vertex())) {
            return error("vertex", name + "'s vertex is " + state(m, h.vertex()));
        }
        if (!usable(m, h.face())) {
            return error("face", name + "'s face is " + state(m, h.face()));
        }
        if (!usable(m, h.edge())) {
            return error("edge", name + "'s edge is " + state(m, h.edge()));
        }
        if (h.edge() != h.twin()->edge()) {
            return error("edge", name + " is on edge " + std::to_string(h.edge().index()) +
                                     " but its twin on edge " +
                                     std::to_string(h.twin()->edge().index()));
        }
        const st::HalfedgeIter g = h.edge()->halfedge();
        if (g.index() != static_cast<int>(i) && g.index() != h.twin().index()) {
            return error("edge", name + " says it is on edge " + std::to_string(h.edge().index()) +
                                     ", whose halfedge is " + hname(g.index()));
        }
    }
    for (std::size_t e = 0; e < m.edges.size(); ++e) {
        st::Edge& edge = m.edges[e];
        if (edge.deleted) {
            continue;
        }
        const std::string name = "edge " + std::to_string(e);
        if (!usable(m, edge.halfedge())) {
            return error("edge", name + "'s halfedge is " + state(m, edge.halfedge()));
        }
        if (edge.halfedge()->edge().index() != static_cast<int>(e)) {
            return error("edge", name + "'s halfedge " + hname(edge.halfedge().index()) +
                                     " is on edge " +
                                     std::to_string(edge.halfedge()->edge().index()));
        }
        // MeshEdit's halfedges 2e and 2e+1 are edge e's for good.
        const int a = edge.halfedge().index(), b = edge.halfedge()->twin().index();
        if (e < old_edges && !((a == int(2 * e) && b == int(2 * e + 1)) ||
                               (a == int(2 * e + 1) && b == int(2 * e)))) {
            return error("edge", name + " now holds " + hname(a) + " and " + hname(b) +
                                     "; an edge keeps the two halfedges it had (give new "
                                     "halfedges a new edge)");
        }
    }
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        st::Face& face = m.faces[f];
        if (!face.deleted && !face.isBoundary() && !usable(m, face.halfedge())) {
            return error("face", "face " + std::to_string(f) + "'s halfedge is " +
                                     state(m, face.halfedge()));
        }
    }
    return {};
}

// A boundary vertex is anchored at its outgoing boundary halfedge in MeshEdit; the course
// lets a vertex keep any outgoing halfedge.
void reanchor(Mesh& mesh) {
    for (const Vertex v : mesh.vertices()) {
        const Halfedge start = mesh.halfedge(v);
        if (!start.is_valid() || !mesh.is_valid(start) || mesh.from_vertex(start) != v) {
            continue;
        }
        Halfedge h = start;
        for (int i = 0; i < 4096; ++i) {
            if (mesh.is_boundary(h)) {
                if (h != start) {
                    mesh.set_halfedge(v, h);
                }
                break;
            }
            const Halfedge p = mesh.prev(h);
            if (!p.is_valid() || !mesh.is_valid(p)) {
                break;
            }
            h = Mesh::twin(p);
            if (h == start || mesh.from_vertex(h) != v) {
                break;
            }
        }
    }
}

}  // namespace

void copy_in(const Mesh& mesh, st::HalfedgeMesh& out) {
    if (mesh.has_garbage()) {
        throw std::logic_error("copy_in: the mesh has deleted elements");
    }
    st::HalfedgeMesh* m = &out;
    out.halfedges.resize(mesh.halfedges_size());
    out.vertices.resize(mesh.vertices_size());
    out.edges.resize(mesh.edges_size());
    out.faces.clear();
    out.faces.resize(mesh.faces_size());
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    for (const Vertex v : mesh.vertices()) {
        st::Vertex& x = out.vertices[v.idx()];
        x.deleted = false;  // isNew and newPosition stay: upsample()'s scratch
        x.position = to_student(mesh.position(v));
        const Halfedge h = mesh.halfedge(v);
        x.halfedge() = h.is_valid() ? st::HalfedgeIter(m, int(h.idx())) : st::HalfedgeIter();
    }
    for (const Edge e : mesh.edges()) {
        st::Edge& x = out.edges[e.idx()];
        x.deleted = false;
        x.isCrease = crease && crease[e] != 0;
        // Odd edges name their second halfedge, so a student cannot rely on an edge's
        // halfedge being the one with a face (as the course promises nothing of the kind).
        x.halfedge() = st::HalfedgeIter(m, int(2 * e.idx() + (e.idx() & 1u)));
    }
    for (const Face f : mesh.faces()) {
        out.faces[f.idx()].halfedge() = st::HalfedgeIter(m, int(mesh.halfedge(f).idx()));
    }
    std::vector<int> loop_face(mesh.halfedges_size(), -1);
    for (const Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h) && loop_face[h.idx()] < 0) {
            const int f = int(out.faces.size());
            out.newFace()->halfedge() = st::HalfedgeIter(m, int(h.idx()));
            st::HalfedgeMesh::set_boundary(out.faces.back(), true);
            for (const Halfedge g : mesh.loop(h)) {
                loop_face[g.idx()] = f;
            }
        }
    }
    for (const Halfedge h : mesh.halfedges()) {
        st::Halfedge& x = out.halfedges[h.idx()];
        x.deleted = false;
        const Face f = mesh.face(h);
        x.setNeighbors(st::HalfedgeIter(m, int(mesh.next(h).idx())),
                       st::HalfedgeIter(m, int(Mesh::twin(h).idx())),
                       st::VertexIter(m, int(mesh.from_vertex(h).idx())),
                       st::EdgeIter(m, int(Mesh::edge(h).idx())),
                       st::FaceIter(m, f.is_valid() ? int(f.idx()) : loop_face[h.idx()]));
    }
}

BridgeError copy_out(st::HalfedgeMesh& in, Mesh& mesh) {
    const std::size_t nv0 = mesh.vertices_size(), ne0 = mesh.edges_size();
    const std::size_t nf0 = mesh.faces_size();
    if (BridgeError e = check(in, ne0); !e.invariant.empty()) {
        return e;
    }
    // Where each of the student's elements lands: old ones keep their index, new live ones
    // are appended in the student's order, boundary loops are no face.
    std::vector<Vertex> vmap(in.vertices.size());
    std::vector<Face> fmap(in.faces.size());
    std::vector<Halfedge> hmap(in.halfedges.size());
    std::size_t nv = nv0, ne = ne0, nf = nf0;
    for (std::size_t i = 0; i < in.vertices.size(); ++i) {
        if (i < nv0 || !in.vertices[i].deleted) {
            vmap[i] = Vertex(std::uint32_t(i < nv0 ? i : nv++));
        }
    }
    for (std::size_t i = 0; i < in.faces.size(); ++i) {
        const st::Face& f = in.faces[i];
        if (!f.isBoundary() && (i < nf0 || !f.deleted)) {
            fmap[i] = Face(std::uint32_t(i < nf0 ? i : nf++));
        }
    }
    for (std::size_t e = 0; e < in.edges.size(); ++e) {
        st::Edge& edge = in.edges[e];
        if (e < ne0) {
            hmap[2 * e] = Halfedge(std::uint32_t(2 * e));
            hmap[2 * e + 1] = Halfedge(std::uint32_t(2 * e + 1));
        } else if (!edge.deleted) {
            const std::uint32_t k = std::uint32_t(ne++);
            const st::HalfedgeIter h = edge.halfedge();
            hmap[std::size_t(h.index())] = Halfedge(2 * k);
            hmap[std::size_t(h->twin().index())] = Halfedge(2 * k + 1);
        }
    }
    mesh.new_elements(nv - nv0, ne - ne0, nf - nf0);
    for (std::size_t i = nv0; i < nv; ++i) {
        mesh.carry_default(Vertex(std::uint32_t(i)));
    }
    for (std::size_t i = ne0; i < ne; ++i) {
        mesh.carry_default(Edge(std::uint32_t(i)));
        mesh.carry_default(Halfedge(std::uint32_t(2 * i)));
        mesh.carry_default(Halfedge(std::uint32_t(2 * i + 1)));
    }
    for (std::size_t i = nf0; i < nf; ++i) {
        mesh.carry_default(Face(std::uint32_t(i)));
    }

    for (std::size_t i = 0; i < in.halfedges.size(); ++i) {
        st::Halfedge& h = in.halfedges[i];
        if (h.deleted || !hmap[i].is_valid()) {
            continue;
        }
        const Halfedge g = hmap[i];
        mesh.set_next(g, hmap[std::size_t(h.next().index())]);
        mesh.set_vertex(Mesh::twin(g), vmap[std::size_t(h.vertex().index())]);
        mesh.set_face(g, fmap[std::size_t(h.face().index())]);
    }
    for (std::size_t i = 0; i < in.vertices.size(); ++i) {
        st::Vertex& v = in.vertices[i];
        if (!vmap[i].is_valid()) {
            continue;
        }
        if (v.deleted) {
            mesh.mark_deleted(vmap[i]);
            continue;
        }
        const st::HalfedgeIter h = v.halfedge();
        mesh.set_halfedge(vmap[i], usable(in, h) ? hmap[std::size_t(h.index())] : Halfedge());
        mesh.position(vmap[i]) = Vec3(v.position.x, v.position.y, v.position.z);
    }
    for (std::size_t e = 0; e < ne0; ++e) {
        if (in.edges[e].deleted) {
            mesh.mark_deleted(Edge(std::uint32_t(e)));
        }
    }
    for (std::size_t i = 0; i < in.faces.size(); ++i) {
        st::Face& f = in.faces[i];
        if (!fmap[i].is_valid()) {
            continue;
        }
        if (f.deleted) {
            mesh.mark_deleted(fmap[i]);
        } else {
            mesh.set_halfedge(fmap[i], hmap[std::size_t(f.halfedge().index())]);
        }
    }
    reanchor(mesh);
    return {};
}

namespace {

struct Bound {
    Mesh* mesh;
};

// Writes the student's mesh back before a MeshEdit operation; a broken structure cannot be
// operated on, so it stops the student's call with the rule it breaks.
void write_back(st::HalfedgeMesh& student, Mesh& mesh, const char* op) {
    if (const BridgeError e = copy_out(student, mesh); !e.invariant.empty()) {
        throw std::logic_error(std::string("before ") + op + ": invariant " + e.invariant + ": " +
                               e.message);
    }
    if (mesh.has_garbage()) {
        throw std::logic_error(std::string("before ") + op +
                               ": elements were deleted (upsample() should only flip and split)");
    }
}

st::EdgeIter flip_bound(st::HalfedgeMesh& student, st::EdgeIter e) {
    Mesh& mesh = *static_cast<Bound*>(student.ops_->context)->mesh;
    write_back(student, mesh, "flipEdge");
    (void)flip(mesh, Edge(std::uint32_t(e.index())));
    copy_in(mesh, student);
    return e;
}

st::VertexIter split_bound(st::HalfedgeMesh& student, st::EdgeIter e) {
    Mesh& mesh = *static_cast<Bound*>(student.ops_->context)->mesh;
    write_back(student, mesh, "splitEdge");
    const OpResult<Vertex> m = split(mesh, Edge(std::uint32_t(e.index())));
    copy_in(mesh, student);
    return m ? st::VertexIter(&student, int(m.value().idx())) : st::VertexIter();
}

}  // namespace

void bind_operations(st::HalfedgeMesh& student, Mesh& mesh, st::HalfedgeMesh::Operations& ops) {
    static thread_local Bound bound;  // one student call at a time per process
    bound.mesh = &mesh;
    ops.flip = &flip_bound;
    ops.split = &split_bound;
    ops.context = &bound;
    student.ops_ = &ops;
}

}  // namespace meshedit::cli::grade
