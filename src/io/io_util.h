#pragma once
/// \file
/// Helpers the format writers share (private to meshedit_io). File access itself is in
/// meshedit/files/files.h.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/core/number_text.h"  // every writer spells doubles this way
#include "meshedit/files/files.h"

namespace meshedit::io_util {

/// A texture path as a file wrote it (OBJ's map_Kd, glTF's image uri, COLLADA's init_from),
/// made a path: backslashes made slashes and, for a `uri` (glTF, COLLADA), a `file://` prefix
/// dropped and %XX escapes decoded;
/// a relative one is taken from `folder` (the file's). Absolute when that file exists, else
/// as written: a missing texture is said by whoever shows it, never a failure to read.
std::string resolve_texture(std::string written, const std::filesystem::path& folder, bool uri);
/// The path to write for a texture into a file in `folder`: relative to that folder when the
/// texture's path is absolute (so the output folder can move with its textures).
std::string texture_relative_to(const std::string& texture, const std::filesystem::path& folder);

/// The text of a text format's file: `bytes` without a UTF-8 byte-order mark. \throws
/// IoError naming `name` for UTF-16 or UTF-32 text (a byte-order mark or NUL bytes in the first
/// line), which the text formats do not read.
std::string_view text_of(std::string_view bytes, const std::string& name);

/// The next token of `line` separated by spaces, tabs, CR or FF (removed from `line` with the
/// whitespace before it); empty at the end of the line.
std::string_view next_token(std::string_view& line);

/// `text` without the spaces, tabs, CR and FF around it (a name with spaces inside).
std::string_view trim(std::string_view text);

/// The next line of `text` from `pos` that holds a token (blank lines skipped), without its
/// '\n'; `pos` moves past it and `line` counts every line read. Empty at the end.
std::string_view next_content_line(std::string_view text, std::size_t& pos, std::size_t& line);

/// `token` as a double (a leading '+' allowed, as some exporters write it); nullopt unless the
/// whole token is one number.
std::optional<double> parse_double(std::string_view token);

/// `mesh` itself when it has dense indices, else a garbage-collected copy kept in `storage`.
/// Writers need dense indices because files number vertices 0…n−1.
const Mesh& compacted(const Mesh& mesh, std::optional<Mesh>& storage);

/// Corner values (the halfedge arriving at each vertex) as one value per vertex, or false
/// when two corners of a vertex differ. Vertices on no face keep `value`'s default.
template <class T>
bool per_vertex(const Mesh& mesh, const HalfedgeProperty<T>& corner, std::vector<T>& value) {
    std::vector<std::uint8_t> seen(mesh.vertices_size(), 0);
    value.assign(mesh.vertices_size(), T{});
    for (const Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h)) {
            continue;
        }
        const std::uint32_t v = mesh.to_vertex(h).idx();
        if (seen[v] != 0 && !(value[v] == corner[h])) {
            return false;
        }
        seen[v] = 1;
        value[v] = corner[h];
    }
    return true;
}

}  // namespace meshedit::io_util
