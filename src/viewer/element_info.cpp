// The info panel's rows for the selected element (ElementRef's own helpers are in core).

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/normals.h"
#include "meshedit/viewer/editor.h"

namespace meshedit::viewer {

namespace {

using Kind = ElementRef::Kind;
using Rows = std::vector<std::pair<std::string, std::string>>;

/// Lists longer than this are cut ("…, 31 (40 in all)") so a huge valence cannot flood the
/// panel.
constexpr std::size_t kMaxListed = 32;

std::string number(double value) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", value);
    std::string s(buf);
    if (s == "-0.0000") {
        s = "0.0000";
    }
    return s;
}

std::string point(const Vec3& p) {
    // Appended piecewise: `"(" + string` trips a GCC 12 -Wrestrict false positive.
    std::string out(1, '(');
    out += number(p.x);
    out += ", ";
    out += number(p.y);
    out += ", ";
    out += number(p.z);
    out += ')';
    return out;
}

/// A curve point: curves are 2D.
std::string point2(const Vec3& p) {
    std::string out(1, '(');
    out += number(p.x);
    out += ", ";
    out += number(p.y);
    out += ')';
    return out;
}

template <class H>
std::string index_list(const std::vector<H>& handles) {
    std::string out;
    for (std::size_t i = 0; i < handles.size() && i < kMaxListed; ++i) {
        if (i > 0) {
            out += ", ";
        }
        out += handles[i].is_valid() ? std::to_string(handles[i].idx()) : "none";
    }
    if (handles.size() > kMaxListed) {
        out += ", … (" + std::to_string(handles.size()) + " in all)";
    }
    return out.empty() ? "none" : out;
}

std::string yes_no(bool b) {
    return b ? "yes" : "no";
}

bool is_crease(const Mesh& mesh, Edge e) {
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    return crease && crease[e] != 0;
}

Rows vertex_info(const Mesh& mesh, Vertex v) {
    Rows rows;
    rows.emplace_back("position", point(mesh.position(v)));
    if (mesh.is_isolated(v)) {
        rows.emplace_back("degree", "0");
        rows.emplace_back("boundary", "isolated vertex");
        return rows;
    }
    std::vector<Vertex> ring(mesh.vertices(v).begin(), mesh.vertices(v).end());
    std::vector<Face> faces(mesh.faces(v).begin(), mesh.faces(v).end());
    rows.emplace_back("degree", std::to_string(mesh.valence(v)));
    rows.emplace_back("boundary", yes_no(mesh.is_boundary(v)));
    std::vector<Halfedge> outgoing(mesh.halfedges(v).begin(), mesh.halfedges(v).end());
    rows.emplace_back("neighbours", index_list(ring));
    rows.emplace_back("faces", index_list(faces));
    rows.emplace_back("halfedge", std::to_string(mesh.halfedge(v).idx()));
    rows.emplace_back("outgoing", index_list(outgoing));
    return rows;
}

Rows edge_info(const Mesh& mesh, Edge e) {
    const Halfedge h = Mesh::halfedge(e, 0);
    const Vertex a = mesh.from_vertex(h);
    const Vertex b = mesh.to_vertex(h);
    const Vec3& pa = mesh.position(a);
    const Vec3& pb = mesh.position(b);
    Rows rows;
    rows.emplace_back("vertices", index_list(std::vector<Vertex>{a, b}));
    rows.emplace_back("halfedges", index_list(std::vector<Halfedge>{h, Mesh::twin(h)}));
    rows.emplace_back("midpoint", point(0.5 * (pa + pb)));
    rows.emplace_back("length", number(distance(pa, pb)));
    rows.emplace_back("boundary", yes_no(mesh.is_boundary(e)));
    rows.emplace_back("crease", yes_no(is_crease(mesh, e)));
    rows.emplace_back("faces", index_list(std::vector<Face>{mesh.face(e, 0), mesh.face(e, 1)}));
    return rows;
}

Rows halfedge_info(const Mesh& mesh, Halfedge h) {
    Rows rows;
    // CS184's h->vertex() is the source; the core's to_vertex(h) the head: name both ends.
    rows.emplace_back("from (vertex())", std::to_string(mesh.from_vertex(h).idx()));
    rows.emplace_back("to", std::to_string(mesh.to_vertex(h).idx()));
    rows.emplace_back("next", std::to_string(mesh.next(h).idx()));
    rows.emplace_back("prev", std::to_string(mesh.prev(h).idx()));
    rows.emplace_back("twin", std::to_string(Mesh::twin(h).idx()));
    rows.emplace_back("edge", std::to_string(Mesh::edge(h).idx()));
    const Face f = mesh.face(h);
    rows.emplace_back("face", f.is_valid() ? std::to_string(f.idx()) : "none (boundary)");
    return rows;
}

Rows face_info(const Mesh& mesh, Face f) {
    std::vector<Vertex> corners(mesh.vertices(f).begin(), mesh.vertices(f).end());
    std::vector<Halfedge> sides(mesh.halfedges(f).begin(), mesh.halfedges(f).end());
    std::vector<Face> neighbours;
    neighbours.reserve(sides.size());
    for (Halfedge h : sides) {
        neighbours.push_back(mesh.face(Mesh::twin(h)));
    }
    const Vec3 area = face_area_vector(mesh, f);
    Rows rows;
    rows.emplace_back("degree", std::to_string(sides.size()));
    rows.emplace_back("vertices", index_list(corners));
    rows.emplace_back("halfedges", index_list(sides));
    rows.emplace_back("neighbours", index_list(neighbours));
    rows.emplace_back("boundary", yes_no(mesh.is_boundary(f)));
    rows.emplace_back("normal", point(normalize(area)));
    rows.emplace_back("area", number(0.5 * norm(area)));
    return rows;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> element_info(const Mesh& mesh,
                                                              const ElementRef& element) {
    if (element.kind == Kind::None) {
        return {};
    }
    Rows rows{{"type", kind_name(element.kind)}, {"index", std::to_string(element.index)}};
    if (!is_live(mesh, element)) {
        rows.emplace_back("state", describe(mesh, element).ends_with("(deleted)")
                                       ? "deleted"
                                       : "not in the mesh");
        return rows;
    }
    Rows more;
    switch (element.kind) {
        case Kind::Vertex:
            more = vertex_info(mesh, Vertex(element.index));
            break;
        case Kind::Edge:
            more = edge_info(mesh, Edge(element.index));
            break;
        case Kind::Halfedge:
            more = halfedge_info(mesh, Halfedge(element.index));
            break;
        case Kind::Face:
            more = face_info(mesh, Face(element.index));
            break;
        case Kind::None:
            break;
    }
    rows.insert(rows.end(), std::make_move_iterator(more.begin()),
                std::make_move_iterator(more.end()));
    return rows;
}

namespace {

template <class H>
std::vector<ElementRef> refs(const std::vector<H>& handles, ElementRef (*make)(H)) {
    std::vector<ElementRef> out;
    for (std::size_t i = 0; i < handles.size() && i < kMaxListed; ++i) {
        if (handles[i].is_valid()) {
            out.push_back(make(handles[i]));
        }
    }
    return out;
}

template <class H, class Range>
std::vector<H> all(const Range& range) {
    return std::vector<H>(range.begin(), range.end());
}

}  // namespace

std::vector<std::pair<std::string, std::vector<ElementRef>>> element_links(
    const Mesh& mesh, const ElementRef& element) {
    std::vector<std::pair<std::string, std::vector<ElementRef>>> links;
    if (!is_live(mesh, element)) {
        return links;
    }
    const auto vertex = [](Vertex v) { return ElementRef::vertex(v); };
    const auto edge = [](Edge e) { return ElementRef::edge(e); };
    const auto halfedge = [](Halfedge h) { return ElementRef::halfedge(h); };
    const auto face = [](Face f) { return ElementRef::face(f); };
    switch (element.kind) {
        case Kind::Vertex: {
            const Vertex v(element.index);
            if (mesh.is_isolated(v)) {
                break;
            }
            links.emplace_back("neighbours", refs(all<Vertex>(mesh.vertices(v)), +vertex));
            links.emplace_back("faces", refs(all<Face>(mesh.faces(v)), +face));
            links.emplace_back("halfedge",
                               refs(std::vector<Halfedge>{mesh.halfedge(v)}, +halfedge));
            links.emplace_back("outgoing", refs(all<Halfedge>(mesh.halfedges(v)), +halfedge));
            break;
        }
        case Kind::Edge: {
            const Edge e(element.index);
            const Halfedge h = Mesh::halfedge(e, 0);
            links.emplace_back(
                "vertices",
                refs(std::vector<Vertex>{mesh.from_vertex(h), mesh.to_vertex(h)}, +vertex));
            links.emplace_back("halfedges",
                               refs(std::vector<Halfedge>{h, Mesh::twin(h)}, +halfedge));
            links.emplace_back("faces",
                               refs(std::vector<Face>{mesh.face(e, 0), mesh.face(e, 1)}, +face));
            break;
        }
        case Kind::Halfedge: {
            const Halfedge h(element.index);
            links.emplace_back("from (vertex())",
                               refs(std::vector<Vertex>{mesh.from_vertex(h)}, +vertex));
            links.emplace_back("to", refs(std::vector<Vertex>{mesh.to_vertex(h)}, +vertex));
            links.emplace_back("next", refs(std::vector<Halfedge>{mesh.next(h)}, +halfedge));
            links.emplace_back("prev", refs(std::vector<Halfedge>{mesh.prev(h)}, +halfedge));
            links.emplace_back("twin", refs(std::vector<Halfedge>{Mesh::twin(h)}, +halfedge));
            links.emplace_back("edge", refs(std::vector<Edge>{Mesh::edge(h)}, +edge));
            links.emplace_back("face", refs(std::vector<Face>{mesh.face(h)}, +face));
            break;
        }
        case Kind::Face: {
            const Face f(element.index);
            std::vector<Face> neighbours;
            for (Halfedge h : mesh.halfedges(f)) {
                neighbours.push_back(mesh.face(Mesh::twin(h)));
            }
            links.emplace_back("vertices", refs(all<Vertex>(mesh.vertices(f)), +vertex));
            links.emplace_back("halfedges", refs(all<Halfedge>(mesh.halfedges(f)), +halfedge));
            links.emplace_back("neighbours", refs(neighbours, +face));
            break;
        }
        case Kind::None:
            break;
    }
    return links;
}

std::vector<std::pair<std::string, std::string>> control_point_info(const BezierCurve& curve,
                                                                    std::uint32_t index) {
    if (index >= curve.control_points.size()) {
        return {};
    }
    const Vec3& p = curve.control_points[index];
    return {{"type", "control point"},
            {"index", std::to_string(index)},
            {"position", point2(p)},
            {"points", std::to_string(curve.control_points.size())},
            {"degree", std::to_string(curve.degree())}};
}

}  // namespace meshedit::viewer
