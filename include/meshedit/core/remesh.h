#pragma once
/// \file
/// Isotropic remeshing (Botsch and Kobbelt 2004): split long edges, collapse short ones,
/// flip toward valence 6, smooth tangentially and project back onto the input surface, a few
/// times over, so that every edge approaches one target length (docs/remesh.md).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/op_status.h"

namespace meshedit {

struct RemeshOptions {
    /// The edge length to approach; 0 means the mean edge length of the input.
    double target_length = 0.0;
    /// Rounds of split, collapse, flip, smooth and project (1 to 100).
    int iterations = 3;
    /// Before remeshing, mark every edge whose dihedral angle exceeds this many degrees as a
    /// crease (crease_by_angle(), normals.h), so that sharp edges stay sharp and straight;
    /// infinity: off (only the creases already marked are kept).
    double feature_angle_deg = kNoFeatureAngle;
    /// Only these faces are remeshed (empty: every face): an edge is split, collapsed or
    /// flipped only when both its faces are among them (or what they became), a vertex moves
    /// only when every face around it is, so the region's border and the rest stay where they
    /// were (renumbered at the end, as always).
    std::vector<Face> faces;
    /// Called with the fraction done (0…1), non-decreasing, last with 1; may be empty.
    std::function<void(double)> progress;
};

struct RemeshReport {
    double target_length = 0.0;  ///< the length used (the mean when 0 was asked for)
    std::size_t splits = 0, collapses = 0, flips = 0;
    std::size_t creases_marked = 0;  ///< by feature_angle_deg, before the first round
};

/// Why remesh() cannot run, or ok: polygons (triangulate first), no faces, a target
/// length that is negative, not finite, or so small against the mesh that the result would
/// not fit (more than about 100 million triangles or the memory budget), iterations out of
/// 1 to 100, a feature angle that is NaN or outside 0 to 180 (infinity: off). Pure.
OpStatus check_remesh(const Mesh& mesh, const RemeshOptions& options);

/// Remeshes in place. Boundary edges and crease edges are features: their vertices move only
/// along them (features are split at midpoints and collapsed along themselves, never smoothed)
/// and a vertex on three or more feature edges never moves. Every other vertex is smoothed in
/// its tangent plane and projected onto the closest point of the input surface (a
/// TriangleTree of the input as it was). Collapses keep the link condition and turn no face
/// over; garbage is collected at the end. \pre check_remesh() returned ok.
/// \post validate(mesh) passes.
RemeshReport remesh(Mesh& mesh, const RemeshOptions& options);

}  // namespace meshedit
