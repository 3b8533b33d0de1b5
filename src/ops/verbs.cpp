// The table of verbs: each row names a core operation and says how it is written, checked,
// run and described. The functions here only translate between a step and the core's API;
// the operations themselves, with their predicates and diagrams, are in src/local_ops
// and src/algorithms.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/loop_steps.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/simplify.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/ops/ops.h"
#include "phase_verbs.h"
#include "reduce_verbs.h"
#include "region_verbs.h"
#include "repair_verbs.h"
#include "smooth_verbs.h"

namespace meshedit::ops {
namespace {

std::string idx(std::uint32_t i) {
    return std::to_string(i);
}

// The result of an op that deletes elements is named by its size, not its index: the viewer
// renumbers when it saves, so an index in its status line could later name another element.
std::string corners(const Mesh& mesh, Face f) {
    return std::to_string(mesh.valence(f)) + " corners";
}

// ------------------------------------------------------------------ local operations

OpStatus check_flip(const Mesh& mesh, const Step& step) {
    return is_flip_ok(mesh, named_edge(mesh, step));
}
StepResult run_flip(Mesh& mesh, const Step& step, const RunOptions&) {
    const Edge e = named_edge(mesh, step);
    flip(mesh, e);
    return local(ElementRef::edge(e),
                 "flipped edge " + idx(e.idx()) + ": " + describe(mesh, ElementRef::edge(e)));
}

OpStatus check_split(const Mesh& mesh, const Step& step) {
    return is_split_ok(mesh, named_edge(mesh, step));
}
StepResult run_split(Mesh& mesh, const Step& step, const RunOptions&) {
    const Edge e = named_edge(mesh, step);
    const Vertex m = *split(mesh, e);
    return local(ElementRef::vertex(m),
                 "split edge " + idx(e.idx()) + ": new vertex " + idx(m.idx()));
}

OpStatus check_bisect(const Mesh& mesh, const Step& step) {
    return is_bisect_ok(mesh, named_edge(mesh, step));
}
StepResult run_bisect(Mesh& mesh, const Step& step, const RunOptions&) {
    const Edge e = named_edge(mesh, step);
    const Vertex m = *bisect(mesh, e);
    return local(ElementRef::vertex(m),
                 "bisected edge " + idx(e.idx()) + ": new vertex " + idx(m.idx()));
}

OpStatus check_collapse(const Mesh& mesh, const Step& step) {
    if (step.target == Target::Face) {
        return is_collapse_face_ok(mesh, named_face(mesh, step));
    }
    return is_collapse_ok(mesh, named_edge(mesh, step));
}
StepResult run_collapse(Mesh& mesh, const Step& step, const RunOptions&) {
    if (step.target == Target::Face) {
        const Face f = named_face(mesh, step);
        const Vertex v = *collapse_face(mesh, f);
        return local(ElementRef::vertex(v),
                     "collapsed face " + idx(f.idx()) + " into vertex " + idx(v.idx()));
    }
    const Edge e = named_edge(mesh, step);
    const Vertex v = *collapse(mesh, e);
    return local(ElementRef::vertex(v),
                 "collapsed edge " + idx(e.idx()) + " into vertex " + idx(v.idx()));
}

OpStatus check_dissolve(const Mesh& mesh, const Step& step) {
    if (step.target == Target::Vertex) {
        return is_dissolve_vertex_ok(mesh, named_vertex(mesh, step));
    }
    return is_dissolve_edge_ok(mesh, named_edge(mesh, step));
}
StepResult run_dissolve(Mesh& mesh, const Step& step, const RunOptions&) {
    if (step.target == Target::Vertex) {
        const Vertex v = named_vertex(mesh, step);
        const Face f = *dissolve_vertex(mesh, v);
        return local(ElementRef::face(f), "dissolved vertex " + idx(v.idx()) +
                                              ": its faces are one face of " + corners(mesh, f) +
                                              " (selected)");
    }
    const Edge e = named_edge(mesh, step);
    const Face f = *dissolve_edge(mesh, e);
    if (!f.is_valid()) {
        return local({}, "dissolved boundary edge " + idx(e.idx()) + ": its face joined the hole");
    }
    return local(ElementRef::face(f), "dissolved edge " + idx(e.idx()) +
                                          ": its faces are one face of " + corners(mesh, f) +
                                          " (selected)");
}

OpStatus check_make_boundary(const Mesh& mesh, const Step& step) {
    return is_make_boundary_ok(mesh, named_face(mesh, step));
}
StepResult run_make_boundary(Mesh& mesh, const Step& step, const RunOptions&) {
    const Face f = named_face(mesh, step);
    const Halfedge h = *make_boundary(mesh, f);
    return local(h.is_valid() ? ElementRef::edge(Mesh::edge(h)) : ElementRef{},
                 "face " + idx(f.idx()) + " is now a hole");
}

OpStatus check_fill(const Mesh& mesh, const Step& step) {
    const Edge e = named_edge(mesh, step);
    if (const OpStatus on_hole = check_on_a_hole(mesh, e); !on_hole) {
        return on_hole;
    }
    return is_fill_hole_ok(mesh, hole_side(mesh, e));
}
StepResult run_fill(Mesh& mesh, const Step& step, const RunOptions&) {
    const Face f = *fill_hole(mesh, hole_side(mesh, named_edge(mesh, step)));
    return local(ElementRef::face(f), "filled the hole with face " + idx(f.idx()) + " (" +
                                          std::to_string(mesh.valence(f)) + " corners)");
}

OpStatus check_weld(const Mesh& mesh, const Step& step) {
    return is_weld_ok(mesh, named_edge(mesh, step), named_second_edge(mesh, step));
}
StepResult run_weld(Mesh& mesh, const Step& step, const RunOptions&) {
    const Edge e1 = named_edge(mesh, step);
    const Edge e2 = named_second_edge(mesh, step);
    weld(mesh, e1, e2);
    return local(ElementRef::edge(e1), "welded edges " + idx(e2.idx()) + " and " + idx(e1.idx()) +
                                           " into one edge (selected)");
}

OpStatus check_poke(const Mesh& mesh, const Step& step) {
    return is_poke_ok(mesh, named_face(mesh, step));
}
StepResult run_poke(Mesh& mesh, const Step& step, const RunOptions&) {
    const Face f = named_face(mesh, step);
    const std::size_t n = mesh.valence(f);
    const Vertex c = *poke(mesh, f);
    return local(ElementRef::vertex(c), "poked face " + idx(f.idx()) + ": vertex " + idx(c.idx()) +
                                            " in a fan of " + std::to_string(n) + " triangles");
}

OpStatus check_extrude(const Mesh& mesh, const Step& step) {
    return is_extrude_ok(mesh, named_face(mesh, step), step.amounts[0], step.amounts[1]);
}
StepResult run_extrude(Mesh& mesh, const Step& step, const RunOptions&) {
    const Face f = *extrude_face(mesh, named_face(mesh, step), step.amounts[0], step.amounts[1]);
    return local(ElementRef::face(f), "extruded face " + idx(f.idx()) + " by " +
                                          number_text(step.amounts[0]) + ", shrink " +
                                          number_text(step.amounts[1]));
}

OpStatus check_inset(const Mesh& mesh, const Step& step) {
    return is_inset_ok(mesh, named_face(mesh, step), step.amounts[0]);
}
StepResult run_inset(Mesh& mesh, const Step& step, const RunOptions&) {
    const Face f = *inset_face(mesh, named_face(mesh, step), step.amounts[0]);
    return local(ElementRef::face(f),
                 "inset face " + idx(f.idx()) + ", shrink " + number_text(step.amounts[0]));
}

OpStatus check_bevel(const Mesh& mesh, const Step& step) {
    if (step.target == Target::Vertex) {
        return is_bevel_vertex_ok(mesh, named_vertex(mesh, step), step.amounts[0]);
    }
    return is_bevel_edge_ok(mesh, named_edge(mesh, step), step.amounts[0]);
}
StepResult run_bevel(Mesh& mesh, const Step& step, const RunOptions&) {
    const double t = step.amounts[0];
    const bool vertex = step.target == Target::Vertex;
    const std::string what =
        vertex ? "vertex " + idx(step.a) : "edge " + idx(named_edge(mesh, step).idx());
    const Face f = vertex ? *bevel_vertex(mesh, named_vertex(mesh, step), t)
                          : *bevel_edge(mesh, named_edge(mesh, step), t);
    return local(ElementRef::face(f), "bevelled " + what + " at " + number_text(t) +
                                          ": a new face of " + corners(mesh, f) + " (selected)");
}

// Boundary edges may be marked too: harmless, Loop treats them as sharp anyway, and the
// mark survives if the boundary is later closed.
OpStatus check_crease(const Mesh& mesh, const Step& step) {
    named_edge(mesh, step);
    return OpStatus::ok();
}
StepResult run_crease(Mesh& mesh, const Step& step, const RunOptions&) {
    const Edge e = named_edge(mesh, step);
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    mesh.touch(e);  // a write through the property's handle: tell a recorded edit
    crease[e] = crease[e] != 0 ? 0 : 1;
    return local(
        ElementRef::edge(e),
        "edge " + idx(e.idx()) + (crease[e] != 0 ? " is now a crease" : " is no longer a crease"),
        false);
}

// move:vI:X,Y,Z: what the viewer records for a drag or a move, rotate or scale (the exact
// final position, so a replay is bit-identical).
OpStatus check_move(const Mesh& mesh, const Step& step) {
    named_vertex(mesh, step);
    const Vec3 p{step.amounts[0], step.amounts[1], step.amounts[2]};
    if (!is_finite(p)) {
        return OpStatus::refused("cannot move: the position must be finite");
    }
    if (!std::isfinite(sqrnorm(p))) {  // as a drag: normals and areas square coordinates
        return OpStatus::refused(
            "cannot move: the position is beyond the range of numbers (its square overflows)");
    }
    return OpStatus::ok();
}
StepResult run_move(Mesh& mesh, const Step& step, const RunOptions&) {
    const Vertex v = named_vertex(mesh, step);
    mesh.position(v) = {step.amounts[0], step.amounts[1], step.amounts[2]};
    return local(ElementRef::vertex(v),
                 "moved vertex " + idx(v.idx()) + " to (" + number_text(step.amounts[0]) + ", " +
                     number_text(step.amounts[1]) + ", " + number_text(step.amounts[2]) + ")");
}

// ------------------------------------------------------------------ whole-mesh operations

// compact: the numbering a file gets, now. The viewer renumbers when it saves and after a
// whole-mesh edit (local edits leave tombstones) and records this step, so a recorded session
// names the same elements on replay.
OpStatus check_compact(const Mesh&, const Step&) {
    return OpStatus::ok();
}
StepResult run_compact(Mesh& mesh, const Step&, const RunOptions&) {
    const bool had_garbage = mesh.has_garbage();
    mesh.garbage_collection();
    StepResult result;
    result.renumbers = had_garbage;
    result.topology = had_garbage;
    result.message = had_garbage ? "renumbered densely: V " + std::to_string(mesh.n_vertices()) +
                                       " E " + std::to_string(mesh.n_edges()) + " F " +
                                       std::to_string(mesh.n_faces())
                                 : "nothing to renumber (no deleted elements)";
    return result;
}

std::size_t non_triangles(const Mesh& mesh) {
    std::size_t n = 0;
    for (const Face f : mesh.faces()) {
        n += mesh.valence(f) != 3 ? 1 : 0;
    }
    return n;
}

OpStatus check_loop(const Mesh& mesh, const Step& step) {
    if (const OpStatus why = phased_loop_refusal(mesh); !why) {
        return why;
    }
    if (mesh.n_faces() == 0) {
        return OpStatus::refused("cannot subdivide: the mesh has no faces");
    }
    if (const std::size_t n = non_triangles(mesh); n > 0) {
        return OpStatus::composed(
            "cannot subdivide: Loop needs triangles and " + std::to_string(n) + " of the " +
            std::to_string(mesh.n_faces()) +
            " faces are polygons (triangulate them first: the `triangulate` step, Ctrl+T "
            "in the viewer)");
    }
    return plan_loop(mesh, step.levels).status;
}
StepResult run_loop(Mesh& mesh, const Step& step, const RunOptions& options) {
    StepResult result;
    result.renumbers = true;
    for (int level = 0; level < step.levels; ++level) {
        LoopOptions loop;
        loop.weights = options.weights;
        loop.uv = step.uv.value_or(loop.uv);
        if (options.progress) {
            loop.progress = [&](double f) { options.progress((level + f) / step.levels); };
        }
        loop_subdivide(mesh, loop);
    }
    result.message = "Loop: " + std::to_string(mesh.n_faces()) + " faces";
    return result;
}

// loop_step, loop_step:N: the next N phases of a phased Loop (core/loop_steps.h).
OpStatus check_loop_step_verb(const Mesh& mesh, const Step& step) {
    const int next = next_loop_phase(mesh);
    if (const OpStatus why = check_phases_left("Loop", step.levels, next); !why) {
        return why;
    }
    if (next == 1) {
        Step one = step;
        one.levels = 1;
        if (const OpStatus why = check_loop(mesh, one); !why) {
            return why;
        }
    }
    return check_loop_step(mesh);
}
StepResult run_loop_step(Mesh& mesh, const Step& step, const RunOptions& options) {
    StepResult result;
    result.renumbers = next_loop_phase(mesh) <= 2 && mesh.has_garbage();
    LoopOptions loop;
    loop.weights = options.weights;
    for (int phase = 0; phase < step.levels; ++phase) {
        const LoopStepReport report = loop_step(mesh, loop);
        result.message = report.message;
    }
    return result;
}
// A phased Loop's levels make what Loop's make (apply_steps() counts four phases a level).
SubdivisionPlan plan_loop_step(const Mesh& mesh, int levels) {
    return plan_loop(mesh, levels);
}

OpStatus check_quads(const Mesh& mesh, const Step& step) {
    if (const OpStatus why = phased_loop_refusal(mesh); !why) {
        return why;
    }
    if (mesh.n_faces() == 0) {
        return OpStatus::refused("cannot subdivide: the mesh has no faces");
    }
    return plan_quad_subdivision(mesh, step.levels).status;
}
StepResult run_quads(Mesh& mesh, const Step& step, const RunOptions& options, QuadScheme scheme) {
    StepResult result;
    result.renumbers = true;
    for (int level = 0; level < step.levels; ++level) {
        QuadSubdivisionOptions quads;
        quads.scheme = scheme;
        quads.uv = step.uv.value_or(quads.uv);
        if (options.progress) {
            quads.progress = [&](double f) { options.progress((level + f) / step.levels); };
        }
        quad_subdivide(mesh, quads);
    }
    result.message =
        std::string(scheme == QuadScheme::Linear ? "linear subdivision" : "Catmull-Clark") + ": " +
        std::to_string(mesh.n_faces()) + " quads";
    return result;
}
StepResult run_catmull_clark(Mesh& mesh, const Step& step, const RunOptions& options) {
    return run_quads(mesh, step, options, QuadScheme::CatmullClark);
}
StepResult run_linear(Mesh& mesh, const Step& step, const RunOptions& options) {
    return run_quads(mesh, step, options, QuadScheme::Linear);
}

OpStatus check_triangulate(const Mesh& mesh, const Step& step) {
    if (step.target == Target::Face) {
        return is_triangulate_ok(mesh, named_face(mesh, step));
    }
    return OpStatus::ok();
}
StepResult run_triangulate(Mesh& mesh, const Step& step, const RunOptions&) {
    if (step.target == Target::Face) {
        const Face f = named_face(mesh, step);
        const std::size_t n = mesh.valence(f);
        triangulate(mesh, f);
        return local(ElementRef::face(f), n == 3 ? "face " + idx(f.idx()) + " is a triangle already"
                                                 : "cut face " + idx(f.idx()) + " into " +
                                                       std::to_string(n - 2) + " triangles");
    }
    const std::size_t n = triangulate(mesh);
    StepResult result;
    const std::size_t left = non_triangles(mesh);
    result.message = n == 0 && left == 0 ? "every face is a triangle already"
                                         : "triangulated " + std::to_string(n) + " faces";
    if (left > 0) {
        // A polygon whose every fan would repeat an existing edge (rare: a face folded onto
        // its neighbours) stays whole rather than make the mesh invalid.
        result.notices.push_back(std::to_string(left) +
                                 " polygons could not be cut without doubling an edge");
        result.message += "; " + result.notices.back();
    }
    return result;
}

OpStatus check_flip_orientation(const Mesh&, const Step&) {
    return OpStatus::ok();
}
StepResult run_flip_orientation(Mesh& mesh, const Step&, const RunOptions&) {
    flip_orientation(mesh);
    StepResult result;
    result.message = "reversed the orientation of all " + std::to_string(mesh.n_faces()) +
                     " faces (normals now point the other way)";
    return result;
}

constexpr std::array<double, kMaxAmounts> kNoDefaults{};
constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// clang-format off
constexpr std::array kVerbs{
    Verb{"flip", kEdgeArg, 0, 0, kNoDefaults, "flip:A-B",
         "flips the interior edge A-B: it turns inside its two faces to join the corners "
         "after its ends (triangles stay triangles, polygons keep their sides)",
         "flip the selected edge", check_flip, run_flip, nullptr, false, kDefaultTraits,
         CodeNames::Flip, nullptr, "flip_edge"},
    Verb{"split", kEdgeArg, 0, 0, kNoDefaults, "split:A-B",
         "splits A-B at its midpoint and divides the triangles beside it (a polygon only "
         "gains the vertex); the new vertex gets the next free index (`V` before the split)",
         "split the selected edge", check_split, run_split, nullptr, false, kDefaultTraits,
         CodeNames::Split, nullptr, "split_edge"},
    Verb{"bisect", kEdgeArg, 0, 0, kNoDefaults, "bisect:A-B",
         "inserts a vertex at the midpoint of A-B without dividing any face (each face beside "
         "it gains a corner); the new vertex gets index `V`",
         "bisect the selected edge (a midpoint vertex, no new edges across faces)",
         check_bisect, run_bisect},
    Verb{"collapse", kEdgeArg | kFaceArg, 0, 0, kNoDefaults, "collapse:A-B, collapse:fI",
         "collapses A-B to its midpoint (the smaller index survives, the other is deleted), "
         "or face I to the average of its corners (its smallest-index corner survives); "
         "indices are not renumbered until the file is written",
         "collapse the selected edge or face", check_collapse, run_collapse, nullptr, false,
         kDefaultTraits, CodeNames::Collapse},
    Verb{"dissolve", kVertexArg | kEdgeArg, 0, 0, kNoDefaults, "dissolve:vI, dissolve:A-B",
         "removes vertex I and merges the faces around it into one, or removes A-B and merges "
         "its two faces (a boundary edge's face joins the hole)",
         "dissolve the selected vertices and edges (faces: make them holes)",
         check_dissolve, run_dissolve},
    Verb{"make_boundary", kFaceArg, 0, 0, kNoDefaults, "make_boundary:fI",
         "deletes face I, leaving a hole (merged with holes beside it)",
         "delete the selected faces, leaving holes", check_make_boundary, run_make_boundary},
    Verb{"fill", kEdgeArg, 0, 0, kNoDefaults, "fill:A-B",
         "fills the hole that boundary edge A-B borders with one polygon",
         "fill the hole beside the selected boundary edge with one face", check_fill, run_fill},
    Verb{"weld", kEdgePair, 0, 0, kNoDefaults, "weld:A-B+C-D",
         "glues boundary edges A-B and C-D into one interior edge: A and B stay, each moved to "
         "the midpoint of itself and the end of C-D it meets (the faces' orientation decides "
         "which)",
         "weld the two selected boundary edges", check_weld, run_weld},
    Verb{"poke", kFaceArg, 0, 0, kNoDefaults, "poke:fI",
         "adds a vertex at the average of face I's corners and joins it to each corner (a fan "
         "of triangles; Scotty3D's inset vertex)",
         "poke the selected face (a centre vertex and a fan of triangles)", check_poke, run_poke},
    Verb{"extrude", kFaceArg, 2, 1, kNoDefaults, "extrude:fI:H, extrude:fI:H,S",
         "surrounds face I with a ring of quads and moves it H model units along its normal, "
         "shrunk S of the way to its centre (S below 1, default 0)",
         "extrude the selected face (drag: height up/down, shrink left/right)",
         check_extrude, run_extrude},
    Verb{"inset", kFaceArg, 1, 1, kNoDefaults, "inset:fI:S",
         "a ring of quads inside face I, whose inner face is shrunk S of the way to its "
         "centre (S below 1)",
         "inset the selected face (drag: the amount)", check_inset, run_inset},
    Verb{"bevel", kVertexArg | kEdgeArg, 1, 1, kNoDefaults, "bevel:vI:T, bevel:A-B:T",
         "replaces vertex I or edge A-B with a face whose corners sit a fraction T (0 to below "
         "1) along each edge leaving it",
         "bevel the selected vertex or edge (drag: the amount)", check_bevel, run_bevel},
    Verb{"extrude_region", kRegion, 1, 1, kNoDefaults, "extrude_region:R:H",
         "extrudes the faces R as one region by height H along the area-weighted normal of "
         "each of its pieces: walls join its border to the moved copy, shared sides stay "
         "joined (Blender's extrude region); the faces R become the top",
         "extrude the selected faces as one region (drag: the height)", check_extrude_region,
         run_extrude_region, nullptr, false, kChangesTopology},
    Verb{"inset_region", kRegion, 1, 1, kNoDefaults, "inset_region:R:T",
         "insets the faces R as one region (Blender's inset faces): a ring of quads T wide "
         "inside its border, the border's copies moved into the region, an even ring; the "
         "faces R keep their handles inside it",
         "inset the selected faces as one region (drag: the thickness)", check_inset_region,
         run_inset_region, nullptr, false, kChangesTopology},
    Verb{"simplify_region", kRegion, 1, 0, {0.5, 0.0, 0.0},
         "simplify_region:R, simplify_region:R:K",
         "QEM simplification of the faces R only, to about K of them (0 < K < 1, default "
         "0.5): only edges between their inner vertices collapse, so their border and the "
         "rest of the mesh stay bit for bit",
         "simplify the selected faces to half (their border fixed)", check_simplify_region,
         run_simplify_region, nullptr, false, kChangesTopology},
    Verb{"remesh_region", kRegion, 2, 0, {0.0, 3.0, 0.0},
         "remesh_region:R, remesh_region:R:L, remesh_region:R:L,N",
         "remesh's N rounds (default 3) on the faces R only, toward edge length L (0 or left "
         "out: the mean of their edges): only edges between two of their faces change and only "
         "vertices inside them move, so their border and the rest stay",
         "remesh the selected faces (their border fixed)", check_remesh_region,
         run_remesh_region, nullptr, false, kChangesTopology | kRebuildsMesh},
    Verb{"dissolve_region", kRegion, 0, 0, kNoDefaults, "dissolve_region:R",
         "merges each piece of the faces R (faces joined across edges) into one face, its inner "
         "vertices and edges dissolved (Blender's dissolve faces); refused for a piece that is "
         "not a disk",
         "merge the selected faces into one face per piece", check_dissolve_region,
         run_dissolve_region, nullptr, false, kChangesTopology},
    Verb{"subdivide_region", kRegion, 0, 0, kNoDefaults, "subdivide_region:R",
         "subdivides the faces R once, linearly: triangles into four, other faces into one "
         "quad per corner; each face beside R that gains a midpoint is cut into a fan of "
         "triangles from it (the transition ring)",
         "subdivide the selected faces once (linear, with a transition ring)",
         check_subdivide_region, run_subdivide_region, nullptr, false, kChangesTopology},
    Verb{"loop_region", kRegion, 0, 0, kNoDefaults, "loop_region:R",
         "subdivide_region's pattern with Loop's rules inside the triangles R (Warren's "
         "weights): their inner vertices and the edges between two of them smoothed, their "
         "border and the rest unmoved; over a whole closed mesh it is `loop`",
         "Loop-subdivide the selected triangles once (border fixed, a transition ring)",
         check_loop_region, run_loop_region, nullptr, false, kChangesTopology},
    Verb{"catmull_clark_region", kRegion, 0, 0, kNoDefaults, "catmull_clark_region:R",
         "subdivide_region's pattern with Catmull-Clark's rules inside the faces R (every "
         "face into quads): their border and the rest unmoved; over a whole closed mesh it "
         "is `catmull_clark`",
         "Catmull-Clark-subdivide the selected faces once (border fixed, a transition ring)",
         check_catmull_clark_region, run_catmull_clark_region, nullptr, false,
         kChangesTopology},
    // The selection a list carries (run_steps()): set by these, named `sel` by region verbs.
    Verb{"select", kRegion | kElementList, 0, 0, kNoDefaults, "select:R",
         "selects the faces R (or the vertices or edges R lists), for the region verbs that "
         "follow to name as `sel`; what the viewer records for a region selection",
         "select faces", check_select, run_select, nullptr, false, 0, CodeNames::ByIndex,
         select_listed},
    Verb{"select_none", kWholeMesh, 0, 0, kNoDefaults, "select_none", "clears the selection",
         "clear the selection", check_select, run_select, nullptr, false, 0, CodeNames::ByIndex,
         select_none},
    Verb{"select_loop", kEdgeArg, 0, 0, kNoDefaults, "select_loop:A-B",
         "selects the edge loop through A-B (on across vertices of valence 4; stops at poles "
         "and the border)",
         "select the edge loop", check_select, run_select, nullptr, false, 0, CodeNames::ByIndex,
         select_loop},
    Verb{"select_ring", kEdgeArg, 0, 0, kNoDefaults, "select_ring:A-B",
         "selects the edge ring through A-B (across quads to the opposite edges)",
         "select the edge ring", check_select, run_select, nullptr, false, 0, CodeNames::ByIndex,
         select_ring},
    Verb{"select_linked", kWholeMesh, 0, 0, kNoDefaults, "select_linked",
         "selects every face joined to the selection (its pieces)", "select the joined pieces",
         check_select, run_select, nullptr, false, 0, CodeNames::ByIndex, select_linked},
    Verb{"select_more", kWholeMesh, 0, 0, kNoDefaults, "select_more",
         "grows the selected faces (or vertices) by one ring", "grow the selection",
         check_select, run_select, nullptr, false, 0, CodeNames::ByIndex, select_more},
    Verb{"select_less", kWholeMesh, 0, 0, kNoDefaults, "select_less",
         "shrinks the selected faces (or vertices) by one ring", "shrink the selection",
         check_select, run_select, nullptr, false, 0, CodeNames::ByIndex, select_less},
    Verb{"select_invert", kWholeMesh, 0, 0, kNoDefaults, "select_invert",
         "selects every element of the selection's kind it does not hold", "invert the selection",
         check_select, run_select, nullptr, false, 0, CodeNames::ByIndex, select_invert},
    Verb{"select_boundary", kWholeMesh, 0, 0, kNoDefaults, "select_boundary",
         "selects the faces on the border", "select the border's faces", check_select,
         run_select, nullptr, false, 0, CodeNames::ByIndex, select_boundary},
    Verb{"select_creases", kWholeMesh, 0, 0, kNoDefaults, "select_creases",
         "selects the crease edges", "select the creases", check_select, run_select, nullptr,
         false, 0, CodeNames::ByIndex, select_creases},
    Verb{"select_valence", kWholeMesh, 1, 1, kNoDefaults, "select_valence:K",
         "selects the vertices with K edges", "select vertices by valence", check_select,
         run_select, nullptr, false, 0, CodeNames::ByIndex, select_valence},
    Verb{"select_degree", kWholeMesh, 1, 1, kNoDefaults, "select_degree:K",
         "selects the faces with K corners", "select faces by corner count", check_select,
         run_select, nullptr, false, 0, CodeNames::ByIndex, select_degree},
    Verb{"crease", kEdgeArg, 0, 0, kNoDefaults, "crease:A-B",
         "toggles the `e:crease` mark of A-B (kept by COLLADA, used by Loop)",
         "toggle crease on the selected edge", check_crease, run_crease, nullptr, false, 0},
    Verb{"crease_by_angle", kWholeMesh, 1, 0, {30.0}, "crease_by_angle, crease_by_angle:D",
         "marks every interior edge whose dihedral angle (between its faces' normals) exceeds "
         "D degrees (0 to 180, default 30) as a crease; the creases there stay",
         "mark the edges sharper than the info panel's feature angle as creases",
         check_crease_by_angle_step, run_crease_by_angle, nullptr, false, kToolAmounts},
    Verb{"move", kVertexArg, 3, 3, kNoDefaults, "move:vI:X,Y,Z",
         "puts vertex I at (X, Y, Z) (the viewer records drags and move, rotate and scale "
         "this way)",
         "drag the selected vertex (M moves a selection)", check_move, run_move, nullptr, false,
         0},
    Verb{"loop", kWholeMesh | kLevels | kUvArg, 0, 0, kNoDefaults,
         "loop, loop:K, loop:K:uv=U",
         "K levels (default 1) of Loop subdivision (Warren weights) of a triangle mesh; old "
         "vertices keep their indices, the vertex on old edge `e` gets index `V + e`; texture "
         "coordinates follow OpenSubdiv's face-varying option U (default `corners`)",
         "Loop-subdivide the mesh", check_loop, run_loop, plan_loop, false, kDefaultTraits,
         CodeNames::ByIndex, nullptr, "upsample"},
    Verb{"loop_step", kWholeMesh | kLevels, 0, 0, kNoDefaults, "loop_step, loop_step:N",
         "the next N phases (default 1) of Loop as it is taught: 1 compute the new positions, "
         "2 split every edge, 3 flip the new edges that join an old and a new vertex, 4 move "
         "every vertex; four phases make one `loop`",
         "Loop one phase at a time (positions, split, flip, move)", check_loop_step_verb,
         run_loop_step, plan_loop_step, true},
    Verb{"cc_step", kWholeMesh | kLevels, 0, 0, kNoDefaults, "cc_step, cc_step:N",
         "the next N phases (default 1) of Catmull-Clark as it is taught: 1 a face point in "
         "each face (poke), 2 split every old edge at its edge point, 3 move every old vertex "
         "to its vertex point, 4 dissolve the edges from face points to old vertices (quads); "
         "four phases make one `catmull_clark`, up to numbering",
         "Catmull-Clark one phase at a time (face, edge, vertex points, reconnect)",
         check_cc_step_verb, run_cc_step},
    Verb{"catmull_clark", kWholeMesh | kLevels | kUvArg, 0, 0, kNoDefaults,
         "catmull_clark, catmull_clark:K, catmull_clark:K:uv=U",
         "K levels (default 1) of Catmull-Clark subdivision (OpenSubdiv's Catmark rules, "
         "creases and boundaries sharp) of any polygon mesh: every face of k corners becomes k "
         "quads; old vertices keep their indices, edge `e`'s point is `V + e`, face `f`'s "
         "`V + E + f`; texture coordinates follow OpenSubdiv's face-varying option U (default "
         "`corners`)",
         "Catmull-Clark-subdivide the mesh (any polygons; quads come out)", check_quads,
         run_catmull_clark, plan_quad_subdivision},
    Verb{"linear", kWholeMesh | kLevels | kUvArg, 0, 0, kNoDefaults,
         "linear, linear:K, linear:K:uv=U",
         "K levels (default 1) of linear subdivision: the faces of Catmull-Clark, the points "
         "at centroids and midpoints, the surface unchanged; texture coordinates linear too "
         "(U is accepted and changes nothing, as in OpenSubdiv's bilinear scheme)",
         "subdivide into quads without smoothing (linear)", check_quads, run_linear,
         plan_quad_subdivision},
    Verb{"simplify", kWholeMesh | kAttributesArg, 3, 0, {0.5, kUnbounded, kNoFeatureAngle},
         "simplify, simplify:R, simplify:R,E, simplify:R,E,F, simplify:R,E,F:attributes=A",
         "QEM simplification (Garland-Heckbert) of a triangle mesh to about R of its faces "
         "(0 < R < 1, default 0.5) or to R faces (a whole number), stopping before a collapse "
         "whose error exceeds E times the bounding-box diagonal (left out or `inf`: no bound): "
         "edge collapses, cheapest quadric error first, boundaries and creases held, no face "
         "turned over; with F, the edges sharper than F degrees are marked as creases first "
         "(`crease_by_angle:F`); with texture coordinates, colours or materials A = aware "
         "(default) holds UV seams and material borders, turns no UV triangle over and "
         "weighs UVs and colours in the quadric, blind weighs positions only; indices are "
         "renumbered when written",
         "simplify the mesh to the share of its faces the info panel sets (QEM)",
         check_simplify_step, run_simplify, nullptr, false, kDefaultTraits | kToolAmounts},
    Verb{"remesh", kWholeMesh, 3, 0, {0.0, 3.0, kNoFeatureAngle},
         "remesh, remesh:L, remesh:L,N, remesh:L,N,F",
         "isotropic remeshing (Botsch-Kobbelt) of a triangle mesh toward edge length L (0 or "
         "left out: the mean edge length) in N rounds (default 3) of split, collapse, flip, "
         "tangential smoothing and projection onto the input; boundaries and creases kept, and "
         "with F the edges sharper than F degrees marked as creases first "
         "(`crease_by_angle:F`), so they stay sharp and straight",
         "remesh toward the mean edge length (3 rounds)", check_remesh_step, run_remesh,
         nullptr, false, kDefaultTraits | kToolAmounts},
    Verb{"smooth", kWholeMesh, 3, 0, {10.0, 0.5, 0.0}, "smooth, smooth:N,L, smooth:N,L,K",
         "N steps (default 10) of explicit Laplacian smoothing with uniform weights: every "
         "vertex moves L (0 < L <= 1, default 0.5) of the way to the mean of its neighbours; "
         "boundary and crease vertices stay; K = 1 scales a closed mesh back to its volume",
         "smooth the mesh (uniform Laplacian, the info panel's steps and lambda)",
         check_smooth_uniform, run_smooth_uniform, nullptr, false, kDefaultTraits | kToolAmounts},
    Verb{"smooth_cotan", kWholeMesh, 3, 0, {10.0, 0.5, 0.0},
         "smooth_cotan, smooth_cotan:N,L, smooth_cotan:N,L,K",
         "as smooth, with cotangent weights (triangles): vertices move along the surface's "
         "normal more than across it",
         "smooth the mesh (cotangent Laplacian)", check_smooth_cotan, run_smooth_cotan, nullptr,
         false, kDefaultTraits | kToolAmounts},
    Verb{"taubin", kWholeMesh, 3, 0, {10.0, 0.5, -0.53}, "taubin, taubin:N,L,M",
         "N rounds (default 10) of Taubin's smoothing without shrinking: a uniform Laplacian "
         "step of L (default 0.5), then one of M (below -L, at least -1, default -0.53)",
         "smooth the mesh without shrinking it (Taubin)", check_taubin, run_taubin, nullptr,
         false, kDefaultTraits | kToolAmounts},
    Verb{"smooth_implicit", kWholeMesh, 3, 0, {1.0, 1.0, 0.0},
         "smooth_implicit, smooth_implicit:T, smooth_implicit:T,N,K",
         "N (default 1) implicit (backward Euler) smoothing steps of time T (default 1): "
         "solves (I - T L) x' = x with cotangent weights (uniform on a mesh with polygons); "
         "K = 1 keeps a closed mesh's volume",
         "smooth the mesh implicitly (backward Euler)", check_smooth_implicit,
         run_smooth_implicit, nullptr, false, kDefaultTraits | kToolAmounts},
    Verb{"smooth_region", kRegion, 2, 0, {10.0, 0.5, 0.0},
         "smooth_region:R, smooth_region:R:N,L",
         "smooth's N uniform steps of L (defaults 10, 0.5) on the inner vertices of the faces "
         "R only: their border and the rest of the mesh stay",
         "smooth the selected faces (their border fixed)", check_smooth_region,
         run_smooth_region, nullptr, false, kChangesTopology},
    Verb{"fair", kRegion, 0, 0, kNoDefaults, "fair:R",
         "moves the inner vertices of the faces R so that the bi-Laplacian vanishes there "
         "(L^2 x = 0, cotangent weights; uniform on a mesh with polygons), every other vertex "
         "fixed: the patch joins the surface around it smoothly",
         "fair the selected faces (their border fixed)", check_fair_step, run_fair, nullptr,
         false, kChangesTopology},
    Verb{"repair", kWholeMesh, 0, 0, kNoDefaults, "repair",
         "`meshedit repair`'s safe sequence: merge vertices within 1e-6 of the bounding-box "
         "diagonal, remove degenerate and duplicate faces, stitch T-junctions (as `stitch`), "
         "orient faces (closed parts outward)",
         "repair the mesh (merge, clean, stitch, orient)", check_repair, run_repair},
    Verb{"merge_by_distance", kWholeMesh, 2, 0, {1e-6, 0.0},
         "merge_by_distance, merge_by_distance:T, merge_by_distance:T,A",
         "merges vertices closer than T times the bounding-box diagonal (default 1e-6; with "
         "A = 1, T is a distance), stitching coincident boundary edges",
         "merge vertices by distance", check_merge_by_distance, run_merge_by_distance},
    Verb{"stitch", kWholeMesh, 1, 0, {0.05}, "stitch, stitch:R",
         "puts each boundary vertex that lies on another part's boundary edge (a T-junction: "
         "at most R of the edge's length off it, default 0.05) into that edge's face, then "
         "merges the vertices that now share edges: closes the cracks between patches "
         "tessellated apart",
         "stitch T-junctions", check_stitch, run_stitch},
    Verb{"remove_degenerate", kWholeMesh, 0, 0, kNoDefaults, "remove_degenerate",
         "removes faces of zero area or a repeated corner, and duplicate faces",
         "remove degenerate and duplicate faces", check_remove_degenerate, run_remove_degenerate},
    Verb{"orient", kWholeMesh, 0, 0, kNoDefaults, "orient",
         "merges vertices at equal positions, then turns faces over so neighbours agree and "
         "closed parts face outward", "orient faces coherently", check_orient, run_orient},
    Verb{"remove_small", kWholeMesh, 1, 0, {10.0}, "remove_small, remove_small:N",
         "removes the components (faces joined through vertices) of fewer than N faces "
         "(default 10); the largest stays even when smaller",
         "remove small components", check_remove_small, run_remove_small},
    Verb{"fill_holes", kWholeMesh, 1, 0, {8.0}, "fill_holes, fill_holes:K",
         "fills every hole of at most K edges (default 8; with triangles on a triangle mesh)",
         "fill small holes", check_fill_holes, run_fill_holes},
    Verb{"fill_holes_fair", kWholeMesh, 1, 0, {0.0}, "fill_holes_fair, fill_holes_fair:K",
         "fills every hole (or those of at most K edges) with triangles as long as the edges "
         "around it, faired so the patch continues the surface (Liepa 2003)",
         "fill holes, refined and faired", check_fill_holes, run_fill_holes_fair},
    Verb{"fill_fair", kEdgeArg, 0, 0, kNoDefaults, "fill_fair:A-B",
         "fills the one hole that boundary edge A-B borders as fill_holes_fair fills each "
         "(refined and faired), reading only that hole and the faces around it; a part it "
         "closes keeps the orientation of the surface around the hole",
         "fill the hole beside the selected boundary edge, refined and faired", check_fill_fair,
         run_fill_fair},
    Verb{"triangulate", kWholeMesh | kFaceArg, 0, 0, kNoDefaults, "triangulate, triangulate:fI",
         "cuts every polygon (or face I) into triangles by diagonals inside it",
         "triangulate every polygon", check_triangulate, run_triangulate},
    Verb{"flip_orientation", kWholeMesh, 0, 0, kNoDefaults, "flip_orientation",
         "reverses every face, so normals point the other way",
         "reverse the orientation of every face", check_flip_orientation,
         run_flip_orientation},
    Verb{"compact", kWholeMesh, 0, 0, kNoDefaults, "compact",
         "renumbers vertices, edges and faces from 0 without the deleted ones, as a written "
         "file numbers them (the viewer does it when it saves and after a whole-mesh edit, and "
         "records it in the session; local edits leave deleted elements as tombstones)",
         "renumber densely (the viewer: on saving)", check_compact, run_compact},
};
// clang-format on

}  // namespace

std::span<const Verb> verbs() {
    return kVerbs;
}

}  // namespace meshedit::ops
