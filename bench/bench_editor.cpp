// The editor around the core at a million faces (issue 20): what a person pressing F, S or C
// on a big mesh waits for. It drives the viewer's command layer (viewer::Editor, the same
// object the window drives) and its renderer (MeshRenderer in a headless EGL or OSMesa context)
// headless.
//
//   bench_editor --job editor_edits_torus_1m|editor_edits_scan_1m|editor_edits_torus_10m
//                [--impl all] [--runs N]      (the 10M torus: torus(2500, 2000), issue 38)
//   bench_editor --job editor_loop_1m --impl core|viewer [--runs N]
//   bench_editor --job editor_simplify_1m --impl core|viewer [--runs N]
//   bench_editor --list
//
// editor_edits_*: 200 × N random local edits (F, S or C on a uniformly random live edge,
// selected first as a click would), then that many undos and redos. One process prints one
// RESULT line per measure, each over every applied edit (p50 as median_ms, p99_ms, max_ms):
//   command          Editor::run (check, apply, undo record, garbage collection), no GPU
//   command_upload   the same plus the renderer's buffer update after it, as the window does
//                    it (MeshRenderer::update from the change's region; glFinish)
//   undo, redo       Editor::undo / redo, no GPU; undo_upload: plus the buffer update
//   drag_move_upload one mouse move of a vertex drag (Editor::drag_to) plus the buffer update
//   extrude_move_upload  one mouse move of an interactive extrude (modal_input) plus the update
// and extras: undo bytes per flip (History::bytes() growth), undo steps still held after the
// edits, the history's total.
// editor_loop_1m: Loop on the 1M torus: `core` loop_subdivide() on a copy; `viewer` the L
// key through Editor::run plus the upload of the new buffers.
// editor_simplify_1m: simplify the 1.2M-face scan to half (issue 40): `core` simplify() and
// the garbage collection on a copy; `viewer` the D key as the window runs it, in the
// background (Editor::set_background): the worker's copy, the operation, the result put in
// as an undo step, no GPU.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "bench_real_meshes.h"
#include "bench_util.h"
#include "gl_context.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/simplify.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/render/mesh_renderer.h"
#include "meshedit/viewer/editor.h"

namespace mb = meshedit::bench;
using namespace meshedit;
using viewer::Editor;

namespace {

constexpr int kEditsPerRun = 200;

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) {
        return 0.0;
    }
    std::sort(v.begin(), v.end());
    const auto i = static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5);
    return v[std::min(i, v.size() - 1)];
}

void print_series(const std::string& job, const std::string& impl, const std::vector<double>& ms,
                  std::map<std::string, double> extra = {}) {
    extra["p99_ms"] = percentile(ms, 0.99);
    extra["max_ms"] = ms.empty() ? 0.0 : *std::max_element(ms.begin(), ms.end());
    mb::print_result(job, impl, ms, extra);
}

Mesh input_mesh(const std::string& job, const std::filesystem::path& data) {
    if (job == "editor_edits_scan_1m") {
        // bunny00 (CGAL's demo data) Loop-subdivided twice: 1,206,530 triangles.
        Mesh mesh = build_mesh(mb::real_mesh("bunny", data));
        loop_subdivide(mesh);
        loop_subdivide(mesh);
        return mesh;
    }
    if (job == "editor_edits_torus_10m") {
        return shapes::torus(2500, 2000);  // 5,000,000 vertices, 10,000,000 triangles
    }
    return shapes::torus(1000, 500);  // 500,000 vertices, 1,000,000 triangles
}

void upload(MeshRenderer& renderer, const Editor& editor, const headless::GlContext& gl) {
    renderer.upload(editor.mesh());
    gl.finish();
}

// What the window does after a command (App::apply): the buffers updated from the change's
// region when the command was a recorded edit, its undo or redo; uploaded whole otherwise.
void follow(MeshRenderer& renderer, const Editor& editor, const viewer::Outcome& outcome,
            const headless::GlContext& gl) {
    if (const auto& region = outcome.region) {
        renderer.update(editor.mesh(), region->faces, region->vertices);
        gl.finish();
    } else {
        upload(renderer, editor, gl);
    }
}

