// read_document(): the one dispatch from a file to a mesh, patch set or curve.

#include "meshedit/io/document.h"

#include <new>

#include "meshedit/io/io.h"

namespace meshedit {

const char* kind_name(DocumentKind kind) {
    switch (kind) {
        case DocumentKind::Mesh:
            return "mesh";
        case DocumentKind::Surface:
            return "surface";
        case DocumentKind::Curve:
            return "curve";
    }
    return "";
}

namespace {

// The documents that are not meshes.
constexpr const char* kPatchesExtension = ".bez";
constexpr const char* kCurveExtension = ".bzc";

}  // namespace

bool is_document_extension(const std::string& extension) {
    return is_mesh_extension(extension) || extension == kPatchesExtension ||
           extension == kCurveExtension;
}

const char* document_extensions() {
    static const std::string text =
        mesh_extension_list(", ") + ", " + kPatchesExtension + " or " + kCurveExtension;
    return text.c_str();
}

std::vector<std::string> document_extension_list() {
    std::vector<std::string> out;
    for (const MeshFormat& format : mesh_formats()) {
        if (format.read != nullptr) {
            out.emplace_back(format.extension);
        }
    }
    out.emplace_back(kPatchesExtension);
    out.emplace_back(kCurveExtension);
    return out;
}

std::vector<std::string> writable_extensions(DocumentKind kind) {
    std::vector<std::string> out;
    if (kind == DocumentKind::Curve) {
        return {kCurveExtension};
    }
    if (kind == DocumentKind::Surface) {
        out.emplace_back(kPatchesExtension);
    }
    for (const MeshFormat& format : mesh_formats()) {
        if (format.write != nullptr) {
            out.emplace_back(format.extension);
        }
    }
    return out;
}

LoadedDocument read_document(const std::filesystem::path& path, const ReadOptions& options) {
    const std::string ext = file_extension(path);
    if (!is_document_extension(ext)) {
        throw IoError(
            path.string(), "",
            (ext.empty() ? std::string("no file extension") : "unknown extension '" + ext + "'") +
                "; expected " + document_extensions());
    }
    LoadedDocument doc;
    try {
        if (ext == ".bzc") {
            doc.kind = DocumentKind::Curve;
            doc.curve = read_bzc(path);
        } else if (ext == ".bez") {
            doc.kind = DocumentKind::Surface;
            doc.patches = read_bez(path);
            doc.density = options.density;
            TessellationOptions tessellation;
            tessellation.density = options.density;
            doc.mesh = tessellate(doc.patches, tessellation);
            if (doc.mesh.n_faces() == 0) {
                throw IoError(path.string(), "",
                              "holds no faces to load (every patch is degenerate: its control "
                              "points coincide)");
            }
        } else {
            LoadedMesh loaded = read_mesh(path);
            doc.kind = DocumentKind::Mesh;
            doc.mesh = std::move(loaded.mesh);
            doc.repairs = std::move(loaded.repairs);
            doc.notices = std::move(loaded.notices);
            doc.unit_meter = loaded.unit_meter;
        }
    } catch (const IoError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        // Whatever went wrong inside a reader, the user needs the file named.
        throw IoError(path.string(), "", e.what());
    }
    return doc;
}

}  // namespace meshedit
