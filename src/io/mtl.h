#pragma once
/// \file
/// OBJ's material libraries (.mtl), read and written (private to meshedit_io): `newmtl`,
/// `Kd` (base colour), `d` / `Tr` (opacity), `map_Kd` (base-colour texture); every other line
/// of a material is kept as it was and written back.

#include <filesystem>
#include <string>

#include "meshedit/core/mesh.h"
#include "meshedit/io/io.h"

namespace meshedit::mtl {

/// Reads the libraries `soup` names (`material_libraries`, relative to `obj`'s folder) into
/// the materials its faces use, by name. A texture path that exists is made absolute (so a
/// converted file elsewhere still finds it). A missing library or material is a notice, not
/// an error: the names are kept.
void read_libraries(const std::filesystem::path& obj, MeshSoup& soup);

/// The .mtl text of `mesh`'s named materials, texture paths relative to `folder` (where the
/// .mtl goes) when they are absolute.
std::string text(const Mesh& mesh, const std::filesystem::path& folder);

}  // namespace meshedit::mtl
