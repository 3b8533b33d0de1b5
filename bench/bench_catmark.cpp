// Catmull-Clark subdivision: MeshEdit against OpenSubdiv Far (Catmark), OpenMesh
// CatmullClarkT and CGAL CatmullClark_subdivision.
//
//     bench_catmark --job cc_1m_1level --impl cgal [--runs 5]
//     bench_catmark --list        (prints every "job impl" pair, one a line)
//
// Jobs: cc_1m_1level (a closed torus of 1000 × 1000 quads, 1M faces → 4M), cc_1m_attrs_1level
// (MeshEdit only: the same torus with texture coordinates and colours, the cost of carrying),
// cc_100k_levels_K (K = 1..3: a closed torus of 330 × 275 quads with one quad in ten cut into two
// triangles, 99,825 mixed faces; cumulative time from the input). Impls: meshedit, openmesh, cgal,
// opensubdiv_min, opensubdiv_full.
//
// Every implementation is built from the same positions and polygons (bench_shapes.h). The
// copy of the input is made in time_runs' untimed setup, which also frees the previous
// result; the timed body is the subdivision only:
//   meshedit         quad_subdivide() K times on a copy of the Mesh (the complete editable
//                    halfedge mesh, double positions);
//   openmesh         CatmullClarkT<PolyMesh> (default traits: float positions),
//                    operator()(mesh, K), its prepare/cleanup included;
//   cgal             Subdivision_method_3::CatmullClark_subdivision(number_of_iterations(K))
//                    on Surface_mesh<Simple_cartesian<double>::Point_3>;
//   opensubdiv_*     TopologyRefinerFactory<TopologyDescriptor>::Create (SCHEME_CATMARK,
//                    VTX_BOUNDARY_EDGE_ONLY), RefineUniform(K) (default options, or
//                    fullTopologyInLastLevel), the vertex buffer of all levels and
//                    PrimvarRefiner::Interpolate of the double positions level by level.
// Memory extras as bench_loop's: peak_rss_mb, rss_before_mb, bytes_per_face (peak − before,
// per output face), bytes_per_face_retained.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>

#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_shapes.h"
#include "bench_subdivision.h"
#include "bench_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/quad_subdivision.h"
#include "support/textured_torus.h"

namespace {

namespace mb = meshedit::bench;
using meshedit::PolygonSoup;
using meshedit::Vec3;

const char* const kImpls[] = {"meshedit", "openmesh", "cgal", "opensubdiv_min", "opensubdiv_full"};

struct Job {
    std::string name;
    int m, n;
    bool mixed;
    int levels;
    bool attributes = false;  // MeshEdit only: texture coordinates and colours carried
};

std::vector<Job> all_jobs() {
    std::vector<Job> jobs{{"cc_1m_1level", 1000, 1000, false, 1},
                          {"cc_1m_attrs_1level", 1000, 1000, false, 1, true}};
    for (int k = 1; k <= 3; ++k) {
        jobs.push_back({"cc_100k_levels_" + std::to_string(k), 330, 275, true, k});
    }
    return jobs;
}

// The polygons of a soup, one at a time: corners(f) is a pointer and a count.
template <class Fn>
void for_each_polygon(const PolygonSoup& soup, const Fn& fn) {
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        fn(&soup.indices[soup.face_offsets[f]], soup.face_offsets[f + 1] - soup.face_offsets[f]);
    }
}

using mb::Outcome;
using Setup = mb::BeforeCopy;

