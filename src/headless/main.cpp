// `meshedit-render` (also `meshedit render`): renders a mesh, Bezier surface or Bezier curve
// to PNG through OSMesa with the same renderer and shaders as the viewer. Errors are one
// line "meshedit-render: <message>"; exit 2 for bad usage or input, 1 for GL failures and
// refused ops (docs/rendering.md).

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/files/io_error.h"
#include "meshedit/io/document.h"
#include "meshedit/ops/ops.h"
#include "meshedit/render/camera.h"
#include "meshedit/render/mesh_renderer.h"
#include "meshedit/render/overlay.h"
#include "meshedit/render/overlay_renderer.h"
#include "meshedit/render/render_target.h"
#include "meshedit/render/shader_program.h"
#include "meshedit/render/shading.h"
#include "osmesa_context.h"

namespace {

using namespace meshedit;

constexpr const char* kUsage =
    "usage: meshedit-render FILE -o OUT.png [options]\n"
    "       (also run as 'meshedit render FILE -o OUT.png …')\n"
    "\n"
    "Renders FILE headless (OSMesa, OpenGL 3.3 core) to a PNG. Same command, same bytes.\n"
    "  FILE .dae .gltf .glb .obj   a mesh (smooth shaded, boundary/crease edges drawn)\n"
    "  FILE .bez                   Bezier patches, tessellated (smooth shaded)\n"
    "  FILE .bzc                   a Bezier curve in the [0,1]^2 square (2D view)\n"
    "\n"
    "Options:\n"
    "  -o, --output OUT.png     the image to write (required)\n"
    "  --size WxH               image size in pixels (default 512x384)\n"
    "  --ops LIST               edits before drawing, e.g. flip:0-6,split:1-2,loop:2\n"
    "  --shading MODE           name or number (default phong):\n"
    "%s"
    "  --smooth | --flat        area-weighted vertex normals (default) or face normals\n"
    "  --wireframe              draw the edges over the surface\n"
    "  --camera AZ,EL[,DIST]    orbit angles in degrees and distance to the bounding-box\n"
    "                           centre (default 30,20 at the distance that frames the box)\n"
    "  --select v:I|e:A-B|h:A-B|f:I\n"
    "                           highlight a vertex, the edge A-B, the halfedge A->B, a face\n"
    "  --features | --no-features\n"
    "                           boundary (red) and crease (green) edges; on by default for\n"
    "                           mesh files, off for .bez\n"
    "  --density N              .bez: quads per patch side (default 8)\n"
    "  --net                    .bez: draw the control nets\n"
    "  --t T                    .bzc: the de Casteljau parameter (default 0.5)\n"
    "  --level K                .bzc: draw levels 0..K only (default all, with B(t))\n"
    "  --no-curve               .bzc: hide the full curve\n"
    "  --samples N              multisampling (default 4; 1 = off)\n"
    "  --pick X,Y               also print the element under pixel (X, Y) (ID pass)\n"
    "  --timings                print the time of each phase on stderr\n"
    "  --benchmark N            also draw N times shaded and N times with a trivial shader\n"
    "                           (glFinish each) and print both medians in ms on stdout\n"
    "  -h, --help               this help\n"
    "\n"
    "Exit status: 0 success, 1 GL failure or refused op, 2 bad usage or input.\n";

/// Bad usage or input: exit 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct Options {
    std::filesystem::path input;
    std::filesystem::path output;
    int width = 512;
    int height = 384;
    std::string ops;
    int shading = 1;
    std::optional<bool> smooth;
    bool wireframe = false;
    std::optional<float> azimuth, elevation, distance;
    std::string select;
    std::optional<bool> features;
    int density = 8;
    bool net = false;
    double t = 0.5;
    int level = -1;
    bool curve = true;
    int samples = 4;
    std::optional<std::pair<int, int>> pick;
    bool timings = false;
    int benchmark = 0;
};