int run_edits(const std::string& job, int runs, const std::filesystem::path& data) {
    Editor editor;
    viewer::Document doc;
    doc.mesh = input_mesh(job, data);
    editor.set_document(std::move(doc));
    const auto context =
        headless::make_context({.device = std::nullopt, .width = 64, .height = 64});
    const headless::GlContext& gl = *context;
    MeshRenderer renderer;
    upload(renderer, editor, gl);
    const std::size_t faces = editor.mesh().n_faces();
    // The command rows measure the edit with the Rewiring panel hidden (its diagram is then
    // not built); `diagram` below measures F with it shown.
    editor.view().show_diagram = false;

    std::mt19937_64 rng(20);
    const char* verbs[] = {"flip", "split", "collapse"};
    std::vector<double> command, command_upload, undo, undo_upload, redo;
    std::vector<double> flip_bytes;
    std::size_t refused = 0;
    std::size_t applied = 0;
    for (int run = 0; run < runs; ++run) {
        std::size_t applied_here = 0;
        for (int i = 0; i < kEditsPerRun; ++i) {
            const Mesh& mesh = editor.mesh();
            std::uniform_int_distribution<std::uint32_t> pick(
                0, static_cast<std::uint32_t>(mesh.edges_size() - 1));
            Edge e(pick(rng));
            while (mesh.is_deleted(e)) {
                e = Edge(pick(rng));
            }
            const std::size_t which = rng() % 3;  // 0: a flip, whose undo bytes are measured
            const std::string verb = verbs[which];
            editor.select(ElementRef::edge(e));
            const std::size_t bytes_before = editor.history().bytes();
            const std::size_t steps_before = editor.history().undo_steps();
            auto start = std::chrono::steady_clock::now();
            const viewer::Outcome outcome = editor.run(viewer::edit(verb));
            const double ms = ms_since(start);
            if (outcome.refused) {
                ++refused;
                continue;
            }
            command.push_back(ms);
            start = std::chrono::steady_clock::now();
            follow(renderer, editor, outcome, gl);
            command_upload.push_back(ms + ms_since(start));
            // Only while nothing was dropped is the growth this step's size.
            if (which == 0 && editor.history().undo_steps() == steps_before + 1) {
                flip_bytes.push_back(static_cast<double>(editor.history().bytes() - bytes_before));
            }
            ++applied_here;
        }
        applied += applied_here;
        for (std::size_t i = 0; i < applied_here; ++i) {
            auto start = std::chrono::steady_clock::now();
            const viewer::Outcome undone = editor.run({viewer::Command::Undo});
            if (undone.refused) {
                break;  // the history's bound dropped the older steps
            }
            const double ms = ms_since(start);
            undo.push_back(ms);
            start = std::chrono::steady_clock::now();
            follow(renderer, editor, undone, gl);
            undo_upload.push_back(ms + ms_since(start));
        }
        for (std::size_t i = 0; i < applied_here; ++i) {
            const auto start = std::chrono::steady_clock::now();
            const viewer::Outcome redone = editor.run({viewer::Command::Redo});
            if (redone.refused) {
                break;
            }
            redo.push_back(ms_since(start));
            follow(renderer, editor, redone, gl);
        }
        upload(renderer, editor, gl);
    }
    // F with the Rewiring panel shown: the edit and its diagram, read from the recorded
    // change (no copy of the mesh, so at any size).
    std::vector<double> diagram;
    editor.view().show_diagram = true;
    for (int i = 0; i < kEditsPerRun; ++i) {
        const Mesh& mesh = editor.mesh();
        Edge e(static_cast<std::uint32_t>(rng() % mesh.edges_size()));
        if (mesh.is_deleted(e)) {
            continue;
        }
        editor.select(ElementRef::edge(e));
        const auto start = std::chrono::steady_clock::now();
        const viewer::Outcome flipped = editor.run(viewer::edit("flip"));
        const double ms = ms_since(start);
        if (!flipped.refused && editor.last_diagram()) {
            diagram.push_back(ms);
        }
    }
    editor.view().show_diagram = false;
    // A vertex dragged across 200 mouse moves: each move with its GPU update.
    std::vector<double> drag;
    {
        const Mesh& mesh = editor.mesh();
        Vertex v(static_cast<std::uint32_t>(rng() % mesh.vertices_size()));
        while (mesh.is_deleted(v)) {
            v = Vertex(static_cast<std::uint32_t>(rng() % mesh.vertices_size()));
        }
        editor.select(ElementRef::vertex(v));
        editor.begin_drag();
        const Vec3 from = mesh.position(v);
        for (int i = 1; i <= kEditsPerRun; ++i) {
            const auto start = std::chrono::steady_clock::now();
            const viewer::Outcome moved = editor.drag_to(from + Vec3{1e-4 * i, 0.0, 0.0});
            follow(renderer, editor, moved, gl);
            drag.push_back(ms_since(start));
        }
        editor.end_drag();
    }
    // An interactive extrude of a face (X, then the mouse): the first move builds the ring
    // (one recorded topology change), every other only moves its corners (a position
    // amendment), each with its GPU update; then Enter.
    std::vector<double> extrude;
    std::size_t extruded_faces = 0;
    viewer::Editor::ModalCounts extrude_counts;
    {
        const std::size_t faces_before = editor.mesh().n_faces();
        const Mesh& mesh = editor.mesh();
        Face f(static_cast<std::uint32_t>(rng() % mesh.faces_size()));
        while (mesh.is_deleted(f)) {
            f = Face(static_cast<std::uint32_t>(rng() % mesh.faces_size()));
        }
        editor.select(ElementRef::face(f));
        follow(renderer, editor, editor.run(viewer::interactive(viewer::Modal::Extrude)), gl);
        for (int i = 1; i <= kEditsPerRun; ++i) {
            viewer::ModalInput in;
            in.dy = 0.5 * i;
            in.pixel = 1e-4;
            const auto start = std::chrono::steady_clock::now();
            follow(renderer, editor, editor.modal_input(in), gl);
            extrude.push_back(ms_since(start));
        }
        extrude_counts = editor.modal_counts();
        follow(renderer, editor, editor.confirm_modal(), gl);
        extruded_faces = editor.mesh().n_faces() - faces_before;  // a triangle: 3 sides more
    }
    const auto mib = [](std::size_t b) { return static_cast<double>(b) / (1024.0 * 1024.0); };
    const std::map<std::string, double> sizes = {
        {"faces", static_cast<double>(faces)},
        {"applied", static_cast<double>(applied)},
        {"refused", static_cast<double>(refused)},
        {"undo_steps_held", static_cast<double>(editor.history().undo_steps())},
        {"history_mib", mib(editor.history().bytes())},
        {"bytes_per_flip", percentile(flip_bytes, 0.5)},
        {"bytes_per_flip_max", flip_bytes.empty() ? 0.0 : percentile(flip_bytes, 1.0)}};
    print_series(job, "command", command, sizes);
    print_series(job, "command_upload", command_upload);
    print_series(job, "undo", undo, {{"undone", static_cast<double>(undo.size())}});
    print_series(job, "undo_upload", undo_upload);
    print_series(job, "redo", redo, {{"redone", static_cast<double>(redo.size())}});
    print_series(job, "drag_move_upload", drag);
    print_series(job, "flip_with_diagram", diagram);
    print_series(
        job, "extrude_move_upload", extrude,
        {{"faces_added", static_cast<double>(extruded_faces)},
         {"topology_changes", static_cast<double>(extrude_counts.topology_changes)},
         {"position_amendments", static_cast<double>(extrude_counts.position_amendments)}});
    return 0;
}

