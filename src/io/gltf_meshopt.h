#pragma once
/// \file
/// glTF compression extensions (private to meshedit_io): EXT_meshopt_compression is decoded
/// through libmeshoptimizer into plain buffer views before the accessors are read; any other
/// extension in `extensionsRequired` that changes geometry (KHR_draco_mesh_compression,
/// …) is refused by name; KHR_mesh_quantization is read by gltf.cpp.

#include <tiny_gltf.h>

#include <optional>
#include <string>
#include <string_view>

namespace meshedit::gltf_meshopt {

/// tinygltf cannot load the data-less "fallback" buffers EXT_meshopt_compression files declare
/// (no uri: it takes them for a missing file or the GLB chunk). When `bytes` (a .gltf text or a
/// .glb) has such buffers, returns a copy in which each is a 4-byte embedded placeholder;
/// nullopt if nothing needs rewriting. \throws IoError naming `file` for unreadable JSON.
std::optional<std::string> replace_fallback_buffers(std::string_view bytes, bool binary,
                                                    const std::string& file);

/// \throws IoError naming `file` and the first extension in `extensionsRequired` that MeshEdit
/// does not read (all but EXT_meshopt_compression and those only about materials, textures and
/// lights). Called also when tinygltf failed: a Draco file fails there (its accessors have no
/// buffer view), and the extension is the better reason.
void check_required(const tinygltf::Model& model, const std::string& file);

/// Refuses required extensions MeshEdit does not read, then decodes every compressed buffer
/// view into a buffer of its own (sizes checked against the memory budget first). \throws
/// IoError naming `file` and the extension or buffer view.
void decode(tinygltf::Model& model, const std::string& file);

}  // namespace meshedit::gltf_meshopt
