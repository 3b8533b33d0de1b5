#pragma once
/// \file
/// Loop subdivision one phase at a time, as the course teaches it (docs/teaching.md):
///
///   1. positions  compute the new position of every old vertex and the point of every old
///                 edge; nothing moves yet
///   2. split      split every old edge at its midpoint; the new vertex will go to the edge's
///                 point
///   3. flip       flip every new edge that joins an old and a new vertex
///   4. move       move every vertex to its new position
///
/// Between phases the mesh carries what the next one needs as properties (`v:loop_target`
/// and the flags below), so each phase is an ordinary edit: undone, saved around, rendered
/// (render/overlay.h draws the targets, new and flipped edges). loop_subdivide_classic() is
/// these four phases in a row.

#include <cstddef>
#include <string>

#include "meshedit/core/attributes.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/subdivision.h"

namespace meshedit {

// The properties the phases leave on the mesh (kLoopTarget …) are in attributes.h.

/// The phase loop_step() runs next on `mesh`: 1 when no phased Loop is under way, else 2–4.
int next_loop_phase(const Mesh& mesh);

/// Why the next phase cannot run, or ok: phase 1 refuses what loop_subdivide() refuses
/// (is_loop_ok()); a triangle mesh is needed (polygons: triangulate first, so that the
/// phases show Loop itself). Pure.
OpStatus check_loop_step(const Mesh& mesh);

/// What a phase did.
struct LoopStepReport {
    int phase = 0;          ///< 1–4
    std::size_t count = 0;  ///< vertices positioned, edges split or flipped, vertices moved
    std::string message;    ///< "split 18 edges (phase 2 of 4: …)"
};

/// Runs the next phase. \pre check_loop_step(mesh) is ok.
LoopStepReport loop_step(Mesh& mesh, const LoopOptions& options = {});

}  // namespace meshedit
