// COLLADA 1.4.1 writer: one <geometry> with positions, optional normals, one <polylist>, and
// MeshEdit's crease <extra>, written atomically.

#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

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

void append_vec3_source(std::string& out, const std::string& id, const std::vector<Vec3>& values,
                        const char* names) {
    const std::uint64_t n = values.size();
    out += "        <source id=\"" + id + "\">\n          <float_array id=\"" + id +
           "-array\" count=\"";
    append_number(out, 3 * n);
    out += "\">";
    for (std::size_t i = 0; i < values.size(); ++i) {
        out += i == 0 ? "" : " ";
        append_number(out, values[i].x);
        out += ' ';
        append_number(out, values[i].y);
        out += ' ';
        append_number(out, values[i].z);
    }
    out += "</float_array>\n          <technique_common>\n            <accessor source=\"#" + id +
           "-array\" count=\"";
    append_number(out, n);
    out += "\" stride=\"3\">\n";
    for (int k = 0; k < 3; ++k) {
        out += std::string("              <param name=\"") + names[k] + "\" type=\"float\"/>\n";
    }
    out += "            </accessor>\n          </technique_common>\n        </source>\n";
}

std::string collada_text(const Mesh& mesh, const IoFlags& flags) {
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
    const bool normals = flags.write_normals && !soup.positions.empty();
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
    if (soup.n_faces() > 0) {
        out += "        <polylist count=\"";
        append_number(out, static_cast<std::uint64_t>(soup.n_faces()));
        out +=
            "\">\n          <input semantic=\"VERTEX\" source=\"#mesh-vertices\" offset=\"0\"/>\n";
        if (normals) {
            // The normals are per vertex, so they share the vertex index (offset 0).
            out += "          <input semantic=\"NORMAL\" source=\"#mesh-normals\" offset=\"0\"/>\n";
        }
        out += "          <vcount>";
        for (std::size_t f = 0; f < soup.n_faces(); ++f) {
            out += f == 0 ? "" : " ";
            append_number(out, std::uint64_t{soup.face_offsets[f + 1] - soup.face_offsets[f]});
        }
        out += "</vcount>\n          <p>";
        for (std::size_t i = 0; i < soup.indices.size(); ++i) {
            out += i == 0 ? "" : " ";
            append_number(out, std::uint64_t{soup.indices[i]});
        }
        out += "</p>\n        </polylist>\n";
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
        "  </library_geometries>\n"
        "  <library_visual_scenes>\n"
        "    <visual_scene id=\"scene\" name=\"scene\">\n"
        "      <node id=\"node\" name=\"mesh\">\n"
        "        <instance_geometry url=\"#mesh\"/>\n"
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
        text = collada_text(compact, flags);
    } else {
        text = collada_text(mesh, flags);
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
