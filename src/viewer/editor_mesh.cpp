// The editor's mesh edits: every key that changes the mesh runs a verb of the edit language
// (meshedit/ops/ops.h) through the edit funnel, on the selected edge or the whole mesh.

#include "meshedit/ops/ops.h"
#include "meshedit/viewer/editor.h"

namespace meshedit::viewer {

Outcome Editor::edit_mesh(std::string_view name) {
    const ops::Verb* verb = ops::find_verb(name);
    if (verb == nullptr) {
        return refused("no such edit: '" + std::string(name) + "'");
    }
    const Mesh& mesh = doc_.mesh;
    Edge e;
    if (verb->shape == ops::Shape::Edge) {
        // A selected halfedge stands for its edge, as in CS184.
        const ElementRef& s = doc_.selection;
        if (s.kind == ElementRef::Kind::Edge && is_live(mesh, s)) {
            e = Edge(s.index);
        } else if (s.kind == ElementRef::Kind::Halfedge && is_live(mesh, s)) {
            e = Mesh::edge(Halfedge(s.index));
        } else {
            return refused("select an edge first (click near an edge)");
        }
    }
    const ops::Step step = ops::make_step(name, mesh, e);
    return edit([&] { return verb->check(doc_.mesh, step); },
                [&](Document& doc) {
                    const ops::StepResult result = verb->run(doc.mesh, step, {});
                    Edited edited;
                    edited.message = result.message;
                    edited.changes =
                        result.topology ? kTopology | kSelection : kSelection | kDisplay;
                    if (!result.selected.is_none()) {
                        edited.select = result.selected;
                    } else if (result.renumbers && doc.selection.kind != ElementRef::Kind::Vertex) {
                        edited.select = ElementRef{};  // only vertices keep their numbers
                    }
                    return edited;
                });
}

void Editor::compact() {
    if (doc_.mode == Mode::Curve || !doc_.mesh.has_garbage()) {
        return;
    }
    GarbageCollectionMap map;
    doc_.mesh.garbage_collection(&map);
    doc_.selection = remap(doc_.selection, map);
    hover_ = {};
}

}  // namespace meshedit::viewer
