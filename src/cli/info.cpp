// `meshedit info FILE [--json] [--stats] [--density N]`: counts, topology, bounding box, repairs.

#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <numbers>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "cli.h"
#include "meshedit/core/attribute_summary.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/fields.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/topology.h"
#include "meshedit/io/io.h"

namespace meshedit::cli {
namespace {

using Json = nlohmann::ordered_json;

// V/E/F of one connected part of a mesh.
struct PartCounts {
    std::size_t vertices = 0;
    std::size_t edges = 0;
    std::size_t faces = 0;
};

// Connected parts by a flood fill over edges; a part's edges and faces are counted at its
// vertices (each edge twice, each face once per corner) to avoid a second labelling pass.
std::vector<PartCounts> parts_of(const Mesh& mesh) {
    std::vector<std::uint32_t> label(mesh.vertices_size(), kInvalidIndex);
    std::vector<PartCounts> parts;
    std::vector<Vertex> stack;
    for (const Vertex seed : mesh.vertices()) {
        if (label[seed.idx()] != kInvalidIndex) {
            continue;
        }
        const auto id = static_cast<std::uint32_t>(parts.size());
        parts.emplace_back();
        label[seed.idx()] = id;
        stack.push_back(seed);
        while (!stack.empty()) {
            const Vertex v = stack.back();
            stack.pop_back();
            ++parts[id].vertices;
            if (mesh.is_isolated(v)) {
                continue;
            }
            for (const Vertex w : mesh.vertices(v)) {
                if (label[w.idx()] == kInvalidIndex) {
                    label[w.idx()] = id;
                    stack.push_back(w);
                }
            }
        }
    }
    for (const Edge e : mesh.edges()) {
        ++parts[label[mesh.vertex(e, 0).idx()]].edges;
    }
    for (const Face f : mesh.faces()) {
        ++parts[label[mesh.to_vertex(mesh.halfedge(f)).idx()]].faces;
    }
    return parts;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty()) {
            lines.push_back(line);
        }
    }
    return lines;
}

Json bbox_json(const BoundingBox& box) {
    if (box.is_empty()) {
        return nullptr;
    }
    return Json{{"min", {box.min.x, box.min.y, box.min.z}},
                {"max", {box.max.x, box.max.y, box.max.z}}};
}

std::string bbox_text(const BoundingBox& box, int dims) {
    if (box.is_empty()) {
        return "empty";
    }
    auto point = [dims](const Vec3& p) {
        // Appending (not "(" + …) sidesteps a GCC 12 -Wrestrict false positive.
        std::string s("(");
        s += readable_number(p.x);
        s += ", ";
        s += readable_number(p.y);
        if (dims == 3) {
            s += ", ";
            s += readable_number(p.z);
        }
        s += ")";
        return s;
    };
    return point(box.min) + " .. " + point(box.max);
}

int info_curve(const std::filesystem::path& path, const BezierCurve& curve, bool json) {
    BoundingBox box;
    for (const Vec3& p : curve.control_points) {
        box.add(p);
    }
    if (json) {
        Json j;
        j["file"] = path.string();
        j["kind"] = "bezier-curve";
        j["points"] = curve.control_points.size();
        j["degree"] = curve.degree();
        j["bbox"] = bbox_json(box);
        std::printf("%s\n", j.dump(2).c_str());
        return 0;
    }
    print_row("file", path.string());
    print_row("kind", "Bezier curve");
    print_row("control points", std::to_string(curve.control_points.size()));
    print_row("degree", std::to_string(curve.degree()));
    print_row("bounding box", bbox_text(box, 2));
    return 0;
}

std::size_t count_creases(const Mesh& mesh) {
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    std::size_t n = 0;
    if (crease) {
        for (const Edge e : mesh.edges()) {
            n += crease[e] != 0 ? 1 : 0;
        }
    }
    return n;
}

// How many faces have each number of corners, in increasing order of corners.
std::map<std::size_t, std::size_t> face_degrees(const Mesh& mesh) {
    std::map<std::size_t, std::size_t> count;
    for (const Face f : mesh.faces()) {
        ++count[mesh.valence(f)];
    }
    return count;
}

// "3: 12, 4: 90, 6: 2" (corners: faces).
std::string degrees_text(const std::map<std::size_t, std::size_t>& degrees) {
    std::string out;
    for (const auto& [corners, faces] : degrees) {
        out += (out.empty() ? "" : ", ") + std::to_string(corners) +
               " corners: " + std::to_string(faces);
    }
    return out.empty() ? "none" : out;
}

