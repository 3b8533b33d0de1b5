// Laplacian smoothing (issue 35): MeshEdit against OpenMesh's JacobiLaplaceSmootherT and CGAL's
// smoothing, time per iteration on 1M faces; and implicit smoothing against CGAL's.
//
//     bench_smooth --job smooth_1m_uniform --impl openmesh [--runs 5]
//     bench_smooth --list
//
// Input: torus(1000, 500) (1M triangles, closed), every vertex pushed along a fixed pseudo-
// random direction by up to 1% of the minor radius so that smoothing has work to do.
// Jobs (the timed body is the whole call; the input copy is untimed; ms_per_iteration = the
// median / the iterations):
//   smooth_1m_uniform    10 iterations, uniform weights, λ = 0.5 (OpenMesh's damping):
//       meshedit   smooth() (its one-ring arrays are built inside, so timed)
//       openmesh   JacobiLaplaceSmootherT<TriMesh> (float positions, its default traits),
//                  initialize(Tangential_and_Normal, C0), smooth(10)
//       cgal       Polygon_mesh_processing::tangential_relaxation(vertices, mesh,
//                  number_of_iterations(10)) on Surface_mesh<Simple_cartesian<double>>: CGAL's
//                  explicit per-iteration smoothing closest to a uniform Laplacian step (each
//                  vertex goes to its neighbours' mean, the move projected on its tangent
//                  plane); its other one, angle_and_area_smoothing, optimises angles and areas
//                  and projects onto the input through an AABB tree, further from this job.
//   smooth_1m_implicit   one implicit step t = 1, cotangent weights:
//       meshedit   smooth(Implicit); solve_ms: building the system and the conjugate-gradient
//                  solves
//       cgal       smooth_shape(faces, mesh, time, number_of_iterations(1)): the same backward
//                  Euler step of the cotangent Laplacian, (M − time·L) x' = M x with M the
//                  vertex areas, solved by its default BiCGSTAB with an incomplete LU. MeshEdit
//                  solves (D − t·L) x' = D x (D: the sums of the weights), so CGAL's time is
//                  t × (area / vertices) / 2√3 (a vertex's mean area over the weight sum of a
//                  regular vertex), the same step on this near-regular mesh.

#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/Polygon_mesh_processing/tangential_relaxation.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Smoother/JacobiLaplaceSmootherT.hh>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bench_cgal.h"
#include "bench_quality.h"
#include "bench_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/smoothing.h"

namespace {

namespace mb = meshedit::bench;
using meshedit::Vec3;

constexpr int kIterations = 10;

meshedit::Mesh noisy_torus() {
    meshedit::Mesh mesh = meshedit::shapes::torus(1000, 500);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> noise(-0.004, 0.004);
    for (const meshedit::Vertex v : mesh.vertices()) {
        mesh.position(v) += Vec3{noise(rng), noise(rng), noise(rng)};
    }
    return mesh;
}

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

std::vector<double> run_openmesh(const meshedit::Mesh& in, int runs) {
    TriMesh input;
    std::vector<TriMesh::VertexHandle> vh(in.vertices_size());
    for (const meshedit::Vertex v : in.vertices()) {
        const Vec3& p = in.position(v);
        vh[v.idx()] = input.add_vertex(TriMesh::Point(
            static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)));
    }
    for (const meshedit::Face f : in.faces()) {
        std::vector<TriMesh::VertexHandle> corners;
        for (const meshedit::Vertex v : in.vertices(f)) {
            corners.push_back(vh[v.idx()]);
        }
        input.add_face(corners);
    }
    TriMesh mesh;
    return mb::time_runs(
        runs, [&] { mesh = input; },
        [&] {
            OpenMesh::Smoother::JacobiLaplaceSmootherT<TriMesh> smoother(mesh);
            smoother.initialize(
                OpenMesh::Smoother::JacobiLaplaceSmootherT<TriMesh>::Tangential_and_Normal,
                OpenMesh::Smoother::JacobiLaplaceSmootherT<TriMesh>::C0);
            smoother.smooth(kIterations);
        });
}

// CGAL's time step for MeshEdit's t on `in` (see the file comment).
double cgal_time(const mb::Surface& in, double t) {
    double area = 0.0;
    for (const auto& tri : in.triangles) {
        const Vec3& a = in.points[tri[0]];
        area += 0.5 * norm(cross(in.points[tri[1]] - a, in.points[tri[2]] - a));
    }
    return t * area / static_cast<double>(in.points.size()) / (2.0 * std::sqrt(3.0));
}

std::vector<double> run_cgal(const meshedit::Mesh& in, bool implicit, double t, int runs) {
    const mb::Surface surface = mb::surface_of(in);
    const mb::CgalMesh input = mb::cgal_mesh(surface);
    const double time = cgal_time(surface, t);
    mb::CgalMesh mesh;
    namespace pmp = CGAL::Polygon_mesh_processing;
    return mb::time_runs(
        runs, [&] { mesh = input; },
        [&] {
            if (implicit) {
                pmp::smooth_shape(faces(mesh), mesh, time,
                                  CGAL::parameters::number_of_iterations(1));
            } else {
                pmp::tangential_relaxation(vertices(mesh), mesh,
                                           CGAL::parameters::number_of_iterations(kIterations));
            }
        });
}

}  // namespace

int main(int argc, char** argv) {
    const std::string jobs[] = {"smooth_1m_uniform", "smooth_1m_implicit"};
    const std::string impls[] = {"meshedit", "openmesh", "cgal"};
    mb::JobArgs args;
    if (const std::optional<int> done = mb::read_command_line(argc, argv, jobs, impls, args)) {
        return *done;
    }
    const bool implicit = args.job == "smooth_1m_implicit";
    if (implicit && args.impl == "openmesh") {
        mb::print_result(args.job, args.impl, {0.0}, {{"skipped", 1}});
        return 0;
    }
    const meshedit::Mesh input = noisy_torus();
    meshedit::Mesh mesh;
    meshedit::SmoothOptions options;
    options.iterations = implicit ? 1 : kIterations;
    if (implicit) {
        options.method = meshedit::SmoothMethod::Implicit;
        options.weights = meshedit::SmoothWeights::Cotangent;
    }
    double solve_ms = 0.0;
    const std::vector<double> ms =
        args.impl == "openmesh" ? run_openmesh(input, args.runs)
        : args.impl == "cgal"
            ? run_cgal(input, implicit, options.time, args.runs)
            : mb::time_runs(
                  args.runs, [&] { mesh = input; },
                  [&] { solve_ms = 1000.0 * meshedit::smooth(mesh, options).solve_seconds; });
    std::map<std::string, double> extra{
        {"faces", static_cast<double>(input.n_faces())},
        {"iterations", static_cast<double>(options.iterations)},
        {"ms_per_iteration", mb::median_of(ms) / options.iterations},
        {"peak_rss_mb", mb::peak_rss_mb()}};
    if (implicit && args.impl == "meshedit") {
        extra["solve_ms"] = solve_ms;
    }
    mb::print_result(args.job, args.impl, ms, extra);
    return 0;
}
