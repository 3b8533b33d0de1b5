// Hole filling (issue 35): MeshEdit's fill_hole_fair() against CGAL's
// Polygon_mesh_processing::triangulate_refine_and_fair_hole(), on holes cut out of real scans,
// timed, with the patch measured against the surface that was cut away.
//
//     bench_fill --job fill_bunny_1m_100 --impl cgal [--runs 5] [--data DIR]
//     bench_fill --list
//
// Scans (CGAL's demo data, bench_real_meshes.h), both closed: bunny00.off Loop-subdivided twice
// (1,206,528 triangles, as bench_simplify; three times, 4.8M, for the largest hole) and
// armadillo.off Loop-subdivided twice (832,000). Jobs fill_<scan>_<N>: one hole of at least N
// border edges
// (bench_holes.h: a disc of faces grown from a fixed seed face in the order of the distance
// over the faces' centroids, closed up so that its border is one simple loop; `hole_edges` is
// what it came to). The same holed surface goes to both.
// Impls (the timed body is the fill call alone; the copy of the holed input is untimed):
//   meshedit   fill_hole_fair(mesh, h, {}) on the halfedge Mesh: its defaults, Liepa's density
//              √2 and cotangent fairing (bi-Laplacian) of the new vertices; h, a halfedge of
//              the hole, found untimed, as for CGAL (fill_holes_fair(), which finds every hole
//              itself and turns a part it closes outward, is the repair step's call);
//   cgal       triangulate_refine_and_fair_hole(mesh, h, faces, vertices) on
//              Surface_mesh<Simple_cartesian<double>::Point_3> with its defaults: Delaunay
//              search space (2D constrained Delaunay when the hole is near planar), density
//              control √2, fairing continuity 1 (bi-Laplacian) with its cotangent weights,
//              Eigen's SparseLU; h, a halfedge of the hole, found untimed.
// Quality, by the same code for both (bench_quality.h), of the patch (the faces the fill
// added): hausdorff_pct, the symmetric Hausdorff distance between the patch and the removed
// faces, 100,000 points sampled by area on each, measured to the other through a
// TriangleTree, in % of the scan's bounding-box diagonal; patch_to_original_pct, the patch's
// side alone; bounded_hausdorff_pct and bounded_patch_to_original_pct, the same two by CGAL's
// bounded-error algorithm (within 0.1% of the true distance; the sampler gives a lower bound);
// min_angle_deg of the patch's triangles; patch_faces, patch_vertices (new).

#include <CGAL/Kernel/global_functions.h>  // distance.h needs the 3D midpoint first
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "bench_cgal.h"
#include "bench_holes.h"
#include "bench_quality.h"
#include "bench_real_meshes.h"
#include "bench_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/repair/repair.h"

