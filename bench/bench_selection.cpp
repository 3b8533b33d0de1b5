// bench_selection: region selection on a million faces (issue 37's targets): an edge loop
// and an edge ring around a 1000 × 1000 quad torus (1M quads, every vertex of valence 4, so a
// loop runs 1000 edges), and select linked from one face over the 1000 × 500 triangle torus
// (1M triangles); box select of the middle quarter of a 1280 × 800 view of that torus, through
// the mesh and of what the view shows (a depth buffer of the box, drawn on the CPU).
// MeshEdit only: the targets are absolute (loop ≤ 1 ms, linked ≤ 50 ms, box ≤ 16 ms).
// Short jobs repeat until the timing is stable (bench_util.h); p99 comes with the median.
//
//   bench_selection --job select_loop_1m|select_ring_1m|select_linked_1m|select_grow_1m|
//                         select_box_1m|select_box_visible_1m
//                   --impl meshedit [--runs N]
//   bench_selection --list

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
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
    const std::vector<std::string> names = {"select_box_1m",  "select_box_visible_1m",
                                            "select_grow_1m", "select_linked_1m",
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
    if (job.rfind("select_box", 0) == 0) {
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
        const meshedit::Reach reach = job != "select_box_visible_1m" ? meshedit::Reach::Through
                                      : culled ? meshedit::Reach::VisibleFrontOnly
                                               : meshedit::Reach::Visible;
        const meshedit::ScreenBox box{{320, 200}, {960, 600}, 1280, 800};
        ms = mb::time_runs(args.runs, nullptr, [&] {
            selected = meshedit::elements_in_box(mesh, camera, box,
                                                 meshedit::ElementRef::Kind::Face, reach)
                           .size();
        });
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
    mb::print_result(job, args.impl, ms,
                     {{"selected", static_cast<double>(selected)},
                      {"p99_ms", percentile(ms, 0.99)},
                      {"faces", static_cast<double>(mesh.n_faces())}});
    return 0;
}
