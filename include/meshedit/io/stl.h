#pragma once
/// \file
/// Stereolithography (.stl), the format of 3D printing and CAD export: separate triangles, each
/// with its facet normal, as ASCII (`solid … facet normal … endsolid`, several solids allowed) or
/// binary (an 80-byte header, a triangle count, 50 bytes per triangle of 32-bit floats).

#include <filesystem>
#include <string>
#include <string_view>

#include "meshedit/io/io.h"

namespace meshedit {

/// Triangles of every solid, their corners welded by exact position (a notice says how many);
/// facet normals are only checked against the winding (a notice counts those that disagree).
/// A binary file is recognised by its size (84 + 50 · count bytes) even when its header starts
/// with `solid`. \throws IoError naming the file and the line (ASCII) or the triangle.
MeshSoup read_stl(const std::filesystem::path& path);
/// The same from the file's bytes; `name` names it in errors.
MeshSoup parse_stl(std::string_view bytes, const std::string& name);
/// Writes binary STL, or ASCII when `flags.ascii`; polygons are fanned into triangles and
/// coordinates rounded to float (both reported by unkept_by_format()). Atomic. \throws IoError.
void write_stl(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags = {});

}  // namespace meshedit
