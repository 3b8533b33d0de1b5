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

/// What an inset of a region makes and where its inner border goes, to move it again without
/// rebuilding it (inset_region_positions()).
struct RegionInset {
    std::vector<Vertex> border;  ///< the inner border's vertices: the copies extrude makes
    std::vector<Vec3> base;      ///< where each starts (its original's position)
    std::vector<Vec3> inward;    ///< its move per unit of thickness
};

/// \return ok if `thickness` is a finite number of at least 0, `region` can be extruded as
/// one (is_extrude_region_ok() at height 0) and the thickness keeps the corners finite.
OpStatus is_inset_region_ok(const Mesh& mesh, const FaceSet& region, double thickness);
/// Insets the faces of `region` as one (Blender's inset faces): a ring of quads inside the
/// region's border, `thickness` wide, the whole region inside it. It is extrude_region() at
/// height 0 with the copies of the border moved into the region: each along the bisector of
/// its two border sides' inward directions in their faces' planes, by thickness / cos of half
/// the angle between them (an even ring; at most 4 × thickness at a sharp corner). Inner
/// vertices stay. The faces of the region keep their handles.
OpResult<Face> inset_region(Mesh& mesh, const FaceSet& region, double thickness,
                            RegionInset* made = nullptr);
/// What inset_region() will make of `region`, taken before it runs (the copies get the next
/// vertex indices): for an interactive inset that builds the ring once, then only moves it.
RegionInset inset_region_base(const Mesh& mesh, const FaceSet& region);
/// Moves an inset's inner border to `thickness` (the positions inset_region() gives).
OpStatus inset_region_positions(Mesh& mesh, const RegionInset& made, double thickness);

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

/// How subdivide_region() places the points inside the region.
enum class RegionScheme {
    Linear,        ///< midpoints and centroids: the shape stays
    Loop,          ///< Loop's rules inside (triangles only), Warren's weights
    CatmullClark,  ///< Catmull-Clark's rules inside; every face (triangles too) into quads
};

/// \return ok if `region` holds at least one live face, and for Loop only triangles.
OpStatus is_subdivide_region_ok(const Mesh& mesh, const FaceSet& region,
                                RegionScheme scheme = RegionScheme::Linear);
/// Subdivides the faces of `region` once, linearly: each edge of the region gets its
/// midpoint; a triangle becomes four triangles (Loop's pattern), any other face one quad per
/// corner around its centroid (Catmull-Clark's). Each face beside the region that gained
/// midpoints is cut into a fan of triangles from its first midpoint (the transition ring, as
/// Blender's subdivide and red-green refinement do), so no face is left with a corner in the
/// middle of a straight side. With Loop or Catmull-Clark, the edges with both faces in the
/// region (and no crease) get the scheme's edge points and its inner vertices (every face
/// around them in it, on no crease) its vertex points; the border, its midpoints and
/// everything outside stay, so the refined patch joins the rest without a gap. Over every
/// face of a closed mesh it is loop_subdivide() / catmull_clark() (tested). \return the faces
/// inside the old region.
OpResult<Face> subdivide_region(Mesh& mesh, const FaceSet& region,
                                std::vector<Face>* inside = nullptr,
                                RegionScheme scheme = RegionScheme::Linear);

}  // namespace meshedit
