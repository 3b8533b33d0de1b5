#pragma once
/// \file
/// Opening any file the programs open: a mesh (.dae .gltf .glb .obj .off .ply .stl), Bezier patches
/// (.bez, tessellated and welded into a mesh that every mesh command accepts) or a Bezier curve
/// (.bzc). The viewer, the `meshedit` commands and `meshedit-render` all open files through
/// read_document(), so they accept the same files and say the same things about them.

#include <filesystem>
#include <string>
#include <vector>

#include "meshedit/bezier/bezier_curve.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/build.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

/// What a file holds.
enum class DocumentKind {
    Mesh,     ///< a mesh file
    Surface,  ///< Bezier patches, with their welded tessellation as the mesh
    Curve,    ///< a Bezier curve
};

/// "mesh", "surface", "curve".
const char* kind_name(DocumentKind kind);

struct ReadOptions {
    /// Surface: quads per patch side of the tessellation (TessellationOptions::density).
    int density = 8;
};

/// A file as read, with what the user should hear about it.
struct LoadedDocument {
    DocumentKind kind = DocumentKind::Mesh;
    Mesh mesh;                         ///< Mesh: the file's; Surface: the tessellation
    std::vector<BezierPatch> patches;  ///< Surface
    int density = 8;                   ///< Surface: the density `mesh` was made at
    BezierCurve curve;                 ///< Curve
    BuildReport repairs;               ///< Mesh: what build_mesh() repaired
    std::vector<std::string> notices;  ///< what the reader changed or ignored
    double unit_meter = 1.0;           ///< COLLADA `<unit meter>`
};

/// Reads `path` by its extension. \throws IoError naming the file and the problem (unknown
/// extension, missing file, bad content), also for failures inside a reader that are not
/// IoErrors; std::bad_alloc passes through.
LoadedDocument read_document(const std::filesystem::path& path, const ReadOptions& options = {});

/// Whether `extension` (lower-case, with dot) is a file read_document() opens.
bool is_document_extension(const std::string& extension);

/// ".dae, .gltf, .glb, .obj, .off, .ply, .stl, .bez or .bzc", for messages.
const char* document_extensions();

/// Every extension read_document() opens, in the order messages list them.
std::vector<std::string> document_extension_list();
/// The extensions a document of `kind` is written as: a mesh as any of mesh_formats() that
/// has a writer, patches as .bez (or their tessellation as a mesh), a curve as .bzc.
std::vector<std::string> writable_extensions(DocumentKind kind);

}  // namespace meshedit
