#pragma once
/// \file
/// Helpers shared by the format readers and writers (private to meshedit_io).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "meshedit/core/mesh.h"

namespace meshedit::io_detail {

/// The name errors use for `path` (as the caller spelled it).
inline std::string display_name(const std::filesystem::path& path) {
    return path.string();
}

/// The extension of `path`, lower-cased, with its dot (".dae"); empty if none.
std::string lower_extension(const std::filesystem::path& path);

/// The whole file as bytes. \throws IoError naming `path` if it is missing, a folder, or
/// unreadable.
std::string read_file(const std::filesystem::path& path);

/// Writes `bytes` to `path` (created or truncated) and checks every step, so a full disk
/// surfaces as an exception rather than a short file. \throws std::runtime_error.
void write_file(const std::filesystem::path& path, std::string_view bytes);

/// Shortest decimal text that reads back as exactly `value` (std::to_chars).
std::string format_double(double value);

/// `mesh` itself when it has dense indices, else a garbage-collected copy kept in `storage`.
/// Writers need dense indices because files number vertices 0…n−1.
const Mesh& compacted(const Mesh& mesh, std::optional<Mesh>& storage);

}  // namespace meshedit::io_detail
