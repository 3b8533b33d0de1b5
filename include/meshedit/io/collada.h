#pragma once
/// \file
/// COLLADA 1.4.1/1.5 geometry subset (docs/spec.md §2), read with pugixml.

#include <filesystem>

#include "meshedit/io/io.h"

namespace meshedit {

/// Reads every geometry instanced from the scene's node tree, with node transforms applied
/// and the up axis converted to Y-up. Vertex `i` of a single-geometry file is position `i`
/// of its `<float_array>`. \throws IoError naming the file and the XML element.
MeshSoup read_collada(const std::filesystem::path& path);
/// The same from the file's bytes (parsed in place); `name` names it in errors.
MeshSoup parse_collada(std::string bytes, const std::string& name);

/// Writes one `<geometry>` with a `<polylist>`, positions and (if flags say so) normals, as
/// COLLADA 1.4.1, atomically. \throws IoError.
void write_collada(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags = {});

}  // namespace meshedit
