// The rewiring diagram of a recorded edit (op_diagram.h) without a copy of the mesh: the
// neighbourhood drawn is cut out of the mesh after the edit and, with the change undone, out
// of the mesh before it, into two small meshes numbered alike (an element kept by the edit
// has the same local index on both sides), and drawn as two whole meshes are. GL-free.

#include <algorithm>
#include <array>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "meshedit/overlay/op_diagram.h"

namespace meshedit {
namespace {

using op_diagram_detail::Originals;

// What is cut out: indices in the big mesh, per kind (vertices, edges, faces).
struct Cut {
    std::unordered_set<std::uint32_t> vertices, edges, faces;
};

bool live(const Mesh& mesh, Vertex v) {
    return v.is_valid() && v.idx() < mesh.vertices_size() && !mesh.is_deleted(v);
}
bool live(const Mesh& mesh, Face f) {
    return f.is_valid() && f.idx() < mesh.faces_size() && !mesh.is_deleted(f);
}

// The faces within two rings of `seeds` and of those in `faces`, as they are in `mesh` now:
// every face the picture can show or walk past is among them (its regions are faces on the
// vertices an edit touched, or around the element operated on, and the faces across their
// sides).
void add_faces_near(const Mesh& mesh, const std::vector<Vertex>& seeds,
                    const std::vector<Face>& faces, Cut& cut) {
    std::vector<Vertex> around = seeds;
    for (Face f : faces) {
        if (live(mesh, f)) {
            cut.faces.insert(f.idx());
            for (Vertex v : mesh.vertices(f)) {
                around.push_back(v);
            }
        }
    }
    // Two rings: the regions drawn reach one ring past the seeds (a collapse shows every face
    // at either end), and the picture walks around each of their vertices.
    for (int ring = 0; ring < 2; ++ring) {
        std::vector<Vertex> next;
        for (Vertex v : around) {
            if (!live(mesh, v) || mesh.is_isolated(v)) {
                continue;
            }
            cut.vertices.insert(v.idx());
            for (Face f : mesh.faces(v)) {
                if (cut.faces.insert(f.idx()).second && ring == 0) {
                    for (Vertex w : mesh.vertices(f)) {
                        next.push_back(w);
                    }
                }
            }
        }
        around = std::move(next);
    }
}

// The loops of the cut's faces as they are in `mesh` now: their edges, vertices, and the
// faces across them (only named, not walked).
void add_loops(const Mesh& mesh, Cut& cut) {
    std::vector<std::uint32_t> across;
    for (const std::uint32_t i : cut.faces) {
        if (!live(mesh, Face(i))) {
            continue;
        }
        for (Halfedge h : mesh.halfedges(Face(i))) {
            cut.edges.insert(Mesh::edge(h).idx());
            cut.vertices.insert(mesh.to_vertex(h).idx());
            cut.vertices.insert(mesh.from_vertex(h).idx());
            if (const Face g = mesh.face(Mesh::twin(h)); g.is_valid()) {
                across.push_back(g.idx());
            }
        }
    }
    cut.faces.insert(across.begin(), across.end());
}

std::vector<std::uint32_t> sorted(const std::unordered_set<std::uint32_t>& set) {
    std::vector<std::uint32_t> out(set.begin(), set.end());
    std::sort(out.begin(), out.end());
    return out;
}

// Big-mesh index → local index, for one kind.
struct Numbering {
    std::vector<std::uint32_t> originals;  // sorted: local order is the big mesh's order
    std::unordered_map<std::uint32_t, std::uint32_t> local;
    explicit Numbering(std::vector<std::uint32_t> sorted_originals)
        : originals(std::move(sorted_originals)) {
        for (std::uint32_t i = 0; i < originals.size(); ++i) {
            local.emplace(originals[i], i);
        }
    }
    // How many of them are below `size` (the elements that exist on a side: appended ones
    // sort last).
    std::size_t below(std::size_t size) const {
        return static_cast<std::size_t>(std::lower_bound(originals.begin(), originals.end(), size) -
                                        originals.begin());
    }
    std::uint32_t operator()(std::uint32_t i) const {
        const auto it = local.find(i);
        return it == local.end() ? kInvalidIndex : it->second;
    }
};

// The cut of `mesh` as it is now, as a mesh of the numbering's elements that exist in it. A
// reference to an element outside the cut is left unset (the picture never follows one: the
// cut reaches two rings past what it draws).
Mesh cut_out(const Mesh& mesh, const Numbering& v, const Numbering& e, const Numbering& f) {
    Mesh out;
    const std::size_t nv = v.below(mesh.vertices_size());
    const std::size_t ne = e.below(mesh.edges_size());
    const std::size_t nf = f.below(mesh.faces_size());
    out.resize(nv, ne, nf);
    const auto local_h = [&](Halfedge h) {
        if (!h.is_valid()) {
            return Halfedge();
        }
        const std::uint32_t le = e(Mesh::edge(h).idx());
        return le == kInvalidIndex ? Halfedge() : Halfedge(2 * le + (h.idx() & 1u));
    };
    const auto local_v = [&](Vertex x) { return x.is_valid() ? Vertex(v(x.idx())) : Vertex(); };
    const auto local_f = [&](Face x) { return x.is_valid() ? Face(f(x.idx())) : Face(); };
    for (std::uint32_t i = 0; i < nv; ++i) {
        const Vertex big(v.originals[i]);
        out.position(Vertex(i)) = mesh.position(big);
        out.set_halfedge(Vertex(i), local_h(mesh.halfedge(big)));
        if (mesh.is_deleted(big)) {
            out.mark_deleted(Vertex(i));
        }
    }
    for (std::uint32_t i = 0; i < ne; ++i) {
        const Edge big(e.originals[i]);
        for (unsigned k = 0; k < 2; ++k) {
            const Halfedge h = Mesh::halfedge(big, k);
            const Halfedge mine = Mesh::halfedge(Edge(i), k);
            out.set_vertex(mine, local_v(mesh.to_vertex(h)));
            out.set_face(mine, local_f(mesh.face(h)));
            // set_next() sets prev(n) too: a deleted halfedge's stale next must not.
            if (const Halfedge n = local_h(mesh.next(h)); n.is_valid() && !mesh.is_deleted(big)) {
                out.set_next(mine, n);
            }
        }
        if (mesh.is_deleted(big)) {
            out.mark_deleted(Edge(i));
        }
    }
    for (std::uint32_t i = 0; i < nf; ++i) {
        const Face big(f.originals[i]);
        out.set_halfedge(Face(i), local_h(mesh.halfedge(big)));
        if (mesh.is_deleted(big)) {
            out.mark_deleted(Face(i));
        }
    }
    return out;
}

ElementRef local_ref(const ElementRef& big, const Numbering& v, const Numbering& e,
                     const Numbering& f) {
    switch (big.kind) {
        case ElementRef::Kind::Vertex:
            return ElementRef::vertex(Vertex(v(big.index)));
        case ElementRef::Kind::Edge:
            return ElementRef::edge(Edge(e(big.index)));
        case ElementRef::Kind::Halfedge:
            return ElementRef::halfedge(Halfedge(2 * e(big.index >> 1) + (big.index & 1u)));
        case ElementRef::Kind::Face:
            return ElementRef::face(Face(f(big.index)));
        case ElementRef::Kind::None:
            break;
    }
    return {};
}

// The vertices an element names (its corners, its ends, itself).
std::vector<Vertex> vertices_of(const Mesh& mesh, const ElementRef& element) {
    switch (element.kind) {
        case ElementRef::Kind::Vertex:
            return {Vertex(element.index)};
        case ElementRef::Kind::Edge:
            return {mesh.vertex(Edge(element.index), 0), mesh.vertex(Edge(element.index), 1)};
        case ElementRef::Kind::Halfedge:
            return {mesh.from_vertex(Halfedge(element.index)),
                    mesh.to_vertex(Halfedge(element.index))};
        case ElementRef::Kind::Face: {
            std::vector<Vertex> out;
            for (Vertex v : mesh.vertices(Face(element.index))) {
                out.push_back(v);
            }
            return out;
        }
        case ElementRef::Kind::None:
            break;
    }
    return {};
}

}  // namespace

OpDiagram op_diagram(Mesh& mesh, const MeshChange& change, std::string_view verb, CodeNames names,
                     const std::function<ElementRef(const Mesh& before)>& input_of,
                     const OpDiagramStyle& style) {
    const MeshChange::Region touched = change.region();
    Cut cut;
    // After: the faces near what the edit touched.
    add_faces_near(mesh, touched.vertices, touched.faces, cut);
    // Before (the change undone): the same, and around the element operated on.
    change.undo(mesh);
    ElementRef input;
    std::string title;
    try {
        input = input_of(mesh);
        title = std::string(verb) + " of " + describe(mesh, input);
        std::vector<Vertex> seeds = touched.vertices;
        const std::vector<Vertex> named = vertices_of(mesh, input);
        seeds.insert(seeds.end(), named.begin(), named.end());
        add_faces_near(mesh, seeds, touched.faces, cut);
        add_loops(mesh, cut);
    } catch (...) {
        change.redo(mesh);
        throw;
    }
    change.redo(mesh);
    add_loops(mesh, cut);
    const Numbering v(sorted(cut.vertices)), e(sorted(cut.edges)), f(sorted(cut.faces));
    const Mesh after = cut_out(mesh, v, e, f);
    change.undo(mesh);
    Mesh before;
    try {
        before = cut_out(mesh, v, e, f);
    } catch (...) {
        change.redo(mesh);
        throw;
    }
    change.redo(mesh);
    const Originals originals{v.originals, e.originals, f.originals};
    return op_diagram_detail::draw(before, after, std::move(title), names,
                                   local_ref(input, v, e, f), &originals, style);
}

}  // namespace meshedit
