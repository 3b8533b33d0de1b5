// COLLADA 1.4.1 writer: one <geometry> with positions, normals (the file's per corner, else
// computed per vertex if asked), texture coordinates per corner (both sets), vertex colours, a
// <polylist> per run of faces of one material (so faces keep their order), the materials' libraries
// (collada_material.cpp) and MeshEdit's <extra>s (creases; a lone second texture coordinate set),
// written atomically.

#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "collada_material.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/build.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/number_text.h"
#include "meshedit/io/collada.h"

namespace meshedit {
namespace {

void append_number(std::string& out, double value) {
    append_number_text(out, value);
}

void append_number(std::string& out, std::uint64_t value) {
    char buffer[24];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

// A <source> of `values.size() / stride` tuples, one <param> per letter of `names`.
void append_source(std::string& out, const std::string& id, const std::vector<double>& values,
                   const std::string& names) {
    const std::uint64_t stride = names.size();
    out += "        <source id=\"" + id + "\">\n          <float_array id=\"" + id +
           "-array\" count=\"";
    append_number(out, std::uint64_t{values.size()});
    out += "\">";
    for (std::size_t i = 0; i < values.size(); ++i) {
        out += i == 0 ? "" : " ";
        append_number(out, values[i]);
    }
    out += "</float_array>\n          <technique_common>\n            <accessor source=\"#" + id +
           "-array\" count=\"";
    append_number(out, values.size() / stride);
    out += "\" stride=\"";
    append_number(out, stride);
    out += "\">\n";
    for (const char name : names) {
        out += std::string("              <param name=\"") + name + "\" type=\"float\"/>\n";
    }
    out += "            </accessor>\n          </technique_common>\n        </source>\n";
}

void append_vec3_source(std::string& out, const std::string& id, const std::vector<Vec3>& values,
                        const char* names) {
    std::vector<double> flat;
    flat.reserve(3 * values.size());
    for (const Vec3& v : values) {
        flat.insert(flat.end(), {v.x, v.y, v.z});
    }
    append_source(out, id, flat, names);
}

std::string collada_text(const Mesh& mesh, const IoFlags& flags,
                         const std::filesystem::path& folder) {
    const PolygonSoup soup = to_polygon_soup(mesh);
    std::string out;
    out.reserve(64 * soup.positions.size() + 8 * soup.indices.size() + 2048);
    // A fixed date keeps output reproducible (sample files are committed); the schema
    // requires <created> and <modified>.
    out +=
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
        "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
        "  <asset>\n"
        "    <contributor>\n"
        "      <authoring_tool>MeshEdit</authoring_tool>\n"
        "    </contributor>\n"
        "    <created>2000-01-01T00:00:00Z</created>\n"
        "    <modified>2000-01-01T00:00:00Z</modified>\n"
        "    <unit name=\"meter\" meter=\"1\"/>\n"
        "    <up_axis>Y_UP</up_axis>\n"
        "  </asset>\n"
        "  <library_geometries>\n"
        "    <geometry id=\"mesh\" name=\"mesh\">\n"
        "      <mesh>\n";
    append_vec3_source(out, "mesh-positions", soup.positions, "XYZ");
    // Per-corner values in to_polygon_soup()'s order: the corner at from_vertex(h) is held by
    // the halfedge arriving there.
    const auto corner_normal = mesh.get_property<Halfedge, Vec3>(kCornerNormalProperty);
    const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const auto uv1 = mesh.get_property<Halfedge, Vec2>(kTexCoord1Property);
    const auto colour = mesh.get_property<Vertex, Vec4>(kColorProperty);
    const auto material = mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
    const std::vector<Material>& materials = mesh.materials();
    const bool use_materials = material && !materials.empty();
    const bool corners = corner_normal || uv || uv1;
    if (corners) {
        std::vector<double> n, t, t1;
        for (const Face f : mesh.faces()) {
            for (const Halfedge h : mesh.halfedges(f)) {
                const Halfedge in = mesh.prev(h);
                if (corner_normal) {
                    const Vec3& x = corner_normal[in];
                    n.insert(n.end(), {x.x, x.y, x.z});
                }
                if (uv) {
                    t.insert(t.end(), {uv[in].x, uv[in].y});
                }
                if (uv1) {
                    t1.insert(t1.end(), {uv1[in].x, uv1[in].y});
                }
            }
        }
        if (corner_normal) {
            append_source(out, "mesh-corner-normals", n, "XYZ");
        }
        if (uv) {
            append_source(out, "mesh-map-0", t, "ST");
        }
        if (uv1) {
            append_source(out, "mesh-map-1", t1, "ST");
        }
    }
    if (colour) {
        std::vector<double> c;
        for (const Vertex v : mesh.vertices()) {
            c.insert(c.end(), {colour[v].x, colour[v].y, colour[v].z, colour[v].w});
        }
        append_source(out, "mesh-colors", c, "RGBA");
    }
    const bool normals = !corner_normal && flags.write_normals && !soup.positions.empty();
    if (normals) {
        std::vector<Vec3> vertex_normal;
        compute_vertex_normals(mesh, vertex_normal);
        vertex_normal.resize(soup.positions.size());
        append_vec3_source(out, "mesh-normals", vertex_normal, "XYZ");
    }
    out +=
        "        <vertices id=\"mesh-vertices\">\n"
        "          <input semantic=\"POSITION\" source=\"#mesh-positions\"/>\n"
        "        </vertices>\n";
    // One <polylist> per run of faces of one material; corner c's own index is c.
    const std::uint64_t stride = 1 + (corners ? 1 : 0);
    for (std::size_t first = 0; first < soup.n_faces();) {
        const auto material_of = [&](std::size_t f) {
            return use_materials ? material[Face(static_cast<std::uint32_t>(f))] : 0u;
        };
        std::size_t last = first + 1;
        while (last < soup.n_faces() && material_of(last) == material_of(first)) {
            ++last;
        }
        out += "        <polylist count=\"";
        append_number(out, std::uint64_t{last - first});
        out += "\"";
        if (use_materials && material_of(first) < materials.size()) {
            out += " material=\"material-" + std::to_string(material_of(first)) + "\"";
        }
        out += ">\n          <input semantic=\"VERTEX\" source=\"#mesh-vertices\" offset=\"0\"/>\n";
        if (normals) {
            // The normals are per vertex, so they share the vertex index (offset 0).
            out += "          <input semantic=\"NORMAL\" source=\"#mesh-normals\" offset=\"0\"/>\n";
        }
        if (corner_normal) {
            out +=
                "          <input semantic=\"NORMAL\" source=\"#mesh-corner-normals\" "
                "offset=\"1\"/>\n";
        }
        if (uv) {
            out +=
                "          <input semantic=\"TEXCOORD\" source=\"#mesh-map-0\" offset=\"1\" "
                "set=\"0\"/>\n";
        }
        if (uv1) {  // the second set: its own source, the corner's index like the first's
            out +=
                "          <input semantic=\"TEXCOORD\" source=\"#mesh-map-1\" offset=\"1\" "
                "set=\"1\"/>\n";
        }
        if (colour) {
            out += "          <input semantic=\"COLOR\" source=\"#mesh-colors\" offset=\"0\"/>\n";
        }
        out += "          <vcount>";
        for (std::size_t f = first; f < last; ++f) {
            out += f == first ? "" : " ";
            append_number(out, std::uint64_t{soup.face_offsets[f + 1] - soup.face_offsets[f]});
        }
        out += "</vcount>\n          <p>";
        for (std::size_t i = soup.face_offsets[first]; i < soup.face_offsets[last]; ++i) {
            out += i == soup.face_offsets[first] ? "" : " ";
            append_number(out, std::uint64_t{soup.indices[i]});
            if (stride == 2) {
                out += ' ';
                append_number(out, std::uint64_t{i});
            }
        }
        out += "</p>\n        </polylist>\n";
        first = last;
    }
    if (uv1 && !uv) {
        // Its one set is the mesh's second: readers take the lowest set as the first, so
        // MeshEdit says which it is.
        out +=
            "        <extra>\n          <technique profile=\"MeshEdit\">\n"
            "            <second_texcoord_set_only/>\n          </technique>\n        </extra>\n";
    }
    if (const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty)) {
        std::string pairs;
        std::uint64_t count = 0;
        for (Edge e : mesh.edges()) {
            if (crease[e] != 0) {
                pairs += count == 0 ? "" : " ";
                append_number(pairs, std::uint64_t{mesh.vertex(e, 0).idx()});
                pairs += ' ';
                append_number(pairs, std::uint64_t{mesh.vertex(e, 1).idx()});
                ++count;
            }
        }
        if (count > 0) {
            out +=
                "        <extra>\n          <technique profile=\"MeshEdit\">\n"
                "            <creases count=\"";
            append_number(out, count);
            out += "\">" + pairs + "</creases>\n          </technique>\n        </extra>\n";
        }
    }
    out +=
        "      </mesh>\n"
        "    </geometry>\n"
        "  </library_geometries>\n";
    if (use_materials) {
        out += collada::materials_text(materials, folder);
    }
    out +=
        "  <library_visual_scenes>\n"
        "    <visual_scene id=\"scene\" name=\"scene\">\n"
        "      <node id=\"node\" name=\"mesh\">\n";
    if (use_materials) {
        out +=
            "        <instance_geometry url=\"#mesh\">\n          <bind_material>\n"
            "            <technique_common>\n";
        for (std::size_t i = 0; i < materials.size(); ++i) {
            const std::string m = "material-" + std::to_string(i);
            out += "              <instance_material symbol=\"" + m + "\" target=\"#" + m +
                   "\">\n                <bind_vertex_input semantic=\"UVMap\" "
                   "input_semantic=\"TEXCOORD\" input_set=\"" +
                   std::to_string(materials[i].base_colour_texcoord) +
                   "\"/>\n"
                   "              </instance_material>\n";
        }
        out +=
            "            </technique_common>\n          </bind_material>\n"
            "        </instance_geometry>\n";
    } else {
        out += "        <instance_geometry url=\"#mesh\"/>\n";
    }
    out +=
        "      </node>\n"
        "    </visual_scene>\n"
        "  </library_visual_scenes>\n"
        "  <scene>\n"
        "    <instance_visual_scene url=\"#scene\"/>\n"
        "  </scene>\n"
        "</COLLADA>\n";
    return out;
}

}  // namespace

void write_collada(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags) {
    std::string text;
    if (mesh.has_garbage()) {
        Mesh compact = mesh;
        compact.garbage_collection();
        text = collada_text(compact, flags, path.parent_path());
    } else {
        text = collada_text(mesh, flags, path.parent_path());
    }
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream file(tmp, std::ios::binary | std::ios::trunc);
        file.write(text.data(), static_cast<std::streamsize>(text.size()));
        file.close();
        if (!file) {
            throw IoError(path.string(), "", "write failed: " + std::string(std::strerror(errno)));
        }
    });
}

}  // namespace meshedit
