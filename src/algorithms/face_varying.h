#pragma once
// Private to meshedit_core: corner attributes (texture coordinates, corner normals) through one
// level of Loop, Catmull-Clark or linear subdivision as face-varying values, by the rules of
// OpenSubdiv's face-varying channels (docs/subdivision.md, "Face-varying interpolation").

#include "meshedit/core/math.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/pod_array.h"
#include "meshedit/core/subdivision.h"

namespace meshedit::refine {

enum class Scheme { Loop, CatmullClark, Linear };

/// Which level was run and how corner values follow it.
struct FaceVaryingRules {
    Scheme scheme = Scheme::CatmullClark;
    LoopWeights weights = LoopWeights::Warren;  ///< Loop's weights, for smooth values
    UvInterpolation uv = UvInterpolation::CornersOnly;
};

/// The corner values of `refined`, made by one level of `rules.scheme` from `base` (collected;
/// for Loop all triangles) in the layouts of subdivision.cpp and quad_subdivision.h, from
/// `old` (one value per halfedge of `base`; those of boundary halfedges are not read).
///
/// The values of a vertex are its corners' distinct values; an edge whose faces give either
/// end different values is a seam, a boundary of the value charts. A vertex on no seam (and,
/// by the option, not at a boundary corner) moves by the scheme's own vertex rule; otherwise
/// each of its values is a corner (stays) or a crease along the two edges that bound the run
/// of faces sharing it (3/4 · value + 1/8 · the values at their far ends), as `rules.uv` says.
/// Edge points on seams, boundaries and creases are midpoints of their own face's values.
/// Every output value is computed once, so corners that share a value share its bits.
/// \return one value per halfedge of `refined` (boundary halfedges get T{}).
template <class T>
void refine_face_varying(const Mesh& base, const Mesh& refined, const FaceVaryingRules& rules,
                         const memory::Array<T>& old, memory::Array<T>& out);

}  // namespace meshedit::refine
