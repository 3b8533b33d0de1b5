// The region verbs and the selection verbs of the edit language (region_verbs.h): each
// translates between a step and meshedit_selection's functions.

#include "region_verbs.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "meshedit/core/simplify.h"
#include "meshedit/core/smoothing.h"
#include "meshedit/selection/region_ops.h"
#include "meshedit/selection/selection.h"
#include "phase_verbs.h"

namespace meshedit::ops {
namespace {

FaceSet region_of(const Mesh& mesh, const Step& step) {
    FaceSet out(mesh.faces_size());
    for (const Face f : named_faces(mesh, step)) {
        out.insert(f);
    }
    return out;
}

// The region's faces after a region step: the first selected, the rest with it.
StepResult region_result(const std::vector<Face>& faces, std::string message) {
    StepResult result = local(ElementRef::face(faces.front()), std::move(message));
    for (std::size_t i = 1; i < faces.size(); ++i) {
        result.selected_too.push_back(ElementRef::face(faces[i]));
    }
    return result;
}

std::string count_faces(std::size_t n) {
    return std::to_string(n) + (n == 1 ? " face" : " faces");
}

using Kind = ElementRef::Kind;

template <class H>
ElementSet<H> set_of(const Selection& now, Kind kind, std::size_t size) {
    ElementSet<H> out(size);
    if (now.kind == kind) {
        for (const std::uint32_t i : now.indices) {
            if (i < size) {
                out.insert(H(i));
            }
        }
    }
    return out;
}

template <class H>
Selection selection_of(const ElementSet<H>& set, Kind kind) {
    Selection out;
    out.kind = kind;
    for (const H h : set.elements()) {
        out.indices.push_back(h.idx());
    }
    return out;
}

// The faces the selection touches: its faces, or the faces around its vertices or edges.
FaceSet faces_touched(const Mesh& mesh, const Selection& now) {
    FaceSet out(mesh.faces_size());
    const auto around = [&](Vertex v) {
        if (!mesh.is_deleted(v) && !mesh.is_isolated(v)) {
            for (const Halfedge h : mesh.halfedges(v)) {
                if (mesh.face(h).is_valid()) {
                    out.insert(mesh.face(h));
                }
            }
        }
    };
    for (const std::uint32_t i : now.indices) {
        if (now.kind == Kind::Face && i < mesh.faces_size() && !mesh.is_deleted(Face(i))) {
            out.insert(Face(i));
        } else if (now.kind == Kind::Vertex && i < mesh.vertices_size()) {
            around(Vertex(i));
        } else if (now.kind == Kind::Edge && i < mesh.edges_size() && !mesh.is_deleted(Edge(i))) {
            around(mesh.vertex(Edge(i), 0));
        }
    }
    return out;
}

}  // namespace

OpStatus check_extrude_region(const Mesh& mesh, const Step& step) {
    return is_extrude_region_ok(mesh, region_of(mesh, step), step.amounts[0]);
}
StepResult run_extrude_region(Mesh& mesh, const Step& step, const RunOptions&) {
    const std::vector<Face> faces = named_faces(mesh, step);
    RegionExtrude made;
    extrude_region(mesh, region_of(mesh, step), step.amounts[0], &made);
    return region_result(faces, "extruded " + count_faces(faces.size()) + " as one region by " +
                                    number_text(step.amounts[0]) + ": " +
                                    std::to_string(made.sides.size()) + " walls");
}

OpStatus check_inset_region(const Mesh& mesh, const Step& step) {
    return is_inset_region_ok(mesh, region_of(mesh, step), step.amounts[0]);
}
StepResult run_inset_region(Mesh& mesh, const Step& step, const RunOptions&) {
    const std::vector<Face> faces = named_faces(mesh, step);
    RegionInset made;
    inset_region(mesh, region_of(mesh, step), step.amounts[0], &made);
    return region_result(faces, "inset " + count_faces(faces.size()) + " as one region by " +
                                    number_text(step.amounts[0]) + ": a ring of " +
                                    std::to_string(made.border.size()) + " quads");
}

namespace {

// simplify_region:R:K keeps about K (0 < K < 1) of the faces R, collapsing only edges between
// their inner vertices (region_inner_vertices()): the region's border and the rest stay.
struct RegionSimplify {
    SimplifyOptions options;
    std::vector<Face> faces;
    std::string why;
};
RegionSimplify region_simplify(const Mesh& mesh, const Step& step) {
    RegionSimplify r;
    r.faces = named_faces(mesh, step);
    const double k = step.amounts[0];
    if (!(k > 0.0 && k < 1.0)) {
        r.why =
            "cannot simplify the region: keep a share of its faces above 0 and below 1, "
            "not " +
            number_text(k);
        return r;
    }
    r.options.vertices = region_inner_vertices(mesh, r.faces);
    if (r.options.vertices.empty()) {
        r.why = "cannot simplify the region: every vertex of the " + count_faces(r.faces.size()) +
                " is on their border (select the faces around a vertex too)";
        return r;
    }
    const auto drop =
        static_cast<std::size_t>(std::round(static_cast<double>(r.faces.size()) * (1.0 - k)));
    if (drop == 0) {
        r.why = "cannot simplify the region: keeping " + number_text(k) + " of " +
                count_faces(r.faces.size()) + " removes none";
        return r;
    }
    r.options.target_faces = mesh.n_faces() - std::min(drop, mesh.n_faces() - 1);
    return r;
}

}  // namespace

OpStatus check_simplify_region(const Mesh& mesh, const Step& step) {
    if (const OpStatus why = phased_loop_refusal(mesh, "simplify"); !why) {
        return why;
    }
    const RegionSimplify r = region_simplify(mesh, step);
    if (!r.why.empty()) {
        return OpStatus::composed(r.why);
    }
    return check_simplify(mesh, r.options);
}
StepResult run_simplify_region(Mesh& mesh, const Step& step, const RunOptions& options) {
    RegionSimplify r = region_simplify(mesh, step);
    r.options.progress = options.progress;
    const std::size_t before = mesh.n_faces();
    const SimplifyReport report = simplify(mesh, r.options);
    std::vector<Face> kept;
    for (const Face f : r.faces) {
        if (!mesh.is_deleted(f)) {
            kept.push_back(f);
        }
    }
    const std::size_t removed = before - mesh.n_faces();
    std::string message = "simplified the region of " + count_faces(r.faces.size()) + " to " +
                          std::to_string(r.faces.size() - removed) + " (" +
                          std::to_string(report.collapses) + " collapses; its border and the " +
                          "rest unchanged)";
    if (report.stopped_early) {
        message += "; stopped early: no further collapse inside it keeps the mesh valid";
    }
    StepResult result = kept.empty() ? local(ElementRef{}, message) : region_result(kept, message);
    return result;
}

OpStatus check_dissolve_region(const Mesh& mesh, const Step& step) {
    return is_dissolve_region_ok(mesh, region_of(mesh, step));
}
StepResult run_dissolve_region(Mesh& mesh, const Step& step, const RunOptions&) {
    const std::size_t before = named_faces(mesh, step).size();
    std::vector<Face> merged;
    dissolve_region(mesh, region_of(mesh, step), &merged);
    return region_result(merged, "dissolved " + count_faces(before) + " into " +
                                     count_faces(merged.size()) + " (one per piece)");
}

namespace {

StepResult run_region_scheme(Mesh& mesh, const Step& step, RegionScheme scheme) {
    const std::size_t before = named_faces(mesh, step).size();
    std::vector<Face> inside;
    subdivide_region(mesh, region_of(mesh, step), &inside, scheme);
    const char* how = scheme == RegionScheme::Loop           ? " (Loop inside)"
                      : scheme == RegionScheme::CatmullClark ? " (Catmull-Clark inside)"
                                                             : "";
    return region_result(inside, "subdivided " + count_faces(before) + " into " +
                                     std::to_string(inside.size()) + how +
                                     ", their neighbours cut into fans of triangles");
}

}  // namespace

OpStatus check_subdivide_region(const Mesh& mesh, const Step& step) {
    return is_subdivide_region_ok(mesh, region_of(mesh, step));
}
StepResult run_subdivide_region(Mesh& mesh, const Step& step, const RunOptions&) {
    return run_region_scheme(mesh, step, RegionScheme::Linear);
}
OpStatus check_loop_region(const Mesh& mesh, const Step& step) {
    return is_subdivide_region_ok(mesh, region_of(mesh, step), RegionScheme::Loop);
}
StepResult run_loop_region(Mesh& mesh, const Step& step, const RunOptions&) {
    return run_region_scheme(mesh, step, RegionScheme::Loop);
}
OpStatus check_catmull_clark_region(const Mesh& mesh, const Step& step) {
    return is_subdivide_region_ok(mesh, region_of(mesh, step), RegionScheme::CatmullClark);
}
StepResult run_catmull_clark_region(Mesh& mesh, const Step& step, const RunOptions&) {
    return run_region_scheme(mesh, step, RegionScheme::CatmullClark);
}

// ------------------------------------------------------------------ selection verbs

namespace {

// What a `select` step lists, as indices of its kind. \throws OpError (not a refusal) for an
// element the mesh does not have.
Selection listed(const Mesh& mesh, const Step& step) {
    if (step.region_kind == Kind::Face) {
        Selection out;
        for (const Face f : named_faces(mesh, step)) {
            out.indices.push_back(f.idx());
        }
        return out;
    }
    Selection out{step.region_kind, {}};
    Step one;  // each element as a step of its own, for named_edge()'s and named_vertex()'s errors
    one.verb = step.verb;
    one.text = step.text;
    one.target = step.region_kind == Kind::Edge ? Target::Edge : Target::Vertex;
    for (const auto& [a, b] : step.region) {
        if (step.region_kind == Kind::Edge) {
            one.a = a;
            one.b = b;
            out.indices.push_back(named_edge(mesh, one).idx());
            continue;
        }
        for (std::uint64_t v = a; v <= b; ++v) {
            one.a = static_cast<std::uint32_t>(v);
            out.indices.push_back(named_vertex(mesh, one).idx());
        }
    }
    return out;
}

}  // namespace

OpStatus check_select(const Mesh& mesh, const Step& step) {
    if (step.target == Target::Region) {
        listed(mesh, step);  // throws for an element the mesh does not have
    } else if (step.target == Target::Edge) {
        named_edge(mesh, step);
    }
    return OpStatus::ok();
}
StepResult run_select(Mesh&, const Step& step, const RunOptions&) {
    return local({}, "selection: " + step.text, false);
}

Selection select_listed(const Mesh& mesh, const Step& step, const Selection&) {
    return listed(mesh, step);
}
Selection select_none(const Mesh&, const Step&, const Selection&) {
    return {};
}
Selection select_loop(const Mesh& mesh, const Step& step, const Selection&) {
    Selection out{Kind::Edge, {}};
    for (const Edge e : edge_loop(mesh, named_edge(mesh, step))) {
        out.indices.push_back(e.idx());
    }
    return out;
}
Selection select_ring(const Mesh& mesh, const Step& step, const Selection&) {
    Selection out{Kind::Edge, {}};
    for (const Edge e : edge_ring(mesh, named_edge(mesh, step))) {
        out.indices.push_back(e.idx());
    }
    return out;
}
Selection select_linked(const Mesh& mesh, const Step&, const Selection& now) {
    return selection_of(linked_faces(mesh, faces_touched(mesh, now)), Kind::Face);
}
Selection select_more(const Mesh& mesh, const Step&, const Selection& now) {
    if (now.kind == Kind::Vertex) {
        return selection_of(grow(mesh, set_of<Vertex>(now, Kind::Vertex, mesh.vertices_size())),
                            Kind::Vertex);
    }
    return selection_of(grow(mesh, faces_touched(mesh, now)), Kind::Face);
}
Selection select_less(const Mesh& mesh, const Step&, const Selection& now) {
    if (now.kind == Kind::Vertex) {
        return selection_of(shrink(mesh, set_of<Vertex>(now, Kind::Vertex, mesh.vertices_size())),
                            Kind::Vertex);
    }
    return selection_of(shrink(mesh, set_of<Face>(now, Kind::Face, mesh.faces_size())), Kind::Face);
}
Selection select_invert(const Mesh& mesh, const Step&, const Selection& now) {
    if (now.kind == Kind::Vertex) {
        return selection_of(invert(mesh, set_of<Vertex>(now, Kind::Vertex, mesh.vertices_size())),
                            Kind::Vertex);
    }
    if (now.kind == Kind::Edge) {
        return selection_of(invert(mesh, set_of<Edge>(now, Kind::Edge, mesh.edges_size())),
                            Kind::Edge);
    }
    return selection_of(invert(mesh, set_of<Face>(now, Kind::Face, mesh.faces_size())), Kind::Face);
}
Selection select_boundary(const Mesh& mesh, const Step&, const Selection&) {
    return selection_of(faces_with(mesh, {meshedit::Trait::Boundary}), Kind::Face);
}
Selection select_creases(const Mesh& mesh, const Step&, const Selection&) {
    return selection_of(edges_with(mesh, {meshedit::Trait::Crease}), Kind::Edge);
}
Selection select_valence(const Mesh& mesh, const Step& step, const Selection&) {
    TraitQuery q{meshedit::Trait::Valence};
    q.k = static_cast<std::size_t>(std::max(0.0, step.amounts[0]));
    return selection_of(vertices_with(mesh, q), Kind::Vertex);
}
Selection select_degree(const Mesh& mesh, const Step& step, const Selection&) {
    TraitQuery q{meshedit::Trait::Degree};
    q.k = static_cast<std::size_t>(std::max(0.0, step.amounts[0]));
    return selection_of(faces_with(mesh, q), Kind::Face);
}

}  // namespace meshedit::ops
