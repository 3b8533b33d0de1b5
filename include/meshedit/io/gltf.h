#pragma once
/// \file
/// glTF 2.0 (.gltf with embedded buffers, and .glb) through tinygltf.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "meshedit/io/io.h"

namespace meshedit {

/// Reads the triangle primitives of every mesh in the default scene, node transforms
/// applied; shared vertices are kept shared (indices as stored). \throws IoError.
MeshSoup read_gltf(const std::filesystem::path& path);
/// The same from the file's bytes; `name` names it in errors. Buffer URIs may name files in
/// `folder` only; with no folder, only embedded (data:) buffers load.
MeshSoup parse_gltf(std::string_view bytes, const std::string& name,
                    const std::optional<std::filesystem::path>& folder = std::nullopt);
/// Writes one mesh, one triangle primitive (polygons are fan-triangulated in the file),
/// positions and normals; binary when the extension is .glb. Atomic. \throws IoError.
void write_gltf(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags = {});

}  // namespace meshedit
