// `meshedit compare A B [--json] [--tolerance D] [--field OUT.ply] [--mapping] [--density N]`:
// whether two files hold the same mesh up to renumbering, and how far apart they are
// (core/compare.h).

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "cli.h"
#include "meshedit/core/compare.h"
#include "meshedit/files/files.h"
#include "meshedit/io/io.h"

namespace meshedit::cli {
namespace {

using Json = nlohmann::ordered_json;

// The vertex property --field writes: PLY keeps it as a vertex column of that name, read back
// as the user property "v:ply:deviation" (io.h, UserProperty).
constexpr const char* kDeviationProperty = "v:ply:deviation";

struct Settings {
    std::filesystem::path a, b;
    bool json = false;
    bool mapping = false;
    double tolerance = 0.0;
    std::filesystem::path field;
    int density = 8;
};

std::string counts_text(const std::filesystem::path& path, const Mesh& mesh) {
    return path.string() + ": V " + std::to_string(mesh.n_vertices()) + ", E " +
           std::to_string(mesh.n_edges()) + ", F " + std::to_string(mesh.n_faces());
}

Json counts_json(const std::filesystem::path& path, const Mesh& mesh) {
    return Json{{"file", path.string()},
                {"vertices", mesh.n_vertices()},
                {"edges", mesh.n_edges()},
                {"faces", mesh.n_faces()}};
}

// "0.0123 (0.5%)": a distance and its share of the diagonal, rounded for reading.
std::string with_percent(double distance, double diagonal) {
    return readable_number(distance) + " (" + readable_number(percent_of(distance, diagonal)) +
           "%)";
}

Json ref_json(const ElementRef& ref) {
    return ref.is_none() ? Json(nullptr) : Json(to_string(ref));
}

void write_field(const std::filesystem::path& out, Mesh& a, const Deviation& d) {
    auto values = a.property<Vertex, double>(kDeviationProperty);
    for (const Vertex v : a.vertices()) {
        values[v] = d.vertex[v.idx()];
    }
    report_unkept(out, write_mesh(a, out));
}

// "the same (36 corners)", "12 of 36 differ, max 0.25; first: halfedge 7 of A", "only in A".
std::string attribute_text(const AttributeDifference& x) {
    if (x.in_a != x.in_b) {
        return x.in_a ? "only in A" : "only in B";
    }
    const std::string of = std::to_string(x.compared) + " " + x.elements;
    if (x.differing == 0) {
        return "the same (" + of + ")";
    }
    return std::to_string(x.differing) + " of " + of + " differ" +
           (x.name == "materials" ? "" : ", max " + readable_number(x.max)) +
           "; first: " + to_string(x.first_a) + " of A";
}

int compare(Settings& s) {
    if (!s.field.empty() && file_extension(s.field) != ".ply") {
        throw UsageError("--field writes a .ply file (its vertices carry the deviation), not '" +
                         s.field.string() + "'");
    }
    LoadedDocument a = load_surface(s.a, s.density);
    const LoadedDocument b = load_surface(s.b, s.density);
    const TopologyMatch match = match_topology(a.mesh, b.mesh);
    const Deviation d = measure_deviation(a.mesh, b.mesh, match);
    const std::vector<AttributeDifference> attributes = compare_attributes(a.mesh, b.mesh, match);
    // An attribute one mesh lacks, a material that differs or a value beyond the tolerance
    // makes them different too.
    const auto attribute_same = [&](const AttributeDifference& x) {
        return x.in_a == x.in_b &&
               (x.name == "materials" ? x.differing == 0 : x.max <= s.tolerance);
    };
    const bool same = match.isomorphic && d.max <= s.tolerance &&
                      std::all_of(attributes.begin(), attributes.end(), attribute_same);
    if (!s.field.empty()) {
        write_field(s.field, a.mesh, d);
    }

    if (s.json) {
        Json j;
        j["a"] = counts_json(s.a, a.mesh);
        j["b"] = counts_json(s.b, b.mesh);
        j["isomorphic"] = match.isomorphic;
        j["difference"] = match.isomorphic ? Json(nullptr) : Json(match.difference);
        j["first_difference"] = match.first_a.is_none() ? Json(nullptr)
                                                        : Json{{"a", ref_json(match.first_a)},
                                                               {"b", ref_json(match.first_b)}};
        j["deviation"] = {{"by", d.by_mapping ? "mapping" : "closest_points"},
                          {"max", d.max},
                          {"rms", d.rms},
                          {"hausdorff", d.hausdorff},
                          {"a_to_b", d.a_to_b},
                          {"b_to_a", d.b_to_a},
                          {"diagonal", d.diagonal},
                          {"max_percent", percent_of(d.max, d.diagonal)},
                          {"rms_percent", percent_of(d.rms, d.diagonal)},
                          {"hausdorff_percent", percent_of(d.hausdorff, d.diagonal)}};
        Json attribute_list = Json::array();
        for (const AttributeDifference& x : attributes) {
            attribute_list.push_back(
                {{"name", x.name},
                 {"in_a", x.in_a},
                 {"in_b", x.in_b},
                 {"compared", x.compared},
                 {"differing", x.differing},
                 {"max", x.max},
                 {"first", x.first_a.is_none() ? Json(nullptr) : ref_json(x.first_a)}});
        }
        j["attributes"] = std::move(attribute_list);
        j["tolerance"] = s.tolerance;
        j["same"] = same;
        if (s.mapping && match.isomorphic) {
            Json vertices = Json::array(), faces = Json::array();
            for (const Vertex v : a.mesh.vertices()) {
                vertices.push_back(match.vertex[v.idx()]);
            }
            for (const Face f : a.mesh.faces()) {
                faces.push_back(match.face[f.idx()]);
            }
            j["mapping"] = {{"vertices", std::move(vertices)}, {"faces", std::move(faces)}};
        }
        std::printf("%s\n", j.dump(2).c_str());
        return same ? 0 : 1;
    }

    print_row("A", counts_text(s.a, a.mesh));
    print_row("B", counts_text(s.b, b.mesh));
    print_row("topology",
              match.isomorphic ? "the same up to renumbering" : "different: " + match.difference);
    if (!match.first_a.is_none()) {
        print_row("first difference",
                  to_string(match.first_a) + " of A" +
                      (match.first_b.is_none() ? "" : ", " + to_string(match.first_b) + " of B"));
    }
    print_row("vertex distance",
              "max " + with_percent(d.max, d.diagonal) + ", RMS " +
                  with_percent(d.rms, d.diagonal) +
                  (d.by_mapping ? " (to the matched vertex of B)" : " (to the surface of B)"));
    print_row("Hausdorff distance", with_percent(d.hausdorff, d.diagonal) + " (A to B " +
                                        readable_number(d.a_to_b) + ", B to A " +
                                        readable_number(d.b_to_a) + ")");
    print_row("diagonal", readable_number(d.diagonal) + " (A's bounding box, 100%)");
    for (const AttributeDifference& x : attributes) {
        print_row(x.name, attribute_text(x));
    }
    print_row("result", std::string(same ? "the same" : "different") + " (tolerance " +
                            readable_number(s.tolerance) + ")");
    if (s.mapping && match.isomorphic) {
        for (const Vertex v : a.mesh.vertices()) {
            std::printf("vertex %u -> vertex %u\n", v.idx(), match.vertex[v.idx()]);
        }
        for (const Face f : a.mesh.faces()) {
            std::printf("face %u -> face %u\n", f.idx(), match.face[f.idx()]);
        }
    }
    return same ? 0 : 1;
}

}  // namespace

Command add_compare(CLI::App& meshedit) {
    auto s = std::make_shared<Settings>();
    CLI::App* app = meshedit.add_subcommand(
        "compare", "whether two files hold the same mesh up to renumbering, and how far apart");
    app->add_option("A", s->a, "the first mesh (the reference of the percentages and --field)")
        ->required();
    app->add_option("B", s->b, "the second mesh")->required();
    app->add_flag("--json", s->json, "print one JSON object (fields: docs/cli.md)");
    app->add_option("--tolerance", s->tolerance,
                    "the largest vertex distance that still counts as the same (default 0)")
        ->type_name("D")
        ->check(CLI::NonNegativeNumber);
    app->add_option("--field", s->field,
                    "write A with each vertex's distance to B as the PLY vertex property "
                    "'deviation'")
        ->type_name("OUT.ply");
    app->add_flag("--mapping", s->mapping,
                  "also print the matching: each vertex and face of A and its counterpart in B");
    add_density_option(*app, s->density);
    app->footer(
        "Matches the halfedge structures of A and B up to renumbering (vertices, edges and\n"
        "faces in any order, a face's first corner anywhere, components in any order), then\n"
        "measures how far A's vertices are from their matches in B (or, when the structures\n"
        "differ, from B's surface): max and RMS, and the symmetric Hausdorff distance, also in\n"
        "% of A's bounding-box diagonal. When the structures differ it names the first element\n"
        "where the matching failed.\n"
        "\n"
        "Exit status: 0 the same (structure, and every vertex within --tolerance), 1 different,\n"
        "2 bad usage or unreadable file.");
    return {app, [s] { return compare(*s); }};
}

}  // namespace meshedit::cli
