// A mesh back into the soup a file would hold of it (io.h, soup_from_mesh()): the inverse of
// build_loaded_mesh(), for edits that work on soups (the repair verbs, repair.h).

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "io_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/io/io.h"
#include "user_properties.h"

namespace meshedit {
namespace {

// The properties every mesh has (mesh.cpp's connectivity), which the soup's faces hold.
const std::set<std::string> kConnectivity = {"v:position", "v:halfedge", "v:deleted", "h:next",
                                             "h:prev",     "h:vertex",   "h:face",    "e:deleted",
                                             "f:halfedge", "f:deleted"};

// The user properties of one kind, under their full names as a reader gives them.
std::vector<UserProperty> with_prefix(std::vector<UserProperty> columns,
                                      const std::string& prefix) {
    for (UserProperty& column : columns) {
        column.name = prefix + column.name;
    }
    return columns;
}

// Names `names` (of one element kind) that are neither connectivity nor in `kept`.
void add_unkept(const std::vector<std::string>& names, const std::set<std::string>& kept,
                std::vector<std::string>& unkept) {
    for (const std::string& name : names) {
        if (kConnectivity.count(name) == 0 && kept.count(name) == 0) {
            unkept.push_back("the property " + name);
        }
    }
}

}  // namespace

MeshSoup soup_from_mesh(const Mesh& mesh, std::vector<std::string>* unkept) {
    std::optional<Mesh> storage;
    const Mesh& dense = io_util::compacted(mesh, storage);
    MeshSoup out;
    PolygonSoup& soup = out.soup;
    soup.positions.reserve(dense.n_vertices());
    for (const Vertex v : dense.vertices()) {
        soup.positions.push_back(dense.position(v));
    }
    const auto uv = dense.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const auto uv1 = dense.get_property<Halfedge, Vec2>(kTexCoord1Property);
    const auto normal = dense.get_property<Halfedge, Vec3>(kCornerNormalProperty);
    const auto material = dense.get_property<Face, std::uint32_t>(kMaterialProperty);
    const auto face_color = dense.get_property<Face, Vec4>(kFaceColorProperty);
    if (const auto color = dense.get_property<Vertex, Vec4>(kColorProperty)) {
        out.colors.assign(color.vector().begin(), color.vector().end());
    }
    soup.face_offsets.reserve(dense.n_faces() + 1);
    soup.face_offsets.assign(1, 0);
    for (const Face f : dense.faces()) {
        // Corner i is where halfedge i (from halfedge(f)) leaves, as build_mesh() makes it;
        // its values are held by the halfedge arriving there (soup_attributes.cpp).
        const Halfedge first = dense.halfedge(f);
        Halfedge h = first;
        do {
            soup.indices.push_back(dense.from_vertex(h).idx());
            const Halfedge in = dense.prev(h);
            if (uv) {
                out.corner_texcoords.push_back(uv[in]);
            }
            if (uv1) {
                out.corner_texcoords1.push_back(uv1[in]);
            }
            if (normal) {
                out.corner_normals.push_back(normal[in]);
            }
            h = dense.next(h);
        } while (h != first);
        soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.indices.size()));
        if (material) {
            out.face_materials.push_back(material[f]);
        }
        if (face_color) {
            out.face_colors.push_back(face_color[f]);
        }
    }
    if (material) {
        out.materials = dense.materials();
    }
    if (const auto crease = dense.get_property<Edge, std::uint8_t>(kCreaseProperty)) {
        for (const Edge e : dense.edges()) {
            if (crease[e] != 0) {
                const Halfedge h = dense.halfedge(e, 0);
                out.creases.emplace_back(dense.from_vertex(h).idx(), dense.to_vertex(h).idx());
            }
        }
    }
    out.vertex_properties = with_prefix(user_properties::vertex_columns(dense, "v:ply:"), "v:ply:");
    out.face_properties = with_prefix(user_properties::face_columns(dense, "f:ply:"), "f:ply:");
    if (unkept != nullptr) {
        std::set<std::string> vertex_kept = {kColorProperty},
                              face_kept = {kMaterialProperty, kFaceColorProperty};
        for (const UserProperty& p : out.vertex_properties) {
            vertex_kept.insert(p.name);
        }
        for (const UserProperty& p : out.face_properties) {
            face_kept.insert(p.name);
        }
        add_unkept(dense.property_names<Vertex>(), vertex_kept, *unkept);
        add_unkept(dense.property_names<Halfedge>(),
                   {kTexCoordProperty, kTexCoord1Property, kCornerNormalProperty}, *unkept);
        add_unkept(dense.property_names<Edge>(), {kCreaseProperty}, *unkept);
        add_unkept(dense.property_names<Face>(), face_kept, *unkept);
    }
    return out;
}

}  // namespace meshedit