namespace {

namespace mb = meshedit::bench;
namespace fs = std::filesystem;
using mb::Surface;
using meshedit::Vec3;

struct Scan {
    const char* name;  // in the job's name
    const char* file;  // the demo mesh
    int levels;        // Loop subdivisions
    Vec3 seed;         // the hole grows from the face whose centroid is nearest
    std::vector<int> sizes;
};

// The seeds: a point of the input scan on the bunny's flank (a vertex of bunny00 at mid-length,
// low on the body) and one on the armadillo's back (a vertex at mid-width, chest height). A
// border of 2,000 edges does not fit on the 1.2M-face bunny (a disc that long would cover
// more than half of it), so that size runs on the bunny subdivided once more; on the
// armadillo a disc past 300 edges wraps around its torso (two holes), so it stops there.
const Scan kScans[] = {
    {"bunny_1m", "bunny", 2, {-0.0047601, -0.182012, 0.37846}, {10, 30, 100, 300, 1000}},
    {"bunny_5m", "bunny", 3, {-0.0047601, -0.182012, 0.37846}, {2000}},
    {"armadillo_832k", "armadillo", 2, {-0.979182, 33.2881, -9.63862}, {10, 30, 100, 300}}};

std::string job_name(const Scan& s, int size) {
    return "fill_" + std::string(s.name) + "_" + std::to_string(size);
}

struct Outcome {
    std::vector<double> ms;
    Surface patch;
    std::size_t new_vertices = 0;
    bool faired = false;
};

// The faces from `first` on (those a fill added), with the points they use.
Surface patch_of(const Surface& s, std::size_t first) {
    Surface out;
    out.points = s.points;
    out.triangles.assign(s.triangles.begin() + static_cast<std::ptrdiff_t>(first),
                         s.triangles.end());
    return out;
}

// The surface with only the points its triangles use (CGAL's mesh of it then has no
// isolated vertices).
Surface compacted(const Surface& s) {
    Surface out;
    std::vector<std::uint32_t> index(s.points.size(), UINT32_MAX);
    for (const auto& t : s.triangles) {
        std::array<std::uint32_t, 3> u{};
        for (int i = 0; i < 3; ++i) {
            if (index[t[i]] == UINT32_MAX) {
                index[t[i]] = static_cast<std::uint32_t>(out.points.size());
                out.points.push_back(s.points[t[i]]);
            }
            u[i] = index[t[i]];
        }
        out.triangles.push_back(u);
    }
    return out;
}

// The Hausdorff distance from `from` to `to` by CGAL's bounded-error algorithm (Krivokuća et
// al.): within `bound` of the true one, where the sampler only gives a lower bound.
double bounded_hausdorff(const Surface& from, const Surface& to, double bound) {
    const mb::CgalMesh a = mb::cgal_mesh(compacted(from));
    const mb::CgalMesh b = mb::cgal_mesh(compacted(to));
    return CGAL::Polygon_mesh_processing::bounded_error_Hausdorff_distance<CGAL::Sequential_tag>(
        a, b, bound);
}

Outcome run_meshedit(const Surface& in, int runs) {
    const meshedit::Mesh input = mb::mesh_of(in);
    meshedit::Halfedge border;
    for (const meshedit::Halfedge h : input.halfedges()) {
        if (input.is_boundary(h)) {
            border = h;
            break;
        }
    }
    meshedit::Mesh mesh;
    meshedit::RepairResult result;
    Outcome out;
    out.ms = mb::time_runs(
        runs, [&] { mesh = input; },
        [&] { result = meshedit::fill_hole_fair(mesh, border, meshedit::FairFillOptions{}); });
    if (result.count != 1) {
        throw std::runtime_error("fill_hole_fair filled " + std::to_string(result.count) +
                                 " holes: " + result.sentence);
    }
    out.faired = result.sentence.find("faired") != std::string::npos &&
                 result.sentence.find("not faired") == std::string::npos;
    out.new_vertices = mesh.n_vertices() - input.n_vertices();
    // Faces are appended (the patch's flips and pokes keep to its own faces), and surface_of()
    // keeps their order.
    out.patch = patch_of(mb::surface_of(mesh), input.n_faces());
    return out;
}

Outcome run_cgal(const Surface& in, int runs) {
    const mb::CgalMesh input = mb::cgal_mesh(in);
    mb::CgalMesh::Halfedge_index border;
    for (const auto h : input.halfedges()) {
        if (input.is_border(h)) {
            border = h;
            break;
        }
    }
    mb::CgalMesh mesh;
    std::vector<mb::CgalMesh::Face_index> faces;
    std::vector<mb::CgalMesh::Vertex_index> vertices;
    bool faired = false;
    Outcome out;
    out.ms = mb::time_runs(
        runs,
        [&] {
            mesh = input;
            faces.clear();
            vertices.clear();
        },
        [&] {
            faired = std::get<0>(CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole(
                mesh, border, std::back_inserter(faces), std::back_inserter(vertices)));
        });
    out.faired = faired;
    out.new_vertices = vertices.size();
    // Surface_mesh appends the new faces (the input has no removed elements to reuse).
    const std::size_t first = input.number_of_faces();
    out.patch = patch_of(mb::surface_of(mesh), first);
    if (out.patch.triangles.size() != faces.size()) {
        throw std::runtime_error("CGAL's patch is not the faces it appended");
    }
    return out;
}

Surface scan_surface(const Scan& scan, const fs::path& data_dir) {
    meshedit::Mesh mesh = meshedit::build_mesh(mb::real_mesh(scan.file, data_dir));
    for (int i = 0; i < scan.levels; ++i) {
        meshedit::loop_subdivide(mesh);
    }
    return mb::surface_of(mesh);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> jobs;
    for (const Scan& s : kScans) {
        for (const int n : s.sizes) {
            jobs.push_back(job_name(s, n));
        }
    }
    const std::string impls[] = {"meshedit", "cgal"};
    mb::JobArgs args;
    if (const std::optional<int> done = mb::read_command_line(argc, argv, jobs, impls, args)) {
        return *done;
    }
    const std::string& job = args.job;
    const std::string& impl = args.impl;
    return mb::run_or_skip(job, impl, [&] {
        const Scan* scan = nullptr;
        int size = 0;
        for (const Scan& s : kScans) {
            for (const int n : s.sizes) {
                if (job_name(s, n) == job) {
                    scan = &s;
                    size = n;
                }
            }
        }
        const Surface whole = scan_surface(*scan, args.data);
        std::uint32_t seed_face = 0;
        double nearest = 1e300;
        for (std::size_t f = 0; f < whole.triangles.size(); ++f) {
            const auto& t = whole.triangles[f];
            const double d = distance(
                (whole.points[t[0]] + whole.points[t[1]] + whole.points[t[2]]) * (1.0 / 3.0),
                scan->seed);
            if (d < nearest) {
                nearest = d;
                seed_face = static_cast<std::uint32_t>(f);
            }
        }
        const mb::CutHole hole = mb::cut_hole(whole, seed_face, static_cast<std::size_t>(size));
        const Outcome out = impl == "meshedit" ? run_meshedit(hole.holed, args.runs)
                                               : run_cgal(hole.holed, args.runs);
        meshedit::BoundingBox box;
        for (const Vec3& p : whole.points) {
            box.add(p);
        }
        const meshedit::TriangleTree original(hole.removed.points, hole.removed.triangles);
        const meshedit::TriangleTree patch(out.patch.points, out.patch.triangles);
        const double to_original = mb::one_sided(out.patch, original);
        const double to_patch = mb::one_sided(hole.removed, patch);
        const double pct = 100.0 / box.diagonal();
        const double bound = 1e-3 * std::max(to_original, to_patch) + 1e-12 * box.diagonal();
        const double bounded_to_original = bounded_hausdorff(out.patch, hole.removed, bound);
        const double bounded_to_patch = bounded_hausdorff(hole.removed, out.patch, bound);
        mb::print_result(
            job, impl, out.ms,
            {{"faces_in", static_cast<double>(hole.holed.triangles.size())},
             {"hole_edges", static_cast<double>(hole.border_edges)},
             {"removed_faces", static_cast<double>(hole.removed.triangles.size())},
             {"patch_faces", static_cast<double>(out.patch.triangles.size())},
             {"patch_vertices", static_cast<double>(out.new_vertices)},
             {"faired", out.faired ? 1.0 : 0.0},
             {"hausdorff_pct", pct * std::max(to_original, to_patch)},
             {"patch_to_original_pct", pct * to_original},
             {"bounded_hausdorff_pct", pct * std::max(bounded_to_original, bounded_to_patch)},
             {"bounded_patch_to_original_pct", pct * bounded_to_original},
             {"min_angle_deg", mb::min_angle_deg(out.patch)},
             {"peak_rss_mb", mb::peak_rss_mb()}});
    });
}