Outcome run_meshedit(const PolygonSoup& soup, int levels, int runs, const Setup& before_copy,
                     bool attributes) {
    meshedit::Mesh input = meshedit::build_mesh(soup);
    if (attributes) {
        // Texture coordinates (two seam loops) and RGBA colours: the cost of carrying them
        // against cc_1m_1level.
        meshedit::test::add_angle_uvs(input);
        meshedit::test::add_colors(input);
    }
    meshedit::Mesh mesh;
    Outcome out;
    out.ms = mb::time_runs(
        runs,
        [&] {
            mesh = meshedit::Mesh();
            before_copy();
            mesh = input;
        },
        [&] {
            for (int i = 0; i < levels; ++i) {
                meshedit::quad_subdivide(mesh);
            }
        });
    out.rss_after_mb = mb::current_rss_mb();
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

using OMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

Outcome run_openmesh(const PolygonSoup& soup, int levels, int runs, const Setup& before_copy) {
    OMesh input;
    std::vector<OMesh::VertexHandle> vh;
    for (const Vec3& p : soup.positions) {
        vh.push_back(input.add_vertex(OMesh::Point(static_cast<float>(p.x), static_cast<float>(p.y),
                                                   static_cast<float>(p.z))));
    }
    std::vector<OMesh::VertexHandle> face;
    for_each_polygon(soup, [&](const std::uint32_t* c, std::size_t k) {
        face.clear();
        for (std::size_t i = 0; i < k; ++i) {
            face.push_back(vh[c[i]]);
        }
        input.add_face(face);
    });
    OMesh mesh;
    Outcome out;
    out.ms = mb::time_runs(
        runs,
        [&] {
            mesh = OMesh();
            before_copy();
            mesh = input;
        },
        [&] {
            OpenMesh::Subdivider::Uniform::CatmullClarkT<OMesh> catmull_clark;
            catmull_clark(mesh, static_cast<std::size_t>(levels));
        });
    out.rss_after_mb = mb::current_rss_mb();
    out.faces_out = static_cast<double>(mesh.n_faces());
    out.vertices_out = static_cast<double>(mesh.n_vertices());
    return out;
}

using Kernel = CGAL::Simple_cartesian<double>;
using CMesh = CGAL::Surface_mesh<Kernel::Point_3>;

Outcome run_cgal(const PolygonSoup& soup, int levels, int runs, const Setup& before_copy) {
    CMesh input;
    std::vector<CMesh::Vertex_index> vh;
    for (const Vec3& p : soup.positions) {
        vh.push_back(input.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
    }
    std::vector<CMesh::Vertex_index> face;
    for_each_polygon(soup, [&](const std::uint32_t* c, std::size_t k) {
        face.clear();
        for (std::size_t i = 0; i < k; ++i) {
            face.push_back(vh[c[i]]);
        }
        input.add_face(face);
    });
    CMesh mesh;
    Outcome out;
    out.ms = mb::time_runs(
        runs,
        [&] {
            mesh = CMesh();
            before_copy();
            mesh = input;
        },
        [&] {
            CGAL::Subdivision_method_3::CatmullClark_subdivision(
                mesh, CGAL::parameters::number_of_iterations(levels));
        });
    out.rss_after_mb = mb::current_rss_mb();
    out.faces_out = static_cast<double>(mesh.number_of_faces());
    out.vertices_out = static_cast<double>(mesh.number_of_vertices());
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    mb::JobArgs args;
    std::vector<std::string> names;
    for (const Job& j : all_jobs()) {
        names.push_back(j.name);
    }
    if (const std::optional<int> done = mb::read_command_line(argc, argv, names, kImpls, args)) {
        return *done;
    }
    std::optional<Job> job;
    for (const Job& j : all_jobs()) {
        if (j.name == args.job) {
            job = j;
        }
    }
    const std::string& impl = args.impl;
    if (job->attributes && impl != "meshedit") {
        std::printf("NOTE %s %s: MeshEdit only (the anchors carry no attributes here)\n",
                    job->name.c_str(), impl.c_str());
        mb::print_result(job->name, impl, {0.0}, {{"skipped", 1}});
        return 0;
    }
    const PolygonSoup soup = mb::quad_torus_soup(job->m, job->n, job->mixed);
    // The first level makes one quad per face corner, every later one four per quad.
    double faces_expected = static_cast<double>(soup.indices.size());
    for (int k = 1; k < job->levels; ++k) {
        faces_expected *= 4;
    }
    const int levels = job->levels;
    return mb::run_subdivision_job(
        job->name, impl, levels, static_cast<double>(soup.n_faces()), faces_expected,
        [&](const Setup& before_copy) {
            if (impl == "meshedit") {
                return run_meshedit(soup, levels, args.runs, before_copy, job->attributes);
            }
            if (impl == "openmesh") {
                return run_openmesh(soup, levels, args.runs, before_copy);
            }
            if (impl == "cgal") {
                return run_cgal(soup, levels, args.runs, before_copy);
            }
            std::vector<int> sizes;
            for_each_polygon(soup, [&](const std::uint32_t*, std::size_t k) {
                sizes.push_back(static_cast<int>(k));
            });
            const std::vector<int> corners(soup.indices.begin(), soup.indices.end());
            return mb::run_opensubdiv(OpenSubdiv::Sdc::SCHEME_CATMARK, soup.positions, sizes,
                                      corners, levels, args.runs, impl == "opensubdiv_full",
                                      before_copy);
        });
}