int run_loop(const std::string& impl, int runs) {
    const Mesh torus = shapes::torus(1000, 500);
    std::vector<double> ms;
    std::vector<double> upload_ms;
    // Warm protocol (--warm): one untimed run first, whose memory the timed ones reuse.
    const int first = mb::warm_protocol() ? -1 : 0;
    if (impl == "core") {
        for (int r = first; r < runs; ++r) {
            Mesh copy = torus;
            const auto start = std::chrono::steady_clock::now();
            loop_subdivide(copy);
            if (r >= 0) {
                ms.push_back(ms_since(start));
            }
        }
        mb::print_result("editor_loop_1m", impl, ms, {{"peak_rss_mb", mb::peak_rss_mb()}});
        return 0;
    }
    const auto context =
        headless::make_context({.device = std::nullopt, .width = 64, .height = 64});
    const headless::GlContext& gl = *context;
    MeshRenderer renderer;
    for (int r = first; r < runs; ++r) {
        Editor editor;
        viewer::Document doc;
        doc.mesh = torus;
        editor.set_document(std::move(doc));
        upload(renderer, editor, gl);
        const auto start = std::chrono::steady_clock::now();
        const viewer::Outcome looped = editor.run(viewer::edit("loop"));
        if (looped.refused) {
            std::fprintf(stderr, "bench_editor: Loop was refused\n");
            return 1;
        }
        const double command = ms_since(start);
        const auto up = std::chrono::steady_clock::now();
        follow(renderer, editor, looped, gl);
        if (r >= 0) {
            upload_ms.push_back(ms_since(up));
            ms.push_back(command + upload_ms.back());
        }
    }
    mb::print_result("editor_loop_1m", impl, ms,
                     {{"upload_ms", percentile(upload_ms, 0.5)},
                      {"command_ms", percentile(ms, 0.5) - percentile(upload_ms, 0.5)},
                      {"peak_rss_mb", mb::peak_rss_mb()}});
    return 0;
}

