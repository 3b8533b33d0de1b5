// The editor's selection: picking, moving it through the connectivity (N T H V E G), and
// dragging the selected vertex or control point.

#include "meshedit/viewer/editor.h"

namespace meshedit::viewer {

namespace {

using Kind = ElementRef::Kind;

std::string idx(std::uint32_t i) {
    return std::to_string(i);
}

}  // namespace

Outcome Editor::select(ElementRef element) {
    bool ok = false;
    if (doc_.mode == Mode::Curve) {
        ok = element.kind == ElementRef::Kind::Vertex &&
             element.index < doc_.curve.control_points.size();
    } else {
        ok = is_live(doc_.mesh, element);
    }
    doc_.selection = ok ? element : ElementRef{};
    if (doc_.mode == Mode::Curve) {
        return {kSelection, ok ? "control point " + std::to_string(element.index)
                               : std::string("nothing selected")};
    }
    return {kSelection, describe(doc_.mesh, doc_.selection)};
}

bool Editor::begin_drag() {
    const ElementRef& s = doc_.selection;
    if (s.kind != ElementRef::Kind::Vertex) {
        return false;
    }
    const bool ok = doc_.mode == Mode::Curve ? s.index < doc_.curve.control_points.size()
                                             : is_live(doc_.mesh, s);
    if (!ok) {
        return false;
    }
    // The snapshot is taken on the first real move (the document cannot change before
    // it), so a click without a move costs no copy and leaves no undo step.
    dragging_ = true;
    drag_moved_ = false;
    drag_index_ = s.index;
    return true;
}

Outcome Editor::drag_to(const Vec3& position) {
    if (!dragging_) {
        return {};
    }
    const ElementRef& s = doc_.selection;
    if (s.kind != ElementRef::Kind::Vertex || s.index != drag_index_) {
        return {};  // the selection changed under the drag
    }
    if (!is_finite(position)) {
        return refused("cannot move to a non-finite position");
    }
    Vec3* target = nullptr;
    Vec3 wanted = position;
    if (doc_.mode == Mode::Curve) {
        if (drag_index_ >= doc_.curve.control_points.size()) {
            return {};
        }
        target = &doc_.curve.control_points[drag_index_];
        wanted.z = target->z;  // curves are 2D: keep z
    } else {
        if (!is_live(doc_.mesh, s)) {
            return {};
        }
        target = &doc_.mesh.position(Vertex(drag_index_));
    }
    if (*target == wanted) {
        return {};
    }
    if (!drag_moved_) {
        snapshot();  // one undo step per drag; invalidates nothing: doc_ is copied, not moved
        drag_moved_ = true;
        target = doc_.mode == Mode::Curve ? &doc_.curve.control_points[drag_index_]
                                          : &doc_.mesh.position(Vertex(drag_index_));
    }
    *target = wanted;
    return {doc_.mode == Mode::Curve ? unsigned{kCurve} : unsigned{kGeometry}, ""};
}

void Editor::end_drag() {
    dragging_ = false;
    drag_moved_ = false;
}

Outcome Editor::run_navigation(Command command) {
    const Mesh& mesh = doc_.mesh;
    const ElementRef s = doc_.selection;
    if (!is_live(mesh, s)) {
        if (command == Command::Next || command == Command::Twin) {
            return refused("select a halfedge first (N and T move along halfedges)");
        }
        return refused("select something first");
    }
    const auto go = [&](ElementRef to, std::string note = {}) {
        doc_.selection = to;
        return Outcome{kSelection, describe(mesh, to) + note};
    };

    switch (command) {
        case Command::Next:
        case Command::Twin: {
            if (s.kind != Kind::Halfedge) {
                return refused("select a halfedge first (N and T move along halfedges)");
            }
            const Halfedge h(s.index);
            return go(
                ElementRef::halfedge(command == Command::Next ? mesh.next(h) : Mesh::twin(h)));
        }
        case Command::ToHalfedge:
            switch (s.kind) {
                case Kind::Vertex: {
                    const Vertex v(s.index);
                    if (mesh.is_isolated(v)) {
                        return refused("vertex " + idx(v.idx()) +
                                       " is isolated: it has no halfedge");
                    }
                    return go(ElementRef::halfedge(mesh.halfedge(v)));
                }
                case Kind::Edge:
                    return go(ElementRef::halfedge(Mesh::halfedge(Edge(s.index), 0)));
                case Kind::Face:
                    return go(ElementRef::halfedge(mesh.halfedge(Face(s.index))));
                default:
                    return {kNothing, "already a halfedge"};
            }
        case Command::ToVertex:
            switch (s.kind) {
                case Kind::Halfedge:
                    return go(ElementRef::vertex(mesh.from_vertex(Halfedge(s.index))),
                              " (the halfedge's source)");
                case Kind::Edge:
                    return go(
                        ElementRef::vertex(mesh.from_vertex(Mesh::halfedge(Edge(s.index), 0))));
                case Kind::Face:
                    return go(ElementRef::vertex(mesh.from_vertex(mesh.halfedge(Face(s.index)))));
                default:
                    return {kNothing, "already a vertex"};
            }
        case Command::ToEdge:
            switch (s.kind) {
                case Kind::Halfedge:
                    return go(ElementRef::edge(Mesh::edge(Halfedge(s.index))));
                case Kind::Vertex: {
                    const Vertex v(s.index);
                    if (mesh.is_isolated(v)) {
                        return refused("vertex " + idx(v.idx()) + " is isolated: it has no edge");
                    }
                    return go(ElementRef::edge(Mesh::edge(mesh.halfedge(v))));
                }
                case Kind::Face:
                    return go(ElementRef::edge(Mesh::edge(mesh.halfedge(Face(s.index)))));
                default:
                    return {kNothing, "already an edge"};
            }
        case Command::ToFace:
            switch (s.kind) {
                case Kind::Halfedge: {
                    const Face f = mesh.face(Halfedge(s.index));
                    if (!f.is_valid()) {
                        return refused("the halfedge is on the boundary: it has no face");
                    }
                    return go(ElementRef::face(f));
                }
                case Kind::Edge: {
                    const Edge e(s.index);
                    const Face f = mesh.face(e, 0).is_valid() ? mesh.face(e, 0) : mesh.face(e, 1);
                    return go(ElementRef::face(f));  // every edge has a face (invariant)
                }
                case Kind::Vertex: {
                    const Vertex v(s.index);
                    for (Face f : mesh.faces(v)) {
                        return go(ElementRef::face(f));
                    }
                    return refused("vertex " + idx(v.idx()) + " has no face");
                }
                default:
                    return {kNothing, "already a face"};
            }
        default:
            break;
    }
    return {};
}

}  // namespace meshedit::viewer
