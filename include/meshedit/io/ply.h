#pragma once
/// \file
/// Stanford PLY (.ply), the format of 3D scanners, MeshLab and the Stanford repository: a text
/// header naming elements and their typed properties, then the data as ASCII or binary (either
/// endianness). Read by MeshEdit's own parser: every count, list length and index checked
/// against the bytes that are really there.

#include <filesystem>
#include <string>
#include <string_view>

#include "meshedit/io/io.h"

namespace meshedit {

/// Positions, normals (nx ny nz) and faces (`vertex_indices` or `vertex_index`); vertex
/// colours (red green blue [alpha], uchar, ushort, float or double) as MeshSoup::colors; vertex
/// texture coordinates (s t, u v, texture_u texture_v) and face `texcoord` lists as corner
/// texture coordinates; any other scalar vertex or face property becomes a user property
/// "v:ply:NAME" / "f:ply:NAME" of its own type (io.h, UserProperty); other list properties and
/// other elements are read past, with a notice.
/// \throws IoError naming the file and the line (ASCII) or the element.
MeshSoup read_ply(const std::filesystem::path& path);
/// The same from the file's bytes; `name` names it in errors.
MeshSoup parse_ply(std::string_view bytes, const std::string& name);
/// Writes binary little-endian PLY with double positions (exact), or ASCII with shortest
/// round-trip decimals when `flags.ascii`; the file's normals when one per vertex holds them,
/// else float vertex normals when `flags.write_normals`; vertex colours (uchar when every
/// value is k/255, else float or double, whichever is exact); texture coordinates as vertex
/// s t, or a face `texcoord` list when they have seams;
/// polygons kept; the mesh's vertex and face properties named "v:ply:NAME" / "f:ply:NAME" of an
/// integer, float or double type written back as NAME with that type. Atomic. \throws IoError.
void write_ply(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags = {});

}  // namespace meshedit
