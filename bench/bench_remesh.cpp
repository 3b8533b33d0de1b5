// Isotropic remeshing: MeshEdit against CGAL's Polygon_mesh_processing::isotropic_remeshing,
// timed, with the quality of each result measured by the same code.
//
//     bench_remesh --job remesh_armadillo_208k --impl cgal [--runs 5] [--data DIR]
//     bench_remesh --list
//
// Job: remesh_armadillo_208k (armadillo.off from libcgal-demo, 52,000 triangles,
// Loop-subdivided once: 208,000), target length = the input's mean edge length, 3 iterations.
// Impls (the timed body is the remeshing only; input copies are untimed):
//   meshedit   remesh() on a copy of the halfedge Mesh (its TriangleTree of the input is built
//              inside, so timed);
//   cgal       isotropic_remeshing(faces(mesh), L, mesh, number_of_iterations(3)) on
//              Surface_mesh<Simple_cartesian<double>::Point_3> (its AABB tree of the input,
//              built inside, timed too).
// Quality (bench_quality.h): min_angle_deg, length_spread (stddev / mean of the edge
// lengths), hausdorff_pct (sampled, symmetric, % of the input's bounding-box diagonal).

#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <string>
#include <vector>

#include "bench_quality.h"
#include "bench_real_meshes.h"
#include "bench_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/subdivision.h"

namespace {

namespace mb = meshedit::bench;
namespace fs = std::filesystem;
using mb::Surface;
using meshedit::Vec3;

const char* const kJob = "remesh_armadillo_208k";
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
    meshedit::PolygonSoup soup;
    soup.positions = in.points;
    for (const auto& t : in.triangles) {
        soup.add_face({t[0], t[1], t[2]});
    }
    const meshedit::Mesh input = meshedit::build_mesh(soup);
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

using Kernel = CGAL::Simple_cartesian<double>;
using CMesh = CGAL::Surface_mesh<Kernel::Point_3>;

Outcome run_cgal(const Surface& in, double length, int runs) {
    CMesh input;
    std::vector<CMesh::Vertex_index> vh;
    for (const Vec3& p : in.points) {
        vh.push_back(input.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
    }
    for (const auto& t : in.triangles) {
        input.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
    }
    CMesh mesh;
    Outcome out;
    out.ms = mb::time_runs(
        runs, [&] { mesh = input; },
        [&] {
            CGAL::Polygon_mesh_processing::isotropic_remeshing(
                faces(mesh), length, mesh, CGAL::parameters::number_of_iterations(kIterations));
        });
    mesh.collect_garbage();
    for (auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        out.result.points.push_back({p.x(), p.y(), p.z()});
    }
    for (auto f : mesh.faces()) {
        std::array<std::uint32_t, 3> t{};
        int i = 0;
        for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
            t[i++] = static_cast<std::uint32_t>(v.idx());
        }
        out.result.triangles.push_back(t);
    }
    return out;
}

int usage() {
    std::fprintf(stderr,
                 "usage: bench_remesh --job %s --impl meshedit|cgal [--runs N] [--data DIR]\n"
                 "       bench_remesh --list\n",
                 kJob);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    mb::take_common_flags(argc, argv);
    std::string job, impl;
    int runs = 5;
    fs::path data_dir = fs::canonical("/proc/self/exe").parent_path() / "loop_data";
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        if (arg == "--list") {
            std::printf("%s meshedit\n%s cgal\n", kJob, kJob);
            return 0;
        } else if (arg == "--job" && has_value) {
            job = argv[++i];
        } else if (arg == "--impl" && has_value) {
            impl = argv[++i];
        } else if (arg == "--runs" && has_value) {
            runs = std::atoi(argv[++i]);
        } else if (arg == "--data" && has_value) {
            data_dir = argv[++i];
        } else {
            return usage();
        }
    }
    if (job != kJob || (impl != "meshedit" && impl != "cgal") || runs < 1) {
        return usage();
    }
    try {
        meshedit::Mesh armadillo =
            meshedit::build_mesh(mb::read_off(mb::real_mesh_path("armadillo", data_dir)));
        meshedit::loop_subdivide(armadillo);
        const Surface input = mb::surface_of(armadillo);
        const double length = mean_length(input);
        const Outcome out =
            impl == "meshedit" ? run_meshedit(input, length, runs) : run_cgal(input, length, runs);
        mb::print_result(job, impl, out.ms,
                         {{"faces_in", static_cast<double>(input.triangles.size())},
                          {"faces_out", static_cast<double>(out.result.triangles.size())},
                          {"target_length", length},
                          {"min_angle_deg", mb::min_angle_deg(out.result)},
                          {"length_spread", mb::edge_length_spread(out.result)},
                          {"hausdorff_pct", mb::hausdorff_percent(input, out.result)},
                          {"peak_rss_mb", mb::peak_rss_mb()}});
    } catch (const std::exception& e) {
        std::printf("NOTE %s %s failed: %s\n", job.c_str(), impl.c_str(), e.what());
        mb::print_result(job, impl, {0.0}, {{"skipped", 1}});
        return 1;
    }
    return 0;
}
