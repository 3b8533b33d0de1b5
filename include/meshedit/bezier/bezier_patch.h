#pragma once
/// \file
/// Tensor-product Bezier patches and their tessellation into a welded core mesh.
///
/// A patch has `rows × cols` control points stored row-major, `cp[row * cols + col]` (the
/// .bez files use 4 × 4). It is evaluated rows-by-u then column-by-v: each row is a curve in
/// u (along `col`), evaluated at u; the resulting column of `rows` points is a curve in v,
/// evaluated at v. Parameters are valid in [0, 1]².

#include <span>
#include <vector>

#include "meshedit/core/math.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

/// Value and exact first partial derivatives of a patch at (u, v).
struct PatchPoint {
    Vec3 position;
    Vec3 du;  ///< ∂S/∂u
    Vec3 dv;  ///< ∂S/∂v
    /// normalize(du × dv); where that cross product degenerates (a pole, a collapsed edge)
    /// it is taken at a point inset by 1e-6 (then 1e-4, 1e-2) towards the patch centre,
    /// which approximates the limit normal with the sign of the neighbouring points.
    Vec3 normal;
};

struct BezierPatch {
    int rows = 4;
    int cols = 4;
    std::vector<Vec3> control_points;  ///< row-major, rows × cols

    const Vec3& cp(int row, int col) const { return control_points[row * cols + col]; }
    /// S(u, v) by de Casteljau, rows by u then the column by v.
    Vec3 evaluate(double u, double v) const;
    /// S, ∂S/∂u, ∂S/∂v and the unit normal at (u, v).
    PatchPoint evaluate_with_derivatives(double u, double v) const;
    /// S(u, v) by the tensor-product Bernstein sum, for tests.
    Vec3 evaluate_bernstein(double u, double v) const;
};

struct TessellationOptions {
    /// Quads per patch side: each patch becomes density × density quads, split into
    /// triangles.
    int density = 8;
    /// Points closer than this fraction of their patch's bounding-box diagonal are welded
    /// (of the smaller patch's, for points of two patches).
    double weld_tolerance = 1e-7;
};

/// Tessellates the patches into one triangle mesh: samples every patch on a
/// (density+1)² grid (quad (i, j) split along its (i,j)–(i+1,j+1) diagonal unless that
/// diagonal's ends weld together), welds points within `weld_tolerance` × their patch's
/// bounding-box diagonal across patch seams (spatial hash; a patch far away or much larger
/// cannot weld a small one away),
/// drops triangles with a repeated welded corner (poles), and orients the faces of each
/// connected component consistently before building, since patch sets such as the teapot mix
/// orientations. Each component then faces outward (positive signed volume about its
/// centroid) if it is closed-ish (its face area vectors sum to at most half their total
/// length), else it keeps the area-weighted majority of the input orientation. Vertices are
/// numbered in order of first use by the faces; no isolated vertices.
/// \throws BudgetError (core/budget.h) if the work would not fit the memory budget.
/// \post validate() passes.
Mesh tessellate(std::span<const BezierPatch> patches, const TessellationOptions& options = {});

}  // namespace meshedit
