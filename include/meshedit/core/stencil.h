#pragma once
/// \file
/// Subdivision stencils: which old vertices, with which weights, make the new point of a
/// vertex, an edge or (Catmull-Clark) a face — the rules of loop_rules.h and
/// catmark_rules.h spelled out for one element, for the viewer's stencil view and
/// docs/teaching.md. Weights always sum to 1; `position` is Σ weight·p.

#include <cstddef>
#include <string>
#include <vector>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/subdivision.h"

namespace meshedit {

/// The scheme a stencil is taken from.
enum class StencilScheme {
    LoopWarren,    ///< Loop with Warren's weights (the L key's)
    LoopOriginal,  ///< Loop with Loop's original weights
    CatmullClark,  ///< Catmull-Clark (Shift+C), OpenSubdiv's Catmark rules
};

/// "Loop (Warren's weights)", "Loop (Loop's weights)", "Catmull-Clark".
const char* scheme_name(StencilScheme scheme);

struct StencilTerm {
    Vertex vertex;
    double weight = 0.0;
};

struct Stencil {
    /// Which rule applies: "interior vertex", "dart", "boundary vertex", "crease vertex",
    /// "corner", "isolated vertex", "interior edge", "boundary edge", "crease edge", "face".
    /// Empty when there is no stencil (see `status`).
    std::string rule;
    std::size_t valence = 0;  ///< vertex stencils: the number of edges at the vertex
    /// Contributing old vertices: the element's own first (a vertex; an edge's two ends;
    /// a face's corners), then the others in the order they are met around it.
    std::vector<StencilTerm> terms;
    Vec3 position;  ///< where the new point goes: Σ weight·p
    /// The formula with the numbers filled in, a line each, for the panel (Latin-1 only: the
    /// viewer's font has no Σ or π).
    std::vector<std::string> formula;
    /// Why there is no stencil ("Loop needs triangles: face 3 has 4 corners …"), or ok.
    OpStatus status = OpStatus::ok();

    bool ok() const { return static_cast<bool>(status); }
};

/// The stencil of `element` (a vertex, an edge, a face; a halfedge stands for its edge)
/// under `scheme`: what one level of subdivision would compute for it now. Loop has no face
/// stencil and needs the faces beside an edge to be triangles. Pure.
Stencil subdivision_stencil(const Mesh& mesh, ElementRef element, StencilScheme scheme);

}  // namespace meshedit
