// The editor's selection: picking, moving it through the connectivity (N T H V E G), and
// dragging the selected vertex or control point.

#include "meshedit/core/validate.h"
#include "meshedit/viewer/editor.h"
#include "selection_steps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace meshedit::viewer {

namespace {

using Kind = ElementRef::Kind;

std::string idx(std::uint32_t i) {
    return std::to_string(i);
}

// "vertex 3 by (0.1000, 0.0000, -0.2500), 0.2693": what a drag did, in the info panel's
// number format.
std::string moved_by(bool curve, std::uint32_t index, const Vec3& d) {
    char text[160];
    if (curve) {
        std::snprintf(text, sizeof text, "control point %u by (%.4f, %.4f), %.4f", index, d.x, d.y,
                      norm(d));
    } else {
        std::snprintf(text, sizeof text, "vertex %u by (%.4f, %.4f, %.4f), %.4f", index, d.x, d.y,
                      d.z, norm(d));
    }
    return text;
}

}  // namespace

Outcome Editor::select(ElementRef element) {
    if (std::optional<Outcome> busy = refuse_if_busy()) {
        return *busy;
    }
    bool ok = false;
    if (doc_.mode == Mode::Curve) {
        ok = element.kind == ElementRef::Kind::Vertex &&
             element.index < doc_.curve.control_points.size();
    } else {
        ok = is_live(doc_.mesh, element);
    }
    doc_.selection = ok ? element : ElementRef{};
    doc_.also_selected.clear();
    if (doc_.mode == Mode::Curve) {
        return {kSelection, ok ? "control point " + std::to_string(element.index)
                               : std::string("nothing selected")};
    }
    return {kSelection, describe(doc_.mesh, doc_.selection)};
}

Outcome Editor::toggle_select(ElementRef element) {
    if (std::optional<Outcome> busy = refuse_if_busy()) {
        return *busy;
    }
    if (doc_.mode == Mode::Curve || !is_live(doc_.mesh, element)) {
        return select(element);
    }
    auto& also = doc_.also_selected;
    if (element == doc_.selection) {
        // Deselecting the active element makes the one added before it active.
        doc_.selection = also.empty() ? ElementRef{} : also.back();
        if (!also.empty()) {
            also.pop_back();
        }
        return {kSelection, "deselected " + describe(doc_.mesh, element) + count_text()};
    }
    if (const auto it = std::find(also.begin(), also.end(), element); it != also.end()) {
        also.erase(it);
        return {kSelection, "deselected " + describe(doc_.mesh, element) + count_text()};
    }
    if (!doc_.selection.is_none()) {
        also.push_back(doc_.selection);
    }
    doc_.selection = element;
    return {kSelection, describe(doc_.mesh, element) + count_text()};
}

std::string Editor::count_text() const {
    const std::size_t n = doc_.also_selected.size() + (doc_.selection.is_none() ? 0 : 1);
    return n > 1 ? " (" + std::to_string(n) + " selected)" : "";
}

Outcome Editor::recorded_selection(const std::function<Outcome()>& change) {
    const ElementRef before = doc_.selection;
    std::vector<ElementRef> also_before = doc_.also_selected;
    Outcome out = change();
    if (out.refused || doc_.mode != Mode::Mesh ||
        (before == doc_.selection && also_before == doc_.also_selected)) {
        return out;
    }
    ledger_.select(doc_, before, std::move(also_before),
                   ops::select_step_text(doc_.mesh, selected()), stroke_);
    return out;
}

Outcome Editor::select_all() {
    return recorded_selection([&] { return choose_all(); });
}

Outcome Editor::choose_all() {
    if (doc_.mode == Mode::Curve) {
        return refused("select all is for meshes");
    }
    const Mesh& mesh = doc_.mesh;
    Kind kind = doc_.selection.is_none() ? Kind::Face : doc_.selection.kind;
    if (kind == Kind::Halfedge) {
        kind = Kind::Edge;
    }
    std::vector<ElementRef> all;
    const auto add_live = [&](std::size_t n, auto make, auto deleted) {
        all.reserve(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            if (!deleted(i)) {
                all.push_back(make(i));
            }
        }
    };
    switch (kind) {
        case Kind::Vertex:
            add_live(
                mesh.vertices_size(), [](std::uint32_t i) { return ElementRef::vertex(Vertex(i)); },
                [&](std::uint32_t i) { return mesh.is_deleted(Vertex(i)); });
            break;
        case Kind::Edge:
            add_live(
                mesh.edges_size(), [](std::uint32_t i) { return ElementRef::edge(Edge(i)); },
                [&](std::uint32_t i) { return mesh.is_deleted(Edge(i)); });
            break;
        default:
            add_live(
                mesh.faces_size(), [](std::uint32_t i) { return ElementRef::face(Face(i)); },
                [&](std::uint32_t i) { return mesh.is_deleted(Face(i)); });
            break;
    }
    if (all.empty()) {
        return refused("nothing to select");
    }
    doc_.selection = all.back();
    all.pop_back();
    doc_.also_selected = std::move(all);
    const char* noun = kind == Kind::Vertex ? " vertices"
                       : kind == Kind::Edge ? " edges"
                                            : " faces";
    return {kSelection, "selected all " + std::to_string(doc_.also_selected.size() + 1) + noun};
}