// Everything `meshedit info` prints about `path`.
// --stats: area, volume of a closed mesh, Gauss–Bonnet, every field's min/mean/max.
Json stats_json(const Mesh& mesh, bool closed) {
    Json j;
    j["area"] = surface_area(mesh);
    if (closed) {
        j["volume"] = signed_volume(mesh);
    }
    j["total_angle_defect"] = total_angle_defect(mesh);
    Json fields = Json::object();
    for (const FieldInfo* info_ptr : mesh_fields(mesh)) {
        const FieldInfo& info = *info_ptr;
        const FieldStats s = field_stats(compute_field(mesh, info));
        fields[std::string(info.name)] = {
            {"count", s.count}, {"min", s.min}, {"mean", s.mean}, {"max", s.max}};
    }
    j["fields"] = std::move(fields);
    return j;
}

void print_stats(const Mesh& mesh, bool closed, long euler_characteristic) {
    print_row("area", readable_number(surface_area(mesh)));
    print_row("volume", closed ? readable_number(signed_volume(mesh)) : "(open: none)");
    print_row("angle defect", readable_number(total_angle_defect(mesh) / std::numbers::pi) +
                                  " pi (Gauss-Bonnet: 2 pi chi = " +
                                  std::to_string(2 * euler_characteristic) + " pi)");
    for (const FieldInfo* info_ptr : mesh_fields(mesh)) {
        const FieldInfo& info = *info_ptr;
        const FieldStats s = field_stats(compute_field(mesh, info));
        const std::string unit = info.unit.empty() ? "" : " " + std::string(info.unit);
        print_row(std::string(info.name),
                  s.count == 0 ? "(no values)"
                               : "min " + readable_number(s.min) + ", mean " +
                                     readable_number(s.mean) + ", max " + readable_number(s.max) +
                                     unit + " (" + std::to_string(s.count) + " values)");
    }
}

Json attributes_json(const Mesh& mesh, const AttributeSummary& a) {
    Json materials = Json::array();
    for (const Material& m : mesh.materials()) {
        Json j = {{"name", m.name}};
        if (m.has_base_colour) {
            j["base_colour"] = {m.base_colour.x, m.base_colour.y, m.base_colour.z};
        }
        if (m.has_opacity) {
            j["opacity"] = m.opacity;
        }
        if (!m.base_colour_texture.empty()) {
            std::error_code ec;
            j["texture"] = m.base_colour_texture;
            j["texture_found"] = std::filesystem::exists(m.base_colour_texture, ec);
            j["texture_texcoord_set"] = m.base_colour_texcoord;
        }
        materials.push_back(std::move(j));
    }
    return {{"texcoords", a.texcoords},
            {"uv_seam_edges", a.uv_seam_edges},
            {"second_texcoords", a.second_texcoords},
            {"second_uv_seam_edges", a.second_uv_seam_edges},
            {"corner_normals", a.corner_normals},
            {"vertex_colours", a.vertex_colours},
            {"face_colours", a.face_colours},
            {"material_border_edges", a.material_borders},
            {"materials", a.face_materials ? materials : Json::array()}};
}

