// QEM simplification: MeshEdit against meshoptimizer, OpenMesh's Decimater and CGAL's
// edge_collapse, timed, with the quality of each result measured by the same code.
//
//     bench_simplify --job qem_torus_1m_to_100k --impl meshoptimizer [--runs 5] [--data DIR]
//     bench_simplify --list
//
// Jobs: qem_torus_1m_to_100k (torus(1000, 500), 1M triangles → 100k), qem_bunny_1m_to_100k
// (bunny00.off from libcgal-demo, 75,408 triangles, Loop-subdivided twice: 1.2M → 100k),
// qem_torus_attrs_1m_to_100k (the same torus with texture coordinates cut along two seams and
// vertex colours, tests/support/textured_torus.h; attribute-aware, MeshEdit only: the cost
// of carrying UVs and colours against the first job).
// Impls (the timed body is the simplification only; input copies are untimed):
//   meshedit       simplify() to 100,000 faces on a copy of the halfedge Mesh (doubles);
//   meshoptimizer  meshopt_simplify() to 300,000 indices, target_error 1 (no bound), float
//                  positions, an index buffer in and out (no connectivity kept);
//   openmesh       DecimaterT + ModQuadricT (no error bound), initialize() and
//                  decimate_to_faces(0, 100000) on a TriMesh (float positions);
//   cgal           Surface_mesh_simplification::edge_collapse with GarlandHeckbert_plane_policies
//                  and a Count_stop_predicate of 150,000 edges (100,000 faces of a closed mesh).
// OpenMesh and CGAL run at most twice (10–20 s a run here). Quality (untimed, the same code
// for all): the symmetric Hausdorff distance between input
// and result, sampled (100,000 points on each surface by area, each measured to the other
// through TriangleTree), as a percentage of the input's bounding-box diagonal.

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <meshoptimizer.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <array>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "bench_cgal.h"
#include "bench_quality.h"
#include "bench_real_meshes.h"
#include "bench_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/closest_point.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/simplify.h"
#include "meshedit/core/subdivision.h"
#include "support/textured_torus.h"

