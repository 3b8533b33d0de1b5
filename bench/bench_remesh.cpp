// Isotropic remeshing: MeshEdit against CGAL's Polygon_mesh_processing::isotropic_remeshing,
// timed, with the quality of each result measured by the same code.
//
//     bench_remesh --job remesh_armadillo_208k --impl cgal [--runs 5] [--data DIR]
//     bench_remesh --list
//
// Jobs, target length = the input's mean edge length, 3 iterations:
//   remesh_armadillo_208k  armadillo.off from libcgal-demo, 52,000 triangles, Loop-subdivided
//                          once: 208,000;
//   remesh_bunny_75k       bunny00.off from libcgal-demo as it is (75,408 triangles, closed);
//   remesh_torus_80k       the 200 × 200 torus of shapes::torus (80,000 triangles, every
//                          vertex of valence 6 before).
// Impls (the timed body is the remeshing only; input copies are untimed):
//   meshedit   remesh() on a copy of the halfedge Mesh (its TriangleTree of the input is built
//              inside, so timed);
//   cgal       isotropic_remeshing(faces(mesh), L, mesh, number_of_iterations(3)) on
//              Surface_mesh<Simple_cartesian<double>::Point_3> (its AABB tree of the input,
//              built inside, timed too).
// Quality (bench_quality.h): min_angle_deg, length_spread (stddev / mean of the edge
// lengths), hausdorff_pct (sampled, symmetric, % of the input's bounding-box diagonal),
// valence6_pct (the share of inner vertices of valence 6) and valence4_or_less (how many).

#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <cstdio>
#include <string>
#include <vector>

#include "bench_cgal.h"
#include "bench_quality.h"
#include "bench_real_meshes.h"
#include "bench_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"

namespace {

namespace mb = meshedit::bench;
namespace fs = std::filesystem;
using mb::Surface;
using meshedit::Vec3;

const char* const kJobs[] = {"remesh_armadillo_208k", "remesh_bunny_75k", "remesh_torus_80k"};
constexpr int kIterations = 3;

double mean_length(const Surface& s) {
    double sum = 0.0;
    std::size_t n = 0;
    for (const auto& t : s.triangles) {
        for (int i = 0; i < 3; ++i) {
            sum += distance(s.points[t[i]], s.points[t[(i + 1) % 3]]);
            ++n;
        }
    }
    return sum / static_cast<double>(n);  // each interior edge twice: the same mean
}

struct Outcome {
    std::vector<double> ms;
    Surface result;
};

Outcome run_meshedit(const Surface& in, double length, int runs) {
    const meshedit::Mesh input = mb::mesh_of(in);
    meshedit::Mesh mesh;
    meshedit::RemeshOptions options;
    options.target_length = length;
    options.iterations = kIterations;
    Outcome out;
    out.ms = mb::time_runs(
        runs, [&] { mesh = input; }, [&] { meshedit::remesh(mesh, options); });
    out.result = mb::surface_of(mesh);
    return out;
}

using Kernel = mb::CgalKernel;
using CMesh = mb::CgalMesh;

Outcome run_cgal(const Surface& in, double length, int runs) {
    const CMesh input = mb::cgal_mesh(in);
    CMesh mesh;
    Outcome out;
    out.ms = mb::time_runs(
        runs, [&] { mesh = input; },
        [&] {
            CGAL::Polygon_mesh_processing::isotropic_remeshing(
                faces(mesh), length, mesh, CGAL::parameters::number_of_iterations(kIterations));
        });
    out.result = mb::surface_of(mesh);
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string jobs[] = {kJobs[0], kJobs[1], kJobs[2]};
    const std::string impls[] = {"meshedit", "cgal"};
    mb::JobArgs args;
    if (const std::optional<int> done = mb::read_command_line(argc, argv, jobs, impls, args)) {
        return *done;
    }
    const std::string& job = args.job;
    const std::string& impl = args.impl;
    const int runs = args.runs;
    const fs::path& data_dir = args.data;
    return mb::run_or_skip(job, impl, [&] {
        meshedit::Mesh scan;
        if (job == "remesh_armadillo_208k") {
            scan = meshedit::build_mesh(mb::real_mesh("armadillo", data_dir));
            meshedit::loop_subdivide(scan);
        } else if (job == "remesh_bunny_75k") {
            scan = meshedit::build_mesh(mb::real_mesh("bunny00", data_dir));
        } else {
            scan = meshedit::shapes::torus(200, 200);
        }
        const Surface input = mb::surface_of(scan);
        const double length = mean_length(input);
        const Outcome out =
            impl == "meshedit" ? run_meshedit(input, length, runs) : run_cgal(input, length, runs);
        const mb::Valences valences = mb::interior_valences(out.result);
        mb::print_result(job, impl, out.ms,
                         {{"faces_in", static_cast<double>(input.triangles.size())},
                          {"faces_out", static_cast<double>(out.result.triangles.size())},
                          {"target_length", length},
                          {"min_angle_deg", mb::min_angle_deg(out.result)},
                          {"length_spread", mb::edge_length_spread(out.result)},
                          {"hausdorff_pct", mb::hausdorff_percent(input, out.result)},
                          {"valence6_pct", valences.six_pct},
                          {"valence4_or_less", static_cast<double>(valences.four_or_less)},
                          {"peak_rss_mb", mb::peak_rss_mb()}});
    });
}
