#pragma once
/// \file
/// A mesh's materials (Mesh::materials()): what a face's kMaterialProperty index names. The
/// fields MeshEdit understands are those every format shares; the rest of a material as its
/// file wrote it is kept to be written back.

#include <string>
#include <vector>

#include "meshedit/core/math.h"

namespace meshedit {

struct Material {
    std::string name;
    Vec3 base_colour{1.0, 1.0, 1.0};  ///< OBJ's Kd, glTF's baseColorFactor (rgb)
    double opacity = 1.0;             ///< OBJ's d (1 - Tr), glTF's baseColorFactor alpha
    std::string base_colour_texture;  ///< OBJ's map_Kd, glTF's baseColorTexture image (a path)
    /// The texture's bytes when the file embedded it (a .glb's image, a data: URI) instead of
    /// naming a file; base_colour_texture is then only a name for it ("Texture.png"). glTF
    /// writes them back embedded; the formats that name files say they cannot keep them.
    std::string base_colour_texture_bytes;
    /// Which texture coordinate set the texture reads: 0 the first (kTexCoordProperty), 1 the
    /// second (kTexCoord1Property). glTF's baseColorTexture.texCoord; COLLADA's binding of the
    /// texture's texcoord to an input set. A set the mesh lacks draws with the first.
    unsigned base_colour_texcoord = 0;
    /// Whether the file said the colour and the opacity: an OBJ material whose .mtl is missing
    /// or has no Kd (d, Tr) line has neither, and is written back without them rather than
    /// with invented values.
    bool has_base_colour = true;
    bool has_opacity = true;
    /// Lines of an OBJ .mtl this material had that MeshEdit has no meaning for ("Ks 0 0 0",
    /// "illum 2"), written back as they were.
    std::vector<std::string> other;

    bool operator==(const Material&) const = default;
};

}  // namespace meshedit
