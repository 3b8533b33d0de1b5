// bench_local_ops: the local operations of issue 16 in bulk. MeshEdit only (no anchor does
// these in bulk): the point is the cost per operation, and that it does not grow with the
// mesh, i.e. that each operation is local (run_bench.py puts the sizes side by side).
//
//   bench_local_ops --job JOB --impl meshedit [--runs N]
//   bench_local_ops --list
//
// Input: a closed quad-dominant torus (no boundary): an m × n grid of quads on a torus
// (R = 1, r = 0.4), one quad in ten cut into two triangles; 10k, 100k, 1M (and 4M) faces.
// Jobs:
//   dissolves_collapses_1e6_quad100k  10^6 attempts on the 100k mesh, each a uniformly random
//       choice of dissolve_edge, dissolve_vertex, collapse (edge) and collapse_face on a
//       uniformly random live element; a fresh copy whenever the mesh falls below half its
//       faces (the copy untimed).
//   local_ops_mix_{10k,100k,1m,4m}  the same mix, 10^5 attempts, a fresh copy (untimed)
//       after every faces/10 attempts, so that every size sees the same relative wear. 4M is
//       past the last cache level: a local op's cost rises while the mesh outgrows the caches
//       and levels off after, where a cost growing with the mesh would keep growing.
//   local_ops_window_{10k,100k,1m,4m}  the mix rows, with elements drawn from a window of
//       1000 faces' worth of indices that slides 2 faces per attempt (the torus numbers every
//       kind row by row, so the window is a band of the surface): the working set no longer
//       grows with the mesh, so what remains is the operations' own cost, which must be flat.
//   local_op_{dissolve_edge,dissolve_vertex,collapse_edge,collapse_face}_{10k,100k,1m}  one
//       op alone, as the mix rows.
//   extrude_all_faces_{10k,100k,1m}  extrude_face on every face of a fresh copy (height half a
//       grid step, shrink 0.2); no reserve for the growth.
// Each attempt calls the op, which checks its predicate (is_*_ok) first and returns the
// refusal, leaving the mesh as it was: refused attempts are counted, not skipped by the
// caller. Random numbers: std::mt19937 with a fixed seed, drawn in the timed region (one draw
// picks the op, one per try picks an element: a random index, drawn again while deleted).
// Every run does the same work; the first validates every mesh before it is replaced and at
// the end (untimed) and the program fails if one is invalid.

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bench_shapes.h"
#include "bench_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/validate.h"

