// The front door of meshedit_io: dispatch by extension to each format's reader and writer,
// and read_mesh(). Nothing else: the helpers writers share are in io_util.cpp, file access in
// meshedit_files, whole documents (meshes, patches, curves) in document.cpp.

#include "meshedit/io/io.h"

#include <system_error>

#include "io_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/io/collada.h"
#include "meshedit/io/gltf.h"
#include "meshedit/io/obj.h"
#include "meshedit/io/off.h"
#include "meshedit/io/ply.h"
#include "meshedit/io/stl.h"
#include "soup_attributes.h"
#include "user_properties.h"

namespace fs = std::filesystem;

namespace meshedit {

// ----------------------------------------------------------------- reading

bool is_mesh_extension(const std::string& extension) {
    return extension == ".dae" || extension == ".gltf" || extension == ".glb" ||
           extension == ".obj" || extension == ".off" || extension == ".ply" || extension == ".stl";
}

const char* mesh_extensions() {
    return ".dae, .gltf, .glb, .obj, .off, .ply or .stl";
}

MeshSoup read_soup(const fs::path& path) {
    const std::string ext = file_extension(path);
    if (ext == ".bez" || ext == ".bzc") {
        throw IoError(path.string(), "",
                      "a Bezier " + std::string(ext == ".bez" ? "patch" : "curve") +
                          " file, not a mesh (load it as Bezier data)");
    }
    if (!is_mesh_extension(ext)) {
        throw IoError(path.string(), "",
                      ext.empty()
                          ? std::string("no file extension; expected ") + mesh_extensions()
                          : "unknown extension '" + ext + "'; expected " + mesh_extensions());
    }
    MeshSoup soup = ext == ".dae"   ? read_collada(path)
                    : ext == ".obj" ? read_obj(path)
                    : ext == ".off" ? read_off(path)
                    : ext == ".ply" ? read_ply(path)
                    : ext == ".stl" ? read_stl(path)
                                    : read_gltf(path);
    // One wording, whatever the format, for a file with nothing to load (an empty OBJ, a
    // text file named .obj, a glTF of lines only): never an empty mesh from a file.
    if (soup.soup.n_faces() == 0) {
        std::string why = "holds no faces to load";
        for (std::size_t i = 0; i < soup.notices.size(); ++i) {
            why += (i == 0 ? " (" : "; ") + soup.notices[i] +
                   (i + 1 == soup.notices.size() ? ")" : "");
        }
        throw IoError(path.string(), "", why);
    }
    return soup;
}

LoadedMesh read_mesh(const fs::path& path) {
    MeshSoup soup = read_soup(path);
    LoadedMesh loaded;
    try {
        loaded.mesh = build_mesh(soup.soup, &loaded.repairs);
    } catch (const TopologyError& e) {
        throw IoError(path.string(), "", e.what());
    }
    user_properties::attach(soup, loaded.repairs, loaded.mesh);
    soup_attributes::attach(soup, loaded.repairs, loaded.mesh);
    loaded.notices = std::move(soup.notices);
    loaded.unit_meter = soup.unit_meter;

    if (!soup.creases.empty()) {
        auto crease = loaded.mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
        std::size_t missing = 0;
        for (const auto& [a, b] : soup.creases) {
            // Indices are the file's (build_mesh keeps vertex i = position i); a crease
            // between vertices that share no edge cannot be marked.
            const std::size_t n = soup.soup.positions.size();
            const Edge e = (a < n && b < n) ? loaded.mesh.find_edge(Vertex(a), Vertex(b)) : Edge();
            if (e.is_valid()) {
                crease[e] = 1;
            } else {
                ++missing;
            }
        }
        if (missing > 0) {
            loaded.notices.push_back("ignored " + std::to_string(missing) +
                                     " crease(s) between vertices that share no edge");
        }
    }
    return loaded;
}

// ----------------------------------------------------------------- writing

std::vector<std::string> unkept_by_format(const Mesh& mesh, const std::string& ext) {
    std::vector<std::string> unkept;
    const bool obj = ext == ".obj";
    const bool off = ext == ".off";
    const bool gltf = ext == ".gltf" || ext == ".glb";
    const bool ply = ext == ".ply";
    const bool stl = ext == ".stl";
    if (!ply) {
        std::string names;
        for (const auto& [kind, list] : {std::pair{"v:ply:", mesh.property_names<Vertex>()},
                                         std::pair{"f:ply:", mesh.property_names<Face>()}}) {
            for (const std::string& name : list) {
                if (name.rfind(kind, 0) == 0) {
                    names += (names.empty() ? "" : ", ") + name;
                }
            }
        }
        if (!names.empty()) {
            unkept.push_back("the PLY properties " + names + " (only PLY keeps them)");
        }
    }
    if (!obj && !gltf) {
        // OBJ and glTF write the attributes of the attributes issue so far.
        const std::string format = ext == ".dae" ? "COLLADA" : ext.substr(1);
        if (mesh.has_property<Halfedge>(kTexCoordProperty)) {
            unkept.push_back(
                "texture coordinates (MeshEdit writes them to OBJ and glTF only so "
                "far)");
        }
        if (mesh.has_property<Halfedge>(kCornerNormalProperty)) {
            unkept.push_back("the file's normals (the " + format +
                             " file gets normals computed from the faces, if any)");
        }
        const auto material = mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
        if (material && !mesh.materials().empty()) {
            unkept.push_back(std::to_string(mesh.materials().size()) +
                             " material(s) and which faces use them (MeshEdit writes them to "
                             "OBJ and glTF only so far)");
        }
    }
    if (!obj && !off && !gltf && !ply && !stl) {
        return unkept;  // COLLADA keeps polygons, creases and every double
    }
    std::size_t creases = 0;
    if (const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty)) {
        for (const Edge e : mesh.edges()) {
            creases += crease[e] != 0 ? 1 : 0;
        }
    }
    const std::string format = obj ? "OBJ" : off ? "OFF" : ply ? "PLY" : stl ? "STL" : "glTF";
    if (creases > 0) {
        unkept.push_back(std::to_string(creases) + " crease mark" + (creases == 1 ? "" : "s") +
                         " (" + format + " has no crease edges)");
    }
    if (gltf || stl) {
        std::size_t polygons = 0;
        for (const Face f : mesh.faces()) {
            polygons += mesh.is_triangle(f) ? 0 : 1;
        }
        if (polygons > 0) {
            unkept.push_back(std::to_string(polygons) + " polygon" + (polygons == 1 ? "" : "s") +
                             " (" + format + " stores triangles: each is fanned)");
        }
        for (const Vertex v : mesh.vertices()) {
            const Vec3& p = mesh.position(v);
            if (static_cast<double>(static_cast<float>(p.x)) != p.x ||
                static_cast<double>(static_cast<float>(p.y)) != p.y ||
                static_cast<double>(static_cast<float>(p.z)) != p.z) {
                unkept.push_back("coordinates beyond 32-bit float precision (" + format +
                                 " stores floats)");
                break;
            }
        }
    }
    return unkept;
}

std::vector<std::string> write_mesh(const Mesh& mesh, const fs::path& path, const IoFlags& flags) {
    const std::string ext = file_extension(path);
    std::optional<Mesh> storage;
    const Mesh& dense = io_util::compacted(mesh, storage);
    if (ext == ".dae") {
        write_collada(dense, path, flags);
    } else if (ext == ".gltf" || ext == ".glb") {
        write_gltf(dense, path, flags);
    } else if (ext == ".obj") {
        write_obj(dense, path, flags);
    } else if (ext == ".off") {
        write_off(dense, path);
    } else if (ext == ".ply") {
        write_ply(dense, path, flags);
    } else if (ext == ".stl") {
        write_stl(dense, path, flags);
    } else {
        throw IoError(path.string(), "",
                      ext.empty()
                          ? std::string("no file extension; expected ") + mesh_extensions()
                          : "cannot write '" + ext + "' files; expected " + mesh_extensions());
    }
    return unkept_by_format(dense, ext);
}

}  // namespace meshedit
