#pragma once
/// \file
/// QEM simplification (Garland–Heckbert): edge collapses in order of their quadric error,
/// each survivor placed where the error is least (docs/simplify.md).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/op_status.h"

namespace meshedit {

/// Whether simplify() weighs texture coordinates, vertex colours and materials
/// (docs/simplify.md, "Attributes").
enum class SimplifyAttributes : std::uint8_t {
    /// No collapse across a UV seam or material border, no UV triangle turned over, UVs and
    /// colours in the quadric (Hoppe 1999) and set at its optimum. A mesh with none of them
    /// takes Blind's path, bit for bit.
    Aware,
    /// Positions only; the attributes follow collapse()'s carry (UVs and colours copied).
    Blind,
};

struct SimplifyOptions {
    /// Stop once the mesh has at most this many faces (at least 1).
    std::size_t target_faces = 1;
    /// Stop before a collapse whose error exceeds this, as a fraction of the bounding-box
    /// diagonal (the error is the root of the area-weighted mean squared distance to the
    /// planes the quadric holds); infinity: no bound.
    double max_error = std::numeric_limits<double>::infinity();
    /// Refuse a collapse that turns the normal of a face that stays by more than this many
    /// degrees (or makes it degenerate).
    double max_normal_change_deg = 60.0;
    /// Before simplifying, mark every edge whose dihedral angle exceeds this many degrees as a
    /// crease (crease_by_angle(), normals.h); infinity: off (the creases already marked are
    /// kept all the same).
    double feature_angle_deg = kNoFeatureAngle;
    /// Aware by default; it changes nothing on a mesh without UVs, colours or materials.
    SimplifyAttributes attributes = SimplifyAttributes::Aware;
    /// Only these vertices move or go: an edge collapses only when both its ends are listed,
    /// so every other vertex (a region's border, everything outside it) stays bit for bit;
    /// empty: every vertex (simplify_region: a region's inner vertices).
    std::vector<Vertex> vertices;
    /// Called with the fraction done (0…1), non-decreasing, at coarse intervals, last with 1.
    std::function<void(double)> progress;
};

/// What simplify() did.
struct SimplifyReport {
    std::size_t collapses = 0;
    /// Candidate collapses skipped: the link condition failed, or a face would flip.
    std::size_t refused_topology = 0;
    std::size_t refused_normal = 0;
    /// Candidate collapses skipped because they would pull a crease vertex off its crease:
    /// a non-crease edge between two crease vertices, or a crease edge between two corners.
    std::size_t refused_crease = 0;
    /// Aware only: collapses skipped because they would mix two UV charts at a corner (a
    /// vertex where three charts meet, a seam's end), or turn a UV triangle over.
    std::size_t refused_seam = 0;
    std::size_t refused_uv_flip = 0;
    std::size_t creases_marked = 0;  ///< by feature_angle_deg, before the first collapse
    /// The largest error of an applied collapse (same unit as SimplifyOptions::max_error).
    double largest_error = 0.0;
    /// True when it stopped at max_error (or ran out of collapses) above target_faces.
    bool stopped_early = false;
};

/// Why simplify() cannot run with `options`, or ok: the mesh has polygons (QEM here works
/// on triangles: triangulate first), no faces, a target of 0 or not below the face count, a
/// negative or NaN error bound or angle, a feature angle that is NaN or outside 0 to 180
/// (infinity: off). Pure.
OpStatus check_simplify(const Mesh& mesh, const SimplifyOptions& options);

/// Collapses edges, cheapest quadric error first, until the mesh has at most
/// options.target_faces faces or the next error exceeds options.max_error.
///
/// Quadrics: each face contributes its plane's quadric weighted by its area to its three
/// corners; boundary and crease edges add a plane through the edge perpendicular to its face,
/// weighted by 100 × the edge's squared length, so features hold. Each collapse goes through
/// collapse() (its link condition), moves the survivor to the point that minimises the summed
/// quadric (a 3 × 3 solve; the best of the two ends and the midpoint when the system is
/// ill-conditioned), and is refused when a face that stays would turn by more than
/// max_normal_change_deg. Crease vertices (on a kCreaseProperty edge) stay exactly on their
/// creases, as remesh() keeps them: a collapse along a crease puts the survivor at one of the
/// edge's ends (the corner's, if one is a corner: the end of a crease, three or more crease
/// edges, or two that turn by more than 30 degrees; two corners never collapse), a collapse of
/// another edge with one crease end puts it at that end, and one between two crease vertices
/// is refused. With SimplifyAttributes::Aware on a mesh with texture coordinates, colours or
/// materials, the attribute quadrics join the position quadric, a collapse that would turn a
/// UV triangle over or mix two charts at a corner is refused, the survivor's corners take the
/// UV quadric's best value inside a chart (along a seam each side's two corners interpolated,
/// else the seam end's corners), its colour the colour quadric's best within the input's
/// range, and material borders get the boundary's penalty planes. Deleted elements stay
/// tombstoned (garbage collection is the caller's). \pre check_simplify() returned ok.
/// \post validate(mesh) passes.
SimplifyReport simplify(Mesh& mesh, const SimplifyOptions& options);

}  // namespace meshedit
