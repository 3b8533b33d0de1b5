// Loop subdivision: MeshEdit against OpenMesh LoopT, CGAL Loop_subdivision and OpenSubdiv Far.
//
// One (job, impl) per process, so that peak RSS belongs to one implementation:
//
//     bench_loop --job loop_1m_1level --impl cgal --runs 5 [--data DIR]
//     bench_loop --list        (prints every "job impl" pair, one a line)
//
// Jobs: loop_1m_1level (torus(1000, 500), 1M faces, one level), loop_1m_attrs_1level (MeshEdit
// only: the same torus with texture coordinates and colours, the cost of carrying them),
// loop_10m_1level (torus(2500, 2000), 10M faces → 40M: the memory a face takes at that size),
// loop_100k_levels_K (torus(250, 200), 100k faces, K = 1..4 levels, cumulative time from the
// input), loop_real_NAME_levels_K (NAME = bunny, armadillo from CGAL's demo data, K = 1..3). Impls:
// meshedit, openmesh, cgal, opensubdiv_min, opensubdiv_full.
//
// Inputs: every implementation is built from the same position and triangle arrays (a
// MeshEdit-built soup: the torus from shapes::torus, the real meshes read from .off and passed
// once through build_mesh() so that all libraries get the same manifold triangles, unreferenced
// vertices dropped). The copy of the input is made in time_runs' untimed setup, which also
// frees the previous result; the timed body is the subdivision only:
//   meshedit         loop_subdivide() K times on a copy of the Mesh (result: the complete
//                    editable halfedge mesh, double positions);
//   openmesh         LoopT<TriMesh> (default traits: float positions), operator()(mesh, K),
//                    which includes the subdivider's prepare/cleanup (its temporary properties);
//   cgal             Subdivision_method_3::Loop_subdivision(number_of_iterations(K)) on
//                    Surface_mesh<Simple_cartesian<double>::Point_3>;
//   opensubdiv_*     TopologyRefinerFactory<TopologyDescriptor>::Create from the triangle
//                    arrays (SCHEME_LOOP, boundary VTX_BOUNDARY_EDGE_ONLY like the other
//                    three), RefineUniform(K) (default options, or fullTopologyInLastLevel),
//                    the allocation of the vertex buffer for all levels (as in the Far
//                    tutorials), and PrimvarRefiner::Interpolate of the double positions level
//                    by level. Creating the descriptor arrays is input preparation (untimed).
//
// Memory (method, printed as extras): rss_before_mb is the process RSS (/proc/self/statm) in
// the first setup, after malloc_trim(0), just before the input is copied (the shared input
// arrays and the library's own input mesh are resident, the copy that becomes the result is
// not); peak_rss_mb is getrusage's ru_maxrss after all runs; bytes_per_face = (peak_rss −
// rss_before) / faces_out, so it counts the result plus whatever the library needs
// transiently at its peak; bytes_per_face_retained = (RSS right after the last run −
// rss_before) / faces_out, the memory the result keeps. For OpenSubdiv the "result" is the
// refiner with every level plus the vertex buffer of every level (what the Far tutorials
// keep). None of the anchors has memory accounting of its own; for MeshEdit
// bytes_per_face_exact = mesh.bytes() / faces_out (capacity of all property arrays).

#include <malloc.h>
#include <unistd.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_cgal.h"
#include "bench_real_meshes.h"
#include "bench_subdivision.h"
#include "bench_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "support/textured_torus.h"

namespace {

namespace fs = std::filesystem;
using meshedit::Vec3;
using meshedit::bench::current_rss_mb;
using meshedit::bench::mem_available_mb;
using meshedit::bench::OsdPoint;
using meshedit::bench::print_result;
using meshedit::bench::time_runs;

const char* const kImpls[] = {"meshedit", "openmesh", "cgal", "opensubdiv_min", "opensubdiv_full"};

// ------------------------------------------------------------------------------ inputs

/// The shared input: points and triangles (counter-clockwise), every vertex referenced.
using Input = meshedit::bench::Surface;

/// Triangles of a soup of triangles (anything else is an error: all inputs here are triangles).
Input input_from_soup(const meshedit::PolygonSoup& soup) {
    Input in;
    std::vector<std::uint32_t> remap(soup.positions.size(), UINT32_MAX);
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        if (soup.face_offsets[f + 1] - soup.face_offsets[f] != 3) {
            throw std::runtime_error("input face " + std::to_string(f) + " is not a triangle");
        }
        std::array<std::uint32_t, 3> t{};
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t v = soup.indices[soup.face_offsets[f] + i];
            if (remap[v] == UINT32_MAX) {
                remap[v] = static_cast<std::uint32_t>(in.points.size());
                in.points.push_back(soup.positions[v]);
            }
            t[i] = remap[v];
        }
        in.triangles.push_back(t);
    }
    return in;
}

