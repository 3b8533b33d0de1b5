#pragma once
/// \file
/// COLLADA 1.4.1/1.5 geometry subset (docs/spec.md §2), read with pugixml.

#include <filesystem>

#include "meshedit/io/io.h"

namespace meshedit {

/// Reads every geometry instanced from the scene's node tree, with node transforms applied
/// and the up axis converted to Y-up. Vertex `i` of a single-geometry file is position `i`
/// of its `<float_array>`. Kept besides positions: each primitive's NORMAL and first
/// TEXCOORD set per corner, COLOR per vertex (a vertex's first corner's), each face's material
/// through `<bind_material>` (name, diffuse colour or texture image, transparency). A bad
/// TEXCOORD or COLOR index or value drops that attribute with a notice.
/// \throws IoError naming the file and the XML element.
MeshSoup read_collada(const std::filesystem::path& path);
/// The same from the file's bytes (parsed in place); `name` names it in errors.
MeshSoup parse_collada(std::string bytes, const std::string& name);

/// Writes one `<geometry>` as COLLADA 1.4.1, atomically: positions, the file's normals and
/// texture coordinates per corner (else computed normals if flags say so), vertex colours
/// (RGBA), a `<polylist>` per run of faces of one material, the materials' effects and
/// images, and the crease marks in MeshEdit's `<extra>`. \throws IoError.
void write_collada(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags = {});

}  // namespace meshedit
