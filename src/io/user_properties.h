#pragma once
/// \file
/// User properties (io.h, UserProperty) between soups, meshes and writers (private to
/// meshedit_io).

#include <string>
#include <string_view>
#include <vector>

#include "meshedit/core/build.h"
#include "meshedit/core/mesh.h"
#include "meshedit/io/io.h"

namespace meshedit::user_properties {

/// Adds `soup`'s vertex and face user properties to `mesh`, built from it by build_mesh() with
/// `report`: vertex i is soup vertex i and a copy made for a split vertex takes the values of
/// the vertex it copies; faces skip the dropped ones. A name the mesh already uses is skipped.
void attach(const MeshSoup& soup, const BuildReport& report, Mesh& mesh);

/// The vertex (or face) properties of `mesh` whose names start with `prefix` ("v:ply:") and
/// whose type is one of UserProperty's, in the order they were added (a PLY file's order): the name
/// without the prefix, the type, and a value per element index.
std::vector<UserProperty> vertex_columns(const Mesh& mesh, std::string_view prefix);
std::vector<UserProperty> face_columns(const Mesh& mesh, std::string_view prefix);

}  // namespace meshedit::user_properties
