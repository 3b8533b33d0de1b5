#pragma once
/// \file
/// Files as bytes, the layer below every format and below the renderer's PNG writer: names
/// and extensions, reading a whole file with one wording for each error, and the atomic
/// write every writer goes through. Errors are IoErrors naming the file (io_error.h).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "meshedit/files/io_error.h"

namespace meshedit {

/// The extension of `path`, lower-cased, with its dot (".dae"); empty if none.
std::string file_extension(const std::filesystem::path& path);

/// Appends Unicode code point `codepoint` to `out` in UTF-8 (the encoding of every text the
/// programs keep: XML read from UTF-16, characters typed into the viewer).
void append_utf8(std::string& out, std::uint32_t codepoint);

/// The whole file as bytes, read once into a buffer sized from the file (big buffers in huge
/// pages, see core/memory.h); `/proc`-style files that report no size are read in growing
/// steps. \throws IoError naming `path`: "no such file", "is a folder, not a file", "is not a
/// regular file" (a FIFO, a device, a socket: reading one could block or never end), "is N
/// bytes, more than the memory budget" (core/budget.h; `max_bytes` overrides), "cannot open:
/// <reason>", "read error".
std::string read_file(const std::filesystem::path& path, std::size_t max_bytes = 0);

/// A fingerprint of `bytes`: their 64-bit FNV-1a hash as 16 lower-case hex digits. Session
/// files name their input with it, so a replay on another file is noticed.
std::string content_hash(std::string_view bytes);

/// Writes `bytes` to `path` (created or truncated) and checks every step, so a full disk
/// surfaces as an exception rather than a short file. \throws std::runtime_error.
void write_file(const std::filesystem::path& path, std::string_view bytes);

/// Runs `write(tmp)` on a temporary path in `target`'s folder, then renames it over
/// `target`; on any failure the temporary file is removed and `target` is untouched. A
/// symbolic link is written through (the file it names is replaced, the link kept) only when
/// the link and its folder belong to the running user or to root. Temporaries a killed writer
/// of the same target left behind are removed first, if they are the running user's.
/// \throws IoError naming `target` if the folder is not writable, a link on the way is not to
/// be trusted, or the rename fails.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& tmp)>& write);

}  // namespace meshedit
