// The table of verbs: each row names a core operation and says how it is written, checked,
// run and described. The functions here only translate between a step and the core's API;
// the operations themselves, with their predicates and diagrams, are in src/core.

#include <array>
#include <string>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/ops/ops.h"

namespace meshedit::ops {
namespace {

std::string idx(std::uint32_t i) {
    return std::to_string(i);
}

// The result of a local step: the element it documents and a sentence.
StepResult local(ElementRef selected, std::string message, bool topology = true) {
    StepResult result;
    result.selected = selected;
    result.message = std::move(message);
    result.topology = topology;
    return result;
}

// ------------------------------------------------------------------ local operations

std::string check_flip(const Mesh& mesh, const Step& step) {
    return std::string(is_flip_ok(mesh, named_edge(mesh, step)).reason());
}
StepResult run_flip(Mesh& mesh, const Step& step, const RunOptions&) {
    const Edge e = named_edge(mesh, step);
    flip(mesh, e);
    return local(ElementRef::edge(e),
                 "flipped edge " + idx(e.idx()) + ": " + describe(mesh, ElementRef::edge(e)));
}

std::string check_split(const Mesh& mesh, const Step& step) {
    return std::string(is_split_ok(mesh, named_edge(mesh, step)).reason());
}
StepResult run_split(Mesh& mesh, const Step& step, const RunOptions&) {
    const Edge e = named_edge(mesh, step);
    const Vertex m = *split(mesh, e);
    return local(ElementRef::vertex(m),
                 "split edge " + idx(e.idx()) + ": new vertex " + idx(m.idx()));
}

std::string check_collapse(const Mesh& mesh, const Step& step) {
    return std::string(is_collapse_ok(mesh, named_edge(mesh, step)).reason());
}
StepResult run_collapse(Mesh& mesh, const Step& step, const RunOptions&) {
    const Edge e = named_edge(mesh, step);
    const Vertex v = *collapse(mesh, e);
    return local(ElementRef::vertex(v),
                 "collapsed edge " + idx(e.idx()) + " into vertex " + idx(v.idx()));
}

// Boundary edges may be marked too: harmless, Loop treats them as sharp anyway, and the
// mark survives if the boundary is later closed.
std::string check_crease(const Mesh& mesh, const Step& step) {
    named_edge(mesh, step);
    return {};
}
StepResult run_crease(Mesh& mesh, const Step& step, const RunOptions&) {
    const Edge e = named_edge(mesh, step);
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    crease[e] = crease[e] != 0 ? 0 : 1;
    return local(
        ElementRef::edge(e),
        "edge " + idx(e.idx()) + (crease[e] != 0 ? " is now a crease" : " is no longer a crease"),
        false);
}

// ------------------------------------------------------------------ whole-mesh operations

std::string check_loop(const Mesh& mesh, const Step& step) {
    if (mesh.n_faces() == 0) {
        return "cannot subdivide: the mesh has no faces";
    }
    return plan_loop(mesh, step.levels).refusal;
}
StepResult run_loop(Mesh& mesh, const Step& step, const RunOptions& options) {
    StepResult result;
    result.renumbers = true;
    std::size_t triangulated = 0;
    for (int level = 0; level < step.levels; ++level) {
        LoopOptions loop;
        loop.weights = options.weights;
        if (options.progress) {
            loop.progress = [&](double f) { options.progress((level + f) / step.levels); };
        }
        triangulated += loop_subdivide(mesh, loop).triangulated_faces;
    }
    result.message = "Loop: " + std::to_string(mesh.n_faces()) + " faces";
    if (triangulated > 0) {
        result.message +=
            " (triangulated " + std::to_string(triangulated) + " non-triangle faces first)";
        result.notices.push_back("triangulated " + std::to_string(triangulated) +
                                 " non-triangle faces before subdividing");
    }
    return result;
}

std::string check_triangulate(const Mesh&, const Step&) {
    return {};
}
StepResult run_triangulate(Mesh& mesh, const Step&, const RunOptions&) {
    const std::size_t n = triangulate(mesh);
    StepResult result;
    result.message = n == 0 ? "every face is a triangle already"
                            : "triangulated " + std::to_string(n) + " faces";
    if (n > 0) {
        result.notices.push_back("triangulated " + std::to_string(n) + " faces");
    }
    return result;
}

// clang-format off
constexpr std::array kVerbs{
    Verb{"flip", Shape::Edge, "flip:A-B",
         "flips the interior edge A-B: it turns inside its two faces to join the corners "
         "after its ends (triangles stay triangles, polygons keep their sides)",
         "flip the selected edge", check_flip, run_flip},
    Verb{"split", Shape::Edge, "split:A-B",
         "splits A-B at its midpoint and divides the triangles beside it (a polygon only "
         "gains the vertex); the new vertex gets the next free index (`V` before the split)",
         "split the selected edge", check_split, run_split},
    Verb{"collapse", Shape::Edge, "collapse:A-B",
         "collapses A-B to its midpoint; the smaller index survives, the other is deleted "
         "(indices are not renumbered until the file is written)",
         "collapse the selected edge", check_collapse, run_collapse},
    Verb{"crease", Shape::Edge, "crease:A-B",
         "toggles the `e:crease` mark of A-B (kept by COLLADA, used by Loop)",
         "toggle crease on the selected edge", check_crease, run_crease},
    Verb{"loop", Shape::Levels, "loop, loop:K",
         "K levels (default 1) of Loop subdivision (Warren weights); old vertices keep their "
         "indices, the vertex on old edge `e` gets index `V + e`",
         "Loop-subdivide the mesh", check_loop, run_loop},
    Verb{"triangulate", Shape::None, "triangulate",
         "triangulates every non-triangle face",
         "triangulate every polygon", check_triangulate, run_triangulate},
};
// clang-format on

}  // namespace

std::span<const Verb> verbs() {
    return kVerbs;
}

}  // namespace meshedit::ops