// ------------------------------------------------------------------------------ jobs

struct Job {
    std::string name;
    std::string input;  // "torus_1m", "torus_100k", or a real mesh name
    int levels = 1;
    bool attributes = false;  // MeshEdit only: the torus with texture coordinates and colours
};

std::vector<Job> all_jobs() {
    std::vector<Job> jobs{{"loop_1m_1level", "torus_1m", 1},
                          {"loop_1m_attrs_1level", "torus_1m", 1, true},
                          {"loop_10m_1level", "torus_10m", 1}};
    for (int k = 1; k <= 4; ++k) {
        jobs.push_back({"loop_100k_levels_" + std::to_string(k), "torus_100k", k});
    }
    for (const char* name : {"bunny", "armadillo"}) {
        for (int k = 1; k <= 3; ++k) {
            jobs.push_back(
                {"loop_real_" + std::string(name) + "_levels_" + std::to_string(k), name, k});
        }
    }
    return jobs;
}

Input load_input(const Job& job, const fs::path& data_dir) {
    if (job.input == "torus_1m") {
        return input_from_soup(meshedit::to_polygon_soup(meshedit::shapes::torus(1000, 500)));
    }
    if (job.input == "torus_10m") {  // 5,000,000 vertices, 10,000,000 triangles
        return input_from_soup(meshedit::to_polygon_soup(meshedit::shapes::torus(2500, 2000)));
    }
    if (job.input == "torus_100k") {
        return input_from_soup(meshedit::to_polygon_soup(meshedit::shapes::torus(250, 200)));
    }
    const meshedit::PolygonSoup raw = meshedit::bench::real_mesh(job.input, data_dir);
    meshedit::BuildReport report;
    const meshedit::Mesh mesh = meshedit::build_mesh(raw, &report);
    if (report.repaired()) {
        std::printf(
            "NOTE %s: input repaired by build_mesh (%s); every impl gets the repaired "
            "triangles\n",
            job.input.c_str(), report.summary().c_str());
    }
    return input_from_soup(meshedit::to_polygon_soup(mesh));
}

// ------------------------------------------------------------------------------ impls

using meshedit::bench::Outcome;

Outcome run_meshedit(const Input& in, int levels, int runs,
                     const std::function<void()>& before_copy, bool attributes) {
    meshedit::Mesh input = meshedit::bench::mesh_of(in);
    if (attributes) {
        // The same torus, numbered alike, carrying texture coordinates (two seam loops) and
        // RGBA colours: the cost of carrying them against loop_1m_1level.
        input = meshedit::test::uv_torus(1000, 500);
        meshedit::test::add_colors(input);
    }
    meshedit::Mesh mesh;
    Outcome out;
    out.ms = time_runs(
        runs,
        [&] {
            mesh = meshedit::Mesh();
            before_copy();
            mesh = input;
        },
        [&] {
            for (int i = 0; i < levels; ++i) {
                meshedit::loop_subdivide(mesh);
            }
        });
    out.rss_after_mb = current_rss_mb();
    out.faces_out = static_cast<double>(mesh.n_faces());
    out.vertices_out = static_cast<double>(mesh.n_vertices());
    out.extra["bytes_per_face_exact"] = static_cast<double>(mesh.bytes()) / out.faces_out;
    if (levels == 1) {
        // The compulsory traffic of one level (the report's bandwidth section): every array
        // of the input read once, every array of the result written once.
        out.extra["bytes_moved"] = static_cast<double>(input.bytes() + mesh.bytes());
    }
    return out;
}

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

