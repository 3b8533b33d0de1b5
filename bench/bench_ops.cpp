// Local operations and vertex normals: MeshEdit vs OpenMesh (TriMesh, double) and CGAL
// (Surface_mesh<Epick::Point_3>), on the same vertex/triangle arrays.
//
//   bench_ops --job flips_1e6|splits_1e6|normals_6p4m --impl meshedit|openmesh|cgal [--runs N]
//
// One (job, impl) per process, so the orchestrator (bench/run_bench.py) can give each a fresh
// address space. Each run works on a fresh copy of the input mesh, made untimed. Prints one
// RESULT line (bench/README.md) and NOTE lines on what differs between the implementations.
//
// Edge indices: the random sequences are indices into each library's own edge numbering. In
// all three that is the order edges were created (while building from the same triangles,
// then by the operations), so the sequences are comparable but do not pick the same
// geometric edges.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bench_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/validate.h"

namespace {

namespace mb = meshedit::bench;

constexpr std::uint64_t kSeed = 0x6d65736865646974ULL;  // "meshedit"
constexpr std::size_t kOps = 1'000'000;

// ----------------------------------------------------------------- the libraries' meshes

struct OmTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};
using OmMesh = OpenMesh::TriMesh_ArrayKernelT<OmTraits>;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgMesh = CGAL::Surface_mesh<Kernel::Point_3>;

meshedit::Mesh make_meshedit(const meshedit::PolygonSoup& soup) {
    return meshedit::build_mesh(soup);
}

OmMesh make_openmesh(const meshedit::PolygonSoup& soup) {
    OmMesh mesh;
    mesh.reserve(soup.positions.size(), soup.indices.size() / 2, soup.n_faces());
    std::vector<OmMesh::VertexHandle> vh;
    vh.reserve(soup.positions.size());
    for (const meshedit::Vec3& p : soup.positions) {
        vh.push_back(mesh.add_vertex(OmMesh::Point(p.x, p.y, p.z)));
    }
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const std::uint32_t* c = &soup.indices[soup.face_offsets[f]];
        mesh.add_face(vh[c[0]], vh[c[1]], vh[c[2]]);
    }
    return mesh;
}

CgMesh make_cgal(const meshedit::PolygonSoup& soup) {
    CgMesh mesh;
    mesh.reserve(static_cast<CgMesh::size_type>(soup.positions.size()),
                 static_cast<CgMesh::size_type>(soup.indices.size() / 2),
                 static_cast<CgMesh::size_type>(soup.n_faces()));
    std::vector<CgMesh::Vertex_index> vh;
    vh.reserve(soup.positions.size());
    for (const meshedit::Vec3& p : soup.positions) {
        vh.push_back(mesh.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
    }
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const std::uint32_t* c = &soup.indices[soup.face_offsets[f]];
        mesh.add_face(vh[c[0]], vh[c[1]], vh[c[2]]);
    }
    return mesh;
}

std::size_t n_faces(const meshedit::Mesh& m) {
    return m.n_faces();
}
std::size_t n_faces(const OmMesh& m) {
    return m.n_faces();
}
std::size_t n_faces(const CgMesh& m) {
    return m.number_of_faces();
}
std::size_t n_edges(const meshedit::Mesh& m) {
    return m.edges_size();
}
std::size_t n_edges(const OmMesh& m) {
    return m.n_edges();
}
std::size_t n_edges(const CgMesh& m) {
    return m.number_of_edges();
}

// ----------------------------------------------------------------- flips

// Each returns whether the flip was applied; each checks the same conditions (live interior
// edge, two triangles, opposite corners distinct and not already joined).
bool flip_one(meshedit::Mesh& mesh, std::uint32_t e) {
    return meshedit::flip(mesh, meshedit::Edge(e)).ok();  // calls is_flip_ok
}

bool flip_one(OmMesh& mesh, std::uint32_t e) {
    const OmMesh::EdgeHandle eh = mesh.edge_handle(static_cast<unsigned>(e));
    if (!mesh.is_flip_ok(eh)) {  // boundary, a == d, existing a-d edge
        return false;
    }
    mesh.flip(eh);
    return true;
}

bool flip_one(CgMesh& mesh, std::uint32_t e) {
    const CgMesh::Edge_index ei(static_cast<CgMesh::size_type>(e));
    if (mesh.is_border(ei)) {
        return false;
    }
    const CgMesh::Halfedge_index h = mesh.halfedge(ei);
    const CgMesh::Halfedge_index t = mesh.opposite(h);
    if (mesh.next(mesh.next(mesh.next(h))) != h || mesh.next(mesh.next(mesh.next(t))) != t) {
        return false;
    }
    const CgMesh::Vertex_index a = mesh.target(mesh.next(h));
    const CgMesh::Vertex_index d = mesh.target(mesh.next(t));
    if (a == d || CGAL::halfedge(a, d, mesh).second) {
        return false;
    }
    CGAL::Euler::flip_edge(h, mesh);
    return true;
}

