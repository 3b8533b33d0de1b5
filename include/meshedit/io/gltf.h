#pragma once
/// \file
/// glTF 2.0 (.gltf with embedded buffers, and .glb) through tinygltf.

#include <filesystem>

#include "meshedit/io/io.h"

namespace meshedit {

/// Reads the triangle primitives of every mesh in the default scene, node transforms
/// applied; shared vertices are kept shared (indices as stored). \throws IoError.
MeshSoup read_gltf(const std::filesystem::path& path);
/// Writes one mesh, one triangle primitive (polygons are fan-triangulated in the file),
/// positions and normals; binary when the extension is .glb. Atomic. \throws IoError.
void write_gltf(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags = {});

}  // namespace meshedit
