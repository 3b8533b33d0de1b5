// What a mesh carries besides its shape (attribute_summary.h).

#include "meshedit/core/attribute_summary.h"

#include "meshedit/core/number_text.h"

#include <filesystem>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace meshedit {

bool is_material_border(const Mesh& mesh, Edge e, const FaceProperty<std::uint32_t>& material) {
    const Halfedge h = mesh.halfedge(e, 0);
    const Halfedge t = mesh.halfedge(e, 1);
    return !mesh.is_boundary(h) && !mesh.is_boundary(t) &&
           material[mesh.face(h)] != material[mesh.face(t)];
}

AttributeSummary summarize_attributes(const Mesh& mesh) {
    AttributeSummary s;
    const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const auto uv1 = mesh.get_property<Halfedge, Vec2>(kTexCoord1Property);
    const auto material = mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
    s.texcoords = static_cast<bool>(uv);
    s.second_texcoords = static_cast<bool>(uv1);
    s.corner_normals = mesh.has_property<Halfedge>(kCornerNormalProperty);
    s.vertex_colours = mesh.has_property<Vertex>(kColorProperty);
    s.face_colours = mesh.has_property<Face>(kFaceColorProperty);
    s.face_materials = material && !mesh.materials().empty();
    for (const Edge e : mesh.edges()) {
        s.uv_seam_edges += uv && is_uv_seam(mesh, e, uv) ? 1 : 0;
        s.second_uv_seam_edges += uv1 && is_uv_seam(mesh, e, uv1) ? 1 : 0;
        s.material_borders += s.face_materials && is_material_border(mesh, e, material) ? 1 : 0;
    }
    for (const Material& m : mesh.materials()) {
        if (!m.base_colour_texture.empty()) {
            std::error_code ec;
            ++s.textured_materials;
            s.missing_textures += std::filesystem::exists(m.base_colour_texture, ec) ? 0 : 1;
        }
    }
    return s;
}

std::vector<std::pair<std::string, std::string>> attribute_rows(const Mesh& mesh,
                                                                const AttributeSummary& a) {
    std::vector<std::pair<std::string, std::string>> rows;
    rows.emplace_back(
        "texture coordinates",
        a.texcoords ? "per corner, " + std::to_string(a.uv_seam_edges) + " seam edges" : "none");
    if (a.second_texcoords) {
        rows.emplace_back("second texture coordinate set",
                          "per corner, " + std::to_string(a.second_uv_seam_edges) + " seam edges");
    }
    rows.emplace_back("corner normals", a.corner_normals ? "per corner (from the file)" : "none");
    rows.emplace_back("colours", a.vertex_colours
                                     ? (a.face_colours ? "per vertex and per face" : "per vertex")
                                 : a.face_colours ? "per face"
                                                  : "none");
    const std::vector<Material>& materials = mesh.materials();
    rows.emplace_back("materials", a.face_materials
                                       ? std::to_string(materials.size()) + ", " +
                                             std::to_string(a.material_borders) + " border edges"
                                       : "none");
    for (std::size_t i = 0; a.face_materials && i < materials.size(); ++i) {
        const Material& m = materials[i];
        std::string value = "'" + m.name + "'";
        if (m.has_base_colour) {
            value += " colour " + readable_number(m.base_colour.x) + " " +
                     readable_number(m.base_colour.y) + " " + readable_number(m.base_colour.z);
        }
        if (m.has_opacity && m.opacity != 1.0) {
            value += " opacity " + readable_number(m.opacity);
        }
        if (!m.base_colour_texture.empty()) {
            std::error_code ec;
            value += " texture " + m.base_colour_texture +
                     (std::filesystem::exists(m.base_colour_texture, ec) ? "" : " (missing)") +
                     (m.base_colour_texcoord != 0 ? " on the second texture coordinate set" : "");
        }
        rows.emplace_back("material " + std::to_string(i), value);
    }
    return rows;
}

}  // namespace meshedit