template <class T>
T parse_number(std::string_view text, std::string_view what) {
    T value{};
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end || text.empty()) {
        throw UsageError("bad " + std::string(what) + " '" + std::string(text) + "'");
    }
    return value;
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
        std::snprintf(line, sizeof line, "                             %d %-10s %s\n", mode.number,
                      std::string(mode.name).c_str(), std::string(mode.description).c_str());
        table += line;
    }
    return table;
}

Options parse_args(int argc, char** argv) {
    Options options;
    std::vector<std::string> args(argv + 1, argv + argc);
    auto value = [&](std::size_t& i) -> const std::string& {
        if (i + 1 >= args.size()) {
            throw UsageError(args[i] + " needs a value");
        }
        return args[++i];
    };
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "-o" || a == "--output") {
            options.output = value(i);
        } else if (a == "--size") {
            const auto parts = split(value(i), 'x');
            if (parts.size() != 2) {
                throw UsageError("--size wants WxH, got '" + args[i] + "'");
            }
            options.width = parse_number<int>(parts[0], "width");
            options.height = parse_number<int>(parts[1], "height");
            if (options.width < 1 || options.height < 1 || options.width > 8192 ||
                options.height > 8192) {
                throw UsageError("--size out of range (1..8192): '" + args[i] + "'");
            }
        } else if (a == "--ops") {
            options.ops = value(i);
        } else if (a == "--shading") {
            const auto mode = find_shading_mode(value(i));
            if (!mode) {
                throw UsageError("unknown shading mode '" + args[i] + "' (see --help)");
            }
            options.shading = mode->number;
        } else if (a == "--smooth") {
            options.smooth = true;
        } else if (a == "--flat") {
            options.smooth = false;
        } else if (a == "--wireframe") {
            options.wireframe = true;
        } else if (a == "--camera") {
            const auto parts = split(value(i), ',');
            if (parts.size() != 2 && parts.size() != 3) {
                throw UsageError("--camera wants AZ,EL[,DIST], got '" + args[i] + "'");
            }
            options.azimuth = parse_number<float>(parts[0], "azimuth");
            options.elevation = parse_number<float>(parts[1], "elevation");
            if (parts.size() == 3) {
                options.distance = parse_number<float>(parts[2], "distance");
                if (!(*options.distance > 0.0f)) {
                    throw UsageError("--camera distance must be positive");
                }
            }
        } else if (a == "--select") {
            options.select = value(i);
        } else if (a == "--features") {
            options.features = true;
        } else if (a == "--no-features") {
            options.features = false;
        } else if (a == "--density") {
            options.density = parse_number<int>(value(i), "density");
            if (options.density < 1 || options.density > 256) {
                throw UsageError("--density must be in 1..256");
            }
        } else if (a == "--net") {
            options.net = true;
        } else if (a == "--t") {
            options.t = parse_number<double>(value(i), "t");
        } else if (a == "--level") {
            options.level = parse_number<int>(value(i), "level");
        } else if (a == "--no-curve") {
            options.curve = false;
        } else if (a == "--samples") {
            options.samples = parse_number<int>(value(i), "samples");
        } else if (a == "--timings") {
            options.timings = true;
        } else if (a == "--benchmark") {
            options.benchmark = parse_number<int>(value(i), "benchmark count");
            if (options.benchmark < 1) {
                throw UsageError("--benchmark wants a positive count");
            }
        } else if (a == "--pick") {
            const auto parts = split(value(i), ',');
            if (parts.size() != 2) {
                throw UsageError("--pick wants X,Y");
            }
            options.pick =
                std::pair(parse_number<int>(parts[0], "x"), parse_number<int>(parts[1], "y"));
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option '" + a + "' (see --help)");
        } else if (options.input.empty()) {
            options.input = a;
        } else {
            throw UsageError("unexpected argument '" + a + "'");
        }
    }
    if (options.input.empty()) {
        throw UsageError("no input file (see --help)");
    }
    if (options.output.empty()) {
        throw UsageError("no output file: give -o OUT.png");
    }
    return options;
}

