#pragma once
/// \file
/// What a mesh carries besides its shape (attributes.h): texture coordinates and their seams,
/// corner normals, colours, materials and their borders. `meshedit info`, the viewer's info
/// panel and the seam lines of the view read it from here.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

/// Whether edge e is a seam of the corner values `corner` (texture coordinates, split
/// normals): an interior edge whose two faces give one of its ends different values. A
/// boundary edge is not a seam.
template <class T>
bool corners_differ(const Mesh& mesh, Edge e, const HalfedgeProperty<T>& corner) {
    const Halfedge h = mesh.halfedge(e, 0);
    const Halfedge t = mesh.halfedge(e, 1);
    if (mesh.is_boundary(h) || mesh.is_boundary(t)) {
        return false;
    }
    // h's face has the corner at to(h) on h and the one at from(h) on prev(h); t's face the
    // same two vertices on prev(t) and t.
    return !(corner[h] == corner[mesh.prev(t)]) || !(corner[mesh.prev(h)] == corner[t]);
}

/// Whether edge e is a UV seam (corners_differ() of its texture coordinates).
inline bool is_uv_seam(const Mesh& mesh, Edge e, const HalfedgeProperty<Vec2>& uv) {
    return corners_differ(mesh, e, uv);
}

/// Whether edge e separates faces of two materials.
bool is_material_border(const Mesh& mesh, Edge e, const FaceProperty<std::uint32_t>& material);

struct AttributeSummary {
    bool texcoords = false;                ///< h:texcoord
    std::size_t uv_seam_edges = 0;         ///< is_uv_seam() edges
    bool second_texcoords = false;         ///< h:texcoord1
    std::size_t second_uv_seam_edges = 0;  ///< is_uv_seam() edges of h:texcoord1
    bool corner_normals = false;           ///< h:normal (split normals a file gave)
    bool vertex_colours = false;           ///< v:color
    bool face_colours = false;             ///< f:color
    bool face_materials = false;           ///< f:material with Mesh::materials()
    std::size_t material_borders = 0;      ///< is_material_border() edges
    std::size_t textured_materials = 0;
    std::size_t missing_textures = 0;  ///< texture paths that name no file
};

AttributeSummary summarize_attributes(const Mesh& mesh);

/// The summary as rows of (name, value) for `meshedit info` and the viewer's info panel:
/// texture coordinates (and the second set, when the mesh has one), corner normals, colours,
/// materials, then one row per material (name, colour, opacity, texture path, "(missing)" when it
/// names no file).
std::vector<std::pair<std::string, std::string>> attribute_rows(const Mesh& mesh,
                                                                const AttributeSummary& a);

}  // namespace meshedit