namespace {

namespace mb = meshedit::bench;
using meshedit::Edge;
using meshedit::Face;
using meshedit::Mesh;
using meshedit::PolygonSoup;
using meshedit::Vertex;

constexpr std::uint32_t kSeed = 16;  // issue 16

enum Op { kDissolveEdge, kDissolveVertex, kCollapseEdge, kCollapseFace, kOps };
constexpr const char* kOpNames[kOps] = {"dissolve_edge", "dissolve_vertex", "collapse_edge",
                                        "collapse_face"};

struct Size {
    const char* name;
    int m, n;  // quads around the ring and around the tube; faces = 1.1 m n
};
constexpr Size kSizes[] = {{"10k", 130, 70}, {"100k", 455, 200}, {"1m", 1300, 700}};
// The mix once more at 4M faces: past the last cache level, where a local op's cost levels off.
constexpr Size kBeyondCaches = {"4m", 2600, 1400};

struct Job {
    enum Kind { kMix, kExtrude } kind;
    Size size;
    std::vector<Op> ops;         // drawn uniformly
    std::uint64_t attempts = 0;  // kMix
    std::uint64_t batch = 0;     // attempts per fresh copy; 0: only when below half the faces
    std::uint64_t window = 0;    // faces in the sliding window of indices; 0: the whole mesh
};

constexpr std::uint64_t kWindowFaces = 1000;
constexpr std::uint64_t kWindowStep = 2;  // faces the window slides per attempt

constexpr const char* kMixText =
    "op drawn uniformly from dissolve_edge, dissolve_vertex, collapse (edge) and collapse_face";
constexpr const char* kBatchText =
    "on random live elements; a fresh copy (untimed) after every faces/10 attempts (or below "
    "half the faces), so every size sees the same relative wear";

// In the order of the report: the 10^6 row, then each kind of row from small to large.
std::vector<std::pair<std::string, Job>> jobs() {
    const std::vector<Op> mix = {kDissolveEdge, kDissolveVertex, kCollapseEdge, kCollapseFace};
    const auto batch = [](const Size& s) { return std::uint64_t(s.m) * s.n * 11 / 100; };
    std::vector<std::pair<std::string, Job>> out;
    out.push_back({"dissolves_collapses_1e6_quad100k", {Job::kMix, kSizes[1], mix, 1'000'000, 0}});
    for (const Size& s : kSizes) {
        out.push_back(
            {std::string("local_ops_mix_") + s.name, {Job::kMix, s, mix, 100'000, batch(s)}});
    }
    out.push_back(
        {"local_ops_mix_4m", {Job::kMix, kBeyondCaches, mix, 100'000, batch(kBeyondCaches)}});
    for (const Size& s : {kSizes[0], kSizes[1], kSizes[2], kBeyondCaches}) {
        out.push_back({std::string("local_ops_window_") + s.name,
                       {Job::kMix, s, mix, 100'000, batch(s), kWindowFaces}});
    }
    for (int op = 0; op < kOps; ++op) {
        for (const Size& s : kSizes) {
            out.push_back({std::string("local_op_") + kOpNames[op] + "_" + s.name,
                           {Job::kMix, s, {Op(op)}, 100'000, batch(s)}});
        }
    }
    for (const Size& s : kSizes) {
        out.push_back({std::string("extrude_all_faces_") + s.name, {Job::kExtrude, s, {}, 0, 0}});
    }
    return out;
}

// The INFO line: how the job is run.
std::string describe(const Job& job) {
    if (job.kind == Job::kExtrude) {
        return "extrude_face on every face of a fresh copy (height half a grid step, shrink "
               "0.2), in index order; no reserve for the growth";
    }
    const std::string what =
        job.ops.size() > 1 ? kMixText : kOpNames[job.ops[0]] + std::string(" alone");
    if (job.batch == 0) {
        return std::to_string(job.attempts) + " attempts, " + what +
               ", on a random live element; a fresh copy (untimed) whenever the mesh falls "
               "below half its faces";
    }
    if (job.window > 0) {
        return std::to_string(job.attempts) + " attempts, " + what + ", on random live " +
               "elements of a window of " + std::to_string(job.window) + " faces' worth of " +
               "indices sliding " + std::to_string(kWindowStep) + " faces per attempt; a " +
               "fresh copy (untimed) after every faces/10 attempts";
    }
    return std::to_string(job.attempts) + " attempts, " + what + ", " + kBatchText;
}

std::uint32_t pick(std::mt19937& rng, std::size_t n) {
    return std::uint32_t((std::uint64_t(rng()) * n) >> 32);
}

// Where elements are drawn from: every index, or `width` faces' worth of indices from face
// `base` on, scaled to each kind's array.
struct Window {
    std::uint64_t base = 0;
    std::uint64_t width = 0;  // 0: every index
};

template <class H>
H random_live(const Mesh& mesh, std::mt19937& rng, std::size_t size, const Window& window) {
    if (window.width > 0) {
        const std::size_t faces = mesh.faces_size();
        const std::size_t start = window.base * size / faces;
        const std::size_t width = std::max<std::size_t>(1, window.width * size / faces);
        for (int tries = 0; tries < 1000; ++tries) {
            const H h(std::uint32_t((start + pick(rng, width)) % size));
            if (!mesh.is_deleted(h)) {
                return h;
            }
        }
        // The window is used up (never seen at these rates): anywhere then.
    }
    for (;;) {
        const H h(pick(rng, size));
        if (!mesh.is_deleted(h)) {
            return h;
        }
    }
}

bool attempt(Mesh& mesh, Op op, std::mt19937& rng, const Window& w) {
    switch (op) {
        case kDissolveEdge:
            return dissolve_edge(mesh, random_live<Edge>(mesh, rng, mesh.edges_size(), w)).ok();
        case kDissolveVertex:
            return dissolve_vertex(mesh, random_live<Vertex>(mesh, rng, mesh.vertices_size(), w))
                .ok();
        case kCollapseEdge:
            return collapse(mesh, random_live<Edge>(mesh, rng, mesh.edges_size(), w)).ok();
        default:
            return collapse_face(mesh, random_live<Face>(mesh, rng, mesh.faces_size(), w)).ok();
    }
}

void check_valid(const Mesh& mesh, const std::string& job, const char* when) {
    if (const auto error = meshedit::validate(mesh)) {
        std::fprintf(stderr, "bench_local_ops: %s: invalid mesh %s: [%s] %s\n", job.c_str(), when,
                     error->invariant.c_str(), error->message.c_str());
        std::exit(1);
    }
}

struct Tally {
    std::uint64_t attempted[kOps] = {}, applied[kOps] = {}, copies = 0;
    std::uint64_t total_applied() const {
        std::uint64_t sum = 0;
        for (const std::uint64_t a : applied) {
            sum += a;
        }
        return sum;
    }
};

// One run of a kMix job: milliseconds of the attempts alone (fresh copies excluded).
double run_mix(const std::string& name, const Job& job, const Mesh& pristine, Mesh& mesh,
               Tally& tally, bool check) {
    using Clock = std::chrono::steady_clock;
    std::mt19937 rng(kSeed);
    mesh = pristine;
    malloc_trim(0);  // cold, as bench::time_runs
    const std::size_t half = pristine.n_faces() / 2;
    const std::size_t n_ops = job.ops.size();
    double ms = 0;
    std::uint64_t in_batch = 0;
    Window window{0, job.window};
    auto t0 = Clock::now();
    for (std::uint64_t i = 0; i < job.attempts; ++i) {
        const Op op = n_ops == 1 ? job.ops[0] : job.ops[pick(rng, n_ops)];
        ++tally.attempted[op];
        tally.applied[op] += attempt(mesh, op, rng, window) ? 1 : 0;
        window.base = (window.base + kWindowStep) % mesh.faces_size();
        if (++in_batch == job.batch || mesh.n_faces() < half) {
            if (i + 1 == job.attempts) {
                break;  // the last mesh: validated by the caller
            }
            ms += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
            if (check) {
                check_valid(mesh, name, "before a fresh copy");
            }
            mesh = pristine;
            ++tally.copies;
            in_batch = 0;
            window.base = 0;
            t0 = Clock::now();
        }
    }
    ms += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    return ms;
}

int run_mix_job(const std::string& name, const Job& job, int runs) {
    const Mesh pristine = mb::quad_torus(job.size.m, job.size.n, true);
    Mesh mesh;
    std::vector<double> ms;
    Tally first;
    for (int r = 0; r < runs; ++r) {
        Tally tally;
        ms.push_back(run_mix(name, job, pristine, mesh, tally, r == 0));
        if (r == 0) {
            check_valid(mesh, name, "at the end");
            first = tally;
        } else if (tally.total_applied() != first.total_applied()) {
            std::fprintf(stderr, "bench_local_ops: %s: run %d applied %llu ops, run 1 %llu\n",
                         name.c_str(), r + 1,
                         static_cast<unsigned long long>(tally.total_applied()),
                         static_cast<unsigned long long>(first.total_applied()));
            return 1;
        }
    }
    const double median = mb::median_of(ms);
    const auto applied = double(first.total_applied());
    std::printf("INFO %s\n", describe(job).c_str());
    std::string per_op = "applied / attempted:";
    for (int op = 0; op < kOps; ++op) {
        if (first.attempted[op] > 0) {
            per_op.append(" ").append(kOpNames[op]).append(" ");
            per_op.append(std::to_string(first.applied[op])).append(" / ");
            per_op.append(std::to_string(first.attempted[op])).append(";");
        }
    }
    per_op.back() = '.';
    std::printf("INFO %s\n", per_op.c_str());
    mb::print_result(name, "meshedit", ms,
                     {{"faces", double(pristine.n_faces())},
                      {"attempts", double(job.attempts)},
                      {"applied", applied},
                      {"refused", double(job.attempts) - applied},
                      {"fresh_copies", double(first.copies)},
                      {"ns_per_attempt", median * 1e6 / double(job.attempts)},
                      {"ns_per_applied", applied > 0 ? median * 1e6 / applied : 0.0},
                      {"peak_rss_mb", mb::peak_rss_mb()}});
    return 0;
}

int run_extrude_job(const std::string& name, const Job& job, int runs) {
    const Mesh pristine = mb::quad_torus(job.size.m, job.size.n, true);
    const auto n_faces = static_cast<std::uint32_t>(pristine.faces_size());
    std::size_t sides = 0;
    for (const Face f : pristine.faces()) {
        sides += pristine.valence(f);
    }
    const double height = 0.5 * 2.0 * M_PI * 0.4 / job.size.n;
    Mesh mesh;
    std::uint64_t refused = 0;
    const std::vector<double> ms = mb::time_runs(
        runs,
        [&] {
            mesh = pristine;
            refused = 0;
        },
        [&] {
            for (std::uint32_t f = 0; f < n_faces; ++f) {
                refused += extrude_face(mesh, Face(f), height, 0.2) ? 0 : 1;
            }
        });
    check_valid(mesh, name, "after extruding");
    if (refused != 0 || mesh.n_faces() != n_faces + sides) {
        std::fprintf(stderr, "bench_local_ops: %s: %llu refused, %zu faces (expected %zu)\n",
                     name.c_str(), static_cast<unsigned long long>(refused), mesh.n_faces(),
                     std::size_t(n_faces) + sides);
        return 1;
    }
    std::printf("INFO %s\n", describe(job).c_str());
    mb::print_result(name, "meshedit", ms,
                     {{"faces", double(n_faces)},
                      {"faces_out", double(mesh.n_faces())},
                      {"ns_per_face", mb::median_of(ms) * 1e6 / n_faces},
                      {"peak_rss_mb", mb::peak_rss_mb()}});
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const auto all = jobs();
    std::vector<std::string> names;
    for (const auto& [job, spec] : all) {
        names.push_back(job);
    }
    const std::string impls[] = {"meshedit"};
    mb::JobArgs args;
    if (const std::optional<int> done = mb::read_command_line(argc, argv, names, impls, args)) {
        return *done;
    }
    const std::string& job = args.job;
    const int runs = args.runs;
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const auto& j) { return j.first == job; });
    return it->second.kind == Job::kMix ? run_mix_job(job, it->second, runs)
                                        : run_extrude_job(job, it->second, runs);
}
