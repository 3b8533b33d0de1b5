#pragma once
/// \file
/// Operations on a region of faces as one (Blender's extrude region and subdivide on a face
/// selection). Each keeps the contract of the local operations (local_ops.h): a pure
/// predicate, a refusal that names its reason and leaves the mesh untouched, the attribute
/// carry stated beside the diagram (docs/halfedge.md, "Operations on a region").

#include <vector>

#include "meshedit/core/local_ops.h"
#include "meshedit/selection/selection.h"

namespace meshedit {

/// What an extrude of a region made, to move its top again without rebuilding it
/// (extrude_region_positions(), as extrude_positions() does for one face).
struct RegionExtrude {
    std::vector<Vertex> moved;  ///< the top's vertices: the new copies and the inner ones
    std::vector<Vec3> base;     ///< where each was at height 0
    std::vector<Vec3> normal;   ///< the unit normal of its piece of the region
    std::vector<Face> sides;    ///< the new side quads
};

/// \return ok if `region` holds live faces, has a border (a whole closed piece has no side
/// to extrude from), touches itself at no vertex (only across edges may its faces meet), and,
/// for a height other than 0, every piece has a normal and the moved corners stay finite.
OpStatus is_extrude_region_ok(const Mesh& mesh, const FaceSet& region, double height);
/// Extrudes the faces of `region` as one (Blender's extrude region): the border's vertices
/// are copied, a quad joins each border edge to its copy, and the region's vertices move by
/// `height` along the area-weighted normal of their piece (a piece: faces joined across
/// edges). Edges shared by two faces of the region stay inside it, so neighbours stay joined.
/// The faces of the region keep their handles and become the top.
OpResult<Face> extrude_region(Mesh& mesh, const FaceSet& region, double height,
                              RegionExtrude* made = nullptr);
/// What extrude_region() will make of `region` (the copies get the next vertex indices, the
/// walls the next face indices), taken before it runs: for an interactive extrude that builds
/// the topology once and then only moves the top.
RegionExtrude extrude_region_base(const Mesh& mesh, const FaceSet& region);
/// Moves an extruded region's top to `height` (the same positions extrude_region() gives).
OpStatus extrude_region_positions(Mesh& mesh, const RegionExtrude& made, double height);

/// \return ok if `region` holds live faces and every piece of it (faces joined across
/// edges) with more than one face is a disk: one border loop that visits each vertex once, and
/// V - E + F = 1. Checked by running the dissolves on a copy (O(mesh)): a region operation is
/// a user's action, not an inner loop.
OpStatus is_dissolve_region_ok(const Mesh& mesh, const FaceSet& region);
/// Merges each piece of `region` into one face (Blender's dissolve faces): its inner vertices
/// are dissolved (dissolve_vertex()), then the edges left between its faces (dissolve_edge());
/// what each keeps is what those operations carry. \return the faces left, one per piece.
OpResult<Face> dissolve_region(Mesh& mesh, const FaceSet& region,
                               std::vector<Face>* merged = nullptr);

/// \return ok if `region` holds at least one live face.
OpStatus is_subdivide_region_ok(const Mesh& mesh, const FaceSet& region);
/// Subdivides the faces of `region` once, linearly: each edge of the region gets its
/// midpoint; a triangle becomes four triangles (Loop's pattern), any other face one quad per
/// corner around its centroid (Catmull-Clark's). Each face beside the region that gained
/// midpoints is cut into a fan of triangles from its first midpoint (the transition ring, as
/// Blender's subdivide and red-green refinement do), so no face is left with a corner in the
/// middle of a straight side. \return the faces inside the old region.
OpResult<Face> subdivide_region(Mesh& mesh, const FaceSet& region,
                                std::vector<Face>* inside = nullptr);

}  // namespace meshedit
