// `meshedit convert`, `subdivide`, `simplify`, `remesh` and `check`: the commands that load
// a mesh, maybe change it, and write or judge it.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "cli.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/validate.h"
#include "meshedit/files/files.h"
#include "meshedit/io/io.h"
#include "meshedit/ops/ops.h"
#include "progress.h"

namespace meshedit::cli {
namespace {

void print_load_messages(const LoadedDocument& input) {
    for (const std::string& notice : input.notices) {
        print_notice(notice);
    }
}

ops::ApplyOptions apply_options(ProgressBar& bar, LoopWeights weights) {
    ops::ApplyOptions options;
    options.weights = weights;
    options.progress = [&bar](double f) { bar.update(f); };
    options.notice = [](const std::string& text) { print_notice(text); };
    return options;
}

// An OpError means the list was fine but the mesh said no; name the input too so the line
// stands on its own in a log.
[[noreturn]] void rethrow_with_file(const ops::OpError& e, const std::filesystem::path& in) {
    throw ops::OpError(in.string() + ": " + e.what(), e.refused());
}

// --feature-angle of simplify and remesh: the third amount of their verbs.
void add_feature_angle_option(CLI::App& app, double& degrees) {
    app.add_option("--feature-angle", degrees,
                   "first mark every edge sharper than DEG degrees (0 to 180) as a crease, "
                   "which the operation keeps (default: off)")
        ->type_name("DEG");
}

// The whole-mesh commands (subdivide, simplify, remesh): IN's mesh through one step of the
// language (none: a plain conversion), as `convert --ops` runs it, written to OUT; a refusal
// names IN.
int run_one_step(const std::filesystem::path& in, const std::filesystem::path& out, int density,
                 const char* what, LoopWeights weights,
                 const std::function<std::optional<ops::Step>(const Mesh&)>& step_of) {
    check_mesh_output(out);
    LoadedDocument input = load_surface(in, density);
    print_load_messages(input);
    if (const std::optional<ops::Step> step = step_of(input.mesh)) {
        ProgressBar bar(what);
        try {
            ops::apply_steps(input.mesh, {*step}, apply_options(bar, weights));
        } catch (const ops::OpError& e) {
            rethrow_with_file(e, in);
        }
    }
    write_output(input.mesh, out);
    return 0;
}

}  // namespace

// The steps of --ops: a comma list, or @FILE, a session file (one step per line, '#' lines a
// header; the viewer's Ctrl+Shift+E writes them). A session names the file it was recorded
// on by its hash: a replay on another file is allowed, with a note.
std::vector<ops::Step> steps_of(const std::string& ops, const std::filesystem::path& in) {
    if (ops.empty() || ops.front() != '@') {
        return ops::parse(ops);
    }
    const std::filesystem::path session = ops.substr(1);
    const std::string text = read_file(session);
    std::vector<ops::Step> steps;
    try {
        steps = ops::parse_session(text);
    } catch (const ops::SyntaxError& e) {
        throw ops::SyntaxError(session.string() + ": " + e.what());
    } catch (const BudgetError& e) {
        throw BudgetError(session.string() + ": " + e.what());
    }
    const std::optional<std::string> recorded = ops::session_header_value(text, "input-fnv1a64");
    if (recorded && std::filesystem::is_regular_file(in)) {
        if (const std::string actual = content_hash(read_file(in)); actual != *recorded) {
            print_notice(session.string() + " was recorded on another file (fnv1a64 " + *recorded +
                         "; " + in.string() + " has " + actual +
                         "): its indices may name other elements");
        }
    }
    return steps;
}

Command add_convert(CLI::App& meshedit) {
    struct Settings {
        std::filesystem::path in, out;
        std::string ops;
        CLI::Option* ops_option = nullptr;
        int density = 8;
        bool ascii = false;
    };
    auto s = std::make_shared<Settings>();
    CLI::App* app = meshedit.add_subcommand(
        "convert", "convert between formats, applying edits such as flip:0-6,loop");
    app->add_option("IN", s->in, "the input file")->required();
    app->add_option("OUT", s->out, "the output file")->required();
    s->ops_option =
        app->add_option("--ops", s->ops,
                        "comma list of edits, run in order, or @FILE, a session file (one per "
                        "line, '#' lines skipped); an edge is named by its two vertices' "
                        "indices, as the file numbers them:\n" +
                            ops::help_lines())
            ->type_name("LIST");
    add_density_option(*app, s->density);
    add_strict_option(*app);
    app->add_flag("--ascii", s->ascii, "write PLY and STL as text rather than binary");
    const std::string formats = mesh_extension_list(" ");
    app->footer(
        "Reads IN (" + formats +
        ", or a .bez tessellated at --density),\n"
        "applies the --ops edits in order and writes OUT in the format of its extension\n(" +
        formats +
        "; PLY and STL binary unless --ascii).\n"
        "A .bzc curve converts only to .bzc, and a .bez to .bez keeps its patches (both written\n"
        "as the CS184 course's skeleton reads them). OUT is written to a temporary file and\n"
        "renamed, so a failed run never leaves a partial OUT.\n"
        "\n"
        "Examples:\n"
        "  meshedit convert dae/cube.dae cube.obj\n"
        "  meshedit convert dae/cube.dae out.dae --ops flip:0-6,split:0-1,loop:2\n"
        "  meshedit convert dae/cube.dae out.dae --ops @session.ops   (a viewer session)\n"
        "\n"
        "Exit status: 0 ok, 1 an op was refused, 2 bad usage, bad input, a named edge that does\n"
        "not exist, or an unwritable output.");
    return {app, [s] {
                std::vector<ops::Step> steps;
                if (s->ops_option->count() > 0) {
                    try {
                        steps = steps_of(s->ops, s->in);
                    } catch (const ops::SyntaxError& e) {
                        throw UsageError(std::string("convert: ") + e.what());
                    }
                }
                if (file_extension(s->in) == ".bzc" && file_extension(s->out) == ".bzc") {
                    if (!steps.empty()) {
                        throw UsageError("convert: --ops applies to meshes, not to a .bzc curve");
                    }
                    write_bzc(read_bzc(s->in), s->out);
                    return 0;
                }
                if (file_extension(s->in) == ".bez" && file_extension(s->out) == ".bez") {
                    if (!steps.empty()) {
                        throw UsageError(
                            "convert: --ops edits meshes; .bez to .bez keeps the patches as they "
                            "are (convert to .dae to edit the tessellation)");
                    }
                    write_bez(read_bez(s->in), s->out);
                    return 0;
                }
                check_mesh_output(s->out);
                LoadedDocument input = load_surface(s->in, s->density);
                print_load_messages(input);
                {
                    ProgressBar bar("convert");
                    try {
                        ops::apply_steps(input.mesh, steps,
                                         apply_options(bar, LoopWeights::Warren));
                    } catch (const ops::OpError& e) {
                        rethrow_with_file(e, s->in);
                    }
                }
                IoFlags flags;
                flags.ascii = s->ascii;
                write_output(input.mesh, s->out, flags);
                return 0;
            }};
}

Command add_subdivide(CLI::App& meshedit) {
    struct Settings {
        std::filesystem::path in, out;
        int levels = 0;
        std::string weights = "warren";
        std::string scheme = "loop";
        std::string uv;  // empty: the core's default (corners)
        int density = 8;
    };
    auto s = std::make_shared<Settings>();
    CLI::App* app =
        meshedit.add_subcommand("subdivide", "Loop, Catmull-Clark or linear subdivision, K levels");
    app->add_option("IN", s->in, "the input file")->required();
    app->add_option("OUT", s->out, "the output file")->required();
    app->add_option("-n", s->levels, "number of levels, 0 to 12 (required)")
        ->type_name("K")
        ->required()
        ->check(CLI::Range(0, 12));
    app->add_option("--weights", s->weights,
                    "warren: u = 3/16 for valence 3, else 3/(8n) (the default, as in "
                    "CS184); loop: Loop's original weights")
        ->type_name("W")
        ->check(CLI::IsMember({"warren", "loop"}));
    app->add_option("--scheme", s->scheme,
                    "loop (the default: triangles only), catmull-clark (any polygons, "
                    "OpenSubdiv's Catmark rules) or linear (Catmull-Clark's faces, no "
                    "smoothing)")
        ->type_name("S")
        ->check(CLI::IsMember({"loop", "catmull-clark", "linear"}));
    app->add_option("--uv-interpolation", s->uv,
                    "how texture coordinates are refined, OpenSubdiv's face-varying options: "
                    "none (smooth everywhere), corners (the default: chart corners stay), "
                    "corners+1, corners+2, boundaries (linear along seams and boundaries) "
                    "or all (linear)")
        ->type_name("U")
        ->check([](const std::string& name) -> std::string {
            if (parse_uv_interpolation(name)) {
                return {};
            }
            return "unknown texture-coordinate interpolation '" + name + "' (one of " +
                   uv_interpolation_names() + ")";
        });
    add_density_option(*app, s->density);
    add_strict_option(*app);
    app->footer(
        "Subdivides IN K times and writes OUT. Loop turns every triangle into four each\n"
        "time and refuses polygons (triangulate first: `meshedit convert --ops triangulate`).\n"
        "Catmull-Clark and linear turn a face of k corners into k quads, then every quad into\n"
        "four. Boundary and crease edges (\"e:crease\", stored in MeshEdit's COLLADA <extra>)\n"
        "stay sharp; docs/subdivision.md has the rules.\n"
        "\n"
        "Examples:\n"
        "  meshedit subdivide dae/cube.dae cube2.dae -n 2\n"
        "  meshedit subdivide dae/quadball.dae smooth.dae -n 2 --scheme catmull-clark\n"
        "  meshedit subdivide textured.obj smooth.obj -n 2 --scheme catmull-clark \\\n"
        "      --uv-interpolation boundaries\n"
        "\n"
        "Exit status: 0 ok, 1 a level that does not fit, 2 bad usage, bad input or an\n"
        "unwritable output.");
    return {app, [s] {
                const LoopWeights weights =
                    s->weights == "warren" ? LoopWeights::Warren : LoopWeights::Loop;
                return run_one_step(
                    s->in, s->out, s->density, "subdivide", weights,
                    [&](const Mesh&) -> std::optional<ops::Step> {
                        if (s->levels == 0) {
                            return std::nullopt;
                        }
                        // --scheme's spelling (a hyphen, as the other options) → the verb's.
                        std::string verb = s->scheme;
                        std::replace(verb.begin(), verb.end(), '-', '_');
                        return ops::parse_step(verb + ":" + std::to_string(s->levels) +
                                               (s->uv.empty() ? "" : ":uv=" + s->uv));
                    });
            }};
}

Command add_simplify(CLI::App& meshedit) {
    struct Settings {
        std::filesystem::path in, out;
        std::size_t faces = 0;
        double ratio = 0.0;
        double max_error = std::numeric_limits<double>::infinity();
        double feature_angle = kNoFeatureAngle;
        std::string attributes;
        int density = 8;
    };
    auto s = std::make_shared<Settings>();
    CLI::App* app = meshedit.add_subcommand("simplify", "QEM simplification to N faces");
    app->add_option("IN", s->in, "the input file (triangles)")->required();
    app->add_option("OUT", s->out, "the output file")->required();
    auto* faces = app->add_option("--faces", s->faces, "keep at most N faces")->type_name("N");
    auto* ratio = app->add_option("--ratio", s->ratio, "keep about R of the faces, 0 < R < 1")
                      ->type_name("R");
    faces->excludes(ratio);
    app->add_option("--max-error", s->max_error,
                    "stop before a collapse whose error exceeds E × the bounding-box diagonal "
                    "(default: no bound)")
        ->type_name("E")
        ->check(CLI::NonNegativeNumber);
    add_feature_angle_option(*app, s->feature_angle);
    app->add_option("--attributes", s->attributes,
                    "aware (default): UV seams and material borders held, no UV triangle turned "
                    "over, UVs and colours weighed; blind: positions only")
        ->type_name("aware|blind")
        ->check(CLI::IsMember({"aware", "blind"}));
    add_density_option(*app, s->density);
    add_strict_option(*app);
    app->footer(
        "Simplifies IN by edge collapses, cheapest quadric error first (Garland-Heckbert:\n"
        "area-weighted plane quadrics, boundaries and creases held, the survivor at the\n"
        "point of least error, no face turned over), until it has --faces N faces (or --ratio R\n"
        "of them) or the next collapse would exceed --max-error, and writes OUT.\n"
        "--feature-angle DEG marks the edges sharper than DEG degrees as creases first; crease\n"
        "vertices stay on their creases.\n"
        "With texture coordinates, vertex colours or materials, --attributes aware (the\n"
        "default) keeps UV seams and material borders, turns no UV triangle over and puts\n"
        "each new corner's UV and colour where the attribute quadric is least.\n"
        "docs/simplify.md has the details.\n"
        "\n"
        "Example:\n"
        "  meshedit simplify dae/teapot.dae small.dae --ratio 0.1\n"
        "\n"
        "Exit status: 0 ok, 1 refused (polygons, a target out of range), 2 bad usage, bad\n"
        "input or an unwritable output.");
    return {
        app, [s, faces, ratio] {
            if (faces->count() == 0 && ratio->count() == 0) {
                throw UsageError("simplify: give --faces N or --ratio R");
            }
            if (ratio->count() > 0 && !(s->ratio > 0.0 && s->ratio < 1.0)) {
                throw UsageError("simplify: --ratio must be above 0 and below 1, not " +
                                 ratio->as<std::string>());
            }
            // Through the language, as `--ops simplify:R,E`: one rounding of a share into a
            // face count, one refusal and one "stopped at" message for every program.
            const double kept = faces->count() > 0 ? static_cast<double>(s->faces) : s->ratio;
            return run_one_step(
                s->in, s->out, s->density, "simplify", LoopWeights::Warren, [&](const Mesh& mesh) {
                    ops::Step step =
                        ops::make_step("simplify", mesh, ElementRef{},
                                       std::array<double, 3>{kept, s->max_error, s->feature_angle});
                    if (!s->attributes.empty()) {
                        step = ops::parse_step(step.text + ":attributes=" + s->attributes);
                    }
                    return std::optional(step);
                });
        }};
}

Command add_remesh(CLI::App& meshedit) {
    struct Settings {
        std::filesystem::path in, out;
        double length = 0.0;
        int iterations = 3;
        double feature_angle = kNoFeatureAngle;
        int density = 8;
    };
    auto s = std::make_shared<Settings>();
    CLI::App* app = meshedit.add_subcommand("remesh", "isotropic remeshing toward one edge length");
    app->add_option("IN", s->in, "the input file (triangles)")->required();
    app->add_option("OUT", s->out, "the output file")->required();
    app->add_option("--length", s->length, "the target edge length (default: the mean)")
        ->type_name("L");
    app->add_option("--iterations", s->iterations, "rounds, 1 to 100 (default 3)")->type_name("N");
    add_feature_angle_option(*app, s->feature_angle);
    add_density_option(*app, s->density);
    add_strict_option(*app);
    app->footer(
        "Remeshes IN toward edges of length L (Botsch-Kobbelt: split edges longer than 4/3 L,\n"
        "collapse those shorter than 4/5 L, flip toward valence 6, smooth tangentially and\n"
        "project onto the input surface, N times) and writes OUT. Boundaries and creases are\n"
        "kept; --feature-angle 40 marks the edges sharper than 40 degrees as creases first, so\n"
        "the sharp edges of a file without crease marks (OFF, STL) stay sharp and straight.\n"
        "docs/remesh.md has the details.\n"
        "\n"
        "Example:\n"
        "  meshedit remesh dae/teapot.dae even.dae --length 0.15\n"
        "\n"
        "Exit status: 0 ok, 1 refused (polygons, a length that would make too many triangles,\n"
        "iterations out of range), 2 bad usage, bad input or an unwritable output.");
    return {app, [s] {
                return run_one_step(
                    s->in, s->out, s->density, "remesh", LoopWeights::Warren,
                    [&](const Mesh& mesh) {
                        return std::optional(ops::make_step(
                            "remesh", mesh, ElementRef{},
                            std::array<double, 3>{s->length, static_cast<double>(s->iterations),
                                                  s->feature_angle}));
                    });
            }};
}

Command add_check(CLI::App& meshedit) {
    struct Settings {
        std::filesystem::path file;
        int density = 8;
        bool problems = false;
        bool json = false;
    };
    auto s = std::make_shared<Settings>();
    CLI::App* app = meshedit.add_subcommand("check", "validate the halfedge invariants");
    app->add_option("FILE", s->file, "the file to check")->required();
    add_density_option(*app, s->density);
    auto* problems = app->add_flag(
        "--problems", s->problems,
        "list what is wrong beyond the invariants: the loader's cuts, holes, degenerate faces, "
        "parts inside out, small parts, faces that pass through each other");
    app->add_flag("--json", s->json, "with --problems: one JSON object")->needs(problems);
    app->footer(
        "Loads FILE (a mesh, a .bez tessellated at --density, or a .bzc curve) and checks every\n"
        "halfedge invariant (docs/halfedge.md). Prints \"FILE: OK\" with the counts, or the\n"
        "first broken invariant and its element. Repairs the loader made are listed as notes\n"
        "on stderr. With --problems it lists, one line each, what else is wrong and where\n"
        "(the viewer's Problems panel lists the same), and exits 1 when anything is.\n"
        "\n"
        "Exit status: 0 valid (and, with --problems, nothing wrong), 1 the mesh breaks an\n"
        "invariant (or has problems), 2 bad usage or a file that cannot be read.");
    return {app, [s] {
                const std::filesystem::path& path = s->file;
                ReadOptions options;
                options.density = s->density;
                const LoadedDocument input = read_document(path, options);
                if (input.kind == DocumentKind::Curve) {
                    // A curve has no invariants beyond what read_bzc() checks (N ≥ 2, finite
                    // points).
                    std::printf("%s: OK (Bezier curve, %zu points, degree %d)\n",
                                path.string().c_str(), input.curve.control_points.size(),
                                input.curve.degree());
                    return 0;
                }
                print_load_messages(input);
                if (s->problems) {
                    return print_problems(path, input, s->json);
                }
                if (input.repairs.repaired()) {
                    // One note line however many kinds of repair the summary lists.
                    std::string summary = input.repairs.summary();
                    while (!summary.empty() && summary.back() == '\n') {
                        summary.pop_back();
                    }
                    for (std::size_t at = summary.find('\n'); at != std::string::npos;
                         at = summary.find('\n', at)) {
                        summary.replace(at, 1, "; ");
                    }
                    print_notice(path.string() + ": repaired on load: " + summary);
                }
                if (const auto error = validate(input.mesh)) {
                    std::printf("%s: INVALID: %s [%s]\n", path.string().c_str(),
                                error->message.c_str(), error->invariant.c_str());
                    return 1;
                }
                std::printf("%s: OK (%zu vertices, %zu edges, %zu faces)\n", path.string().c_str(),
                            input.mesh.n_vertices(), input.mesh.n_edges(), input.mesh.n_faces());
                return 0;
            }};
}

}  // namespace meshedit::cli