int run_simplify(const std::string& impl, int runs, const std::filesystem::path& data) {
    const Mesh scan = input_mesh("editor_edits_scan_1m", data);
    std::vector<double> ms;
    const int first = mb::warm_protocol() ? -1 : 0;
    std::size_t faces_out = 0;
    for (int r = first; r < runs; ++r) {
        if (impl == "core") {
            Mesh copy = scan;
            const auto start = std::chrono::steady_clock::now();
            SimplifyOptions half;
            half.target_faces = copy.n_faces() / 2;
            simplify(copy, half);
            copy.garbage_collection();
            if (r >= 0) {
                ms.push_back(ms_since(start));
            }
            faces_out = copy.n_faces();
            continue;
        }
        Editor editor;
        viewer::Document doc;
        doc.mesh = scan;
        editor.set_document(std::move(doc));
        editor.set_background(true);
        const auto start = std::chrono::steady_clock::now();
        const viewer::Outcome started = editor.press(viewer::key_of('D'), viewer::kNoMods);
        const std::optional<viewer::Outcome> done = editor.wait_job();
        if (started.refused || !done || done->refused) {
            std::fprintf(stderr, "bench_editor: D was refused: %s\n", started.message.c_str());
            return 1;
        }
        if (r >= 0) {
            ms.push_back(ms_since(start));
        }
        faces_out = editor.mesh().n_faces();
    }
    mb::print_result(
        "editor_simplify_1m", impl, ms,
        {{"faces_out", static_cast<double>(faces_out)}, {"peak_rss_mb", mb::peak_rss_mb()}});
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string edit_jobs[] = {"editor_edits_torus_1m", "editor_edits_scan_1m",
                                     "editor_edits_torus_10m"};
    if (argc == 2 && std::string(argv[1]) == "--list") {
        for (const auto& job : edit_jobs) {
            std::printf("%s all\n", job.c_str());
        }
        std::printf("editor_loop_1m core\neditor_loop_1m viewer\n");
        std::printf("editor_simplify_1m core\neditor_simplify_1m viewer\n");
        return 0;
    }
    mb::JobArgs args;
    args.impl = "all";
    args.runs = 1;
    mb::take_common_flags(argc, argv);
    if (!mb::parse_job_args(argc, argv, args)) {
        std::fprintf(stderr, "usage: bench_editor --list | --job JOB [--impl IMPL] [--runs N]\n");
        return 2;
    }
    try {
        if (mb::one_of(edit_jobs, args.job)) {
            return run_edits(args.job, args.runs, args.data);
        }
        if (args.job == "editor_loop_1m" && (args.impl == "core" || args.impl == "viewer")) {
            return run_loop(args.impl, args.runs);
        }
        if (args.job == "editor_simplify_1m" && (args.impl == "core" || args.impl == "viewer")) {
            return run_simplify(args.impl, args.runs, args.data);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_editor: %s\n", e.what());
        return 1;
    }
    std::fprintf(stderr, "bench_editor: unknown job/impl %s %s\n", args.job.c_str(),
                 args.impl.c_str());
    return 2;
}
