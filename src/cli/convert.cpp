// `meshedit convert`, `meshedit subdivide` and `meshedit check`: the commands that load a
// mesh, maybe change it, and write or judge it.

#include <cstdio>
#include <string>

#include "cli.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/validate.h"
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

// Refuses an output we cannot write before doing any work, so a typo in the output name
// does not cost a long subdivision first.
void check_mesh_output(const std::filesystem::path& out) {
    if (!is_mesh_extension(file_extension(out))) {
        throw IoError(out.string(), "",
                      "unknown extension '" + out.extension().string() +
                          "' (meshedit writes .dae, .gltf, .glb and .obj)");
    }
}

int density_option(const Args& args) {
    return args.value("--density") != nullptr
               ? parse_int(*args.value("--density"), "--density", 1, 256)
               : TessellationOptions{}.density;
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

}  // namespace

int run_convert(const std::vector<std::string>& argv) {
    const Args args = parse_args("convert", argv, {{"--ops", true}, {"--density", true}});
    if (args.help) {
        std::printf(
            "usage: meshedit convert IN OUT [--ops LIST] [--density N]\n"
            "\n"
            "Reads IN (.dae .gltf .glb .obj, or .bez tessellated at --density N, default 8),\n"
            "applies the --ops edits in order and writes OUT in the format of its extension\n"
            "(.dae .gltf .glb .obj). A .bzc curve converts only to .bzc. OUT is written to a\n"
            "temporary file and renamed, so a failed run never leaves a partial OUT.\n"
            "\n"
            "  --ops LIST   comma list of these steps, run in order (an edge is named by the\n"
            "               indices of its two vertices, as numbered in the file):\n"
            "%s"
            "\n"
            "Examples:\n"
            "  meshedit convert dae/cube.dae cube.obj\n"
            "  meshedit convert dae/cube.dae out.dae --ops flip:0-6,split:0-1,loop:2\n"
            "\n"
            "Exit status: 0 ok, 1 an op was refused, 2 bad usage, bad input, a named edge\n"
            "that does not exist, or an unwritable output.\n",
            ops::help_lines().c_str());
        return 0;
    }
    expect_positionals("convert", args, 2, "IN and OUT");
    const std::filesystem::path in = args.positional[0];
    const std::filesystem::path out = args.positional[1];
    std::vector<ops::Step> steps;
    if (const std::string* list = args.value("--ops")) {
        try {
            steps = ops::parse(*list);
        } catch (const ops::SyntaxError& e) {
            throw UsageError(std::string("convert: ") + e.what());
        }
    }

    if (file_extension(in) == ".bzc" && file_extension(out) == ".bzc") {
        if (!steps.empty()) {
            throw UsageError("convert: --ops applies to meshes, not to a .bzc curve");
        }
        write_bzc(read_bzc(in), out);
        return 0;
    }
    check_mesh_output(out);
    LoadedDocument input = load_surface(in, density_option(args));
    print_load_messages(input);
    {
        ProgressBar bar("convert");
        try {
            ops::apply_steps(input.mesh, steps, apply_options(bar, LoopWeights::Warren));
        } catch (const ops::OpError& e) {
            rethrow_with_file(e, in);
        }
    }
    write_mesh(input.mesh, out);
    return 0;
}

int run_subdivide(const std::vector<std::string>& argv) {
    const Args args =
        parse_args("subdivide", argv, {{"-n", true}, {"--weights", true}, {"--density", true}});
    if (args.help) {
        std::printf(
            "usage: meshedit subdivide IN OUT -n K [--weights warren|loop] [--density N]\n"
            "\n"
            "Loop-subdivides IN K times (every triangle becomes four each time) and writes\n"
            "OUT. Non-triangle faces are triangulated first, with a note. Boundary and crease\n"
            "edges (\"e:crease\", stored in MeshEdit's COLLADA <extra>) stay sharp.\n"
            "\n"
            "  -n K                number of levels, 0 to 12\n"
            "  --weights warren    u = 3/16 for valence 3, else 3/(8n) (default, as in CS184)\n"
            "  --weights loop      Loop's original weights\n"
            "  --density N         tessellation density when IN is a .bez (default 8)\n"
            "\n"
            "Example:\n"
            "  meshedit subdivide dae/cube.dae cube2.dae -n 2\n"
            "\n"
            "Exit status: 0 ok, 2 bad usage, bad input or an unwritable output.\n");
        return 0;
    }
    expect_positionals("subdivide", args, 2, "IN and OUT");
    if (args.value("-n") == nullptr) {
        throw UsageError("subdivide: missing -n K (see meshedit subdivide --help)");
    }
    const int levels = parse_int(*args.value("-n"), "-n", 0, 12);
    LoopWeights weights = LoopWeights::Warren;
    if (const std::string* w = args.value("--weights")) {
        if (*w == "loop") {
            weights = LoopWeights::Loop;
        } else if (*w != "warren") {
            throw UsageError("subdivide: bad value '" + *w +
                             "' for --weights (expected warren or loop)");
        }
    }
    const std::filesystem::path in = args.positional[0];
    const std::filesystem::path out = args.positional[1];
    check_mesh_output(out);
    LoadedDocument input = load_surface(in, density_option(args));
    print_load_messages(input);
    if (levels > 0) {
        const ops::Step loop = ops::parse_step("loop:" + std::to_string(levels));
        ProgressBar bar("subdivide");
        try {
            ops::apply_steps(input.mesh, {loop}, apply_options(bar, weights));
        } catch (const ops::OpError& e) {
            rethrow_with_file(e, in);
        }
    }
    write_mesh(input.mesh, out);
    return 0;
}

int run_check(const std::vector<std::string>& argv) {
    const Args args = parse_args("check", argv, {{"--density", true}});
    if (args.help) {
        std::printf(
            "usage: meshedit check FILE [--density N]\n"
            "\n"
            "Loads FILE (a mesh, a .bez tessellated at --density N, or a .bzc curve) and\n"
            "checks every halfedge invariant (docs/halfedge.md). Prints\n"
            "\"FILE: OK\" with the counts, or the first broken invariant and its element.\n"
            "Repairs the loader made are listed as notes on stderr.\n"
            "\n"
            "Exit status: 0 valid, 1 the mesh breaks an invariant, 2 bad usage or a file\n"
            "that cannot be read.\n");
        return 0;
    }
    expect_positionals("check", args, 1, "FILE");
    const std::filesystem::path path = args.positional[0];
    if (file_extension(path) == ".bzc") {
        // A curve has no invariants beyond what read_bzc() checks (N ≥ 2, finite points).
        const BezierCurve curve = read_bzc(path);
        std::printf("%s: OK (Bezier curve, %zu points, degree %d)\n", path.string().c_str(),
                    curve.control_points.size(), curve.degree());
        return 0;
    }
    const LoadedDocument input = load_surface(path, density_option(args));
    print_load_messages(input);
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
        std::printf("%s: INVALID: %s [%s]\n", path.string().c_str(), error->message.c_str(),
                    error->invariant.c_str());
        return 1;
    }
    std::printf("%s: OK (%zu vertices, %zu edges, %zu faces)\n", path.string().c_str(),
                input.mesh.n_vertices(), input.mesh.n_edges(), input.mesh.n_faces());
    return 0;
}

}  // namespace meshedit::cli
