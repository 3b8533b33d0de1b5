#pragma once
// Private to meshedit_algorithms: what remeshing does with the attributes (docs/remesh.md,
// "Attributes"). Texture coordinate seams, split-normal seams and material borders are
// features the remesher keeps (AttributeSeams); at the end every corner, vertex colour and
// face material is taken again from the input surface (project_attributes()): barycentric on
// the closest input triangle of the face's own chart, so a corner beside a seam never takes
// the far side's values.

#include <functional>
#include <vector>

#include "meshedit/core/closest_point.h"
#include "meshedit/core/mesh.h"

namespace meshedit::remeshing {

/// The face-varying and face attributes of one mesh whose change across an edge makes it a
/// seam: every texture coordinate set, the corner normals, the material.
class AttributeSeams {
public:
    explicit AttributeSeams(const Mesh& mesh);
    /// Whether the mesh has any of them.
    bool any() const { return !vec2_.empty() || normal_ || material_; }
    /// An interior edge across which a corner value of either end, or the material, differs.
    bool is_seam(Edge e) const;

private:
    const Mesh& mesh_;
    std::vector<HalfedgeProperty<Vec2>> vec2_;
    HalfedgeProperty<Vec3> normal_;
    FaceProperty<std::uint32_t> material_;
};

/// Whether `mesh` has anything project_attributes() would write.
bool has_projected_attributes(const Mesh& mesh);

/// Takes every attribute of `mesh` again from `source` (a triangle mesh without garbage whose
/// face t is `tree`'s triangle t, in the units of `mesh`'s positions): each face's material
/// and face colour from the input triangle closest to its centre, which names its chart (the
/// faces joined across edges that are no seam); each corner's values (texture coordinates,
/// normals, renormalised) barycentric on the closest input triangle of that chart; each
/// vertex colour barycentric on the closest input triangle. Only faces `changes` accepts, and
/// of them only the corners and vertices `moves` accepts. `hints`: per vertex, an input
/// triangle near it (TriangleTree::closest()'s hint; shorter or kInvalidIndex: none).
void project_attributes(Mesh& mesh, const Mesh& source, const TriangleTree& tree,
                        const std::function<bool(Face)>& changes,
                        const std::function<bool(Vertex)>& moves,
                        const std::vector<std::uint32_t>& hints);

}  // namespace meshedit::remeshing
