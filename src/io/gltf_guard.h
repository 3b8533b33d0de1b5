#pragma once
/// \file
/// What stands between a hostile glTF file and tinygltf (private to meshedit_io): a nesting
/// check run on the JSON before tinygltf parses it (its JSON-to-value conversion recurses once
/// per level), and file-system callbacks that let a buffer URI name only regular files inside
/// the model's own folder.

#include <tiny_gltf.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace meshedit::gltf_guard {

/// JSON nested deeper than this is refused (real files nest fewer than 20 levels).
inline constexpr std::size_t kMaxJsonDepth = 512;

/// Checks the nesting depth of the JSON in `bytes` (a .gltf text, or the JSON chunk of a
/// binary .glb). \throws IoError naming `file` and the line where the limit is passed.
void check_json_depth(std::string_view bytes, bool binary, const std::string& file);

/// File access for tinygltf confined to one folder: a buffer URI may name only a regular
/// file inside `folder` or below it (no absolute paths, no `..` or symbolic link leading
/// out, no FIFOs or devices), at most `max_bytes` long. What was refused, and why, is kept
/// for the error message (tinygltf itself only says "file not found").
class ConfinedFiles {
public:
    /// With no folder, no file may be read at all.
    ConfinedFiles(const std::optional<std::filesystem::path>& folder, std::size_t max_bytes);

    /// Callbacks for TinyGLTF::SetFsCallbacks(); valid while this object lives.
    tinygltf::FsCallbacks callbacks();
    /// The first refusal ("'../x.bin' lies outside the model's folder"), or empty.
    const std::string& refusal() const { return refusal_; }

private:
    static bool file_exists(const std::string& path, void* self);
    static std::string expand_path(const std::string& path, void* self);
    static bool read_whole_file(std::vector<unsigned char>* out, std::string* err,
                                const std::string& path, void* self);
    static bool write_whole_file(std::string* err, const std::string& path,
                                 const std::vector<unsigned char>& contents, void* self);

    /// The canonical path of `path` if it may be read, else empty (and refusal_ set).
    std::filesystem::path admit(const std::string& path);
    void refuse(const std::string& uri, const std::string& why);
    /// Whether `path` is the base folder joined with something (tinygltf's first search).
    bool in_base(const std::string& path) const;
    /// The URI as the file wrote it (after percent-decoding), from the joined path.
    std::string uri_of(const std::string& path) const;

    std::filesystem::path root_;  // canonical
    bool no_files_ = false;
    std::string prefix_;  // what tinygltf puts before a URI: the folder and a '/'
    std::size_t max_bytes_;
    std::string refusal_;
};

}  // namespace meshedit::gltf_guard
