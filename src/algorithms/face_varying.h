#pragma once
// Private to meshedit_core: corner attributes (texture coordinates, corner normals) through one
// level of Loop, Catmull-Clark or linear subdivision as face-varying values, by the rules of
// OpenSubdiv's face-varying channels (docs/subdivision.md, "Face-varying interpolation").

#include <cstddef>
#include <cstdint>

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

/// One level's corner values made from the old level, before the refinement replaces it:
/// the values at the old corners, edge points and face points, and the few facts about the
/// old connectivity that writing them into the new corners needs.
template <class T>
struct FaceVaryingLevel {
    Scheme scheme = Scheme::CatmullClark;
    std::size_t edges = 0;    ///< the old level's edge count
    memory::Array<T> face;    ///< per old face: its face point's value (quads)
    memory::Array<T> edge;    ///< per old interior halfedge: its edge point's, its side
    memory::Array<T> vertex;  ///< per old interior halfedge: its head's new value
    memory::Array<std::uint8_t> boundary;       ///< per old halfedge
    memory::Array<std::uint32_t> corners;       ///< old faces' halfedges, from halfedge(f)
    memory::Array<std::uint32_t> corner_start;  ///< face f's are [start[f], start[f + 1])
};

/// The values one level of `rules.scheme` makes from `base` (collected; for Loop all
/// triangles) and `old` (one value per halfedge of `base`; those of boundary halfedges are
/// not read).
///
/// The values of a vertex are its corners' distinct values; an edge whose faces give either
/// end different values is a seam, a boundary of the value charts. A vertex on no seam (and,
/// by the option, not at a boundary corner) moves by the scheme's own vertex rule; otherwise
/// each of its values is a corner (stays) or a crease along the two edges that bound the run
/// of faces sharing it (3/4 · value + 1/8 · the values at their far ends), as `rules.uv` says.
/// Edge points on seams, boundaries and creases are midpoints of their own face's values.
/// Every output value is computed once, so corners that share a value share its bits.
template <class T>
FaceVaryingLevel<T> prepare_face_varying(const Mesh& base, const FaceVaryingRules& rules,
                                         const memory::Array<T>& old);

/// The values of the refined mesh's `refined_halfedges` corners, in the layouts of
/// subdivision.cpp and quad_subdivision.h (boundary halfedges get T{}).
template <class T>
void write_face_varying(const FaceVaryingLevel<T>& level, std::size_t refined_halfedges,
                        memory::Array<T>& out);

}  // namespace meshedit::refine
