#pragma once
/// \file
/// Catmull-Clark subdivision one phase at a time, the quad twin of loop_steps.h (Alt+L):
///
///   1. face points  poke every face: a new vertex at its centroid, joined to its corners
///   2. edge points  split every old edge; the new vertex goes to the edge point, the mean
///                   of the edge's ends and its two face points (the midpoint on a boundary
///                   or crease edge)
///   3. vertex points move every old vertex: (n − 2)/n · p + (Σ neighbours + Σ face
///                   points)/n² (the neighbours as they were), 3/4 · p + 1/8 · (a + b) on a
///                   boundary or crease, a corner stays
///   4. reconnect    dissolve every edge from a face point to an old vertex: each face of k
///                   corners is now k quads
///
/// Each phase is an ordinary edit (undone, saved around); the mesh carries which vertices are
/// face points and edge points between phases (`v:cc_face_point`, `v:cc_edge_point`,
/// `v:cc_moved`). Four phases make what quad_subdivide() makes, up to numbering.

#include <cstddef>
#include <string>

#include "meshedit/core/mesh.h"
#include "meshedit/core/op_status.h"

namespace meshedit {

/// The phase cc_step() runs next on `mesh`: 1 when no phased Catmull-Clark is under way.
int next_cc_phase(const Mesh& mesh);

/// Why the next phase cannot run, or ok: phase 1 refuses a mesh without faces and what
/// plan_quad_subdivision() refuses (its memory budget), and a phased Loop under way. Pure.
OpStatus check_cc_step(const Mesh& mesh);

/// What a phase did.
struct CcStepReport {
    int phase = 0;          ///< 1–4
    std::size_t count = 0;  ///< faces poked, edges split, vertices moved, edges dissolved
    std::string message;    ///< "Catmull-Clark 2/4: split 12 edges at their edge points"
};

/// Runs the next phase. \pre check_cc_step(mesh) is ok. \post validate(mesh) passes.
CcStepReport cc_step(Mesh& mesh);

}  // namespace meshedit
