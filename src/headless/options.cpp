// meshedit-render's command line on CLI11, and the --select syntax.

#include "options.h"

#include "meshedit/core/fields.h"
#include "meshedit/io/io.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "command_line.h"
#include "gl_context.h"
#include "meshedit/overlay/shading.h"

namespace meshedit::headless {
namespace {

template <class T>
T parse_number(std::string_view text, std::string_view what) {
    T value{};
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || text.empty()) {
        throw UsageError("bad " + std::string(what) + " '" + std::string(text) + "'");
    }
    if constexpr (std::is_floating_point_v<T>) {
        // from_chars reads "nan" and "inf", and 1e39 as a float is infinite: a camera there
        // draws a blank image.
        if (!std::isfinite(value)) {
            throw UsageError("bad " + std::string(what) + " '" + std::string(text) +
                             "': not a finite number");
        }
    }
    return value;
}

// A CLI11 check: a finite number from `lo` to `hi` (CLI::Range lets NaN through).
CLI::Validator finite_range(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](const std::string& text) -> std::string {
            double value = 0.0;
            const char* end = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(text.data(), end, value);
            if (ec != std::errc() || ptr != end || !std::isfinite(value) || value < lo ||
                value > hi) {
                char range[64];
                std::snprintf(range, sizeof range, "%g to %g", lo, hi);
                return "'" + text + "' is not a number from " + std::string(range);
            }
            return {};
        },
        "");
}

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t at = text.find(separator, start);
        parts.push_back(text.substr(start, at - start));
        if (at == std::string_view::npos) {
            return parts;
        }
        start = at + 1;
    }
}

std::string shading_table() {
    std::string table;
    for (const ShadingMode& mode : kShadingModes) {
        char line[160];
        std::snprintf(line, sizeof line, "\n  %d %-10s %s", mode.number,
                      std::string(mode.name).c_str(), std::string(mode.description).c_str());
        table += line;
    }
    return table;
}

// The values of the options that take text: checked after parsing, with the words the
// program has always used.
struct Raw {
    std::string size, shading, camera, pick, color;
};

void finish(const Raw& raw, Options& o) {
    if (!raw.size.empty()) {
        const auto parts = split(raw.size, 'x');
        if (parts.size() != 2) {
            throw UsageError("--size wants WxH, got '" + raw.size + "'");
        }
        o.width = parse_number<int>(parts[0], "width");
        o.height = parse_number<int>(parts[1], "height");
        if (o.width < 1 || o.height < 1 || o.width > 8192 || o.height > 8192) {
            throw UsageError("--size out of range (1..8192): '" + raw.size + "'");
        }
    }
    if (!raw.shading.empty()) {
        const auto mode = find_shading_mode(raw.shading);
        if (!mode) {
            throw UsageError("unknown shading mode '" + raw.shading + "' (see --help)");
        }
        o.shading = mode->number;
    }
    if (!raw.color.empty()) {
        const auto color = find_surface_color(raw.color);
        if (!color) {
            throw UsageError("unknown surface colour '" + raw.color + "' (see --help)");
        }
        o.color = color->color;
    }
    if (!raw.camera.empty()) {
        const auto parts = split(raw.camera, ',');
        if (parts.size() != 2 && parts.size() != 3) {
            throw UsageError("--camera wants AZ,EL[,DIST], got '" + raw.camera + "'");
        }
        o.azimuth = parse_number<float>(parts[0], "azimuth");
        o.elevation = parse_number<float>(parts[1], "elevation");
        if (parts.size() == 3) {
            o.distance = parse_number<float>(parts[2], "distance");
            if (!(*o.distance > 0.0f)) {
                throw UsageError("--camera distance must be positive");
            }
        }
    }
    if (!raw.pick.empty()) {
        const auto parts = split(raw.pick, ',');
        if (parts.size() != 2) {
            throw UsageError("--pick wants X,Y");
        }
        o.pick = std::pair(parse_number<int>(parts[0], "x"), parse_number<int>(parts[1], "y"));
    }
}

}  // namespace

