#pragma once
/// \file
/// Loop subdivision with boundary and crease rules (docs/spec.md §3, docs/halfedge.md "Loop
/// rules").

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

/// Weight `u` for an interior vertex of valence n: `p' = (1 - n·u)·p + u·Σ neighbours`.
enum class LoopWeights {
    Warren,  ///< u = 3/16 for n = 3, else 3/(8n) (the default, as in CS184)
    Loop,    ///< Loop's original: u = (5/8 − (3/8 + 1/4·cos(2π/n))²) / n; equal to
             ///< Warren's at n = 3 (3/16) and n = 6 (1/16), different at every other n
};

/// How the subdivisions (Loop, Catmull-Clark) refine texture coordinates, the corners'
/// `h:texcoord`: as face-varying values, OpenSubdiv's `Sdc::Options::FVarLinearInterpolation`
/// (docs/subdivision.md, "Face-varying interpolation"). A seam (an edge whose two faces give a
/// vertex different coordinates) is a boundary of the UV charts; each option says which
/// values stay where they are instead of being smoothed. Linear subdivision refines every
/// option linearly, as OpenSubdiv's bilinear scheme does.
enum class UvInterpolation : std::uint8_t {
    None,          ///< "none": smooth everywhere, seams and boundaries as creases
    CornersOnly,   ///< "corners": a chart corner (one face of its chart) stays (the default)
    CornersPlus1,  ///< "corners+1": also where three or more charts meet
    CornersPlus2,  ///< "corners+2": also darts and a corner's partner across a seam
    Boundaries,    ///< "boundaries": linear along seams and the mesh boundary
    All,           ///< "all": linear everywhere (edge midpoints, face centroids)
};
/// "none", "corners", "corners+1", "corners+2", "boundaries" or "all".
std::string_view uv_interpolation_name(UvInterpolation uv);
/// The option named `name` (as uv_interpolation_name() spells it), or nothing.
std::optional<UvInterpolation> parse_uv_interpolation(std::string_view name);
/// "none, corners, corners+1, corners+2, boundaries, all", for messages.
std::string uv_interpolation_names();

struct LoopOptions {
    LoopWeights weights = LoopWeights::Warren;
    /// How texture coordinates are refined (Blender's subdivision modifier's default, "Keep
    /// Corners", is CornersOnly).
    UvInterpolation uv = UvInterpolation::CornersOnly;
    /// Called with the fraction done (0…1), non-decreasing, at coarse intervals (about a
    /// hundred calls per million faces), last with exactly 1; may be empty.
    std::function<void(double)> progress;
    /// Threads for meshes of 100,000 faces or more (smaller ones use the calling thread):
    /// at most this many; 0 means thread_count() (threads.h). The result is the same for any
    /// number.
    /// loop_subdivide() only; progress is always called from the calling thread.
    unsigned max_threads = 0;
};

/// What loop_subdivide() did besides subdividing.
struct LoopReport {
    /// Non-triangle faces triangulated before subdividing (the caller shows a notice).
    std::size_t triangulated_faces = 0;
};

/// \return ok unless Loop must refuse `mesh`: two triangles on the same three corners (a
/// closed two-triangle pillow) would come out joined by doubled edges, which a valid mesh
/// may not have (docs/halfedge.md, `multi-edge`). O(F).
OpStatus is_loop_ok(const Mesh& mesh);

/// What `levels` levels of a subdivision scheme would make of a mesh, and whether they may
/// run: the one "does it fit" answer every caller (the editor, `--ops loop:K`, `meshedit
/// subdivide`) asks before subdividing (plan_loop() here, plan_quad_subdivision() in
/// quad_subdivision.h).
struct SubdivisionPlan {
    /// Element counts after the last level (for Loop: non-triangles triangulated first).
    double vertices = 0, edges = 0, faces = 0;
    /// Estimated peak memory in bytes: the last level's arrays four times over (the level's
    /// own temporaries, an undo snapshot or a writer's copy, normals, file buffers).
    double bytes = 0;
    /// Ok when the levels may run; else why not, as "cannot subdivide: level 3 would …".
    OpStatus status = OpStatus::ok();
    bool ok() const { return static_cast<bool>(status); }
};
SubdivisionPlan plan_loop(const Mesh& mesh, int levels = 1);

/// One level of Loop subdivision: every triangle becomes four.
///
/// Non-triangle faces are triangulated first (counted in the report) and garbage is
/// collected first. Then, with V, E, F the counts at that point: old vertices keep their
/// indices and the vertex inserted on edge `e` gets index `V + e`; the result has V + E
/// vertices, 2E + 3F edges and 4F faces. Edge points are `3/8(A+B) + 1/8(C+D)`, or the
/// midpoint on boundary and crease edges ("sharp" edges). A vertex on no sharp edge, or on
/// exactly one (a dart), moves by the chosen weights; a vertex on exactly two sharp edges
/// uses `3/4·p + 1/8·(a + b)` with their far ends a, b; a vertex on three or more sharp edges
/// is a corner and stays put. Both halves of a crease edge stay creases; the new edges
/// inside old faces are not creases.
///
/// Properties follow the attribute carry (docs/halfedge.md, "What every operation carries";
/// src/algorithms/refine_carry.h): a blending vertex property gets the positions' own
/// weights, edge halves and face parts copy their parent, texture coordinates are refined as
/// face-varying values by `options.uv`, other corner attributes interpolate linearly.
/// The edge and face layout of the result is documented in src/algorithms/subdivision.cpp.
/// \throws std::invalid_argument with the reason if is_loop_ok() refuses (nothing changed).
/// \throws std::length_error if the result would not fit 32-bit indices (checked before
///         anything but the triangulation and collection above changes). If building the
///         result throws (std::bad_alloc), the mesh is left empty but valid.
/// \post validate(mesh) passes; F' = 4F.
LoopReport loop_subdivide(Mesh& mesh, const LoopOptions& options = {});

/// The classic algorithm (compute all positions, split every original edge in index order,
/// flip each new edge joining an old and a new vertex, then move), kept as the reference the
/// fast path is tested against. Built on split() and flip(); several times slower.
/// For the same input it gives the same vertex indices, faces (by vertex index), crease edges
/// and positions (to rounding) as loop_subdivide(). Edge and face indices differ, so after
/// several levels the two results describe the same surface with different numbering.
/// Properties behave as split() and flip() leave them (old elements keep their values).
/// \throws std::logic_error if split() or flip() refuses (never on a valid manifold
///         triangle mesh without doubled triangles).
LoopReport loop_subdivide_classic(Mesh& mesh, const LoopOptions& options = {});

}  // namespace meshedit