Outcome run_openmesh(const Input& in, int levels, int runs,
                     const std::function<void()>& before_copy) {
    OMesh input;
    std::vector<OMesh::VertexHandle> vh;
    vh.reserve(in.points.size());
    for (const Vec3& p : in.points) {
        vh.push_back(input.add_vertex(OMesh::Point(static_cast<float>(p.x), static_cast<float>(p.y),
                                                   static_cast<float>(p.z))));
    }
    for (const auto& t : in.triangles) {
        input.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
    }
    if (input.n_faces() != in.triangles.size()) {
        std::printf("NOTE openmesh: %zu of %zu input triangles refused by add_face\n",
                    in.triangles.size() - input.n_faces(), in.triangles.size());
    }
    OMesh mesh;
    Outcome out;
    out.ms = time_runs(
        runs,
        [&] {
            mesh = OMesh();
            before_copy();
            mesh = input;
        },
        [&] {
            OpenMesh::Subdivider::Uniform::LoopT<OMesh> loop;
            loop(mesh, static_cast<std::size_t>(levels));
        });
    out.rss_after_mb = current_rss_mb();
    out.faces_out = static_cast<double>(mesh.n_faces());
    out.vertices_out = static_cast<double>(mesh.n_vertices());
    return out;
}

using CMesh = meshedit::bench::CgalMesh;

Outcome run_cgal(const Input& in, int levels, int runs, const std::function<void()>& before_copy) {
    const CMesh input = meshedit::bench::cgal_mesh(in);
    if (input.number_of_faces() != in.triangles.size()) {
        std::printf("NOTE cgal: %zu of %zu input triangles refused by add_face\n",
                    in.triangles.size() - input.number_of_faces(), in.triangles.size());
    }
    CMesh mesh;
    Outcome out;
    out.ms = time_runs(
        runs,
        [&] {
            mesh = CMesh();
            before_copy();
            mesh = input;
        },
        [&] {
            CGAL::Subdivision_method_3::Loop_subdivision(
                mesh, CGAL::parameters::number_of_iterations(levels));
        });
    out.rss_after_mb = current_rss_mb();
    out.faces_out = static_cast<double>(mesh.number_of_faces());
    out.vertices_out = static_cast<double>(mesh.number_of_vertices());
    return out;
}

Outcome run_opensubdiv(const Input& in, int levels, int runs, bool full_topology,
                       const std::function<void()>& before_copy) {
    // Input preparation (untimed): the descriptor's arrays.
    const std::vector<int> sizes(in.triangles.size(), 3);
    std::vector<int> corners;
    corners.reserve(3 * in.triangles.size());
    for (const auto& t : in.triangles) {
        corners.insert(corners.end(),
                       {static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
    }
    return meshedit::bench::run_opensubdiv(OpenSubdiv::Sdc::SCHEME_LOOP, in.points, sizes, corners,
                                           levels, runs, full_topology, before_copy);
}

// ------------------------------------------------------------------------------ main

}  // namespace

int main(int argc, char** argv) {
    meshedit::bench::JobArgs args;
    std::vector<std::string> names;
    for (const Job& j : all_jobs()) {
        names.push_back(j.name);
    }
    if (const std::optional<int> done =
            meshedit::bench::read_command_line(argc, argv, names, kImpls, args)) {
        return *done;
    }
    std::optional<Job> job;
    for (const Job& j : all_jobs()) {
        if (j.name == args.job) {
            job = j;
        }
    }
    const std::string& job_name = args.job;
    const std::string& impl = args.impl;
    const int runs = args.runs;
    const fs::path& data_dir = args.data;

    Input input;
    try {
        input = load_input(*job, data_dir);
    } catch (const std::exception& e) {
        std::printf("NOTE %s %s failed: %s\n", job_name.c_str(), impl.c_str(), e.what());
        print_result(job_name, impl, {0.0}, {{"skipped", 1}});
        return 1;
    }
    if (job->attributes && impl != "meshedit") {
        std::printf("NOTE %s %s: MeshEdit only (the anchors carry no attributes here)\n",
                    job_name.c_str(), impl.c_str());
        print_result(job_name, impl, {0.0}, {{"skipped", 1}});
        return 0;
    }
    const double faces_in = static_cast<double>(input.triangles.size());
    double faces_expected = faces_in;
    for (int k = 0; k < job->levels; ++k) {
        faces_expected *= 4;
    }
    const int levels = job->levels;
    return meshedit::bench::run_subdivision_job(
        job->name, impl, levels, faces_in, faces_expected,
        [&](const std::function<void()>& before_copy) {
            if (impl == "meshedit") {
                return run_meshedit(input, levels, runs, before_copy, job->attributes);
            }
            if (impl == "openmesh") {
                return run_openmesh(input, levels, runs, before_copy);
            }
            if (impl == "cgal") {
                return run_cgal(input, levels, runs, before_copy);
            }
            return run_opensubdiv(input, levels, runs, impl == "opensubdiv_full", before_copy);
        });
}
