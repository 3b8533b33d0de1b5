#pragma once
// Private to meshedit_io: the images a glTF file embeds (a .glb's buffer views, data: URIs),
// kept as their bytes (never decoded) so that a material's texture survives a read and a
// write (material.h's base_colour_texture_bytes).

#include <map>
#include <string>
#include <string_view>

#include <tiny_gltf.h>

namespace meshedit::gltf_images {

/// The bytes of each embedded image, by image index.
using Embedded = std::map<int, std::string>;

/// tinygltf's image loader: keeps an embedded image's bytes in the Embedded that `user_data`
/// points to and accepts every image unread (a file named by a uri stays a path).
bool keep_embedded(tinygltf::Image* image, int index, std::string* err, std::string* warn,
                   int width, int height, const unsigned char* bytes, int size, void* user_data);

/// "png", "jpg", "tga" … from the bytes' first ones; "bin" when unknown.
std::string extension_of(std::string_view bytes);
/// A file name for an embedded image: `stem` without path separators, and its extension.
std::string file_name(std::string stem, std::string_view bytes);
/// "image/png" or "image/jpeg": the images glTF holds; empty for any other.
std::string mime_of(std::string_view bytes);
/// Standard base64 with padding, for a data: URI.
std::string base64(std::string_view bytes);

}  // namespace meshedit::gltf_images
