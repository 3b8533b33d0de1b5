#pragma once
/// \file
/// Wavefront OBJ, read by MeshEdit's own parser (exact doubles, every index checked); polygons
/// are kept as polygons.

#include <filesystem>
#include <string>
#include <string_view>

#include "meshedit/io/io.h"

namespace meshedit {

/// \throws IoError naming the file and line.
MeshSoup read_obj(const std::filesystem::path& path);
/// The same from the file's bytes; `name` names it in errors.
MeshSoup parse_obj(std::string_view bytes, const std::string& name);
/// The text write_obj() writes: `v` lines (`v x y z r g b [a]` from kColorProperty) and `f`
/// lines, `vt` from kTexCoordProperty, `vn` from kCornerNormalProperty (else area-weighted
/// vertex normals if flags say so), `usemtl` from kMaterialProperty and `mtllib library` when `library` is not empty; every double in its
/// shortest round-trip decimals (the fuzz targets read it back without a file).
std::string obj_text(const Mesh& mesh, const IoFlags& flags = {}, const std::string& library = {});
/// Writes obj_text(), atomically, and the mesh's materials to NAME.mtl beside it.
/// \throws IoError.
void write_obj(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags = {});

}  // namespace meshedit
