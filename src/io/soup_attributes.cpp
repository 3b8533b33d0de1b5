// Corner attributes and materials from a soup onto its mesh (soup_attributes.h).

#include "soup_attributes.h"

#include <cstdint>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/normals.h"

namespace meshedit::soup_attributes {
namespace {

// Normals that are what MeshEdit computes anyway (area-weighted, per vertex: a file MeshEdit
// wrote) carry nothing: they are not kept, so writing never warns about them.
bool computed_anyway(const Mesh& mesh, const HalfedgeProperty<Vec3>& normal) {
    std::vector<Vec3> computed;
    compute_vertex_normals(mesh, computed);
    for (const Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h)) {
            continue;
        }
        const Vec3 n = normal[h];
        const double length = norm(n);
        if (!(length > 0) || norm(n / length - computed[mesh.to_vertex(h).idx()]) > 1e-6) {
            return false;
        }
    }
    return true;
}

}  // namespace

void attach(const MeshSoup& soup, const BuildReport& report, Mesh& mesh) {
    const PolygonSoup& s = soup.soup;
    // build_mesh() keeps vertex i as soup vertex i; the copies it makes of a split vertex
    // take their colour through the corners below.
    const bool colors = !soup.colors.empty() && soup.colors.size() == s.positions.size();
    VertexProperty<Vec4> color;
    if (colors) {
        color = mesh.property<Vertex, Vec4>(kColorProperty);
        for (std::size_t v = 0; v < soup.colors.size() && v < mesh.vertices_size(); ++v) {
            color[Vertex(static_cast<std::uint32_t>(v))] = soup.colors[v];
        }
    }
    const bool face_colors = soup.face_colors.size() == s.n_faces() && !soup.face_colors.empty();
    const bool texcoords = soup.corner_texcoords.size() == s.indices.size();
    const bool texcoords1 = soup.corner_texcoords1.size() == s.indices.size();
    const bool corner_normals = soup.corner_normals.size() == s.indices.size();
    const bool vertex_normals =
        !corner_normals && !soup.normals.empty() && soup.normals.size() == s.positions.size();
    const bool materials = soup.face_materials.size() == s.n_faces();
    if (!texcoords && !texcoords1 && !corner_normals && !vertex_normals && !materials &&
        !face_colors && !colors) {
        return;
    }
    HalfedgeProperty<Vec2> uv, uv1;
    HalfedgeProperty<Vec3> normal;
    FaceProperty<std::uint32_t> material;
    FaceProperty<Vec4> face_color;
    if (face_colors) {
        face_color = mesh.property<Face, Vec4>(kFaceColorProperty);
    }
    if (texcoords) {
        uv = mesh.property<Halfedge, Vec2>(kTexCoordProperty);
    }
    if (texcoords1) {
        uv1 = mesh.property<Halfedge, Vec2>(kTexCoord1Property);
    }
    if (corner_normals || vertex_normals) {
        normal = mesh.property<Halfedge, Vec3>(kCornerNormalProperty);
    }
    if (materials) {
        material = mesh.property<Face, std::uint32_t>(kMaterialProperty);
        mesh.materials() = soup.materials;
    }
    // Mesh face j is the j-th soup face build_mesh() kept; its i-th halfedge from
    // halfedge(f) leaves corner i and arrives at corner i + 1, whose values it holds.
    std::size_t dropped = 0;
    std::uint32_t j = 0;
    for (std::uint32_t f = 0; f < s.n_faces(); ++f) {
        if (dropped < report.dropped_faces.size() && report.dropped_faces[dropped] == f) {
            ++dropped;
            continue;
        }
        const Face face(j++);
        if (face.idx() >= mesh.faces_size()) {
            break;
        }
        if (materials) {
            material[face] = soup.face_materials[f];
        }
        if (face_colors) {
            face_color[face] = soup.face_colors[f];
        }
        const std::uint32_t first = s.face_offsets[f];
        const std::uint32_t n = s.face_offsets[f + 1] - first;
        Halfedge h = mesh.halfedge(face);
        for (std::uint32_t i = 0; i < n; ++i, h = mesh.next(h)) {
            const std::uint32_t c = first + (i + 1) % n;
            if (colors) {
                color[mesh.to_vertex(h)] = soup.colors[s.indices[c]];
            }
            if (texcoords) {
                uv[h] = soup.corner_texcoords[c];
            }
            if (texcoords1) {
                uv1[h] = soup.corner_texcoords1[c];
            }
            if (corner_normals) {
                normal[h] = soup.corner_normals[c];
            } else if (vertex_normals) {
                normal[h] = soup.normals[s.indices[c]];
            }
        }
    }
    if (normal && computed_anyway(mesh, normal)) {
        mesh.remove_property(normal);
    }
}

}  // namespace meshedit::soup_attributes
