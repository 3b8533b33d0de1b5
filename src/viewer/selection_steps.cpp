// Running a verb of the edit language on every selected element (selection_steps.h).

#include "selection_steps.h"

#include <algorithm>

namespace meshedit::viewer {

namespace {

using Kind = ElementRef::Kind;

// The element as a verb of the language names it: a halfedge by its edge.
ElementRef as_target(const ElementRef& e) {
    return e.kind == Kind::Halfedge ? ElementRef::edge(Mesh::edge(Halfedge(e.index))) : e;
}

ops::Target target_of(Kind kind) {
    switch (kind) {
        case Kind::Vertex:
            return ops::Target::Vertex;
        case Kind::Edge:
        case Kind::Halfedge:
            return ops::Target::Edge;
        case Kind::Face:
            return ops::Target::Face;
        case Kind::None:
            break;
    }
    return ops::Target::None;
}

std::string what_to_select(const ops::Verb& verb) {
    if ((verb.takes & ops::kEdgePair) != 0) {
        return "select two boundary edges first (click one, Shift+click the other)";
    }
    std::vector<std::string> kinds;
    if ((verb.takes & ops::kVertexArg) != 0) {
        kinds.emplace_back("a vertex");
    }
    if ((verb.takes & ops::kEdgeArg) != 0) {
        kinds.emplace_back("an edge");
    }
    if ((verb.takes & ops::kFaceArg) != 0) {
        kinds.emplace_back("a face");
    }
    if ((verb.takes & ops::kRegion) != 0) {
        kinds.emplace_back("faces (click, Shift+click, B or Ctrl+right-drag)");
    }
    std::string out = "select ";
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        out += i == 0 ? "" : (i + 1 == kinds.size() ? " or " : ", ");
        out += kinds[i];
    }
    return out + " first";
}

}  // namespace

std::vector<ops::Step> steps_for_selection(const Mesh& mesh, const ops::Verb& verb,
                                           const std::vector<ElementRef>& selected,
                                           std::span<const double> amounts, std::string& hint) {
    std::vector<ops::Step> steps;
    if ((verb.takes & ops::kRegion) != 0) {  // one step on every selected face
        std::vector<Face> faces;
        for (const ElementRef& e : selected) {
            if (e.kind == Kind::Face) {
                faces.push_back(Face(e.index));
            }
        }
        if (faces.empty()) {
            hint = what_to_select(verb);
        } else {
            steps.push_back(ops::make_region_step(verb.name, faces, amounts));
        }
        return steps;
    }
    if ((verb.takes & ops::kEdgePair) != 0) {
        std::vector<ElementRef> edges;
        for (const ElementRef& e : selected) {
            if (target_of(e.kind) == ops::Target::Edge) {
                edges.push_back(as_target(e));
            }
        }
        if (edges.size() == 2) {
            // The active edge (clicked last) is the one welded onto the other.
            steps.push_back(ops::make_step(verb.name, mesh, edges[1], amounts, edges[0]));
        } else {
            hint = what_to_select(verb) + (edges.size() > 2
                                               ? " (" + std::to_string(edges.size()) +
                                                     " edges are selected; weld takes two)"
                                               : "");
        }
        return steps;
    }
    for (const ElementRef& e : selected) {
        if (verb.accepts(target_of(e.kind))) {
            steps.push_back(ops::make_step(verb.name, mesh, as_target(e), amounts));
        }
    }
    if (steps.empty()) {
        hint = what_to_select(verb);
    }
    return steps;
}

std::vector<std::uint32_t> selected_vertices(const Mesh& mesh,
                                             const std::vector<ElementRef>& selected) {
    std::vector<std::uint32_t> out;
    for (const ElementRef& e : selected) {
        switch (e.kind) {
            case Kind::Vertex:
                out.push_back(e.index);
                break;
            case Kind::Edge:
            case Kind::Halfedge: {
                const Edge edge =
                    e.kind == Kind::Edge ? Edge(e.index) : Mesh::edge(Halfedge(e.index));
                out.push_back(mesh.vertex(edge, 0).idx());
                out.push_back(mesh.vertex(edge, 1).idx());
                break;
            }
            case Kind::Face:
                for (const Vertex v : mesh.vertices(Face(e.index))) {
                    out.push_back(v.idx());
                }
                break;
            case Kind::None:
                break;
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

StepsRun run_steps(Mesh& mesh, const std::vector<ops::Step>& steps, std::string_view what) {
    ops::StepsRun done = ops::run_steps(mesh, steps, ops::OnRefusal::Skip);
    StepsRun run;
    run.ran = done.ran;
    run.refused = done.refused;
    run.first_refusal = std::move(done.first_refusal);
    run.made = std::move(done.made);
    run.done = done.done;
    for (const ops::Step* step : done.done) {
        run.steps.push_back(step->text);
    }
    if (run.ran == 1 && run.refused == 0) {
        run.message = std::move(done.last_message);
    } else if (run.ran > 0) {
        run.message = std::string(what) + ": " + std::to_string(run.ran) + " of " +
                      std::to_string(steps.size()) + " done";
        if (run.refused > 0) {
            run.message +=
                " (" + std::to_string(run.refused) + " refused; first: " + run.first_refusal + ")";
        }
    }
    return run;
}

}  // namespace meshedit::viewer

namespace meshedit::viewer {

std::string move_step(const Mesh& mesh, std::uint32_t v) {
    const Vec3& p = mesh.position(Vertex(v));
    const double at[] = {p.x, p.y, p.z};
    return ops::make_step("move", mesh, ElementRef::vertex(Vertex(v)), at).text;
}

void select_made(Document& doc, const std::vector<ElementRef>& made) {
    doc.selection = made.empty() ? ElementRef{} : made.back();
    doc.also_selected.assign(made.begin(), made.end() - (made.empty() ? 0 : 1));
}

}  // namespace meshedit::viewer
