#pragma once
/// \file
/// Loop subdivision with boundary and crease rules (SPEC §3, docs/halfedge.md "Loop rules").

#include <cstddef>
#include <functional>

#include "meshedit/core/mesh.h"

namespace meshedit {

/// Name of the edge property (`std::uint8_t`, non-zero = sharp) that marks crease edges.
inline constexpr const char* kCreaseProperty = "e:crease";

/// Weight `u` for an interior vertex of valence n: `p' = (1 - n·u)·p + u·Σ neighbours`.
enum class LoopWeights {
    Warren,  ///< u = 3/16 for n = 3, else 3/(8n) (the default, as in CS184)
    Loop,    ///< Loop's original: u = (5/8 − (3/8 + 1/4·cos(2π/n))²) / n
};

struct LoopOptions {
    LoopWeights weights = LoopWeights::Warren;
    /// Called with the fraction done (0…1) during long runs; may be empty.
    std::function<void(double)> progress;
};

/// What loop_subdivide() did besides subdividing.
struct LoopReport {
    /// Non-triangle faces triangulated before subdividing (the caller shows a notice).
    std::size_t triangulated_faces = 0;
};

/// One level of Loop subdivision: every triangle becomes four.
///
/// Old vertices keep their indices; the vertex inserted on old edge `e` gets index
/// `V + e` (after garbage collection, which this performs first). Edge points are
/// `3/8(A+B) + 1/8(C+D)`, or the midpoint on boundary and crease edges ("sharp" edges).
/// A vertex on no sharp edge, or on exactly one (a dart), moves by the chosen weights; a
/// vertex on exactly two sharp edges uses `3/4·p + 1/8·(a + b)` with their far ends a, b;
/// a vertex on three or more sharp edges is a corner and stays put.
/// Both halves of a crease edge stay creases. \post F' = 4F on a triangle mesh.
LoopReport loop_subdivide(Mesh& mesh, const LoopOptions& options = {});

/// The classic algorithm (split every original edge, flip each new edge joining an old and a
/// new vertex, then move), kept as the reference the fast path is tested against. It gives
/// the same vertex indices, positions and faces as loop_subdivide().
LoopReport loop_subdivide_classic(Mesh& mesh, const LoopOptions& options = {});

}  // namespace meshedit