int parse_options(int argc, char** argv, Options& o) {
    CLI::App app(
        "Renders FILE headless (EGL or OSMesa, OpenGL 3.3 core) to a PNG, with the viewer's "
        "renderer and shaders. Same command, same bytes.",
        "meshedit-render");
    command_line::style(app);
    Raw raw;
    app.add_option("FILE", o.input,
                   "a mesh (" + meshedit::mesh_extension_list(" ") +
                       ": smooth shaded, boundary and crease edges drawn), Bezier patches (.bez, "
                       "tessellated) or a Bezier curve (.bzc, in the "
                       "[0,1]^2 square)")
        ->required();
    app.add_option("-o,--output", o.output, "the image to write")->type_name("OUT.png")->required();
    app.add_option("--size", raw.size, "image size in pixels (default 512x384)")->type_name("WxH");
    app.add_option("--ops", o.ops,
                   "edits before drawing, e.g. flip:0-6,split:1-2,loop:2, or @FILE (a session "
                   "file)")
        ->type_name("LIST");
    app.add_option("--shading", raw.shading, "name or number (default phong):" + shading_table())
        ->type_name("MODE");
    std::string colors;
    for (const SurfaceColorMode& mode : kSurfaceColors) {
        colors += "\n  " + std::string(mode.name) + ": " + std::string(mode.description);
    }
    app.add_option("--color", raw.color,
                   "where the surface colour comes from (default auto):" + colors)
        ->type_name("FROM");
    app.add_flag_callback(
        "--smooth", [&o] { o.smooth = true; }, "area-weighted vertex normals (the default)");
    app.add_flag_callback(
        "--flat", [&o] { o.smooth = false; }, "face normals");
    app.add_flag("--wireframe", o.wireframe, "draw the edges over the surface");
    app.add_option("--camera", raw.camera,
                   "orbit angles in degrees and distance to the bounding-box centre (default "
                   "30,20 at the distance that frames the box)")
        ->type_name("AZ,EL[,DIST]");
    app.add_option_function<std::string>(
           "--up", [&o](const std::string& v) { o.up = v == "z" ? UpAxis::Z : UpAxis::Y; },
           "which axis is up: y, z (the CS184 course's models), or file (the file's declared "
           "axis, +Y once read; the default); --camera's angles turn about it")
        ->type_name("y|z|file")
        ->check(CLI::IsMember({"y", "z", "file"}));
    app.add_option("--select", o.select,
                   "highlight a vertex, the edge A-B, the halfedge A->B, a face, what the "
                   "last step of --ops made (result), or the selection --ops carries at its "
                   "end (sel: what its select verbs chose)")
        ->option_text("vI|A-B|hA-B|fI|result|sel");
    app.add_option_function<std::string>(
           "--stencil",
           [&o](const std::string& v) {
               // IsMember below admits these three spellings only.
               o.stencil = v == "catmull-clark"   ? StencilScheme::CatmullClark
                           : v == "loop-original" ? StencilScheme::LoopOriginal
                                                  : StencilScheme::LoopWarren;
           },
           "draw the --select element's subdivision stencil: its vertices with their weights "
           "(loop: Warren's weights, as L; loop-original: Loop's; catmull-clark: as Shift+C)")
        ->type_name("loop|loop-original|catmull-clark")
        ->check(CLI::IsMember({"loop", "loop-original", "catmull-clark"}));
    app.add_option_function<std::string>(
           "--patch-steps",
           [&o](const std::string& text) {
               std::array<double, 4> a{};
               char c1 = 0, c2 = 0, c3 = 0;
               std::istringstream in(text);
               if (!(in >> a[0] >> c1 >> a[1] >> c2 >> a[2] >> c3 >> a[3]) || c1 != ',' ||
                   c2 != ',' || c3 != ',' || !(in >> std::ws).eof() || a[0] < 0 ||
                   a[0] != std::floor(a[0]) || a[3] < 0 || a[3] != std::floor(a[3]) ||
                   !(a[1] >= 0 && a[1] <= 1 && a[2] >= 0 && a[2] <= 1)) {
                   throw CLI::ValidationError(
                       "--patch-steps",
                       "wants I,U,V,S: a patch index, u and v in [0, 1] and a "
                       "step (whole numbers from 0), got '" +
                           text + "'");
               }
               o.patch_steps = a;
           },
           ".bez: patch I evaluated at (U, V) by de Casteljau up to step S: along u on every "
           "row, then along v (docs/teaching.md)")
        ->type_name("I,U,V,S");
    app.add_flag("--problems", o.problems,
                 "marks what `meshedit check --problems` lists, as the viewer's Problems panel "
                 "does: load cuts, holes, degenerate faces, inside-out and small parts, faces "
                 "passing through each other (the cuts only without --ops)");
    app.add_flag("--marks-near", o.marks_near,
                 "a phased Loop's marks (--ops loop_step) only within two rings of the --select "
                 "element, as the viewer's Alt+N");
    app.add_option_function<double>(
           "--auto-smooth", [&o](double deg) { o.normals.auto_smooth_deg = deg; },
           "smooth shading also splits at edges whose faces turn by more than DEG degrees "
           "(Blender's Auto Smooth; crease edges always split)")
        ->type_name("DEG")
        ->check(finite_range(0.0, 180.0));
    app.add_flag_callback(
        "--no-crease-split", [&o] { o.normals.creases = false; },
        "smooth shading across crease edges too (as before crease-aware normals)");
    app.add_option("--envmap", o.envmap,
                   "shading 7's environment: an equirectangular PNG, JPEG, HDR or EXR (default: "
                   "a procedural studio)")
        ->type_name("FILE");
    app.add_option("--shader-dir", o.shader_dir,
                   "shading 8 and 9 load mesh8.frag and mesh9.frag from DIR (docs/shaders.md)")
        ->type_name("DIR");
    app.add_option("--exposure", o.exposure, "shading 7: the environment's brightness in stops")
        ->type_name("EV")
        ->check(finite_range(-16.0, 16.0));
    std::string field_names;
    for (const FieldInfo& info : field_infos()) {
        field_names += (field_names.empty() ? "" : "|") + std::string(info.name);
    }
    // Checked once the mesh is read: its own scalar properties are fields too (fields.h).
    app.add_option("--field", o.field,
                   "colour the surface by a scalar field, with its legend (docs/fields.md); "
                   "the mesh's own vertex or face numbers (a PLY column) are fields too")
        ->type_name(field_names + "|NAME");
    app.add_option_function<std::string>(
           "--colormap", [&o](const std::string& name) { o.colormap = find_colormap(name); },
           "the field's colour map (default: diverging for signed curvature, else viridis)")
        ->type_name("viridis|magma|diverging")
        ->check(CLI::IsMember({"viridis", "magma", "diverging"}));
    app.add_option_function<std::string>(
           "--field-source",
           [&o](const std::string& v) {
               std::uint32_t index = 0;
               const char* end = v.data() + v.size();
               if (v.size() < 2 || v[0] != 'v' ||
                   std::from_chars(v.data() + 1, end, index).ptr != end) {
                   throw CLI::ValidationError("--field-source", "wants vI, got '" + v + "'");
               }
               o.field_source = index;
           },
           "--field distance: the vertex it is measured from (default v0)")
        ->type_name("vI");
    app.add_flag("--op-diagram", o.op_diagram,
                 "draw what the last step of --ops rewired instead of the mesh: its "
                 "neighbourhood before and after, halfedges named as in its code "
                 "(docs/teaching.md)");
    app.add_flag_callback(
        "--features", [&o] { o.features = true; },
        "boundary (red) and crease (green) edges: on by default for mesh "
        "files, off for .bez");
    app.add_flag_callback(
        "--no-features", [&o] { o.features = false; }, "no boundary or crease edges");
    app.add_option("--density", o.density, ".bez: quads per patch side, 1 to 256 (default 8)")
        ->type_name("N")
        ->check(CLI::Range(1, 256));
    app.add_flag("--net", o.net, ".bez: draw the control nets");
    app.add_option("--t", o.t, ".bzc: the de Casteljau parameter (default 0.5)")
        ->type_name("T")
        ->check(finite_range(0.0, 1.0));
    app.add_option("--level", o.level, ".bzc: draw levels 0..K only (default all, with B(t))")
        ->type_name("K");
    app.add_flag_callback(
        "--no-curve", [&o] { o.curve = false; }, ".bzc: hide the full curve");
    app.add_option("--samples", o.samples, "multisampling (default 4; 1 = off)")
        ->type_name("N")
        ->check(CLI::Range(1, 64));
    app.add_option("--pick", raw.pick, "also print the element under pixel (X, Y) (ID pass)")
        ->type_name("X,Y");
    app.add_option_function<std::string>(
           "--backend",
           [&o](const std::string& v) {
               o.backend = v == "egl"      ? Backend::Egl
                           : v == "osmesa" ? Backend::OsMesa
                                           : Backend::Auto;
           },
           "where the GL context comes from: egl (a GPU's EGL device, else Mesa's surfaceless "
           "platform), osmesa, or auto (EGL if it gives a context, else OSMesa; the default)")
        ->type_name("auto|egl|osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    app.add_option("--device", o.device,
                   "render on EGL device N, as --verbose lists them (default: the first GPU, "
                   "else Mesa's surfaceless platform)")
        ->type_name("N")
        ->check(CLI::NonNegativeNumber);
    app.add_flag("--verbose", o.verbose,
                 "say on stderr which backend, EGL device and GL renderer drew the image");
    std::string backends;
    for (const std::string& name : compiled_backends()) {
        backends += (backends.empty() ? "" : " ") + name;
    }
    app.set_version_flag("--version", std::string("meshedit-render ") + MESHEDIT_VERSION +
                                          "\nbackends: " + backends);
    app.add_flag("--timings", o.timings, "print the time of each phase on stderr");
    command_line::add_memory_budget_option(app);
    const CLI::Option* threads = command_line::add_threads_option(app);
    app.add_option("--benchmark", o.benchmark,
                   "also draw N times shaded and N times with a trivial shader (glFinish each) "
                   "and print both medians in ms on stdout")
        ->type_name("N")
        ->check(CLI::PositiveNumber);
    app.footer(
        "Also run as 'meshedit render FILE -o OUT.png …'.\n"
        "Exit status: 0 success, 1 GL failure or refused op, 2 bad usage or input.");
    // The test suites run once per backend by setting this (tests/render/CMakeLists.txt).
    if (const char* env = std::getenv("MESHEDIT_RENDER_BACKEND"); env != nullptr && *env != 0) {
        const std::string name = env;
        if (name != "auto" && name != "egl" && name != "osmesa") {
            throw UsageError("MESHEDIT_RENDER_BACKEND=" + name + ": wants auto, egl or osmesa");
        }
        o.backend = name == "egl"      ? Backend::Egl
                    : name == "osmesa" ? Backend::OsMesa
                                       : Backend::Auto;
    }
    if (const int status = command_line::parse(app, argc, argv, program_name()); status >= 0) {
        return status;
    }
    // --threads wins over the variable, which is only checked when it is used.
    if (const auto problem = thread_environment_problem(); problem && threads->count() == 0) {
        throw UsageError(*problem);
    }
    finish(raw, o);
    return -1;
}