// ----------------------------------------------------------------- splits (2 -> 4 triangles)

bool split_one(meshedit::Mesh& mesh, std::uint32_t e) {
    return meshedit::split(mesh, meshedit::Edge(e)).ok();  // calls is_split_ok; midpoint
}

bool split_one(OmMesh& mesh, std::uint32_t e) {
    const OmMesh::EdgeHandle eh = mesh.edge_handle(static_cast<unsigned>(e));
    const OmMesh::HalfedgeHandle h = mesh.halfedge_handle(eh, 0);
    const OmMesh::Point mid =
        0.5 * (mesh.point(mesh.from_vertex_handle(h)) + mesh.point(mesh.to_vertex_handle(h)));
    mesh.split(eh, mid);  // TriMesh: connects the new vertex to both opposite corners
    return true;
}

bool split_one(CgMesh& mesh, std::uint32_t e) {
    const CgMesh::Edge_index ei(static_cast<CgMesh::size_type>(e));
    const CgMesh::Halfedge_index h = mesh.halfedge(ei);  // b -> c
    const Kernel::Point_3 mid =
        CGAL::midpoint(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)));
    // hnew: b -> m, followed by h: m -> c.
    const CgMesh::Halfedge_index hnew = CGAL::Euler::split_edge(h, mesh);
    mesh.point(mesh.target(hnew)) = mid;
    const CgMesh::Halfedge_index t = mesh.opposite(h);      // c -> m
    const CgMesh::Halfedge_index tn = mesh.opposite(hnew);  // m -> b
    if (!mesh.is_border(hnew)) {
        CGAL::Euler::split_face(hnew, mesh.next(h), mesh);  // m - a
    }
    if (!mesh.is_border(t)) {
        CGAL::Euler::split_face(t, mesh.next(tn), mesh);  // m - d
    }
    return true;
}

// ----------------------------------------------------------------- jobs

struct Inputs {
    meshedit::PolygonSoup soup;
    std::size_t faces = 0;
};

Inputs torus_soup(int m, int n) {
    Inputs in;
    in.soup = meshedit::to_polygon_soup(meshedit::shapes::torus(m, n));
    in.faces = in.soup.n_faces();
    return in;
}

template <class MeshT>
void check_meshedit(const MeshT&) {}
void check_meshedit(const meshedit::Mesh& mesh) {
    if (const auto error = meshedit::validate(mesh)) {
        std::printf("NOTE meshedit: validate() failed after the last run\n");
    }
}

template <class MeshT>
void run_flips(const std::string& impl, const MeshT& input, std::size_t faces, int runs) {
    std::mt19937_64 rng(kSeed);
    const std::size_t n_e = n_edges(input);
    std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(n_e - 1));
    std::vector<std::uint32_t> seq(kOps);
    for (std::uint32_t& e : seq) {
        e = pick(rng);
    }
    MeshT mesh;
    std::size_t applied = 0;
    const auto ms = mb::time_runs(
        runs, [&] { mesh = input; },
        [&] {
            applied = 0;
            for (const std::uint32_t e : seq) {
                applied += flip_one(mesh, e) ? 1 : 0;
            }
        });
    check_meshedit(mesh);  // untimed: validate() the last run's result
    mb::print_result("flips_1e6", impl, ms,
                     {{"faces", static_cast<double>(faces)},
                      {"applied", static_cast<double>(applied)},
                      {"peak_rss_mb", mb::peak_rss_mb()}});
}

template <class MeshT>
void run_splits(const std::string& impl, const MeshT& input, std::size_t faces, int runs) {
    // Split k picks uniformly among the edges there are before it: each split of a closed
    // triangle mesh adds exactly 3 edges, so the sequence is the same for every library.
    std::mt19937_64 rng(kSeed);
    const std::size_t n_e = n_edges(input);
    std::vector<std::uint32_t> seq(kOps);
    for (std::size_t k = 0; k < kOps; ++k) {
        std::uniform_int_distribution<std::uint32_t> pick(
            0, static_cast<std::uint32_t>(n_e + 3 * k - 1));
        seq[k] = pick(rng);
    }
    MeshT mesh;
    std::size_t applied = 0;
    const auto ms = mb::time_runs(
        runs, [&] { mesh = input; },
        [&] {
            applied = 0;
            for (const std::uint32_t e : seq) {
                applied += split_one(mesh, e) ? 1 : 0;
            }
        });
    if (applied != kOps || n_edges(mesh) != n_e + 3 * kOps) {
        std::printf("NOTE %s: only %zu of %zu splits applied; the sequence is not comparable\n",
                    impl.c_str(), applied, kOps);
    }
    mb::print_result("splits_1e6", impl, ms,
                     {{"faces", static_cast<double>(faces)},
                      {"faces_out", static_cast<double>(n_faces(mesh))},
                      {"applied", static_cast<double>(applied)},
                      {"peak_rss_mb", mb::peak_rss_mb()}});
}