Outcome Editor::select_none() {
    return recorded_selection([&] {
        doc_.selection = {};
        doc_.also_selected.clear();
        return Outcome{kSelection, "selection cleared"};
    });
}

Outcome Editor::select_boundary_loop() {
    return recorded_selection([&] { return choose_boundary_loop(); });
}

Outcome Editor::choose_boundary_loop() {
    const Mesh& mesh = doc_.mesh;
    const ElementRef& s = doc_.selection;
    Halfedge h;
    if (is_live(mesh, s) && (s.kind == Kind::Edge || s.kind == Kind::Halfedge)) {
        const Edge e = s.kind == Kind::Edge ? Edge(s.index) : Mesh::edge(Halfedge(s.index));
        for (int side = 0; side < 2; ++side) {
            if (mesh.is_boundary(mesh.halfedge(e, side))) {
                h = mesh.halfedge(e, side);
            }
        }
    }
    if (!h.is_valid()) {
        return refused("select a boundary edge first (one drawn red), then press Shift+L");
    }
    std::vector<ElementRef> loop;
    Halfedge g = h;
    do {
        loop.push_back(ElementRef::edge(Mesh::edge(g)));
        g = mesh.next(g);
    } while (g != h && loop.size() <= mesh.halfedges_size());
    doc_.selection = loop.front();
    doc_.also_selected.assign(loop.begin() + 1, loop.end());
    return {kSelection, "selected the " + std::to_string(loop.size()) + " edges of a hole"};
}

std::vector<ElementRef> Editor::selected() const {
    std::vector<ElementRef> out;
    const auto live = [&](const ElementRef& e) {
        return doc_.mode != Mode::Curve && is_live(doc_.mesh, e);
    };
    // Active last, as Shift+click adds: the verbs' "made" lists keep that order.
    for (const ElementRef& e : doc_.also_selected) {
        if (live(e)) {
            out.push_back(e);
        }
    }
    if (live(doc_.selection)) {
        out.push_back(doc_.selection);
    }
    return out;
}

std::optional<std::pair<Vec3, Vec3>> Editor::selection_bounds() const {
    if (doc_.mode == Mode::Curve) {
        return std::nullopt;
    }
    std::optional<std::pair<Vec3, Vec3>> box;
    for (const std::uint32_t v : selected_vertices(doc_.mesh, selected())) {
        const Vec3& p = doc_.mesh.position(Vertex(v));
        if (!box) {
            box = std::pair{p, p};
        }
        box->first = {std::min(box->first.x, p.x), std::min(box->first.y, p.y),
                      std::min(box->first.z, p.z)};
        box->second = {std::max(box->second.x, p.x), std::max(box->second.y, p.y),
                       std::max(box->second.z, p.z)};
    }
    return box;
}

Outcome Editor::run_selection(Command command) {
    switch (command) {
        case Command::SelectAll:
            return select_all();
        case Command::SelectNone:
            return select_none();
        case Command::SelectLoop:
            return select_boundary_loop();
        case Command::SelectEdgeLoop:
        case Command::SelectEdgeRing:
        case Command::SelectLinked:
        case Command::SelectMore:
        case Command::SelectLess:
        case Command::SelectInvert:
        case Command::SelectPath:
        case Command::SelectTrait:
            return select_region(command);
        case Command::BoxSelect:
            return {kBoxSelect, "box select: drag a rectangle (Shift adds, Alt selects through)"};
        case Command::BrushSelect:
            return {kBrushSelect,
                    "brush select: drag to paint (Shift+drag takes away, wheel: size, Esc ends)"};
        case Command::FrameSelection:
            if (!selection_bounds()) {
                return refused("select something to frame first");
            }
            return {kFrameSelection, "framed the selection (Space resets the camera)"};
        case Command::Delete:
            return delete_selection();
        case Command::Validate:
            return validate_mesh();
        default:
            break;
    }
    return {};
}