int info(const std::filesystem::path& path, bool json, int density, bool with_stats) {
    ReadOptions options;
    options.density = density;
    const LoadedDocument input = read_document(path, options);
    if (input.kind == DocumentKind::Curve) {
        return info_curve(path, input.curve, json);
    }
    const Mesh& mesh = input.mesh;
    const MeshStats stats = compute_stats(mesh);
    const bool manifold = !input.repairs.repaired();
    const std::size_t creases = count_creases(mesh);
    const std::vector<std::string> repairs = lines_of(input.repairs.summary());
    const BoundingBox box = mesh.bounds();
    const bool bez = input.kind == DocumentKind::Surface;
    const std::map<std::size_t, std::size_t> degrees = face_degrees(mesh);
    const AttributeSummary attributes = summarize_attributes(mesh);

    if (json) {
        Json j;
        j["file"] = path.string();
        j["kind"] = bez ? "bezier-patches" : "mesh";
        if (bez) {
            j["patches"] = input.patches.size();
            j["density"] = density;
        }
        j["vertices"] = stats.vertices;
        j["edges"] = stats.edges;
        j["faces"] = stats.faces;
        j["triangle_mesh"] = mesh.is_triangle_mesh();
        Json histogram = Json::object();
        for (const auto& [corners, faces] : degrees) {
            histogram[std::to_string(corners)] = faces;
        }
        j["face_degrees"] = std::move(histogram);
        j["boundary_loops"] = stats.boundary_loops;
        j["components"] = stats.components;
        j["euler_characteristic"] = stats.euler_characteristic;
        j["genus"] = stats.genus;
        j["manifold"] = manifold;
        j["creases"] = creases;
        j["bbox"] = bbox_json(box);
        j["unit_meter"] = input.unit_meter;
        j["repairs"] = repairs;
        j["notices"] = input.notices;
        if (bez) {
            Json parts = Json::array();
            for (const PartCounts& p : parts_of(mesh)) {
                parts.push_back(
                    {{"vertices", p.vertices},
                     {"edges", p.edges},
                     {"faces", p.faces},
                     {"euler_characteristic", long(p.vertices) - long(p.edges) + long(p.faces)}});
            }
            j["parts"] = std::move(parts);
        }
        j["attributes"] = attributes_json(mesh, attributes);
        if (with_stats) {
            j["stats"] = stats_json(mesh, stats.boundary_loops == 0);
        }
        std::printf("%s\n", j.dump(2).c_str());
        return 0;
    }

    print_row("file", path.string());
    if (bez) {
        print_row("kind", "Bezier patches, " + std::to_string(input.patches.size()) +
                              " tessellated at density " + std::to_string(density) + " and welded");
    }
    print_row("vertices", std::to_string(stats.vertices));
    print_row("edges", std::to_string(stats.edges));
    print_row("faces", std::to_string(stats.faces) +
                           (mesh.is_triangle_mesh() ? " (all triangles)" : " (polygons)"));
    print_row("face degrees", degrees_text(degrees));
    print_row("boundary loops", std::to_string(stats.boundary_loops));
    print_row("components", std::to_string(stats.components));
    print_row("Euler characteristic", std::to_string(stats.euler_characteristic));
    print_row("genus", std::to_string(stats.genus));
    print_row("manifold", manifold ? "yes" : "no (repaired on load, see below)");
    print_row("crease edges", std::to_string(creases));
    print_row("bounding box", bbox_text(box, 3));
    print_row("unit", format_number(input.unit_meter) + " m");
    for (const auto& [name, value] : attribute_rows(mesh, attributes)) {
        print_row(name, value);
    }
    if (repairs.empty()) {
        print_row("repairs", "none");
    }
    for (const std::string& line : repairs) {
        print_row("repair", line);
    }
    for (const std::string& line : input.notices) {
        print_row("notice", line);
    }
    if (bez) {
        const std::vector<PartCounts> parts = parts_of(mesh);
        for (std::size_t i = 0; i < parts.size(); ++i) {
            const PartCounts& p = parts[i];
            print_row("part " + std::to_string(i + 1),
                      "V " + std::to_string(p.vertices) + ", E " + std::to_string(p.edges) +
                          ", F " + std::to_string(p.faces) + ", chi " +
                          std::to_string(long(p.vertices) - long(p.edges) + long(p.faces)));
        }
    }
    if (with_stats) {
        print_stats(mesh, stats.boundary_loops == 0, stats.euler_characteristic);
    }
    return 0;
}

}  // namespace

Command add_info(CLI::App& meshedit) {
    struct Settings {
        std::filesystem::path file;
        bool json = false;
        bool stats = false;
        int density = 8;
    };
    auto s = std::make_shared<Settings>();
    CLI::App* app =
        meshedit.add_subcommand("info", "counts, topology, bounding box, repairs of a file");
    app->add_option("FILE", s->file, "the file to describe")->required();
    app->add_flag("--json", s->json, "print one JSON object (fields: docs/cli.md)");
    app->add_flag("--stats", s->stats,
                  "also area, volume (closed meshes), the total angle defect and min/mean/max "
                  "of every scalar field (docs/fields.md)");
    add_density_option(*app, s->density);
    app->footer(
        "Describes a mesh (" + mesh_extension_list(" ") +
        "), a Bezier patch set (.bez) or a Bezier curve\n"
        "(.bzc). For a mesh: vertices, edges, faces, boundary loops, connected components,\n"
        "Euler characteristic, genus, manifold (the loader repaired nothing), crease edges,\n"
        "bounding box, unit, and what the loader repaired or noticed. A .bez is tessellated\n"
        "(--density) and welded; each connected part is listed with its counts. A .bzc gives\n"
        "its point count, degree and bounding box.\n"
        "\n"
        "Exit status: 0 ok, 2 bad usage or unreadable file.");
    return {app, [s] { return info(s->file, s->json, s->density, s->stats); }};
}

}  // namespace meshedit::cli
