#pragma once
// Private to meshedit_core: the attribute carry of the refinements that rebuild the mesh
// array by array (Loop, Catmull-Clark, linear), which cannot call Mesh::carry() element by
// element without giving up their speed.

#include <functional>

#include <vector>

#include "algorithms/face_varying.h"
#include "meshedit/core/memory.h"
#include "meshedit/core/mesh.h"

namespace meshedit::refine {

/// How one level numbers its result (subdivision.cpp's and quad_subdivision.h's layouts):
/// both keep the old vertices, put edge e's point at V + e and make edges g < 2E the halves
/// of old edge g / 2; Loop's face 4f + i is a part of old face f, Quad's faces are the
/// corners of the old faces in order, and its face f's point is V + E + f.
enum class Layout { Loop, Quad };

/// Blending vertex attributes' channels, three at a time, refined by the refinement's own
/// position rules and weights in the same pass as the positions: `in[i]` holds group i's
/// old values; the refinement writes `out[i]`, sized to the new vertex count.
struct ChannelGroups {
    std::vector<memory::Array<Vec3>> in, out;
};

/// True when the mesh has attributes to carry (any property but connectivity, positions and
/// the crease flags the refinements keep themselves).
bool has_attributes(const Mesh& mesh);

/// Runs `refine` (one level, on a collected mesh; for Loop a triangle mesh) with the mesh's
/// attributes carried: a vertex attribute that blends goes through the refinement's position
/// rules beside the positions (`refine` fills the ChannelGroups it is given), so it gets
/// exactly the positions' weights; other vertex attributes keep their values on old vertices and
/// derive new points from the edge's ends or the face's corners; edges halves copy their edge and
/// the edges inside faces are new; each face copies the face it is a part of. Texture coordinates
/// (each set of kTexCoordSets, Vec2) are face-varying values refined by `rules`
/// (face_varying.h), each with its own seams; corner
/// normals (`h:normal`, Vec3) the same way but always linearly; any other corner attribute
/// copies the old face's corner at the same vertex, or blends the old corners at an edge's
/// ends (an edge point) or at all the face's corners (a face point).
void refine_carrying(Mesh& mesh, const FaceVaryingRules& rules,
                     const std::function<void(Mesh&, ChannelGroups&)>& refine);

}  // namespace meshedit::refine
