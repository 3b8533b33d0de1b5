// Mesh <-> student::HalfedgeMesh. The student's mesh numbers elements as the Mesh does, so a
// handle a student holds names the same element on both sides; boundary loops are extra
// faces after the Mesh's, since the course gives every halfedge a face.

#include "grade_bridge.h"

#include <algorithm>
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

BridgeError error(const char* invariant, ElementRef at, std::string message) {
    return {invariant, std::move(message), at};
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
        const ElementRef at = ElementRef::halfedge(Halfedge(std::uint32_t(i)));
        if (!usable(m, h.twin())) {
            return error("twin", at, name + "'s twin is " + state(m, h.twin()));
        }
        if (h.twin()->twin().index() != static_cast<int>(i)) {
            return error("twin", at,
                         name + "'s twin is " + hname(h.twin().index()) + ", whose twin is " +
                             hname(h.twin()->twin().index()) + ", not " + name);
        }
        if (!usable(m, h.next())) {
            return error("next", at, name + "'s next is " + state(m, h.next()));
        }
        if (!usable(m, h.vertex())) {
            return error("vertex", at, name + "'s vertex is " + state(m, h.vertex()));
        }
        if (!usable(m, h.face())) {
            return error("face", at, name + "'s face is " + state(m, h.face()));
        }
        if (!usable(m, h.edge())) {
            return error("edge", at, name + "'s edge is " + state(m, h.edge()));
        }
        if (h.edge() != h.twin()->edge()) {
            return error("edge", at,
                         name + " is on edge " + std::to_string(h.edge().index()) +
                             " but its twin on edge " + std::to_string(h.twin()->edge().index()));
        }
        const st::HalfedgeIter g = h.edge()->halfedge();
        if (g.index() != static_cast<int>(i) && g.index() != h.twin().index()) {
            return error("edge", at,
                         name + " says it is on edge " + std::to_string(h.edge().index()) +
                             ", whose halfedge is " + hname(g.index()));
        }
    }
    for (std::size_t e = 0; e < m.edges.size(); ++e) {
        st::Edge& edge = m.edges[e];
        if (edge.deleted) {
            continue;
        }
        const std::string name = "edge " + std::to_string(e);
        const ElementRef at = ElementRef::edge(Edge(std::uint32_t(e)));
        if (!usable(m, edge.halfedge())) {
            return error("edge", at, name + "'s halfedge is " + state(m, edge.halfedge()));
        }
        if (edge.halfedge()->edge().index() != static_cast<int>(e)) {
            return error("edge", at,
                         name + "'s halfedge " + hname(edge.halfedge().index()) + " is on edge " +
                             std::to_string(edge.halfedge()->edge().index()));
        }
        // MeshEdit's halfedges 2e and 2e+1 are edge e's for good.
        const int a = edge.halfedge().index(), b = edge.halfedge()->twin().index();
        if (e < old_edges && !((a == int(2 * e) && b == int(2 * e + 1)) ||
                               (a == int(2 * e + 1) && b == int(2 * e)))) {
            return error("edge", at,
                         name + " now holds " + hname(a) + " and " + hname(b) +
                             "; an edge keeps the two halfedges it had (give new "
                             "halfedges a new edge)");
        }
    }
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        st::Face& face = m.faces[f];
        if (!face.deleted && !face.isBoundary() && !usable(m, face.halfedge())) {
            return error(
                "face", ElementRef::face(Face(std::uint32_t(f))),
                "face " + std::to_string(f) + "'s halfedge is " + state(m, face.halfedge()));
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

// upsample() calls flipEdge() and splitEdge() once per edge, so each call updates only what
// the operation touched (a full copy each time made Loop quadratic: 40 s on the teapot). The
// Mesh follows the student's mesh through these calls alone; what the student wrote besides
// them is written back once at the end (copy_out()).
struct Bound {
    Mesh* mesh;
    // The first index of the boundary-loop faces in the student's list: real faces are below.
    std::size_t loops_from = 0;
};

Bound& bound_of(st::HalfedgeMesh& student) {
    return *static_cast<Bound*>(student.ops_->context);
}

// Moves the boundary-loop faces past `n` when new real faces are about to reach them (to twice
// the size, so moves are rare); the slots left behind are deleted placeholders.
void make_room(st::HalfedgeMesh& student, Bound& b, std::size_t n) {
    if (n <= b.loops_from) {
        return;
    }
    const std::size_t from = b.loops_from, loops = student.faces.size() - from;
    const std::size_t to = std::max(2 * n, from + loops);
    student.faces.resize(to + loops);
    for (std::size_t k = 0; k < loops; ++k) {
        st::Face& old = student.faces[from + k];
        st::Face& moved = student.faces[to + k];
        moved = old;
        old = st::Face();
        old.deleted = true;
        const st::HalfedgeIter start = moved.halfedge();
        st::HalfedgeIter h = start;
        do {
            h->face() = st::FaceIter(&student, int(to + k));
            h = h->next();
        } while (h != start);
    }
    for (std::size_t k = from; k < to; ++k) {
        student.faces[k].deleted = true;
    }
    b.loops_from = to;
}

// Copies halfedge `h` of the mesh into the student's, with its vertex's and face's anchors.
// `old_halfedges`: halfedges below it were there before the operation, so a boundary one
// already has its loop's face.
void refresh(const Mesh& mesh, st::HalfedgeMesh& student, Halfedge h, std::size_t old_halfedges) {
    st::HalfedgeMesh* m = &student;
    st::Halfedge& x = student.halfedges[h.idx()];
    const Face f = mesh.face(h);
    st::FaceIter face;
    if (f.is_valid()) {
        face = st::FaceIter(m, int(f.idx()));
        student.faces[f.idx()].deleted = false;
        student.faces[f.idx()].halfedge() = st::HalfedgeIter(m, int(mesh.halfedge(f).idx()));
    } else {
        Halfedge g = h;  // a new boundary halfedge joins the loop of an old one
        while (g.idx() >= old_halfedges) {
            g = mesh.next(g);
        }
        face = student.halfedges[g.idx()].face();
    }
    x.deleted = false;
    x.setNeighbors(st::HalfedgeIter(m, int(mesh.next(h).idx())),
                   st::HalfedgeIter(m, int(Mesh::twin(h).idx())),
                   st::VertexIter(m, int(mesh.from_vertex(h).idx())),
                   st::EdgeIter(m, int(Mesh::edge(h).idx())), face);
    const Vertex v = mesh.from_vertex(h);
    student.vertices[v.idx()].halfedge() = st::HalfedgeIter(m, int(mesh.halfedge(v).idx()));
}

// Grows the student's lists to the mesh's after an operation that appended elements.
void grow(const Mesh& mesh, st::HalfedgeMesh& student, Bound& b) {
    st::HalfedgeMesh* m = &student;
    const std::size_t v0 = student.vertices.size(), e0 = student.edges.size();
    make_room(student, b, mesh.faces_size());
    student.vertices.resize(mesh.vertices_size());
    student.edges.resize(mesh.edges_size());
    student.halfedges.resize(mesh.halfedges_size());
    for (std::size_t i = v0; i < mesh.vertices_size(); ++i) {
        student.vertices[i].position = to_student(mesh.position(Vertex(std::uint32_t(i))));
    }
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    for (std::size_t i = e0; i < mesh.edges_size(); ++i) {
        const Edge e{std::uint32_t(i)};
        student.edges[i].halfedge() = st::HalfedgeIter(m, int(2 * i + (i & 1u)));
        student.edges[i].isCrease = crease && crease[e] != 0;
    }
}

st::EdgeIter flip_bound(st::HalfedgeMesh& student, st::EdgeIter e) {
    Mesh& mesh = *bound_of(student).mesh;
    const Edge edge(std::uint32_t(e.index()));
    if (!flip(mesh, edge)) {
        return e;
    }
    const std::size_t n = mesh.halfedges_size();
    for (unsigned side = 0; side < 2; ++side) {
        for (const Halfedge h : mesh.loop(Mesh::halfedge(edge, side))) {
            refresh(mesh, student, h, n);
        }
    }
    return e;
}

st::VertexIter split_bound(st::HalfedgeMesh& student, st::EdgeIter e) {
    Bound& b = bound_of(student);
    Mesh& mesh = *b.mesh;
    const Edge edge(std::uint32_t(e.index()));
    // The midpoint is of the positions the student sees.
    for (unsigned i = 0; i < 2; ++i) {
        const Vertex v = mesh.vertex(edge, i);
        const st::Vector3D& p = student.vertices[v.idx()].position;
        mesh.position(v) = Vec3(p.x, p.y, p.z);
    }
    const std::size_t old_halfedges = mesh.halfedges_size();
    const OpResult<Vertex> made = split(mesh, edge);
    if (!made) {
        return st::VertexIter();
    }
    grow(mesh, student, b);
    // Everything the split rewired lies in the faces around m and the loop steps beside them.
    const Vertex m = made.value();
    std::vector<Halfedge> touched;
    for (const Halfedge h : mesh.halfedges(m)) {
        const Halfedge t = Mesh::twin(h);
        touched.insert(touched.end(),
                       {h, mesh.next(h), mesh.prev(h), t, mesh.next(t), mesh.prev(t)});
    }
    // Old ones first, so a new boundary halfedge finds its loop's face.
    std::stable_partition(touched.begin(), touched.end(),
                          [&](Halfedge h) { return h.idx() < old_halfedges; });
    for (const Halfedge h : touched) {
        refresh(mesh, student, h, old_halfedges);
    }
    return st::VertexIter(&student, int(m.idx()));
}

}  // namespace

void bind_operations(st::HalfedgeMesh& student, Mesh& mesh, st::HalfedgeMesh::Operations& ops) {
    static thread_local Bound bound;  // one student call at a time per process
    bound.mesh = &mesh;
    bound.loops_from = mesh.faces_size();  // copy_in() put the loops right after the faces
    ops.flip = &flip_bound;
    ops.split = &split_bound;
    ops.context = &bound;
    student.ops_ = &ops;
}

}  // namespace meshedit::cli::grade