namespace {

namespace mb = meshedit::bench;
using mb::Surface;
using mb::surface_of;
namespace fs = std::filesystem;
using meshedit::Vec3;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

const char* const kImpls[] = {"meshedit", "meshoptimizer", "openmesh", "cgal"};
constexpr std::size_t kTargetFaces = 100'000;

Surface load_input(const std::string& job, const fs::path& data_dir) {
    if (job == "qem_torus_1m_to_100k" || job == "qem_torus_attrs_1m_to_100k") {
        return surface_of(meshedit::shapes::torus(1000, 500));
    }
    meshedit::Mesh bunny = meshedit::build_mesh(mb::real_mesh("bunny", data_dir));
    meshedit::loop_subdivide(bunny);
    meshedit::loop_subdivide(bunny);
    return surface_of(bunny);
}

// ------------------------------------------------------------------------------ impls

struct Outcome {
    std::vector<double> ms;
    Surface result;
};

Outcome run_meshedit(const Surface& in, int runs, bool attributes) {
    meshedit::Mesh input = mb::mesh_of(in);
    if (attributes) {
        input = meshedit::test::uv_torus(1000, 500);  // the same torus, numbered alike
        meshedit::test::add_colors(input);
    }
    meshedit::Mesh mesh;
    meshedit::SimplifyOptions options;
    options.target_faces = kTargetFaces;
    Outcome out;
    out.ms = mb::time_runs(
        runs, [&] { mesh = input; }, [&] { meshedit::simplify(mesh, options); });
    mesh.garbage_collection();
    out.result = surface_of(mesh);
    return out;
}

Outcome run_meshoptimizer(const Surface& in, int runs) {
    std::vector<float> positions;
    for (const Vec3& p : in.points) {
        positions.insert(positions.end(), {static_cast<float>(p.x), static_cast<float>(p.y),
                                           static_cast<float>(p.z)});
    }
    std::vector<unsigned> indices;
    for (const auto& t : in.triangles) {
        indices.insert(indices.end(), t.begin(), t.end());
    }
    std::vector<unsigned> result;
    std::size_t count = 0;
    Outcome out;
    out.ms = mb::time_runs(
        runs, [&] { result.assign(indices.size(), 0); },
        [&] {
            count =
                meshopt_simplify(result.data(), indices.data(), indices.size(), positions.data(),
                                 in.points.size(), 3 * sizeof(float), 3 * kTargetFaces, 1.0f);
        });
    out.result.points = in.points;  // meshoptimizer keeps the vertex buffer; unused ones harmless
    for (std::size_t i = 0; i + 2 < count; i += 3) {
        out.result.triangles.push_back({result[i], result[i + 1], result[i + 2]});
    }
    return out;
}

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

Outcome run_openmesh(const Surface& in, int runs) {
    OMesh input;
    std::vector<OMesh::VertexHandle> vh;
    for (const Vec3& p : in.points) {
        vh.push_back(input.add_vertex(OMesh::Point(static_cast<float>(p.x), static_cast<float>(p.y),
                                                   static_cast<float>(p.z))));
    }
    for (const auto& t : in.triangles) {
        input.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
    }
    // Status flags requested by the mesh itself: a decimater that requests them releases them
    // when it goes, and the deleted marks with them.
    input.request_vertex_status();
    input.request_edge_status();
    input.request_halfedge_status();
    input.request_face_status();
    OMesh mesh;
    Outcome out;
    out.ms = mb::time_runs(
        runs, [&] { mesh = input; },
        [&] {
            OpenMesh::Decimater::DecimaterT<OMesh> decimater(mesh);
            OpenMesh::Decimater::ModQuadricT<OMesh>::Handle quadric;
            decimater.add(quadric);
            decimater.module(quadric).unset_max_err();
            decimater.initialize();
            decimater.decimate_to_faces(0, kTargetFaces);
        });
    mesh.garbage_collection();
    for (auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        out.result.points.push_back({p[0], p[1], p[2]});
    }
    for (auto f : mesh.faces()) {
        std::array<std::uint32_t, 3> t{};
        int i = 0;
        for (auto v : mesh.fv_range(f)) {
            t[i++] = static_cast<std::uint32_t>(v.idx());
        }
        out.result.triangles.push_back(t);
    }
    return out;
}

using Kernel = mb::CgalKernel;
using CMesh = mb::CgalMesh;

Outcome run_cgal(const Surface& in, int runs) {
    namespace SMS = CGAL::Surface_mesh_simplification;
    const CMesh input = mb::cgal_mesh(in);
    CMesh mesh;
    Outcome out;
    out.ms = mb::time_runs(
        runs, [&] { mesh = input; },
        [&] {
            SMS::Count_stop_predicate<CMesh> stop(3 * kTargetFaces / 2);
            SMS::GarlandHeckbert_plane_policies<CMesh, Kernel> policies(mesh);
            SMS::edge_collapse(mesh, stop,
                               CGAL::parameters::get_cost(policies.get_cost())
                                   .get_placement(policies.get_placement()));
        });
    out.result = mb::surface_of(mesh);
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> jobs = {"qem_torus_1m_to_100k", "qem_bunny_1m_to_100k",
                                           "qem_torus_attrs_1m_to_100k"};
    mb::JobArgs args;
    if (const std::optional<int> done = mb::read_command_line(argc, argv, jobs, kImpls, args)) {
        return *done;
    }
    const std::string& job = args.job;
    const std::string& impl = args.impl;
    int runs = args.runs;
    const fs::path& data_dir = args.data;
    const bool attributes = job == "qem_torus_attrs_1m_to_100k";
    if (attributes && impl != "meshedit") {
        // meshoptimizer 0.18 has no simplifyWithAttributes; the others carry no UVs here.
        std::printf("NOTE %s %s: MeshEdit only (the anchors do not carry attributes here)\n",
                    job.c_str(), impl.c_str());
        mb::print_result(job, impl, {0.0}, {{"skipped", 1}});
        return 0;
    }
    return mb::run_or_skip(job, impl, [&] {
        const Surface input = load_input(job, data_dir);
        if (impl == "openmesh" || impl == "cgal") {
            runs = std::min(runs, 2);  // 10–20 s a run: two keep `make bench` within its budget
        }
        const Outcome out = impl == "meshedit"        ? run_meshedit(input, runs, attributes)
                            : impl == "meshoptimizer" ? run_meshoptimizer(input, runs)
                            : impl == "openmesh"      ? run_openmesh(input, runs)
                                                      : run_cgal(input, runs);
        mb::print_result(job, impl, out.ms,
                         {{"faces_in", static_cast<double>(input.triangles.size())},
                          {"faces_out", static_cast<double>(out.result.triangles.size())},
                          {"hausdorff_pct", mb::hausdorff_percent(input, out.result)},
                          {"peak_rss_mb", mb::peak_rss_mb()}});
    });
}
