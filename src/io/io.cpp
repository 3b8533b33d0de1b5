// The front door of meshedit_io: the table of formats, dispatch by extension through it to
// each format's reader and writer, and read_mesh(). Nothing else: the helpers writers share are in
// io_util.cpp, file access in meshedit_files, whole documents (meshes, patches, curves) in
// document.cpp.

#include "meshedit/io/io.h"

#include <algorithm>
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

// ----------------------------------------------------------------- the formats

namespace {

void write_off_ignoring_flags(const Mesh& mesh, const fs::path& path, const IoFlags&) {
    write_off(mesh, path);  // OFF has no normals and no binary variant
}

// Each row: extension, name, reader, writer, then what the format keeps: polygons, every
// double, creases, corner attributes (UVs, the file's normals, materials), PLY properties,
// vertex colours, per-vertex UVs and normals, a second UV set.
constexpr MeshFormat kFormats[] = {
    {".dae", "COLLADA", read_collada, write_collada, true, true, true, true, false, true, true,
     true},
    {".gltf", "glTF", read_gltf, write_gltf, false, false, false, true, false, true, true, true},
    {".glb", "glTF", read_gltf, write_gltf, false, false, false, true, false, true, true, true},
    {".obj", "OBJ", read_obj, write_obj, true, true, false, true, false, true, true, false},
    {".off", "OFF", read_off, write_off_ignoring_flags, true, true, false, false, false, true, true,
     false},
    {".ply", "PLY", read_ply, write_ply, true, true, false, false, true, true, true, false},
    {".stl", "STL", read_stl, write_stl, false, false, false, false, false, false, false, false},
};

// True when every corner of each vertex holds the same value of the halfedge property (one
// value per vertex is enough: a format's per-vertex UVs or normals keep it).
template <class T>
bool seamless(const Mesh& mesh, const HalfedgeProperty<T>& corner) {
    std::vector<T> value;
    return io_util::per_vertex(mesh, corner, value);
}

// "OBJ and glTF": the names of the formats that keep what `keeps` asks, each once.
template <class Keeps>
std::string names_of_formats(Keeps keeps) {
    std::vector<std::string> names;
    for (const MeshFormat& format : kFormats) {
        if (keeps(format) && std::find(names.begin(), names.end(), format.name) == names.end()) {
            names.emplace_back(format.name);
        }
    }
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
        text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    }
    return text;
}

}  // namespace

std::span<const MeshFormat> mesh_formats() {
    return kFormats;
}

const MeshFormat* find_mesh_format(const std::string& extension) {
    for (const MeshFormat& format : kFormats) {
        if (extension == format.extension) {
            return &format;
        }
    }
    return nullptr;
}

bool is_mesh_extension(const std::string& extension) {
    return find_mesh_format(extension) != nullptr;
}

std::string mesh_extension_list(const std::string& separator) {
    std::string text;
    for (const MeshFormat& format : kFormats) {
        text += (text.empty() ? "" : separator) + format.extension;
    }
    return text;
}

const char* mesh_extensions() {
    static const std::string text = [] {
        std::string list = mesh_extension_list(", ");
        const std::size_t last = list.rfind(", ");
        return list.replace(last, 2, " or ");
    }();
    return text.c_str();
}

// ----------------------------------------------------------------- reading

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
    MeshSoup soup = find_mesh_format(ext)->read(path);
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
    LoadedMesh loaded = build_loaded_mesh(read_soup(path), path.string());
    // Every face dropped as degenerate is as empty as a point cloud: refused alike, naming
    // what was dropped (issue 40), never a faceless mesh with exit 0.
    if (loaded.mesh.n_faces() == 0) {
        const std::size_t n = loaded.repairs.dropped_faces.size();
        throw IoError(path.string(), "",
                      "holds no faces to load: its " +
                          (n == 1 ? std::string("only face was")
                                  : "all " + std::to_string(n) + " faces were") +
                          " dropped as degenerate (fewer than 3 corners or a repeated corner)");
    }
    return loaded;
}

