// The names flip(), split() and collapse() give their elements (src/local_ops/flip_split.cpp,
// src/local_ops/collapse.cpp: the ASCII diagrams above the code), derived here the way that
// code derives them, so the rewiring diagram (op_diagram.h) labels what a student reads there. A
// test checks that each name lands on the element the diagram in the source shows.

#include <algorithm>

#include "meshedit/overlay/op_diagram.h"

namespace meshedit::op_diagram_detail {
namespace {

template <typename Handle>
const std::string* find(const std::vector<std::pair<std::uint32_t, std::string>>& names, Handle h) {
    for (const auto& [index, name] : names) {
        if (index == h.idx()) {
            return &name;
        }
    }
    return nullptr;
}

bool is_triangle_or_gap(const Mesh& mesh, Halfedge h) {
    return mesh.is_boundary(h) || mesh.is_triangle(mesh.face(h));
}

// h0 = `h0`, its twin t0, the loops' neighbours h1, h2, t1, t2; b -> c along h0, a and d the
// corners after h1 and t1; faces f0, f1. Gaps (boundary halfedges) name no face.
void name_edge_frame(const Mesh& mesh, Halfedge h0, Names& n) {
    const Halfedge t0 = Mesh::twin(h0);
    n.halfedges = {{h0.idx(), "h0"},
                   {t0.idx(), "t0"},
                   {mesh.next(h0).idx(), "h1"},
                   {mesh.prev(h0).idx(), "h2"},
                   {mesh.next(t0).idx(), "t1"},
                   {mesh.prev(t0).idx(), "t2"}};
    n.vertices = {{mesh.from_vertex(h0).idx(), "b"},
                  {mesh.to_vertex(h0).idx(), "c"},
                  {mesh.to_vertex(mesh.next(h0)).idx(), "a"},
                  {mesh.to_vertex(mesh.next(t0)).idx(), "d"}};
    if (mesh.face(h0).is_valid()) {
        n.faces.push_back({mesh.face(h0).idx(), "f0"});
    }
    if (mesh.face(t0).is_valid()) {
        n.faces.push_back({mesh.face(t0).idx(), "f1"});
    }
}

Names flip_names(const Mesh& mesh, Edge e) {
    Names n;
    const Halfedge h0 = Mesh::halfedge(e, 0);
    name_edge_frame(mesh, h0, n);
    const Halfedge h1 = mesh.next(h0);
    const Halfedge t1 = mesh.next(Mesh::twin(h0));
    // Polygons: h3 = next(h1), t3 = next(t1) (the corners the edge turns to follow).
    if (mesh.next(h1) != mesh.prev(h0)) {
        n.halfedges.push_back({mesh.next(h1).idx(), "h3"});
    }
    if (mesh.next(t1) != mesh.prev(Mesh::twin(h0))) {
        n.halfedges.push_back({mesh.next(t1).idx(), "t3"});
    }
    return n;
}

// split(): h0 is the side with a face when the other is a gap; the new elements are
// appended in the order split() allocates them: vertex m, edges s, w (u with a top face),
// faces f3 (f2).
Names split_names(const Mesh& mesh, Edge e) {
    Names n;
    if (!is_triangle_or_gap(mesh, Mesh::halfedge(e, 0)) ||
        !is_triangle_or_gap(mesh, Mesh::halfedge(e, 1))) {
        return n;  // split_beside_polygon(): labelled by index
    }
    const unsigned i = mesh.is_boundary(Mesh::halfedge(e, 1)) ? 1 : 0;
    const Halfedge h0 = Mesh::halfedge(e, i);
    name_edge_frame(mesh, h0, n);
    const bool top = mesh.face(h0).is_valid();
    if (!top) {
        // The gap's neighbours are boundary halfedges of other loops: not h1/a.
        std::erase_if(n.halfedges, [](const auto& p) { return p.second == "h1"; });
        std::erase_if(n.vertices, [](const auto& p) { return p.second == "a"; });
    }
    const auto first_e = static_cast<std::uint32_t>(mesh.edges_size());
    const auto first_f = static_cast<std::uint32_t>(mesh.faces_size());
    n.vertices.push_back({static_cast<std::uint32_t>(mesh.vertices_size()), "m"});
    n.halfedges.push_back({2 * first_e, "s0"});
    n.halfedges.push_back({2 * first_e + 1, "s1"});
    n.halfedges.push_back({2 * (first_e + 1), "w0"});
    n.halfedges.push_back({2 * (first_e + 1) + 1, "w1"});
    n.faces.push_back({first_f, "f3"});
    if (top) {
        n.halfedges.push_back({2 * (first_e + 2), "u0"});
        n.halfedges.push_back({2 * (first_e + 2) + 1, "u1"});
        n.faces.push_back({first_f + 1, "f2"});
    }
    return n;
}

// collapse(): h0 leaves the survivor v0 (the smaller index); h1 = next(h0), h2 = next(h1),
// t1 = next(t0), t2 = next(t1); o1, o2 = twin(h1), twin(h2) and q1, q2 = twin(t1), twin(t2)
// beside triangles; a, d the far corners.
Names collapse_names(const Mesh& mesh, Edge e) {
    Names n;
    Halfedge h0 = Mesh::halfedge(e, 0);
    if (mesh.from_vertex(h0).idx() > mesh.to_vertex(h0).idx()) {
        h0 = Mesh::twin(h0);
    }
    const Halfedge t0 = Mesh::twin(h0);
    const Halfedge h1 = mesh.next(h0);
    const Halfedge h2 = mesh.next(h1);
    const Halfedge t1 = mesh.next(t0);
    const Halfedge t2 = mesh.next(t1);
    n.halfedges = {{h0.idx(), "h0"}, {t0.idx(), "t0"}, {h1.idx(), "h1"},
                   {h2.idx(), "h2"}, {t1.idx(), "t1"}, {t2.idx(), "t2"}};
    n.vertices = {{mesh.from_vertex(h0).idx(), "v0"}, {mesh.to_vertex(h0).idx(), "v1"}};
    if (!mesh.is_boundary(h0) && mesh.is_triangle(mesh.face(h0))) {
        n.halfedges.push_back({Mesh::twin(h1).idx(), "o1"});
        n.halfedges.push_back({Mesh::twin(h2).idx(), "o2"});
        n.vertices.push_back({mesh.to_vertex(h1).idx(), "a"});
        n.faces.push_back({mesh.face(h0).idx(), "f0"});
    }
    if (!mesh.is_boundary(t0) && mesh.is_triangle(mesh.face(t0))) {
        n.halfedges.push_back({Mesh::twin(t1).idx(), "q1"});
        n.halfedges.push_back({Mesh::twin(t2).idx(), "q2"});
        n.vertices.push_back({mesh.to_vertex(t1).idx(), "d"});
        n.faces.push_back({mesh.face(t0).idx(), "f1"});
    }
    return n;
}

}  // namespace

const std::string* Names::halfedge(Halfedge h) const {
    return find(halfedges, h);
}
const std::string* Names::vertex(Vertex v) const {
    return find(vertices, v);
}
const std::string* Names::face(Face f) const {
    return find(faces, f);
}

Names code_names(const Mesh& before, CodeNames names, ElementRef input) {
    if (input.kind == ElementRef::Kind::Halfedge) {
        input = ElementRef::edge(Mesh::edge(Halfedge(input.index)));
    }
    if (input.kind != ElementRef::Kind::Edge) {
        return {};
    }
    const Edge e(input.index);
    switch (names) {
        case CodeNames::Flip:
            return flip_names(before, e);
        case CodeNames::Split:
            return split_names(before, e);
        case CodeNames::Collapse:
            return collapse_names(before, e);
        case CodeNames::ByIndex:
            break;
    }
    return {};
}

}  // namespace meshedit::op_diagram_detail