std::uint32_t parse_index(std::string_view text, std::size_t size, const std::string& spec) {
    const auto index = parse_number<std::uint32_t>(text, "index in --select");
    if (index >= size) {
        throw UsageError("--select " + spec + ": index " + std::string(text) + " out of range (" +
                         std::to_string(size) + ")");
    }
    return index;
}

// "v:I", "e:A-B", "h:A-B", "f:I" → an element of `mesh`. \throws UsageError.
ElementRef parse_selection(const Mesh& mesh, const std::string& spec) {
    if (spec.size() < 3 || spec[1] != ':') {
        throw UsageError("--select wants v:I, e:A-B, h:A-B or f:I, got '" + spec + "'");
    }
    const std::string_view body = std::string_view(spec).substr(2);
    const char kind = spec[0];
    if (kind == 'v' || kind == 'f') {
        if (kind == 'v') {
            const Vertex v(parse_index(body, mesh.vertices_size(), spec));
            if (mesh.is_deleted(v)) {
                throw UsageError("--select " + spec + ": the vertex is deleted");
            }
            return ElementRef::vertex(v);
        }
        const Face f(parse_index(body, mesh.faces_size(), spec));
        if (mesh.is_deleted(f)) {
            throw UsageError("--select " + spec + ": the face is deleted");
        }
        return ElementRef::face(f);
    }
    if (kind != 'e' && kind != 'h') {
        throw UsageError("--select wants v:I, e:A-B, h:A-B or f:I, got '" + spec + "'");
    }
    const auto ends = split(body, '-');
    if (ends.size() != 2) {
        throw UsageError("--select " + spec + ": an edge is A-B (two vertex indices)");
    }
    const Vertex a(parse_index(ends[0], mesh.vertices_size(), spec));
    const Vertex b(parse_index(ends[1], mesh.vertices_size(), spec));
    const Halfedge h =
        mesh.is_deleted(a) || mesh.is_deleted(b) ? Halfedge() : mesh.find_halfedge(a, b);
    if (!h.is_valid()) {
        throw UsageError("--select " + spec + ": no edge joins vertices " + std::string(ends[0]) +
                         " and " + std::string(ends[1]));
    }
    return kind == 'e' ? ElementRef::edge(Mesh::edge(h)) : ElementRef::halfedge(h);
}

