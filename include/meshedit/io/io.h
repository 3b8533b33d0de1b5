#pragma once
/// \file
/// Reading and writing meshes and Bezier data, dispatched by file extension. Each format has
/// its own read_X/write_X pair (collada.h, gltf.h, obj.h, off.h, ply.h, stl.h; the Bezier formats
/// below); this is the front door. document.h reads any file the programs open (mesh, patches or
/// curve).
///
/// Readers produce a MeshSoup (an indexed polygon soup plus what the file said about it);
/// only build_mesh() turns it into a halfedge mesh. Writers always write a temporary file in
/// the target's folder and rename it over the target, so a failed write never leaves a
/// partial or damaged file.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "meshedit/bezier/bezier_curve.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/build.h"
#include "meshedit/core/material.h"
#include "meshedit/core/mesh.h"
#include "meshedit/files/files.h"

namespace meshedit {

/// A per-vertex or per-face value a file holds that MeshEdit has no meaning for (a PLY vertex
/// `float quality`, a face `int label`). read_mesh() keeps it as a mesh property of the same
/// C++ type under `name` ("v:ply:quality", "f:ply:label"); the PLY writer writes such
/// properties back under their own names and types.
struct UserProperty {
    /// int8, uint8, int16, uint16, int32, uint32, float, double.
    enum class Type : std::uint8_t { I8, U8, I16, U16, I32, U32, F32, F64 };
    std::string name;
    Type type = Type::F64;
    /// One per soup vertex or face, in order (a double holds every value of each type exactly).
    std::vector<double> values;
};

/// A mesh as a file holds it, before it becomes a halfedge mesh.
struct MeshSoup {
    PolygonSoup soup;
    /// Per-vertex normals from the file when it has them in a per-vertex form (else empty).
    std::vector<Vec3> normals;
    /// Crease edges as vertex index pairs (MeshEdit's own `<extra>` in COLLADA); read_mesh()
    /// marks them in the "e:crease" edge property.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> creases;
    /// Per corner (one per entry of soup.indices) when the file has them, else empty: texture
    /// coordinates, the second texture coordinate set (glTF TEXCOORD_1, COLLADA's TEXCOORD set
    /// 1) and normals (read_mesh() keeps them as kTexCoordProperty, kTexCoord1Property and
    /// kCornerNormalProperty, attributes.h).
    std::vector<Vec2> corner_texcoords;
    std::vector<Vec2> corner_texcoords1;
    std::vector<Vec3> corner_normals;
    /// Per vertex / per face RGBA colours (0–1) when the file has them, else empty
    /// (read_mesh() keeps them as kColorProperty and kFaceColorProperty).
    std::vector<Vec4> colors;
    std::vector<Vec4> face_colors;
    /// Per face, an index into `materials`, when the file names materials (else empty).
    std::vector<std::uint32_t> face_materials;
    std::vector<Material> materials;
    /// OBJ: the material libraries (`mtllib`) the file names, as written.
    std::vector<std::string> material_libraries;
    /// Values without a meaning in MeshEdit, one per soup vertex / face (UserProperty).
    std::vector<UserProperty> vertex_properties;
    std::vector<UserProperty> face_properties;
    /// `<unit meter="…">` of a COLLADA file (1 for formats without units).
    double unit_meter = 1.0;
    /// Things the reader changed or ignored that a user should hear about ("converted Z_UP
    /// to Y_UP", "ignored 2 <lines> blocks"); one sentence each.
    std::vector<std::string> notices;
};

/// Options for writers.
struct IoFlags {
    bool write_normals = true;  ///< area-weighted vertex normals, where the format has them
    bool ascii = false;         ///< text rather than binary, for formats that have both (PLY, STL)
};

/// One mesh format: its extension, reader and writer, and what it keeps. The one table of
/// formats (mesh_formats()): reading and writing dispatch through it, unkept_by_format() reads
/// what each keeps, and every list of extensions in a message or a help text comes from it.
struct MeshFormat {
    const char* extension;  ///< lower-case, with dot: ".obj"
    const char* name;       ///< "OBJ", for messages
    MeshSoup (*read)(const std::filesystem::path& path);
    void (*write)(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags);
    bool polygons;           ///< polygons as they are (else each is fanned into triangles)
    bool doubles;            ///< every double exactly (else 32-bit floats)
    bool creases;            ///< crease marks (kCreaseProperty)
    bool corner_attributes;  ///< texture coordinates, the file's normals, materials
    bool ply_properties;     ///< the PLY properties MeshEdit has no meaning for (v:ply:*, f:ply:*)
    bool colors;             ///< vertex colours (kColorProperty)
    /// Texture coordinates and normals one per vertex (the seamless case of corner attributes)
    bool vertex_attributes;
    bool second_texcoords;  ///< a second texture coordinate set (kTexCoord1Property)
};

/// Every mesh format, in the order messages list them (.dae, .gltf, .glb, .obj, .off, .ply,
/// .stl).
std::span<const MeshFormat> mesh_formats();
/// The row of `extension` (lower-case, with dot), or nullptr.
const MeshFormat* find_mesh_format(const std::string& extension);
/// Formats by extension (lower-case, with dot): a row of mesh_formats().
bool is_mesh_extension(const std::string& extension);
/// ".dae, .gltf, .glb, .obj, .off, .ply or .stl", for messages.
const char* mesh_extensions();
/// The extensions joined as a help text wants them: mesh_extension_list(" ") is
/// ".dae .gltf .glb .obj .off .ply .stl".
std::string mesh_extension_list(const std::string& separator);

/// Reads a mesh file into a soup. \throws IoError (unknown extension, missing file, bad
/// content), naming the file and the place.
MeshSoup read_soup(const std::filesystem::path& path);

/// A loaded, built mesh with everything the user should be told about it.
struct LoadedMesh {
    Mesh mesh;
    BuildReport repairs;               ///< what build_mesh() repaired
    std::vector<std::string> notices;  ///< from the reader
    double unit_meter = 1.0;
};

/// read_soup() + build_loaded_mesh(). \throws IoError (a TopologyError becomes an IoError
/// naming the file).
LoadedMesh read_mesh(const std::filesystem::path& path);

/// build_mesh() on a soup as read_soup() gives it (or as a repair left it, repair.h), with
/// everything read_mesh() keeps of it: corner attributes, materials, user properties, creases
/// and the reader's notices. \throws IoError naming `name` when the soup cannot be built.
LoadedMesh build_loaded_mesh(MeshSoup soup, const std::string& name);

/// The soup a file would hold of `mesh` (a compacted copy when it has deleted elements), so
/// that build_loaded_mesh() of it gives the mesh back: positions, each face's corners from
/// where halfedge(f) leaves, and what build_loaded_mesh() keeps of a soup (both texture
/// coordinate sets and normals per corner, materials, the PLY properties `v:ply:*` and `f:ply:*`,
/// crease marks). The edits that work on soups (the repair verbs, repair.h) go through it. Every
/// other property is named in `unkept` ("the property v:weight"), when given.
MeshSoup soup_from_mesh(const Mesh& mesh, std::vector<std::string>* unkept = nullptr);

/// What a file of that extension (".obj") cannot keep of `mesh`, one phrase each ("12 crease
/// marks (OBJ has no crease edges)", "30 polygons (glTF stores triangles: each is fanned)",
/// "coordinates beyond 32-bit float precision (glTF stores floats)"); empty if nothing.
std::vector<std::string> unkept_by_format(const Mesh& mesh, const std::string& extension);

/// Writes `mesh` in the format of `path`'s extension (garbage-collected copy if needed),
/// atomically. \return what the format could not keep (unkept_by_format()), for the caller
/// to tell the user. \throws IoError.
std::vector<std::string> write_mesh(const Mesh& mesh, const std::filesystem::path& path,
                                    const IoFlags& flags = {});

/// Bezier patches of a .bez file (docs/spec.md §2). \throws IoError.
std::vector<BezierPatch> read_bez(const std::filesystem::path& path);
/// A Bezier curve of a .bzc file (docs/spec.md §2: N, then N points x y; N ≥ 2). \throws IoError.
BezierCurve read_bzc(const std::filesystem::path& path);
/// read_bez() and read_bzc() from the file's bytes; `name` names it in errors.
std::vector<BezierPatch> parse_bez(std::string_view bytes, const std::string& name);
BezierCurve parse_bzc(std::string_view bytes, const std::string& name);
/// Write .bzc and .bez files atomically, in the CS184 course's grammar (its skeleton reads
/// them with fscanf): the count on the first line, then one point a line (x y; x y z, a
/// patch's 16 points row-major), no comments, every double in the shortest form that reads
/// back the same. \throws IoError (too few points, a patch not 4 × 4, a non-finite number).
void write_bzc(const BezierCurve& curve, const std::filesystem::path& path);
void write_bez(const std::vector<BezierPatch>& patches, const std::filesystem::path& path);

}  // namespace meshedit
