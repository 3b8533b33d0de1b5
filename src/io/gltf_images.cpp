// glTF materials, and the images a glTF file embeds kept as bytes (gltf_images.h).

#include "gltf_images.h"

#include <cstddef>
#include <cstdint>

#include "io_util.h"

namespace meshedit::gltf_images {

bool keep_embedded(tinygltf::Image* image, int index, std::string*, std::string*, int, int,
                   const unsigned char* bytes, int size, void* user_data) {
    const bool embedded = image->uri.empty() || image->uri.rfind("data:", 0) == 0;
    if (embedded && user_data != nullptr && bytes != nullptr && size > 0) {
        (*static_cast<Embedded*>(user_data))[index] =
            std::string(reinterpret_cast<const char*>(bytes), static_cast<std::size_t>(size));
    }
    return true;
}

std::string extension_of(std::string_view bytes) {
    if (bytes.substr(0, 8) == "\x89PNG\r\n\x1a\n") {
        return "png";
    }
    if (bytes.substr(0, 3) == "\xff\xd8\xff") {
        return "jpg";
    }
    if (bytes.substr(0, 4) == "RIFF" && bytes.substr(8, 4) == "WEBP") {
        return "webp";
    }
    if (bytes.substr(0, 2) == "BM") {
        return "bmp";
    }
    return "bin";
}

std::string file_name(std::string stem, std::string_view bytes) {
    for (char& c : stem) {
        c = c == '/' || c == '\\' || c == ':' ? '_' : c;
    }
    return stem + "." + extension_of(bytes);
}

std::string mime_of(std::string_view bytes) {
    const std::string ext = extension_of(bytes);
    return ext == "png" ? "image/png" : ext == "jpg" ? "image/jpeg" : "";
}

std::string base64(std::string_view bytes) {
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = bytes.size() - i < 3 ? bytes.size() - i : 3;
        std::uint32_t v = 0;
        for (std::size_t k = 0; k < 3; ++k) {
            v = v << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        }
        for (std::size_t k = 0; k < 4; ++k) {
            out += k <= n ? kDigits[(v >> (18 - 6 * k)) & 63] : '=';
        }
    }
    return out;
}

// The Material of glTF material `g`: its name, baseColorFactor and baseColorTexture (a path
// resolved against `folder`, or an embedded image's bytes and a name for them).
Material read_material(const tinygltf::Model& model, const tinygltf::Material& g,
                       const Embedded& embedded, const std::filesystem::path& folder) {
    Material m;
    m.name = g.name;
    const std::vector<double>& f = g.pbrMetallicRoughness.baseColorFactor;
    if (f.size() == 4) {
        m.base_colour = Vec3(f[0], f[1], f[2]);
        m.opacity = f[3];
    }
    const int t = g.pbrMetallicRoughness.baseColorTexture.index;
    m.base_colour_texcoord =  // another set than 0 and 1: gltf.cpp says so and draws with 0
        g.pbrMetallicRoughness.baseColorTexture.texCoord == 1 ? 1 : 0;
    if (t >= 0 && static_cast<std::size_t>(t) < model.textures.size()) {
        const int source = model.textures[static_cast<std::size_t>(t)].source;
        if (source >= 0 && static_cast<std::size_t>(source) < model.images.size()) {
            const tinygltf::Image& image = model.images[static_cast<std::size_t>(source)];
            const auto kept = embedded.find(source);
            if (kept != embedded.end()) {
                // A name for it (the image's, else the material's) and its bytes.
                const std::string stem = !image.name.empty() ? image.name
                                         : !g.name.empty()   ? g.name
                                                             : "texture" + std::to_string(source);
                m.base_colour_texture = file_name(stem, kept->second);
                m.base_colour_texture_bytes = kept->second;
            } else if (!image.uri.empty()) {
                m.base_colour_texture = io_util::resolve_texture(image.uri, folder, true);
            }
        }
    }
    return m;
}

}  // namespace meshedit::gltf_images
