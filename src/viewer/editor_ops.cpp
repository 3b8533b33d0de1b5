// The editor's document commands: local operations and Loop on the selected edge or the
// whole mesh, moving the selection through the connectivity, curve and surface commands.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/viewer/editor.h"

namespace meshedit::viewer {

namespace {

using Kind = ElementRef::Kind;

/// Loop refuses results above this many faces (about 6 GB of mesh).
constexpr std::size_t kMaxLoopFaces = std::size_t{64} << 20;

/// Surface tessellation densities the +/- keys step through.
constexpr std::array<int, 12> kDensities{1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64};

Outcome refused(std::string message) {
    return {kNothing, std::move(message), true};
}

/// "cannot flip a boundary edge" stays as it is; "edge is deleted" becomes "cannot flip: edge
/// is deleted".
std::string refusal(std::string_view verb, std::string_view reason) {
    if (reason.rfind("cannot", 0) == 0) {
        return std::string(reason);
    }
    return "cannot " + std::string(verb) + ": " + std::string(reason);
}

std::string idx(std::uint32_t i) {
    return std::to_string(i);
}

/// Faces after one Loop step: non-triangles are fan-triangulated first, then each triangle
/// becomes four.
std::size_t loop_face_count(const Mesh& mesh) {
    std::size_t n = 0;
    for (Face f : mesh.faces()) {
        n += 4 * (mesh.valence(f) - 2);
    }
    return n;
}

}  // namespace

void Editor::compact() {
    if (doc_.mode == Mode::Curve || !doc_.mesh.has_garbage()) {
        return;
    }
    GarbageCollectionMap map;
    doc_.mesh.garbage_collection(&map);
    doc_.selection = remap(doc_.selection, map);
    hover_ = {};
}

// ---------------------------------------------------------------------- mesh operations

Outcome Editor::run_mesh_op(Command command) {
    Mesh& mesh = doc_.mesh;

    if (command == Command::Loop) {
        if (mesh.n_faces() == 0) {
            return refused("nothing to subdivide: the mesh has no faces");
        }
        const std::size_t faces = loop_face_count(mesh);
        if (faces > kMaxLoopFaces) {
            return refused("Loop would make " + std::to_string(faces) +
                           " faces (over the 64M limit)");
        }
        // Copy first, commit after: if Loop throws (no memory, 32-bit indices exceeded) the
        // document is put back as it was.
        Document before = doc_;
        LoopReport report;
        try {
            report = loop_subdivide(mesh);
        } catch (const std::invalid_argument& e) {
            doc_ = std::move(before);
            return refused(e.what());
        } catch (const std::length_error& e) {
            doc_ = std::move(before);
            return refused(std::string("cannot subdivide: ") + e.what());
        } catch (const std::bad_alloc&) {
            doc_ = std::move(before);
            return refused("cannot subdivide: not enough memory");
        }
        commit_edit(std::move(before));
        // Loop keeps old vertex indices; every other element is renumbered.
        if (doc_.selection.kind != Kind::Vertex) {
            doc_.selection = {};
        }
        hover_ = {};
        std::string message = "Loop: " + std::to_string(mesh.n_faces()) + " faces";
        if (report.triangulated_faces > 0) {
            message += " (triangulated " + std::to_string(report.triangulated_faces) +
                       " non-triangle faces first)";
        }
        return {kTopology | kSelection, message};
    }

    // The other operations act on the selected edge (a selected halfedge stands for its edge,
    // as in CS184).
    const ElementRef& s = doc_.selection;
    Edge e;
    if (s.kind == Kind::Edge && is_live(mesh, s)) {
        e = Edge(s.index);
    } else if (s.kind == Kind::Halfedge && is_live(mesh, s)) {
        e = Mesh::edge(Halfedge(s.index));
    } else {
        return refused("select an edge first (click near an edge)");
    }

    switch (command) {
        case Command::Flip: {
            if (const OpStatus ok = is_flip_ok(mesh, e); !ok) {
                return refused(refusal("flip", ok.reason()));
            }
            begin_edit();
            flip(mesh, e);
            doc_.selection = ElementRef::edge(e);
            compact();
            return {kTopology | kSelection,
                    "flipped edge " + idx(e.idx()) + ": " + describe(mesh, ElementRef::edge(e))};
        }
        case Command::Split: {
            if (const OpStatus ok = is_split_ok(mesh, e); !ok) {
                return refused(refusal("split", ok.reason()));
            }
            begin_edit();
            const Vertex m = *split(mesh, e);
            doc_.selection = ElementRef::vertex(m);
            compact();
            return {kTopology | kSelection,
                    "split edge " + idx(e.idx()) + ": new vertex " + idx(doc_.selection.index)};
        }
        case Command::Collapse: {
            if (const OpStatus ok = is_collapse_ok(mesh, e); !ok) {
                return refused(refusal("collapse", ok.reason()));
            }
            begin_edit();
            const Vertex v = *collapse(mesh, e);
            doc_.selection = ElementRef::vertex(v);
            compact();
            return {kTopology | kSelection,
                    "collapsed edge " + idx(e.idx()) + " into vertex " + idx(doc_.selection.index)};
        }
        case Command::ToggleCrease: {
            // Boundary edges may be marked too: harmless, Loop treats them as sharp anyway,
            // and the mark survives if the boundary is later closed.
            begin_edit();
            auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
            crease[e] = crease[e] != 0 ? 0 : 1;
            return {kSelection | kDisplay,
                    "edge " + idx(e.idx()) +
                        (crease[e] != 0 ? " is now a crease" : " is no longer a crease")};
        }
        default:
            break;
    }
    return {};
}

// ---------------------------------------------------------------------------- navigation

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

// --------------------------------------------------------------------------------- curve

Outcome Editor::run_curve(Action action) {
    std::vector<Vec3>& points = doc_.curve.control_points;
    const int last_level = static_cast<int>(points.size()) - 1;
    const int level = view_.level < 0 ? last_level : std::min(view_.level, last_level);
    const auto level_message = [&] {
        return "de Casteljau level " + std::to_string(view_.level) + " of " +
               std::to_string(last_level);
    };

    switch (action.command) {
        case Command::LevelDown:
            if (level >= last_level) {
                return refused("already at the last level (B(t))");
            }
            view_.level = level + 1;
            return {kDisplay, level_message()};
        case Command::LevelUp:
            if (level <= 0) {
                return refused("already at the control polygon");
            }
            view_.level = level - 1;
            return {kDisplay, level_message()};
        case Command::ToggleCurve:
            view_.show_curve = !view_.show_curve;
            return {kDisplay, view_.show_curve ? "curve shown" : "curve hidden"};
        case Command::DecreaseT:
        case Command::IncreaseT: {
            const double step = action.command == Command::IncreaseT ? 0.01 : -0.01;
            // Rounded to 1e-9 so a hundred steps land exactly on 0 and 1.
            return set_t(std::round((view_.t + step) * 1e9) / 1e9);
        }
        case Command::AddPoint: {
            const std::size_t n = points.size();
            if (n == 0) {
                begin_edit();
                points.push_back(Vec3{});
                doc_.selection = ElementRef::vertex(Vertex(0));
                return {kCurve | kSelection | kDisplay, "added control point 0 (1 points)"};
            }
            const ElementRef& s = doc_.selection;
            const std::size_t i =
                (s.kind == Kind::Vertex && s.index < n) ? std::size_t{s.index} : n - 1;
            // Midway to the next point, or past the last one by half the last segment.
            const Vec3 p = i + 1 < n ? 0.5 * (points[i] + points[i + 1])
                           : n >= 2  ? points[i] + 0.5 * (points[i] - points[i - 1])
                                     : points[i] + Vec3{0.5, 0.0, 0.0};
            const bool at_bottom = level >= last_level;
            begin_edit();
            points.insert(points.begin() + static_cast<std::ptrdiff_t>(i + 1), p);
            doc_.selection = ElementRef::vertex(Vertex(static_cast<std::uint32_t>(i + 1)));
            if (at_bottom && view_.level >= 0) {
                view_.level = last_level + 1;  // keep showing B(t)
            }
            return {kCurve | kSelection | kDisplay, "added control point " + std::to_string(i + 1) +
                                                        " (" + std::to_string(points.size()) +
                                                        " points)"};
        }
        case Command::RemovePoint: {
            const std::size_t n = points.size();
            if (n <= 2) {
                return refused("a curve needs at least 2 control points");
            }
            const ElementRef& s = doc_.selection;
            const std::size_t i =
                (s.kind == Kind::Vertex && s.index < n) ? std::size_t{s.index} : n - 1;
            begin_edit();
            points.erase(points.begin() + static_cast<std::ptrdiff_t>(i));
            doc_.selection = {};
            view_.level = std::min(view_.level, last_level - 1);
            return {kCurve | kSelection | kDisplay, "removed control point " + std::to_string(i) +
                                                        " (" + std::to_string(points.size()) +
                                                        " points)"};
        }
        default:
            break;
    }
    return {};
}

// ------------------------------------------------------------------------------- surface

Outcome Editor::run_surface(Command command) {
    if (command == Command::ToggleNets) {
        view_.show_nets = !view_.show_nets;
        return {kDisplay, view_.show_nets ? "control nets shown" : "control nets hidden"};
    }
    int density = 0;
    if (command == Command::DensityUp) {
        const auto it = std::upper_bound(kDensities.begin(), kDensities.end(), doc_.density);
        if (it == kDensities.end()) {
            return refused("density is already at the maximum (" +
                           std::to_string(kDensities.back()) + ")");
        }
        density = *it;
    } else {
        const auto it = std::lower_bound(kDensities.begin(), kDensities.end(), doc_.density);
        if (it == kDensities.begin()) {
            return refused("density is already at the minimum (" +
                           std::to_string(kDensities.front()) + ")");
        }
        density = *(it - 1);
    }
    TessellationOptions options;
    options.density = density;
    Mesh mesh = tessellate(doc_.patches, options);
    const bool had_edits = pristine_revisions_.count(doc_.revision) == 0;
    begin_edit();
    doc_.density = density;
    doc_.mesh = std::move(mesh);
    doc_.selection = {};
    hover_ = {};
    pristine_revisions_.insert(doc_.revision);
    return {kTopology | kSelection, "density " + std::to_string(density) + ": " +
                                        std::to_string(doc_.mesh.n_faces()) + " faces" +
                                        (had_edits ? " (mesh edits replaced)" : "")};
}

}  // namespace meshedit::viewer