Outcome Editor::validate_mesh() {
    const Mesh& mesh = doc_.mesh;
    const std::optional<ValidationError> error = validate(mesh);
    if (!error) {
        return {kNothing, "valid: every invariant of docs/halfedge.md holds (" +
                              std::to_string(mesh.n_vertices()) + " vertices, " +
                              std::to_string(mesh.n_edges()) + " edges, " +
                              std::to_string(mesh.n_faces()) + " faces)"};
    }
    // The culprit, selected without walking anything the failure may have broken: a face by
    // its anchor halfedge (its loop may not close), the others as themselves.
    ElementRef culprit;
    const std::uint32_t i = error->index;
    switch (error->kind) {
        case ElementKind::Vertex:
            culprit = i < mesh.vertices_size() ? ElementRef::vertex(Vertex(i)) : ElementRef{};
            break;
        case ElementKind::Edge:
            culprit = i < mesh.edges_size() ? ElementRef::edge(Edge(i)) : ElementRef{};
            break;
        case ElementKind::Halfedge:
            culprit = i < mesh.halfedges_size() ? ElementRef::halfedge(Halfedge(i)) : ElementRef{};
            break;
        case ElementKind::Face:
            if (i < mesh.faces_size() && mesh.halfedge(Face(i)).idx() < mesh.halfedges_size()) {
                culprit = ElementRef::halfedge(mesh.halfedge(Face(i)));
            }
            break;
    }
    doc_.selection = culprit;
    doc_.also_selected.clear();
    return {kSelection | (culprit.is_none() ? 0u : unsigned{kFrameSelection}),
            "invalid (" + error->invariant + "): " + error->message, true};
}

bool Editor::begin_drag() {
    if (busy()) {
        return false;  // the document takes no edit while an operation runs
    }
    const ElementRef& s = doc_.selection;
    if (s.kind != ElementRef::Kind::Vertex) {
        return false;
    }
    const bool ok = doc_.mode == Mode::Curve ? s.index < doc_.curve.control_points.size()
                                             : is_live(doc_.mesh, s);
    if (!ok) {
        return false;
    }
    // The transaction begins on the first real move (the document cannot change before
    // it), so a click without a move costs nothing and leaves no undo step.
    end_drag();
    dragging_ = true;
    drag_index_ = s.index;
    return true;
}

namespace {

double round_to_pixel(double value, double pixel) {
    // The decimal step just below a pixel: 10^floor(log10(pixel)). Dividing by 10^k (an
    // exact integer for steps below 1) rounds correctly, so 0.3075 stays 0.3075 in a file.
    const double exponent = std::floor(std::log10(pixel));
    if (exponent < 0.0) {
        const double per_unit = std::pow(10.0, -exponent);
        return std::round(value * per_unit) / per_unit;
    }
    const double step = std::pow(10.0, exponent);
    return std::round(value / step) * step;
}

}  // namespace

Outcome Editor::drag_to(const Vec3& position, double pixel) {
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
        if (pixel > 0.0 && std::isfinite(pixel)) {
            // A drag is only as precise as a pixel: no digits beyond it in the file.
            wanted.x = round_to_pixel(wanted.x, pixel);
            wanted.y = round_to_pixel(wanted.y, pixel);
        }
    } else {
        if (!is_live(doc_.mesh, s)) {
            return {};
        }
        target = &doc_.mesh.position(Vertex(drag_index_));
    }
    if (*target == wanted) {
        return {};
    }
    const bool curve = doc_.mode == Mode::Curve;
    if (!drag_) {
        // One undo step per drag, begun on its first move. A mesh vertex's drag is recorded
        // (the vertex's values, a few dozen bytes, whatever the mesh); a control point's
        // curve is small enough to snapshot.
        drag_ = std::make_unique<Transaction>(
            ledger_, doc_, curve ? Transaction::Kind::Snapshot : Transaction::Kind::Positions);
        if (!curve) {
            drag_->touch(Vertex(drag_index_));
        }
        target = curve ? &doc_.curve.control_points[drag_index_]
                       : &doc_.mesh.position(Vertex(drag_index_));
        drag_from_ = *target;
    }
    *target = wanted;
    Outcome out{curve ? unsigned{kCurve} : unsigned{kGeometry},
                "moving " + moved_by(curve, drag_index_, wanted - drag_from_)};
    if (!curve) {
        out.region = MeshChange::Region{{}, {Vertex(drag_index_)}};
    }
    return out;
}

Outcome Editor::end_drag() {
    dragging_ = false;
    if (!drag_) {
        return {};
    }
    std::unique_ptr<Transaction> transaction = std::move(drag_);
    const bool curve = doc_.mode == Mode::Curve;
    const Vec3 now =
        curve ? doc_.curve.control_points[drag_index_] : doc_.mesh.position(Vertex(drag_index_));
    std::vector<std::string> steps;
    if (!curve) {
        steps.push_back(move_step(doc_.mesh, drag_index_));  // one step per drag: where it ends
    }
    Outcome out = transaction->commit(
        kSelection,
        "moved " + moved_by(curve, drag_index_, now - drag_from_) + " (Ctrl+Z undoes it)",
        std::move(steps));
    out.region.reset();  // every move drew itself already
    return out;
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
