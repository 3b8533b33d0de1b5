// Loop subdivision throughput. Each iteration subdivides a fresh copy of the input (the copy
// is made with the timer paused). Counters: faces after subdivision, and mesh.bytes() per
// face afterwards (every property array's capacity, so it includes any slack).

#include <benchmark/benchmark.h>

#include <cstddef>

#include "meshedit/core/mesh.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"

namespace {

using meshedit::Mesh;

// torus(m, n) has 2·m·n triangles.
const Mesh& torus_1m() {
    static const Mesh mesh = meshedit::shapes::torus(1000, 500);  // 1,000,000 faces
    return mesh;
}
const Mesh& torus_100k() {
    static const Mesh mesh = meshedit::shapes::torus(250, 200);  // 100,000 faces
    return mesh;
}

void report(benchmark::State& state, const Mesh& input, const Mesh& result) {
    state.counters["faces_in"] = static_cast<double>(input.n_faces());
    state.counters["faces_out"] = static_cast<double>(result.n_faces());
    state.counters["bytes_per_face"] =
        static_cast<double>(result.bytes()) / static_cast<double>(result.n_faces());
    state.counters["faces_out_per_s"] = benchmark::Counter(
        static_cast<double>(result.n_faces()), benchmark::Counter::kIsIterationInvariantRate);
}

void run_levels(benchmark::State& state, const Mesh& input, int levels) {
    Mesh result;
    for (auto _ : state) {
        state.PauseTiming();
        result = Mesh();  // free the previous result outside the timed region
        Mesh mesh = input;
        state.ResumeTiming();
        for (int i = 0; i < levels; ++i) {
            meshedit::loop_subdivide(mesh);
        }
        benchmark::DoNotOptimize(mesh.position_vector().data());
        state.PauseTiming();
        result = std::move(mesh);
        state.ResumeTiming();
    }
    report(state, input, result);
}

// One level on the 1M-face torus (4M faces out).
void BM_Loop_Torus1M(benchmark::State& state) {
    run_levels(state, torus_1m(), 1);
}
BENCHMARK(BM_Loop_Torus1M)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(5);

// Levels 1-4 on the 100k-face torus (400k ... 25.6M faces out).
void BM_Loop_Torus100k(benchmark::State& state) {
    run_levels(state, torus_100k(), static_cast<int>(state.range(0)));
}
BENCHMARK(BM_Loop_Torus100k)
    ->DenseRange(1, 4)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3);

// The classic reference on a small mesh, for scale (it is not meant to be fast).
void BM_LoopClassic_Torus100k(benchmark::State& state) {
    Mesh result;
    for (auto _ : state) {
        state.PauseTiming();
        result = Mesh();
        Mesh mesh = torus_100k();
        state.ResumeTiming();
        meshedit::loop_subdivide_classic(mesh);
        state.PauseTiming();
        result = std::move(mesh);
        state.ResumeTiming();
    }
    report(state, torus_100k(), result);
}
BENCHMARK(BM_LoopClassic_Torus100k)->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3);

}  // namespace
