#pragma once
/// \file
/// Object File Format (.off), the plain format of Geomview, CGAL's and MeshLab's data sets and
/// many shape benchmarks: a vertex count, a face count, then one line per vertex and one per
/// polygon. Read by MeshEdit's own parser (exact doubles, every count and index checked).

#include <filesystem>
#include <string>
#include <string_view>

#include "meshedit/io/io.h"

namespace meshedit {

/// \throws IoError naming the file and line.
MeshSoup read_off(const std::filesystem::path& path);
/// The same from the file's bytes; `name` names it in errors.
MeshSoup parse_off(std::string_view bytes, const std::string& name);
/// Writes ASCII OFF (shortest round-trip doubles, polygons kept), atomically. \throws IoError.
void write_off(const Mesh& mesh, const std::filesystem::path& path);

}  // namespace meshedit
