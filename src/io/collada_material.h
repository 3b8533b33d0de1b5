#pragma once
/// \file
/// COLLADA materials, both ways (private to meshedit_io): a `<material>` and its
/// `<effect>`'s diffuse colour or texture image as a Material; a mesh's materials as
/// `<library_images>`, `<library_effects>` and `<library_materials>`.

#include <filesystem>
#include <string>
#include <vector>

#include "collada_detail.h"
#include "meshedit/core/material.h"

namespace meshedit::collada {

/// The Material of `<material>` `node`: its name (else its id), and from its effect's
/// profile_COMMON technique the diffuse `<color>` (rgb) or `<texture>`'s image path, and
/// `<transparency>` as the opacity. Whatever cannot be found is left unsaid (has_base_colour
/// false, no texture).
Material read_material(const Document& doc, pugi::xml_node node);

/// The `texcoord` semantic of that diffuse `<texture>` ("" for none): an instance's
/// `<bind_vertex_input>` maps it to an input set.
std::string diffuse_texcoord(const Document& doc, pugi::xml_node node);

/// The libraries for `materials`, material i as id "material-i" (effect "effect-i", image
/// "image-i"), each escaped for XML; a texture path relative to `folder`, the output's.
std::string materials_text(const std::vector<Material>& materials,
                           const std::filesystem::path& folder);

/// `s` with & < > " escaped.
std::string xml_escape(const std::string& s);

}  // namespace meshedit::collada