// "v12", "3-4", "h3-4", "f7" (or the older "v:12", "e:3-4", "h:3-4", "f:7": the edit
// language's grammar, ops::parse_element_name()) → an element of `mesh`.
ElementRef parse_selection(const Mesh& mesh, const std::string& spec) {
    const std::optional<ops::ElementName> name = ops::parse_element_name(spec);
    if (!name) {
        throw UsageError("--select wants vI, A-B, hA-B, fI, result or sel, got '" + spec + "'");
    }
    const auto index = [&](std::uint32_t i, std::size_t size, const char* what) {
        if (i >= size) {
            throw UsageError("--select " + spec + ": no " + what + " " + std::to_string(i) +
                             " (the mesh has " + std::to_string(size) + ")");
        }
        return i;
    };
    switch (name->kind) {
        case ElementRef::Kind::Vertex: {
            const Vertex v(index(name->a, mesh.vertices_size(), "vertex"));
            if (mesh.is_deleted(v)) {
                throw UsageError("--select " + spec + ": the vertex is deleted");
            }
            return ElementRef::vertex(v);
        }
        case ElementRef::Kind::Face: {
            const Face f(index(name->a, mesh.faces_size(), "face"));
            if (mesh.is_deleted(f)) {
                throw UsageError("--select " + spec + ": the face is deleted");
            }
            return ElementRef::face(f);
        }
        default:
            break;
    }
    const Vertex a(index(name->a, mesh.vertices_size(), "vertex"));
    const Vertex b(index(name->b, mesh.vertices_size(), "vertex"));
    const Halfedge h =
        mesh.is_deleted(a) || mesh.is_deleted(b) ? Halfedge() : mesh.find_halfedge(a, b);
    if (!h.is_valid()) {
        throw UsageError("--select " + spec + ": no edge joins vertices " +
                         std::to_string(name->a) + " and " + std::to_string(name->b));
    }
    return name->kind == ElementRef::Kind::Edge ? ElementRef::edge(Mesh::edge(h))
                                                : ElementRef::halfedge(h);
}

}  // namespace meshedit::headless
