#pragma once
/// \file
/// Smoothing and fairing (docs/smoothing.md): explicit Laplacian smoothing with uniform or
/// cotangent weights, Taubin's λ|μ smoothing, implicit (backward Euler) smoothing, an option
/// that restores a closed mesh's enclosed volume, and bi-Laplacian fairing of a region with
/// its border fixed. Positions only: the connectivity and every attribute stay as they are.

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/core/op_status.h"

namespace meshedit {

/// The weights w_ij of the Laplacian L x_i = Σ_j w_ij (x_j − x_i) / Σ_j w_ij.
enum class SmoothWeights {
    Uniform,    ///< 1 per edge: any polygon mesh
    Cotangent,  ///< (cot α + cot β) / 2 (triangles only), negative values clamped to 0
};

enum class SmoothMethod {
    Explicit,  ///< x ← x + λ L x, `iterations` times
    Taubin,    ///< x ← x + λ L x, then x ← x + μ L x (μ < −λ), `iterations` times
    Implicit,  ///< (I − t L) x' = x solved `iterations` times, L from the mesh at the start
};

struct SmoothOptions {
    SmoothMethod method = SmoothMethod::Explicit;
    SmoothWeights weights = SmoothWeights::Uniform;
    int iterations = 10;  ///< 1 to 1000
    double lambda = 0.5;  ///< Explicit, Taubin: in (0, 1]
    double mu = -0.53;    ///< Taubin: below −λ and not below −1
    double time = 1.0;    ///< Implicit: t, above 0 and at most 10⁶
    /// Scales the mesh about its vertex centroid afterwards so that it encloses the volume it
    /// enclosed before (closed meshes, whole mesh only: every vertex moves by the scale).
    bool keep_volume = false;
    /// Vertices on a crease edge (kCreaseProperty) stay where they are; boundary vertices
    /// always do.
    bool fix_creases = true;
    /// Only these vertices move (the rest are fixed); empty: every vertex.
    std::vector<Vertex> vertices;
    /// Called with the fraction done (0…1), non-decreasing; may be empty.
    std::function<void(double)> progress;
};

struct SmoothReport {
    int iterations = 0;
    std::size_t moved = 0;          ///< vertices free to move
    double max_displacement = 0.0;  ///< the largest distance a vertex moved
    bool closed = false;            ///< no boundary: the volumes below are enclosed volumes
    double volume_before = 0.0;     ///< signed volume (divergence theorem; faces fanned)
    double volume_after = 0.0;
    double solve_seconds = 0.0;  ///< Implicit: building, factoring and solving the system
};

/// The signed volume the faces enclose (positive for outward faces on a closed mesh); faces
/// are fanned from their first corner. O(F).
double enclosed_volume(const Mesh& mesh);

/// Why smooth() cannot run, or ok: no faces, a position that is not finite, iterations,
/// λ, μ or t out of range, cotangent weights on polygons, the volume option on a mesh with
/// a boundary or no volume or with a vertex subset, a vertex subset naming a missing vertex,
/// every vertex fixed, or the memory budget. Pure, O(V + F).
OpStatus check_smooth(const Mesh& mesh, const SmoothOptions& options);

/// Smooths positions in place (Jacobi: every vertex of a step reads the positions of the step
/// before); the same bits on any number of threads. \pre check_smooth() returned ok.
/// \post validate(mesh) passes; the connectivity and attributes are unchanged.
SmoothReport smooth(Mesh& mesh, const SmoothOptions& options);

struct FairOptions {
    /// Cotangent needs the faces around the region to be triangles.
    SmoothWeights weights = SmoothWeights::Cotangent;
};

struct FairReport {
    std::size_t moved = 0;  ///< the region's inner vertices
    double max_displacement = 0.0;
    double solve_seconds = 0.0;
};

/// The inner vertices of the faces `region`: those whose every face is in it and that are not
/// on the mesh's boundary, sorted. fair() moves these; smoothing a region moves these (its
/// border stays, so the region joins what is around it). O(the region's one-ring).
std::vector<Vertex> region_inner_vertices(const Mesh& mesh, std::span<const Face> region);

/// Why fair() cannot run, or ok: an empty region or one naming a missing face, no inner
/// vertex (every vertex of the region is on its border), a piece of the region with no fixed
/// vertex around it (a whole closed component), cotangent weights beside polygons, or a
/// position that is not finite. Pure, O(V + F).
OpStatus check_fair(const Mesh& mesh, std::span<const Face> region, const FairOptions& options);

/// Bi-Laplacian fairing: the region's inner vertices (those whose every face is in the region
/// and that are not on the mesh's boundary) solve L² x = 0 with every other vertex fixed, so
/// the patch joins the fixed surface around it smoothly (two rings of it take part). L is the
/// Laplace-Beltrami operator for cotangent weights (divided by each vertex's mixed Voronoi
/// area, as CGAL's and pmp's fairing), the umbrella operator for uniform ones.
/// \pre check_fair() returned ok. \post validate(mesh) passes.
FairReport fair(Mesh& mesh, std::span<const Face> region, const FairOptions& options);

}  // namespace meshedit
