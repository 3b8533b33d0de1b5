// `meshedit-render` (also `meshedit render`): renders a mesh, Bezier surface or Bezier curve
// to PNG through EGL or OSMesa (gl_context.h) with the same renderer and shaders as the
// viewer. Errors are one line "meshedit-render: <message>"; exit 2 for bad usage or input and
// for no GL context, 1 for GL failures and refused ops (docs/rendering.md).

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gl_context.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/fields.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/files/files.h"
#include "meshedit/files/io_error.h"
#include "meshedit/io/document.h"
#include "meshedit/ops/ops.h"
#include "meshedit/overlay/camera.h"
#include "meshedit/overlay/display_data.h"
#include "meshedit/overlay/label_layout.h"
#include "meshedit/overlay/op_diagram.h"
#include "meshedit/overlay/overlay.h"
#include "meshedit/overlay/shading.h"
#include "meshedit/render/environment.h"
#include "meshedit/render/labels.h"
#include "meshedit/render/render_target.h"
#include "meshedit/render/scene.h"
#include "meshedit/render/shader_program.h"
#include "meshedit/repair/problems.h"
#include "options.h"

namespace {

using namespace meshedit;
using headless::Options;
using headless::parse_options;
using headless::parse_selection;
using headless::UsageError;

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Runs --ops on `mesh`; with --op-diagram, the last step separately, returning what it
// rewired (the changes listed under the picture).
// Runs --ops; `result` is what the last step selected, `carried` the selection the list
// carries at its end (the select verbs'), as elements of the mesh.
std::optional<OpDiagram> run_ops(Mesh& mesh, const Options& options, ElementRef& result,
                                 std::vector<ElementRef>& carried) {
    if (options.op_diagram && (!options.select.empty() || options.stencil)) {
        throw UsageError("--op-diagram draws no mesh: --select and --stencil do not apply");
    }
    // @FILE: a session file, as `meshedit convert --ops @FILE` reads it.
    std::vector<ops::Step> steps;
    if (options.ops.front() != '@') {
        steps = ops::parse(options.ops);
    } else {
        const std::string session = options.ops.substr(1);
        try {
            steps = ops::parse_session(read_file(session));
        } catch (const BudgetError& e) {
            throw BudgetError(session + ": " + e.what());
        }
    }
    if (!options.op_diagram) {
        const ops::StepsRun run = ops::run_steps(mesh, steps, ops::OnRefusal::Stop);
        result = run.last;
        for (const std::uint32_t i : run.selection.indices) {
            carried.push_back({run.selection.kind, i});
        }
        return std::nullopt;
    }
    if (steps.empty() || !ops::draws_diagram(steps.back())) {
        throw UsageError(
            "--op-diagram draws a local operation: the last step of --ops must name an element "
            "and change the connectivity (flip:A-B, split:A-B, collapse:A-B, dissolve:vI, …)");
    }
    const ops::Step last = steps.back();
    steps.pop_back();
    ops::apply_steps(mesh, steps);
    // Recorded, as the viewer records it: the diagram is read from the change, at any size.
    MeshRecorder recorder(mesh);
    result = ops::run_step(mesh, last).selected;
    const MeshChange change = recorder.finish();
    OpDiagram diagram =
        op_diagram(mesh, change, last.verb->name, last.verb->names,
                   [&](const Mesh& before) { return ops::named_element(before, last); });
    const Color ink{0.15f, 0.15f, 0.2f, 1.0f};
    diagram.picture.labels.push_back({{0.5 * OpDiagram::kAfterX, diagram.max.y + 0.15, 0.0},
                                      diagram.title,
                                      ink,
                                      OverlayBatch::Label::Side::Centre,
                                      true});
    // The changes listed under the pictures, a line of text apart (the picture's width is
    // what fits it into the image).
    const double pixels_per_unit = options.width / (diagram.max.x - diagram.min.x);
    const double line = 1.5 * diagram_font_px(options.width) / pixels_per_unit;
    double y = diagram.min.y - 0.5 * line;
    for (const std::string& text : diagram.changes) {
        diagram.picture.labels.push_back(
            {{diagram.min.x, y, 0.0}, text, ink, OverlayBatch::Label::Side::Right, true});
        y -= line;
    }
    diagram.min.y = y;
    diagram.max.y += 0.3;
    return diagram;
}

int run(const Options& options) {
    Clock::time_point phase = Clock::now();
    auto lap = [&](const char* name) {
        if (options.timings) {
            std::fprintf(stderr, "%s: %-9s %8.1f ms\n", headless::program_name(), name,
                         ms_since(phase));
        }
        phase = Clock::now();
    };
    // Everything that can fail on bad input happens before the GL context exists.
    const std::optional<EnvironmentImage> environment =
        options.envmap.empty() ? std::nullopt
                               : std::optional<EnvironmentImage>(read_environment(options.envmap));
    ReadOptions read;
    read.density = options.density;
    LoadedDocument doc = read_document(options.input, read);
    const bool is_curve = doc.kind == DocumentKind::Curve;
    const bool is_surface = doc.kind == DocumentKind::Surface;
    Mesh& mesh = doc.mesh;
    const BezierCurve& curve = doc.curve;
    const std::vector<BezierPatch>& patches = doc.patches;
    OverlayBatch overlay;
    SceneContent scene;
    std::optional<ProblemReport> problems;
    std::optional<OpDiagram> diagram;
    std::vector<ElementRef> carried;  // --select sel: the selection --ops ends with
    if (is_curve) {
        if (!options.select.empty() || !options.ops.empty()) {
            throw UsageError("--select and --ops need a mesh or .bez file, not a curve");
        }
        // Every level drawn is one line per point: n(n+1)/2 of them for all levels.
        check_budget(128.0 * de_casteljau_level_points(curve.control_points.size(), options.level),
                     "drawing the de Casteljau levels of a curve of " +
                         std::to_string(curve.control_points.size()) + " points");
        scene.curve = &curve;
        scene.t = options.t;
        scene.level = options.level;
        scene.show_curve = options.curve;
    } else {
        lap("load");
        ElementRef result;
        if (!options.ops.empty()) {
            diagram = run_ops(mesh, options, result, carried);
            lap("ops");
        } else if (options.op_diagram) {
            throw UsageError("--op-diagram draws the last step of --ops: give --ops");
        }
        scene.mesh = &mesh;
        scene.patches = patches;
        scene.show_nets = options.net && is_surface;
        scene.uv_seams = options.color == SurfaceColor::Checker;
        scene.material_borders = options.color == SurfaceColor::Material;
        if (options.patch_steps) {
            const auto& [index, u, v, step] = *options.patch_steps;
            if (!is_surface) {
                throw UsageError("--patch-steps steps a Bezier patch: give a .bez file");
            }
            if (index >= static_cast<double>(patches.size())) {
                throw UsageError("--patch-steps: no patch " +
                                 std::to_string(static_cast<long>(index)) + " (the file has " +
                                 std::to_string(patches.size()) + " patches)");
            }
            scene.steps_patch = static_cast<std::size_t>(index);
            scene.steps_u = u;
            scene.steps_v = v;
            scene.steps = static_cast<int>(step);
        }
        if (options.select == "result") {
            if (result.is_none()) {
                throw UsageError("--select result: the last op of --ops selects nothing");
            }
            scene.selected = result;
        } else if (options.select == "sel") {
            if (carried.empty()) {
                throw UsageError(
                    "--select sel: --ops selects nothing (select:R, select_loop:A-B, "
                    "… choose a selection)");
            }
            scene.selected = carried.back();  // active, as the viewer draws it
            carried.pop_back();
            scene.also_selected = carried;
        } else if (!options.select.empty()) {
            scene.selected = parse_selection(mesh, options.select);
        }
        if (options.marks_near && scene.selected.is_none()) {
            throw UsageError("--marks-near draws the marks near the --select element: select one");
        }
        scene.marks_near_selection = options.marks_near;
        if (options.problems) {
            // The loader's cuts describe the mesh as loaded: after --ops they name other places.
            problems = find_problems(mesh, options.ops.empty() ? &doc.repairs : nullptr);
            scene.problems = &*problems;
        }
        if (options.stencil) {
            if (scene.selected.is_none()) {
                throw UsageError("--stencil draws the stencil of the --select element: select one");
            }
            if (const Stencil s = subdivision_stencil(mesh, scene.selected, *options.stencil);
                !s.ok()) {
                throw UsageError("--stencil: " + s.status.text());
            }
            scene.stencil = options.stencil;
        }
    }
    // What is drawn besides the mesh, derived as the window derives it: the features (for a
    // mesh, not a surface's tessellation unless --features), the scene's marks, the field.
    DisplayData display;
    const FieldInfo* field = options.field.empty() ? nullptr : find_field(mesh, options.field);
    if (!options.field.empty() && field == nullptr) {
        throw UsageError("no field called '" + options.field +
                         "' (the fields: " + field_names(mesh) + ")");
    }
    if (field != nullptr) {
        if (is_curve || diagram) {
            throw UsageError("--field colours a mesh: not a curve or an --op-diagram");
        }
        if (options.field_source >= mesh.vertices_size() ||
            mesh.is_deleted(Vertex(options.field_source))) {
            throw UsageError("--field-source v" + std::to_string(options.field_source) +
                             ": no such vertex");
        }
    }
    FieldRequest wanted;
    wanted.info = field;
    wanted.source = Vertex(options.field_source);
    wanted.colormap = options.colormap;
    const FieldDisplay& shown = display.field(mesh, wanted);
    overlay =
        display.overlay(scene, !is_curve && options.features.value_or(!is_surface), !is_curve);
    if (diagram) {
        overlay = diagram->picture;
        scene.mesh = nullptr;
    }

    const int w = options.width;
    const int h = options.height;
    const float aspect = static_cast<float>(w) / static_cast<float>(h);
    Camera camera;
    if (is_curve) {
        camera.frame_2d({0.0f, 0.0f}, {1.0f, 1.0f}, aspect);
    } else if (diagram) {
        camera.frame_2d({static_cast<float>(diagram->min.x), static_cast<float>(diagram->min.y)},
                        {static_cast<float>(diagram->max.x), static_cast<float>(diagram->max.y)},
                        aspect, 0.02f);
    } else {
        camera.up = options.up;
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
    headless::ContextRequest request;
    request.backend = options.backend;
    request.device = options.device;
    request.width = w;
    request.height = h;
    request.verbose = options.verbose;
    const std::unique_ptr<headless::GlContext> context = headless::make_context(request);
    if (options.verbose) {
        std::fprintf(stderr, "%s: backend %s, GL renderer %s\n", headless::program_name(),
                     context->backend().c_str(), headless::gl_description().c_str());
        std::fprintf(stderr, "%s: shaders from %s\n", headless::program_name(),
                     shader_directory().string().c_str());
        std::fprintf(stderr, "%s: font from %s\n", headless::program_name(),
                     label_font().string().c_str());
    }
    RenderTarget target(w, h, options.samples);
    target.bind();
    lap("context");
    SceneRenderer renderer;
    RenderOptions render_options;
    render_options.shading = options.shading;
    render_options.color = options.color;
    render_options.smooth = options.smooth.value_or(true);
    render_options.wireframe = options.wireframe;
    render_options.exposure = options.exposure;
    renderer.mesh().set_normal_split(options.normals);
    if (environment) {
        renderer.mesh().set_environment(*environment);
    }
    if (!options.shader_dir.empty()) {
        renderer.mesh().set_user_shader_dir(options.shader_dir);
    } else if (options.shading >= 8) {
        std::fprintf(stderr, "%s: note: shading %d draws as 1 without --shader-dir\n",
                     headless::program_name(), options.shading);
    }
    renderer.upload(is_curve || diagram ? nullptr : &mesh);
    if (field != nullptr) {
        renderer.mesh().set_field(field->site, shown.values, shown.coloring);
    }
    for (const std::string& note : renderer.mesh().texture_notes()) {
        std::fprintf(stderr, "%s: note: %s\n", headless::program_name(), note.c_str());
    }
    if (const SurfaceColor shown = renderer.mesh().shown_color(options.color);
        options.color != SurfaceColor::Auto && shown != options.color) {
        std::fprintf(stderr, "%s: note: --color %s: the mesh has no %s; drawn as %s\n",
                     headless::program_name(),
                     std::string(kSurfaceColors[static_cast<int>(options.color)].name).c_str(),
                     options.color == SurfaceColor::Vertex     ? "colours"
                     : options.color == SurfaceColor::Material ? "materials"
                     : options.color == SurfaceColor::Texture  ? "texture with texture coordinates"
                                                               : "texture coordinates",
                     std::string(kSurfaceColors[static_cast<int>(shown)].name).c_str());
    }
    renderer.overlay().upload(overlay);
    context->finish();
    lap("upload");
    auto draw_frame = [&] { renderer.draw(camera, w, h, render_options); };
    draw_frame();
    context->finish();
    check_gl("rendering");
    if (!renderer.mesh().user_shader_error().empty()) {
        throw GlError(renderer.mesh().user_shader_error());
    }
    lap("draw");
    Image image = target.read();
    lap("readback");
    if (!overlay.labels.empty() && !diagram && !is_curve && mesh.n_faces() > 0) {
        const glm::vec3 eye = camera.eye();
        hide_labels_behind(overlay.labels, Vec3(eye.x, eye.y, eye.z), mesh, FaceBvh(mesh));
    }
    draw_labels(image, overlay.labels, camera, diagram ? diagram_font_px(w) : 0);
    if (field != nullptr) {
        draw_legend(image, shown.coloring,
                    std::string(field->title) +
                        (field->unit.empty() ? "" : " (" + std::string(field->unit) + ")"));
    }
    write_png(image, options.output);
    lap("write");

    if (options.benchmark > 0) {
        // Shaded frames against the same triangles with a trivial shader, same context.
        std::vector<double> shaded, bare;
        for (int i = 0; i < options.benchmark; ++i) {
            const Clock::time_point start = Clock::now();
            draw_frame();
            context->finish();
            shaded.push_back(ms_since(start));
        }
        for (int i = 0; i < options.benchmark; ++i) {
            const Clock::time_point start = Clock::now();
            renderer.draw_bare(camera, w, h);
            context->finish();
            bare.push_back(ms_since(start));
        }
        std::printf("triangles %zu size %dx%d samples %d shaded_ms %.1f bare_ms %.1f\n",
                    renderer.mesh().triangle_count(), w, h, target.samples(), median(shaded),
                    median(bare));
    }

    if (options.pick && !is_curve) {
        RenderTarget pick_target(w, h, 1);  // ids must not be blended by multisampling
        pick_target.bind();
        const ElementRef hit =
            renderer.mesh().pick(camera, w, h, options.pick->first, options.pick->second);
        std::printf("%s\n", to_string(hit).c_str());
    }
    return 0;
}

void print_error(const std::string& message) {
    std::fprintf(stderr, "%s: %s\n", headless::program_name(), message.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    try {
        if (const int status = parse_options(argc, argv, options); status >= 0) {
            return status;
        }
        return run(options);
    } catch (const headless::ContextError& e) {
        print_error(e.what());  // no GL here: the machine's setup, as bad input
        return 2;
    } catch (const GlError& e) {
        print_error(e.what());  // a shader that does not compile, a framebuffer refused
        return 1;
    } catch (...) {
        return command_line::exit_status_of_current_exception(headless::program_name());
    }
}
