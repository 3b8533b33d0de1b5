#pragma once
/// \file
/// PLY's vertex colours, texture coordinates and normals as MeshEdit's own attributes
/// (attributes.h), both ways (private to meshedit_io; ply.cpp reads, ply_write.cpp writes).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/io/io.h"

namespace meshedit::ply_attributes {

/// The values of a face `texcoord` list property (MeshLab's per-corner UVs), as read.
struct FaceTexcoords {
    std::vector<std::uint32_t> face;   ///< the face record of each list
    std::vector<std::uint32_t> count;  ///< how many values it holds (2 per corner)
    std::vector<std::size_t> line;     ///< its line in an ASCII file (empty in binary)
    std::vector<double> values;        ///< every list's values, one after the other
};

/// Moves the user properties red green blue [alpha] (uchar, ushort, float or double) into
/// `soup.colors`, a vertex UV pair (s t, u v, texture_u texture_v, texture_s texture_t) and
/// the face lists `uvs` into `soup.corner_texcoords`. Values MeshEdit cannot keep (NaN, a
/// list of the wrong length) drop that attribute with one notice naming where.
void take(MeshSoup& soup, const FaceTexcoords& uvs);

/// What the writer puts in the vertex element for the mesh's own attributes, as columns of
/// its own types: nx ny nz from kCornerNormalProperty when it is seamless (`file_normals`
/// says so), red green blue [alpha] from kColorProperty (uchar when every value is k/255,
/// else float or double, whichever is exact), s t from kTexCoordProperty when it is seamless.
std::vector<UserProperty> vertex_columns(const Mesh& mesh, bool& file_normals);

/// The per-corner UVs of each face, in to_polygon_soup() order, when kTexCoordProperty has
/// seams (else empty); `exact_in_float` says whether float holds every value.
std::vector<Vec2> face_texcoords(const Mesh& mesh, bool& exact_in_float);

}  // namespace meshedit::ply_attributes
