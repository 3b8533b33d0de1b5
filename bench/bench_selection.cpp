// bench_selection: region selection on a million faces (issue 37's targets): an edge loop
// and an edge ring around a 1000 × 1000 quad torus (1M quads, every vertex of valence 4, so a
// loop runs 1000 edges), and select linked from one face over the 1000 × 500 triangle torus
// (1M triangles); box select of the middle quarter of a 1280 × 800 view of that torus, through
// the mesh and of what the view shows. What shows is timed as the viewer pays it: the view's
// points (ShownPoints: a depth buffer of the whole view drawn on the CPU, the points it shows
// binned into tiles) are built when the press starts a region and kept until the view or the
// mesh changes, so the release costs only the query (`select_box_visible_1m`,
// `select_lasso_visible_1m`: the build's time is the row's `view_build_ms`); the first region
// in a new view pays both (`select_box_visible_1m_cold`: build and query, each repetition).
// MeshEdit only: the targets are absolute (loop ≤ 1 ms, linked ≤ 50 ms, box ≤ 16 ms).
// Short jobs repeat until the timing is stable (bench_util.h); p99 comes with the median.
//
//   bench_selection --job select_loop_1m|select_ring_1m|select_linked_1m|select_grow_1m|
//                         select_box_1m|select_box_visible_1m|select_box_visible_1m_cold|
//                         select_lasso_visible_1m
//                   --impl meshedit [--runs N]
//   bench_selection --list

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bench_util.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"
#include "meshedit/overlay/region_pick.h"
#include "meshedit/selection/selection.h"

namespace {

namespace mb = meshedit::bench;
using meshedit::Edge;
using meshedit::Face;
using meshedit::FaceSet;
using meshedit::Mesh;

double percentile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> names = {
        "select_box_1m",  "select_box_visible_1m", "select_box_visible_1m_cold",
        "select_grow_1m", "select_linked_1m",      "select_lasso_visible_1m",
        "select_loop_1m", "select_ring_1m"};
    const std::string impls[] = {"meshedit"};
    mb::JobArgs args;
    if (const std::optional<int> done = mb::read_command_line(argc, argv, names, impls, args)) {
        return *done;
    }
    const std::string& job = args.job;
    const bool quads = job == "select_loop_1m" || job == "select_ring_1m";
    const Mesh mesh =
        quads ? meshedit::shapes::quad_torus(1000, 1000) : meshedit::shapes::torus(1000, 500);
    std::size_t selected = 0;
    std::vector<double> ms;
    std::map<std::string, double> extra;
    if (job.rfind("select_box", 0) == 0 || job == "select_lasso_visible_1m") {
        meshedit::Camera camera;
        camera.frame_mesh(mesh, 1280.0f / 800.0f);
        // Visible as the viewer asks: back faces culled when the renderer culls them (the
        // torus is closed and outward, the camera outside it).
        meshedit::BoundingBox bounds;
        for (const meshedit::Vertex v : mesh.vertices()) {
            bounds.add(mesh.position(v));
        }
        const bool culled =
            meshedit::back_faces_hidden(camera, meshedit::is_closed_and_outward(mesh), bounds);
        const meshedit::Reach reach = job == "select_box_1m" ? meshedit::Reach::Through
                                      : culled               ? meshedit::Reach::VisibleFrontOnly
                                                             : meshedit::Reach::Visible;
        const meshedit::ScreenBox box{{320, 200}, {960, 600}, 1280, 800};
        const auto face = meshedit::ElementRef::Kind::Face;
        if (job == "select_box_1m") {
            ms = mb::time_runs(args.runs, nullptr, [&] {
                selected = meshedit::elements_in_box(mesh, camera, box, face, reach).size();
            });
        } else if (job == "select_box_visible_1m_cold") {
            ms = mb::time_runs(args.runs, nullptr, [&] {
                const meshedit::ShownPoints shown(mesh, camera, 1280, 800, face, reach);
                selected = shown.in_box(mesh, box.a, box.b).size();
            });
        } else {
            // The press: the view's points, built once (timed apart, reported as
            // view_build_ms). A lasso: a star of 64 points over the same quarter.
            std::vector<double> build_ms;
            std::optional<meshedit::ShownPoints> shown;
            build_ms = mb::time_runs(3, nullptr,
                                     [&] { shown.emplace(mesh, camera, 1280, 800, face, reach); });
            extra["view_build_ms"] = mb::median_of(build_ms);
            std::vector<glm::vec2> star;
            for (int i = 0; i < 64; ++i) {
                const double angle = 2.0 * 3.14159265358979 * i / 64.0;
                const double r = i % 2 == 0 ? 1.0 : 0.6;
                star.push_back(glm::vec2(640.0 + 320.0 * r * std::cos(angle),
                                         400.0 + 200.0 * r * std::sin(angle)));
            }
            ms = mb::time_runs(args.runs, nullptr, [&] {
                selected = job == "select_lasso_visible_1m"
                               ? shown->in_lasso(mesh, star).size()
                               : shown->in_box(mesh, box.a, box.b).size();
            });
        }
    } else if (quads) {
        // A different edge each repetition, spread over the mesh.
        std::uint32_t k = 0;
        ms = mb::time_runs(args.runs, nullptr, [&] {
            const Edge e(static_cast<std::uint32_t>((k++ * 7919u) % mesh.edges_size()));
            selected =
                job == "select_loop_1m" ? edge_loop(mesh, e).size() : edge_ring(mesh, e).size();
        });
    } else {
        FaceSet seed(mesh.faces_size());
        seed.insert(Face(12345));
        FaceSet big(mesh.faces_size());
        for (std::uint32_t f = 0; f < mesh.faces_size() / 2; ++f) {
            big.insert(Face(f));
        }
        ms = mb::time_runs(args.runs, nullptr, [&] {
            selected = job == "select_linked_1m" ? linked_faces(mesh, seed).count()
                                                 : grow(mesh, big).count();
        });
    }
    extra["selected"] = static_cast<double>(selected);
    extra["p99_ms"] = percentile(ms, 0.99);
    extra["faces"] = static_cast<double>(mesh.n_faces());
    mb::print_result(job, args.impl, ms, extra);
    return 0;
}
