// bench_build: the halfedge builder on the shapes that once made loading quadratic (issue 14):
// a triangle fan whose hub is vertex 0 (every face shares it, so its pairing bucket holds
// them all) and one polygon with as many corners as the fan has faces (the repeated-corner
// check). Each at 100k, 300k and 1M faces (corners), plus a torus of 1M triangles as the
// ordinary shape to compare with. MeshEdit only: the point is the cost per face staying flat
// as the size grows (run_bench.py puts the sizes side by side), not a ratio to a library.
//
//   bench_build --job build_fan_hub_first_1m|build_polygon_1m|build_torus_1m|… --impl meshedit
//               [--runs N]
//   bench_build --list
//
// The soup is made untimed; the timed part is build_mesh() alone, as read_mesh() calls it.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "bench_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/validate.h"

namespace {

namespace mb = meshedit::bench;
using meshedit::PolygonSoup;
using meshedit::Vec3;

// n triangles (0, i, i+1) around the hub, vertex 0, on an open disk.
PolygonSoup fan(std::uint32_t n) {
    PolygonSoup soup;
    soup.positions.reserve(n + 2);
    soup.positions.push_back({0, 0, 0});
    for (std::uint32_t i = 0; i <= n; ++i) {
        const double a = 2.0 * M_PI * 0.999 * i / n;  // not quite closed: a disk, not a cone
        soup.positions.push_back({std::cos(a), std::sin(a), 0});
    }
    for (std::uint32_t i = 1; i <= n; ++i) {
        soup.add_face({0, i, i + 1});
    }
    return soup;
}

// One polygon with n corners on a circle.
PolygonSoup polygon(std::uint32_t n) {
    PolygonSoup soup;
    soup.positions.reserve(n);
    std::vector<std::uint32_t> corners(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        soup.positions.push_back({std::cos(a), std::sin(a), 0});
        corners[i] = i;
    }
    soup.add_face_range(corners);
    return soup;
}

// The 1000 × 500 torus's triangles, as a soup.
PolygonSoup torus() {
    const meshedit::Mesh mesh = meshedit::shapes::torus(1000, 500);
    PolygonSoup soup;
    for (meshedit::Vertex v : mesh.vertices()) {
        soup.positions.push_back(mesh.position(v));
    }
    for (meshedit::Face f : mesh.faces()) {
        std::vector<std::uint32_t> corners;
        for (meshedit::Vertex v : mesh.vertices(f)) {
            corners.push_back(v.idx());
        }
        soup.add_face_range(corners);
    }
    return soup;
}

std::map<std::string, PolygonSoup (*)()> jobs() {
    std::map<std::string, PolygonSoup (*)()> out;
    out["build_fan_hub_first_100k"] = [] { return fan(100'000); };
    out["build_fan_hub_first_300k"] = [] { return fan(300'000); };
    out["build_fan_hub_first_1m"] = [] { return fan(1'000'000); };
    out["build_polygon_100k"] = [] { return polygon(100'000); };
    out["build_polygon_300k"] = [] { return polygon(300'000); };
    out["build_polygon_1m"] = [] { return polygon(1'000'000); };
    out["build_torus_1m"] = torus;
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    const auto all = jobs();
    std::vector<std::string> names;
    for (const auto& [job, make] : all) {
        names.push_back(job);
    }
    const std::string impls[] = {"meshedit"};
    mb::JobArgs args;
    if (const std::optional<int> done = mb::read_command_line(argc, argv, names, impls, args)) {
        return *done;
    }
    const std::string& job = args.job;
    const std::string& impl = args.impl;
    const int runs = args.runs;
    const auto it = all.find(job);
    const PolygonSoup soup = it->second();
    meshedit::Mesh mesh;
    const std::vector<double> ms = mb::time_runs(
        runs, [&] { mesh = meshedit::Mesh(); }, [&] { mesh = build_mesh(soup); });
    if (meshedit::validate(mesh) || mesh.n_faces() != soup.n_faces()) {
        std::fprintf(stderr, "bench_build: %s built a wrong mesh\n", job.c_str());
        return 1;
    }
    // Per face for fans and tori, per corner for the polygon (its one face has n corners).
    const double units =
        static_cast<double>(soup.n_faces() == 1 ? soup.indices.size() : soup.n_faces());
    mb::print_result(job, impl, ms,
                     {{"faces_out", static_cast<double>(mesh.n_faces())},
                      {"ns_per_face_or_corner", mb::median_of(ms) * 1e6 / units},
                      {"peak_rss_mb", mb::peak_rss_mb()}});
    return 0;
}
