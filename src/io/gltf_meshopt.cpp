// EXT_meshopt_compression (https://github.com/KhronosGroup/glTF/tree/main/extensions/2.0/Vendor/
// EXT_meshopt_compression) through libmeshoptimizer, and the refusal of required extensions
// MeshEdit does not read.

#include "gltf_meshopt.h"

#include <meshoptimizer.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <vector>

#include "meshedit/core/budget.h"
#include "meshedit/files/files.h"

namespace meshedit::gltf_meshopt {
namespace {

constexpr const char* kMeshopt = "EXT_meshopt_compression";

/// Required extensions that only concern materials, textures, lights or shading: MeshEdit
/// reads geometry alone, so they change nothing it reads.
bool irrelevant_to_geometry(const std::string& name) {
    for (const char* prefix : {"KHR_materials_", "KHR_texture_", "EXT_texture_", "KHR_lights_",
                               "KHR_technique", "MSFT_texture_"}) {
        if (name.rfind(prefix, 0) == 0) {
            return true;
        }
    }
    return false;
}

std::uint32_t read_u32(std::string_view bytes, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, sizeof v);
    return v;
}

void put_u32(std::string& out, std::uint32_t v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

/// The number `key` of extension object `ext`, or `fallback` when absent; IoError when it is
/// not a non-negative integer.
std::size_t get_size(const tinygltf::Value& ext, const char* key, std::size_t fallback,
                     const std::string& file, const std::string& where) {
    if (!ext.Has(key)) {
        return fallback;
    }
    const tinygltf::Value& v = ext.Get(key);
    const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    if (!(d >= 0 && d <= 9.0e15 && d == std::floor(d))) {
        throw IoError(file, where, std::string(kMeshopt) + " '" + key + "' is not a valid size");
    }
    return static_cast<std::size_t>(d);
}

std::string get_string(const tinygltf::Value& ext, const char* key, const char* fallback) {
    return ext.Has(key) && ext.Get(key).IsString() ? ext.Get(key).Get<std::string>()
                                                   : std::string(fallback);
}

void decode_view(tinygltf::Model& model, std::size_t v, const std::string& file) {
    tinygltf::BufferView& view = model.bufferViews[v];
    const auto found = view.extensions.find(kMeshopt);
    if (found == view.extensions.end()) {
        return;
    }
    const std::string where = "bufferView " + std::to_string(v);
    const tinygltf::Value& ext = found->second;
    if (!ext.IsObject()) {
        throw IoError(file, where, std::string(kMeshopt) + " is not an object");
    }
    const std::size_t buffer = get_size(ext, "buffer", SIZE_MAX, file, where);
    const std::size_t offset = get_size(ext, "byteOffset", 0, file, where);
    const std::size_t length = get_size(ext, "byteLength", SIZE_MAX, file, where);
    const std::size_t stride = get_size(ext, "byteStride", 0, file, where);
    const std::size_t count = get_size(ext, "count", SIZE_MAX, file, where);
    const std::string mode = get_string(ext, "mode", "");
    const std::string filter = get_string(ext, "filter", "NONE");
    if (buffer >= model.buffers.size()) {
        throw IoError(file, where, std::string(kMeshopt) + " has no valid buffer");
    }
    const std::vector<unsigned char>& source = model.buffers[buffer].data;
    if (length == SIZE_MAX || count == SIZE_MAX || offset > source.size() ||
        length > source.size() - offset) {
        throw IoError(file, where,
                      "the compressed data lies outside its buffer (the file is truncated or "
                      "corrupt)");
    }
    const bool attributes = mode == "ATTRIBUTES";
    if (attributes ? (stride == 0 || stride % 4 != 0 || stride > 256)
                   : (mode != "TRIANGLES" && mode != "INDICES") || (stride != 2 && stride != 4)) {
        throw IoError(file, where,
                      "unsupported " + std::string(kMeshopt) + " mode '" + mode +
                          "' with byteStride " + std::to_string(stride));
    }
    if (mode == "TRIANGLES" && count % 3 != 0) {
        throw IoError(file, where,
                      "TRIANGLES count " + std::to_string(count) + " is not a multiple of 3");
    }
    // Decoded data takes count * stride bytes; compressed data is never smaller than about a
    // byte per element, so a count far beyond the compressed length is a lie.
    if (count > length * 256 + 1024) {
        throw IoError(file, where,
                      "count " + std::to_string(count) + " is too large for " +
                          std::to_string(length) + " compressed bytes");
    }
    const double bytes = static_cast<double>(count) * static_cast<double>(stride);
    if (const auto over = over_budget(bytes)) {
        throw IoError(file, where, "decoding the compressed data " + *over);
    }
    if (view.byteLength > count * stride) {
        throw IoError(file, where,
                      "byteLength " + std::to_string(view.byteLength) +
                          " is larger than the decoded data (" + std::to_string(count * stride) +
                          " bytes)");
    }
    tinygltf::Buffer decoded;
    decoded.data.resize(count * stride);
    const unsigned char* in = source.data() + offset;
    int rc = 0;
    if (attributes) {
        rc = meshopt_decodeVertexBuffer(decoded.data.data(), count, stride, in, length);
    } else if (mode == "TRIANGLES") {
        rc = meshopt_decodeIndexBuffer(decoded.data.data(), count, stride, in, length);
    } else {
        rc = meshopt_decodeIndexSequence(decoded.data.data(), count, stride, in, length);
    }
    if (rc != 0) {
        throw IoError(file, where,
                      "the " + std::string(kMeshopt) + " data is corrupt or truncated (" + mode +
                          " decoder error " + std::to_string(rc) + ")");
    }
    if (filter == "OCTAHEDRAL" && attributes && (stride == 4 || stride == 8)) {
        meshopt_decodeFilterOct(decoded.data.data(), count, stride);
    } else if (filter == "QUATERNION" && attributes && stride == 8) {
        meshopt_decodeFilterQuat(decoded.data.data(), count, stride);
    } else if (filter == "EXPONENTIAL" && attributes) {
        meshopt_decodeFilterExp(decoded.data.data(), count, stride);
    } else if (filter != "NONE") {
        throw IoError(file, where,
                      "unsupported " + std::string(kMeshopt) + " filter '" + filter +
                          "' for mode " + mode + " and byteStride " + std::to_string(stride));
    }
    model.buffers.push_back(std::move(decoded));
    view.buffer = static_cast<int>(model.buffers.size() - 1);
    view.byteOffset = 0;
    if (view.byteLength == 0) {
        view.byteLength = count * stride;
    }
    view.extensions.erase(kMeshopt);
}

}  // namespace

std::optional<std::string> replace_fallback_buffers(std::string_view bytes, bool binary,
                                                    const std::string& file) {
    if (bytes.find(kMeshopt) == std::string_view::npos) {
        return std::nullopt;  // cheap: most files never name the extension
    }
    std::string_view json_text = bytes;
    std::size_t json_end = bytes.size();
    if (binary) {
        // 12-byte header, then the JSON chunk (length, type "JSON", data); tinygltf checks the
        // rest, so an odd layout is handed to it unchanged.
        if (bytes.size() < 20 || bytes.substr(16, 4) != "JSON") {
            return std::nullopt;
        }
        const std::uint32_t length = read_u32(bytes, 12);
        if (length > bytes.size() - 20) {
            return std::nullopt;
        }
        json_text = bytes.substr(20, length);
        json_end = 20 + length;
    }
    nlohmann::json doc = nlohmann::json::parse(json_text, nullptr, false);
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("buffers") ||
        !doc["buffers"].is_array()) {
        return std::nullopt;  // tinygltf reports it
    }
    bool changed = false;
    auto& buffers = doc["buffers"];
    for (std::size_t b = 0; b < buffers.size(); ++b) {
        auto& buf = buffers[b];
        if (!buf.is_object() || buf.contains("uri") || (binary && b == 0)) {
            continue;
        }
        const auto ext = buf.find("extensions");
        if (ext == buf.end() || !ext->is_object() || !ext->contains(kMeshopt)) {
            continue;
        }
        buf["uri"] = "data:application/octet-stream;base64,AAAAAA==";
        buf["byteLength"] = 4;
        changed = true;
    }
    if (!changed) {
        return std::nullopt;
    }
    std::string text = doc.dump();
    if (!binary) {
        return text;
    }
    while (text.size() % 4 != 0) {
        text.push_back(' ');
    }
    const std::string_view rest = bytes.substr(json_end);
    std::string out;
    out.reserve(20 + text.size() + rest.size());
    out.append(bytes.substr(0, 8));
    put_u32(out, static_cast<std::uint32_t>(20 + text.size() + rest.size()));
    put_u32(out, static_cast<std::uint32_t>(text.size()));
    out.append("JSON");
    out.append(text);
    out.append(rest);
    (void)file;
    return out;
}

void check_required(const tinygltf::Model& model, const std::string& file) {
    for (const std::string& name : model.extensionsRequired) {
        if (name != kMeshopt && name != "KHR_mesh_quantization" && !irrelevant_to_geometry(name)) {
            throw IoError(
                file, "",
                "the file requires the glTF extension " + name + ", which MeshEdit does not read");
        }
    }
}

void decode(tinygltf::Model& model, const std::string& file) {
    check_required(model, file);
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
        decode_view(model, v, file);
    }
}

}  // namespace meshedit::gltf_meshopt
