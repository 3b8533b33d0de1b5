// The editor's region selection (Blender's Alt+click loop, Ctrl+Alt+click ring, L linked,
// Ctrl+numpad +/- more and less, Ctrl+I invert): the selection becomes a set
// (selection/selection.h), the set becomes the selection again, the active element kept
// where it still belongs.

#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

#include "meshedit/selection/selection.h"
#include "meshedit/viewer/editor.h"

namespace meshedit::viewer {

namespace {

using Kind = ElementRef::Kind;

// The selection as elements of one kind: a halfedge counts as its edge.
Kind kind_of(const ElementRef& e) {
    return e.kind == Kind::Halfedge ? Kind::Edge : e.kind;
}

ElementRef as_kind(const ElementRef& e) {
    return e.kind == Kind::Halfedge ? ElementRef::edge(Mesh::edge(Halfedge(e.index))) : e;
}

template <class H>
ElementSet<H> set_of(const std::vector<ElementRef>& selected, std::size_t size, Kind kind) {
    ElementSet<H> out(size);
    for (const ElementRef& e : selected) {
        if (kind_of(e) == kind) {
            out.insert(H(as_kind(e).index));
        }
    }
    return out;
}

const char* noun(Kind kind, std::size_t n) {
    const bool one = n == 1;
    return kind == Kind::Vertex ? (one ? " vertex" : " vertices")
           : kind == Kind::Edge ? (one ? " edge" : " edges")
                                : (one ? " face" : " faces");
}

}  // namespace

Outcome Editor::select_region(Command command) {
    return recorded_selection([&] { return choose_region(command); });
}

Outcome Editor::choose_region(Command command) {
    if (std::optional<Outcome> busy = refuse_if_busy()) {
        return *busy;
    }
    const Mesh& mesh = doc_.mesh;
    const std::vector<ElementRef> now = selected();
    const ElementRef active = now.empty() ? ElementRef{} : as_kind(now.back());
    const Kind kind = active.is_none() ? Kind::Face : kind_of(active);
    std::vector<ElementRef> chosen;
    std::string what;
    const auto take = [&](const auto& set, auto make) {
        for (const auto h : set.elements()) {
            chosen.push_back(make(h));
        }
    };
    const auto faces = [](Face f) { return ElementRef::face(f); };
    const auto vertices = [](Vertex v) { return ElementRef::vertex(v); };
    const auto edges = [](Edge e) { return ElementRef::edge(e); };

    switch (command) {
        case Command::SelectEdgeLoop:
        case Command::SelectEdgeRing: {
            const bool loop = command == Command::SelectEdgeLoop;
            if (active.kind != Kind::Edge) {
                return refused(std::string("select an edge first, then press ") +
                               (loop ? "Alt+E for its loop" : "Alt+Shift+E for its ring"));
            }
            const Edge e(active.index);
            for (const Edge g : loop ? edge_loop(mesh, e) : edge_ring(mesh, e)) {
                chosen.push_back(ElementRef::edge(g));
            }
            what = loop ? "selected the edge loop:" : "selected the edge ring:";
            break;
        }
        case Command::SelectLinked: {
            if (now.empty()) {
                return refused(
                    "select a face, edge or vertex first: Ctrl+Shift+L selects its piece");
            }
            // Seeds: the faces the selection touches.
            FaceSet seeds(mesh.faces_size());
            for (const ElementRef& x : now) {
                const ElementRef e = as_kind(x);
                const auto add_faces_of = [&](Vertex v) {
                    if (!mesh.is_isolated(v)) {
                        for (const Halfedge o : mesh.halfedges(v)) {
                            if (mesh.face(o).is_valid()) {
                                seeds.insert(mesh.face(o));
                            }
                        }
                    }
                };
                if (e.kind == Kind::Face) {
                    seeds.insert(Face(e.index));
                } else if (e.kind == Kind::Vertex) {
                    add_faces_of(Vertex(e.index));
                } else {
                    add_faces_of(mesh.vertex(Edge(e.index), 0));
                }
            }
            const FaceSet piece = linked_faces(mesh, seeds);
            if (kind == Kind::Face) {
                take(piece, faces);
            } else if (kind == Kind::Vertex) {
                take(vertices_of_faces(mesh, piece), vertices);
            } else {
                take(edges_of_vertices(mesh, vertices_of_faces(mesh, piece)), edges);
            }
            what = "selected the joined piece:";
            break;
        }
        case Command::SelectMore:
        case Command::SelectLess: {
            const bool more = command == Command::SelectMore;
            if (kind == Kind::Face && !now.empty()) {
                const FaceSet set = set_of<Face>(now, mesh.faces_size(), Kind::Face);
                take(more ? grow(mesh, set) : shrink(mesh, set), faces);
            } else if (kind == Kind::Vertex) {
                const VertexSet set = set_of<Vertex>(now, mesh.vertices_size(), Kind::Vertex);
                take(more ? grow(mesh, set) : shrink(mesh, set), vertices);
            } else {
                return refused(std::string("select faces or vertices first: ") +
                               (more ? "Ctrl+= grows them" : "Ctrl+- shrinks them"));
            }
            what = more ? "grew the selection to" : "shrank the selection to";
            break;
        }
        case Command::SelectPath: {
            const bool two = now.size() == 2 && kind_of(now[0]) == kind_of(now[1]) &&
                             (kind == Kind::Vertex || kind == Kind::Face);
            if (!two) {
                return refused(
                    "select two vertices or two faces first (click one, Shift+click "
                    "the other), then press Alt+P");
            }
            if (kind == Kind::Vertex) {
                const auto path =
                    shortest_vertex_path(mesh, Vertex(now[0].index), Vertex(now[1].index));
                if (!path) {
                    return refused("no path joins the two vertices: they are on separate pieces");
                }
                for (const Vertex v : *path) {
                    chosen.push_back(ElementRef::vertex(v));
                }
            } else {
                const auto path = shortest_face_path(mesh, Face(now[0].index), Face(now[1].index));
                if (!path) {
                    return refused("no path joins the two faces: they are on separate pieces");
                }
                for (const Face f : *path) {
                    chosen.push_back(ElementRef::face(f));
                }
            }
            what = "selected the shortest path:";
            break;
        }
        case Command::SelectTrait: {
            TraitQuery query = tools_.trait;
            query.direction = toward_eye_;
            switch (query.trait) {
                case Trait::Valence:
                    take(vertices_with(mesh, query), vertices);
                    what = "selected the vertices of valence " + std::to_string(query.k) + ":";
                    break;
                case Trait::Degree:
                    take(faces_with(mesh, query), faces);
                    what = "selected the faces of " + std::to_string(query.k) + " corners:";
                    break;
                case Trait::Crease:
                    take(edges_with(mesh, query), edges);
                    what = "selected the crease edges:";
                    break;
                case Trait::FacingAway:
                    take(faces_with(mesh, query), faces);
                    what = "selected the faces turned away from you by more than " +
                           number_text(query.angle_deg) + "°:";
                    break;
                case Trait::Boundary:
                    if (kind == Kind::Vertex) {
                        take(vertices_with(mesh, query), vertices);
                    } else if (kind == Kind::Edge) {
                        take(edges_with(mesh, query), edges);
                    } else {
                        take(faces_with(mesh, query), faces);
                    }
                    what = "selected the border:";
                    break;
            }
            break;
        }
        case Command::SelectInvert:
            if (kind == Kind::Vertex) {
                take(invert(mesh, set_of<Vertex>(now, mesh.vertices_size(), kind)), vertices);
            } else if (kind == Kind::Edge) {
                take(invert(mesh, set_of<Edge>(now, mesh.edges_size(), kind)), edges);
            } else {
                take(invert(mesh, set_of<Face>(now, mesh.faces_size(), kind)), faces);
            }
            what = "inverted the selection:";
            break;
        default:
            return {};
    }
    if (chosen.empty()) {
        doc_.selection = {};
        doc_.also_selected.clear();
        return {kSelection, what + " nothing (the selection is empty)"};
    }
    // The active element stays active where the result still holds it.
    std::size_t at = chosen.size() - 1;
    for (std::size_t i = 0; i < chosen.size(); ++i) {
        if (chosen[i].kind == active.kind && chosen[i].index == active.index) {
            at = i;
        }
    }
    doc_.selection = chosen[at];
    chosen.erase(chosen.begin() + static_cast<std::ptrdiff_t>(at));
    doc_.also_selected = std::move(chosen);
    const std::size_t n = doc_.also_selected.size() + 1;
    return {kSelection, what + " " + std::to_string(n) + noun(kind_of(doc_.selection), n)};
}

ElementRef::Kind Editor::region_kind() const {
    const std::vector<ElementRef> now = selected();
    return now.empty() ? Kind::Face : kind_of(now.back());
}

Outcome Editor::select_elements(const std::vector<ElementRef>& elements, bool add,
                                const std::string& what) {
    if (std::optional<Outcome> busy = refuse_if_busy()) {
        return *busy;
    }
    std::vector<ElementRef> chosen = add ? selected() : std::vector<ElementRef>{};
    const auto key = [](const ElementRef& e) {
        const ElementRef k = as_kind(e);
        return (std::uint64_t{static_cast<unsigned>(k.kind)} << 32) | k.index;
    };
    std::unordered_set<std::uint64_t> have;
    for (const ElementRef& e : chosen) {
        have.insert(key(e));
    }
    for (const ElementRef& e : elements) {
        if (is_live(doc_.mesh, e) && have.insert(key(e)).second) {
            chosen.push_back(e);
        }
    }
    return recorded_selection([&] {
        return take_selection(std::move(chosen), what + ": nothing inside (the selection is empty)",
                              what + ": ", add ? " selected in all" : " selected");
    });
}

Outcome Editor::take_selection(std::vector<ElementRef> chosen, const std::string& if_empty,
                               const std::string& before, const std::string& after) {
    if (chosen.empty()) {
        doc_.selection = {};
        doc_.also_selected.clear();
        return {kSelection, if_empty};
    }
    doc_.selection = chosen.back();  // the last one is active
    chosen.pop_back();
    doc_.also_selected = std::move(chosen);
    const std::size_t n = doc_.also_selected.size() + 1;
    return {kSelection, before + std::to_string(n) + noun(kind_of(doc_.selection), n) + after};
}

Outcome Editor::deselect_elements(const std::vector<ElementRef>& elements,
                                  const std::string& what) {
    if (std::optional<Outcome> busy = refuse_if_busy()) {
        return *busy;
    }
    const auto key = [](const ElementRef& e) {
        const ElementRef k = as_kind(e);
        return (std::uint64_t{static_cast<unsigned>(k.kind)} << 32) | k.index;
    };
    std::unordered_set<std::uint64_t> gone;
    for (const ElementRef& e : elements) {
        gone.insert(key(e));
    }
    std::vector<ElementRef> kept;
    for (const ElementRef& e : selected()) {
        if (gone.count(key(e)) == 0) {
            kept.push_back(e);
        }
    }
    return recorded_selection([&] {
        return take_selection(std::move(kept), what + ": the selection is empty", what + ": ",
                              " selected");
    });
}

}  // namespace meshedit::viewer
