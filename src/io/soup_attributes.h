#pragma once
/// \file
/// A soup's corner attributes and materials onto the mesh built from it (private to
/// meshedit_io; read_mesh()).

#include "meshedit/core/build.h"
#include "meshedit/core/mesh.h"
#include "meshedit/io/io.h"

namespace meshedit::soup_attributes {

/// Keeps `soup`'s texture coordinates and normals (per corner, or per vertex: the seamless
/// case) as kTexCoordProperty / kCornerNormalProperty, its second texture coordinate set as
/// kTexCoord1Property, and its materials as kMaterialProperty
/// and Mesh::materials(), on `mesh` built from it by build_mesh() with `report` (which keeps
/// each kept face's corners in order, halfedge(f) leaving corner 0, and drops the faces it
/// lists).
void attach(const MeshSoup& soup, const BuildReport& report, Mesh& mesh);

}  // namespace meshedit::soup_attributes