int run(const Options& options) {
    Clock::time_point phase = Clock::now();
    auto lap = [&](const char* name) {
        if (options.timings) {
            std::fprintf(stderr, "meshedit-render: %-9s %8.1f ms\n", name, ms_since(phase));
        }
        phase = Clock::now();
    };
    // Everything that can fail on bad input happens before the GL context exists.
    ReadOptions read;
    read.density = options.density;
    LoadedDocument doc = read_document(options.input, read);
    const bool is_curve = doc.kind == DocumentKind::Curve;
    const bool is_surface = doc.kind == DocumentKind::Surface;
    Mesh& mesh = doc.mesh;
    const BezierCurve& curve = doc.curve;
    const std::vector<BezierPatch>& patches = doc.patches;
    OverlayBatch overlay;
    const OverlayStyle style;
    if (is_curve) {
        if (!options.select.empty() || !options.ops.empty()) {
            throw UsageError("--select and --ops need a mesh or .bez file, not a curve");
        }
        add_unit_square(style, overlay);
        add_bezier_curve(curve, options.t, options.level, options.curve, style, overlay);
    } else {
        lap("load");
        if (!options.ops.empty()) {
            ops::apply_steps(mesh, ops::parse(options.ops));
            lap("ops");
        }
        if (options.features.value_or(!is_surface)) {
            add_feature_edges(mesh, style, overlay);
        }
        if (options.net && is_surface) {
            add_control_nets(patches, style, overlay);
        }
        if (!options.select.empty()) {
            add_element_highlight(mesh, parse_selection(mesh, options.select), style.selected,
                                  style, overlay);
        }
    }

    const int w = options.width;
    const int h = options.height;
    const float aspect = static_cast<float>(w) / static_cast<float>(h);
    Camera camera;
    if (is_curve) {
        camera.frame_2d({0.0f, 0.0f}, {1.0f, 1.0f}, aspect);
    } else {
        camera.azimuth_deg = options.azimuth.value_or(30.0f);
        camera.elevation_deg = options.elevation.value_or(20.0f);
        // The control points count too when the nets are drawn.
        std::vector<Vec3> control_points;
        if (options.net) {
            for (const auto& patch : patches) {
                control_points.insert(control_points.end(), patch.control_points.begin(),
                                      patch.control_points.end());
            }
        }
        camera.frame_mesh(mesh, aspect, control_points);
        if (options.distance) {
            camera.distance = *options.distance;
        }
    }

    lap("overlay");
    headless::OsMesaContext context(w, h);
    RenderTarget target(w, h, options.samples);
    target.bind();
    lap("context");
    BackgroundRenderer background;
    MeshRenderer mesh_renderer;
    OverlayRenderer overlay_renderer;
    RenderOptions render_options;
    render_options.shading = options.shading;
    render_options.smooth = options.smooth.value_or(true);
    render_options.wireframe = options.wireframe;
    if (!is_curve) {
        mesh_renderer.upload(mesh);
    }
    overlay_renderer.upload(overlay);
    context.finish();
    lap("upload");
    auto draw_frame = [&] {
        if (is_curve) {
            const float paper[3] = {0.97f, 0.97f, 0.96f};
            background.draw(paper, paper);
        } else {
            background.draw(kBackgroundTop, kBackgroundBottom);
            mesh_renderer.draw(camera, aspect, render_options);
        }
        overlay_renderer.draw(camera, w, h);
    };
    draw_frame();
    context.finish();
    check_gl("rendering");
    lap("draw");
    const Image image = target.read();
    lap("readback");
    write_png(image, options.output);
    lap("write");

    if (options.benchmark > 0) {
        // Shaded frames against the same triangles with a trivial shader, same context.
        std::vector<double> shaded, bare;
        for (int i = 0; i < options.benchmark; ++i) {
            const Clock::time_point start = Clock::now();
            draw_frame();
            context.finish();
            shaded.push_back(ms_since(start));
        }
        for (int i = 0; i < options.benchmark; ++i) {
            const Clock::time_point start = Clock::now();
            background.draw(kBackgroundTop, kBackgroundBottom);
            mesh_renderer.draw_bare(camera, aspect);
            context.finish();
            bare.push_back(ms_since(start));
        }
        std::printf("triangles %zu size %dx%d samples %d shaded_ms %.1f bare_ms %.1f\n",
                    mesh_renderer.triangle_count(), w, h, target.samples(), median(shaded),
                    median(bare));
    }

    if (options.pick && !is_curve) {
        RenderTarget pick_target(w, h, 1);  // ids must not be blended by multisampling
        pick_target.bind();
        const ElementRef hit =
            mesh_renderer.pick(camera, w, h, options.pick->first, options.pick->second);
        std::printf("%s\n", to_string(hit).c_str());
    }
    return 0;
}

void print_error(const std::string& message) {
    std::fprintf(stderr, "meshedit-render: %s\n", message.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "-h" || a == "--help") {
            std::printf(kUsage, shading_table().c_str());
            return 0;
        }
    }
    try {
        return run(parse_args(argc, argv));
    } catch (const UsageError& e) {
        print_error(e.what());
        return 2;
    } catch (const IoError& e) {
        print_error(e.what());
        return 2;
    } catch (const ops::SyntaxError& e) {
        print_error(e.what());
        return 2;
    } catch (const ops::OpError& e) {
        print_error(e.what());
        return e.refused() ? 1 : 2;
    } catch (const GlError& e) {
        print_error(e.what());
        return 1;
    } catch (const std::exception& e) {
        print_error(e.what());
        return 1;
    }
}