void run_normals(const std::string& impl, const Inputs& in, int runs) {
    std::vector<double> ms;
    double checksum = 0.0;  // sum of |x|+|y|+|z| over the normals: a rough sanity check
    std::map<std::string, double> extra;
    if (impl == "meshedit") {
        const meshedit::Mesh mesh = make_meshedit(in.soup);
        // The compulsory traffic, each array once (the bandwidth section of the report):
        // per face its halfedge (4 B) and deleted flag (1), per halfedge next and to-vertex
        // (8), per vertex the position read and the normal written (24 + 24).
        extra["bytes_moved"] = 5.0 * static_cast<double>(mesh.faces_size()) +
                               8.0 * static_cast<double>(mesh.halfedges_size()) +
                               48.0 * static_cast<double>(mesh.vertices_size());
        std::vector<meshedit::Vec3> normals;  // reused across runs
        ms = mb::time_runs(runs, nullptr, [&] { meshedit::compute_vertex_normals(mesh, normals); });
        for (const meshedit::Vec3& n : normals) {
            checksum += std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
        }
        std::printf(
            "NOTE meshedit: compute_vertex_normals, area-weighted (sum of face area "
            "vectors), output buffer reused across runs\n");
    } else if (impl == "openmesh") {
        OmMesh mesh = make_openmesh(in.soup);
        mesh.request_face_normals();
        mesh.request_vertex_normals();
        ms = mb::time_runs(runs, nullptr, [&] {
            mesh.update_face_normals();
            mesh.update_vertex_normals();
        });
        for (const auto v : mesh.vertices()) {
            const auto& n = mesh.normal(v);
            checksum += std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
        }
        std::printf(
            "NOTE openmesh: timed update_face_normals() + update_vertex_normals() (the "
            "latter needs face normals); OpenMesh sums unit face normals (unweighted), "
            "not area-weighted\n");
    } else {
        CgMesh mesh = make_cgal(in.soup);
        auto vnormals = mesh.add_property_map<CgMesh::Vertex_index, Kernel::Vector_3>(
                                "v:normals", CGAL::NULL_VECTOR)
                            .first;
        ms = mb::time_runs(runs, nullptr, [&] {
            CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, vnormals);
        });
        for (const auto v : mesh.vertices()) {
            const auto& n = vnormals[v];
            checksum += std::abs(n.x()) + std::abs(n.y()) + std::abs(n.z());
        }
        std::printf(
            "NOTE cgal: PMP::compute_vertex_normals computes unit face normals, then per "
            "vertex the 'most visible' direction (maximising the minimum angle to the "
            "incident face normals), falling back to a sine(angle)-weighted sum; not "
            "area-weighted\n");
    }
    extra["faces"] = static_cast<double>(in.faces);
    extra["abs_sum"] = checksum;
    extra["peak_rss_mb"] = mb::peak_rss_mb();
    mb::print_result("normals_6p4m", impl, ms, extra);
}

template <class MeshT>
void run_local(const std::string& job, const std::string& impl, const MeshT& input,
               std::size_t faces, int runs) {
    if (job == "flips_1e6") {
        run_flips(impl, input, faces, runs);
    } else {
        run_splits(impl, input, faces, runs);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const std::string jobs[] = {"flips_1e6", "splits_1e6", "normals_6p4m"};
    const std::string impls[] = {"meshedit", "openmesh", "cgal"};
    meshedit::bench::JobArgs args;
    if (const std::optional<int> done =
            meshedit::bench::read_command_line(argc, argv, jobs, impls, args)) {
        return *done;
    }
    const std::string& job = args.job;
    const std::string& impl = args.impl;
    const int runs = args.runs;

    if (job == "normals_6p4m") {
        run_normals(impl, torus_soup(2000, 1600), runs);  // 6,400,000 faces
        return 0;
    }
    const Inputs in = torus_soup(250, 200);  // 100,000 faces
    if (impl == "meshedit") {
        run_local(job, impl, make_meshedit(in.soup), in.faces, runs);
    } else if (impl == "openmesh") {
        run_local(job, impl, make_openmesh(in.soup), in.faces, runs);
    } else {
        run_local(job, impl, make_cgal(in.soup), in.faces, runs);
    }
    return 0;
}
