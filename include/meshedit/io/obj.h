#pragma once
/// \file
/// Wavefront OBJ through tinyobjloader; polygons are kept as polygons.

#include <filesystem>

#include "meshedit/io/io.h"

namespace meshedit {

/// \throws IoError naming the file and line.
MeshSoup read_obj(const std::filesystem::path& path);
/// Writes `v` and `f` lines (and `vn` if flags say so), atomically. \throws IoError.
void write_obj(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags = {});

}  // namespace meshedit