LoadedMesh build_loaded_mesh(MeshSoup soup, const std::string& name) {
    LoadedMesh loaded;
    try {
        loaded.mesh = build_mesh(soup.soup, &loaded.repairs);
    } catch (const TopologyError& e) {
        throw IoError(name, "", e.what());
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
    const MeshFormat* format = find_mesh_format(ext);
    if (format == nullptr) {
        return unkept;
    }
    const std::string name = format->name;
    if (!format->ply_properties) {
        std::string names;
        for (const auto& [kind, list] : {std::pair{"v:ply:", mesh.property_names<Vertex>()},
                                         std::pair{"f:ply:", mesh.property_names<Face>()}}) {
            for (const std::string& property : list) {
                if (property.rfind(kind, 0) == 0) {
                    names += (names.empty() ? "" : ", ") + property;
                }
            }
        }
        if (!names.empty()) {
            unkept.push_back("the PLY properties " + names + " (only " +
                             names_of_formats(std::mem_fn(&MeshFormat::ply_properties)) +
                             " keeps them)");
        }
    }
    if (!format->corner_attributes) {
        const std::string writers = names_of_formats(std::mem_fn(&MeshFormat::corner_attributes));
        // PLY keeps seams of texture coordinates too (MeshLab's face texcoord lists).
        const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
        if (uv && !(format->vertex_attributes && (format->ply_properties || seamless(mesh, uv)))) {
            const std::string keepers = names_of_formats(
                [](const MeshFormat& f) { return f.corner_attributes || f.vertex_attributes; });
            unkept.push_back(std::string("texture coordinates") +
                             (format->vertex_attributes
                                  ? " with seams (" + name + " holds one per vertex)"
                                  : " (" + name + " has none; " + keepers + " keep them)"));
        }
        const auto normal = mesh.get_property<Halfedge, Vec3>(kCornerNormalProperty);
        if (normal && !(format->vertex_attributes && seamless(mesh, normal))) {
            unkept.push_back("the file's normals (the " + name +
                             " file gets normals computed from the faces, if any)");
        }
        const auto material = mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
        if (material && !mesh.materials().empty()) {
            unkept.push_back(std::to_string(mesh.materials().size()) +
                             " material(s) and which faces use them (" + name +
                             " has no materials; " + writers + " keep them)");
        }
    }
    if (!format->second_texcoords && mesh.has_property<Halfedge>(kTexCoord1Property)) {
        unkept.push_back("the second texture coordinate set (" + name + " has one set at most; " +
                         names_of_formats(std::mem_fn(&MeshFormat::second_texcoords)) +
                         " keep it)");
    }
    for (const Material& m : mesh.materials()) {
        if (format->corner_attributes && !format->second_texcoords && m.base_colour_texcoord != 0 &&
            !m.base_colour_texture.empty()) {
            unkept.push_back(
                "material '" + m.name + "''s texture on the second texture coordinate set (" +
                name + " has one set; " +
                names_of_formats(std::mem_fn(&MeshFormat::second_texcoords)) + " keep it)");
        }
    }
    // An image a glTF file embedded: glTF writes it back (PNG and JPEG, the kinds it holds);
    // the other formats only name texture files.
    for (const Material& m : mesh.materials()) {
        if (format->corner_attributes && !m.base_colour_texture_bytes.empty() &&
            !(format->name == std::string("glTF") && (m.base_colour_texture.ends_with(".png") ||
                                                      m.base_colour_texture.ends_with(".jpg")))) {
            unkept.push_back("the embedded texture " + m.base_colour_texture + " of material '" +
                             m.name + "' (" + name +
                             " names texture files; .glb and .gltf embed it)");
        }
    }
    if (!format->colors && mesh.has_property<Vertex>(kColorProperty)) {
        unkept.push_back("vertex colours (" + name + " has no colours; " +
                         names_of_formats(std::mem_fn(&MeshFormat::colors)) + " keep them)");
    }
    // Only OFF has face colours of its own (PLY's face red green blue are PLY properties).
    if (ext != ".off" && mesh.has_property<Face>(kFaceColorProperty)) {
        unkept.push_back("face colours (only OFF keeps them)");
    }
    if (!format->creases) {
        std::size_t creases = 0;
        if (const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty)) {
            for (const Edge e : mesh.edges()) {
                creases += crease[e] != 0 ? 1 : 0;
            }
        }
        if (creases > 0) {
            unkept.push_back(std::to_string(creases) + " crease mark" + (creases == 1 ? "" : "s") +
                             " (" + name + " has no crease edges)");
        }
    }
    if (!format->polygons) {
        std::size_t polygons = 0;
        for (const Face f : mesh.faces()) {
            polygons += mesh.is_triangle(f) ? 0 : 1;
        }
        if (polygons > 0) {
            unkept.push_back(std::to_string(polygons) + " polygon" + (polygons == 1 ? "" : "s") +
                             " (" + name + " stores triangles: each is fanned)");
        }
    }
    if (!format->doubles) {
        for (const Vertex v : mesh.vertices()) {
            const Vec3& p = mesh.position(v);
            if (static_cast<double>(static_cast<float>(p.x)) != p.x ||
                static_cast<double>(static_cast<float>(p.y)) != p.y ||
                static_cast<double>(static_cast<float>(p.z)) != p.z) {
                unkept.push_back("coordinates beyond 32-bit float precision (" + name +
                                 " stores floats)");
                break;
            }
        }
    }
    return unkept;
}

std::vector<std::string> write_mesh(const Mesh& mesh, const fs::path& path, const IoFlags& flags) {
    const std::string ext = file_extension(path);
    const MeshFormat* format = find_mesh_format(ext);
    if (format == nullptr) {
        throw IoError(path.string(), "",
                      ext.empty()
                          ? std::string("no file extension; expected ") + mesh_extensions()
                          : "cannot write '" + ext + "' files; expected " + mesh_extensions());
    }
    std::optional<Mesh> storage;
    const Mesh& dense = io_util::compacted(mesh, storage);
    format->write(dense, path, flags);
    return unkept_by_format(dense, ext);
}

}  // namespace meshedit
