// bench_bandwidth: this machine's memory bandwidth, STREAM-style (McCalpin's copy and triad),
// the physical limit the bandwidth-bound passes (vertex normals, Loop, Catmull-Clark,
// loading) are reported against in docs/performance.md (issue 38).
//
//   bench_bandwidth --job stream_copy|stream_triad --impl machine [--runs N] [--threads N]
//
// Three arrays of 2^24 doubles (128 MiB each: four times the 32 MiB L3 here, as STREAM asks),
// in huge pages as MeshEdit's big arrays are, first touched untimed by the threads that use
// them. Each repetition times one pass on thread_count() threads (MESHEDIT_THREADS: run_bench.py
// measures 1 and all), each thread its own contiguous slice. Bytes are counted as STREAM does:
// copy c = a moves 16 per element, triad a = b + s·c 24; the write-allocate reads are not
// counted, so the figure is the one a pass's compulsory bytes are divided by. GB/s from the
// fastest repetition (STREAM's convention) and from the median.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bench_util.h"
#include "meshedit/core/memory.h"
#include "meshedit/core/threads.h"

namespace mb = meshedit::bench;

namespace {

constexpr std::size_t kElements = std::size_t{1} << 24;
constexpr std::size_t kAlign = std::size_t{2} << 20;  // a huge page

struct FreeDeleter {
    void operator()(double* p) const { std::free(p); }
};
using Buffer = std::unique_ptr<double[], FreeDeleter>;

Buffer huge_buffer() {
    auto* p = static_cast<double*>(std::aligned_alloc(kAlign, kElements * sizeof(double)));
    if (p == nullptr) {
        std::fprintf(stderr, "bench_bandwidth: out of memory\n");
        std::exit(1);
    }
    meshedit::memory::advise_huge_pages(p, kElements * sizeof(double));
    return Buffer(p);
}

// body(begin, end) on `threads` threads, thread t on the t-th slice of [0, kElements).
template <class Body>
void on_slices(unsigned threads, const Body& body) {
    const auto slice = [&](unsigned t) {
        body(kElements * t / threads, kElements * (t + 1) / threads);
    };
    std::vector<std::jthread> workers;
    for (unsigned t = 1; t < threads; ++t) {
        workers.emplace_back(slice, t);
    }
    slice(0);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string jobs[] = {"stream_copy", "stream_triad"};
    const std::string impls[] = {"machine"};
    mb::JobArgs args;
    if (const std::optional<int> done = mb::read_command_line(argc, argv, jobs, impls, args)) {
        return *done;
    }
    const unsigned threads = meshedit::thread_count();
    Buffer a = huge_buffer();
    Buffer b = huge_buffer();
    Buffer c = huge_buffer();
    on_slices(threads, [&](std::size_t begin, std::size_t end) {
        std::fill(a.get() + begin, a.get() + end, 1.0);
        std::fill(b.get() + begin, b.get() + end, 2.0);
        std::fill(c.get() + begin, c.get() + end, 0.5);
    });
    const bool triad = args.job == "stream_triad";
    const double scalar = 3.0;
    double* pa = a.get();
    const double* pb = b.get();
    double* pc = c.get();
    const std::vector<double> ms = mb::time_runs(args.runs, nullptr, [&] {
        on_slices(threads, [&](std::size_t begin, std::size_t end) {
            if (triad) {
                for (std::size_t i = begin; i < end; ++i) {
                    pa[i] = pb[i] + scalar * pc[i];
                }
            } else {
                for (std::size_t i = begin; i < end; ++i) {
                    pc[i] = pa[i];
                }
            }
        });
    });
    // A result the compiler cannot drop, and a check that the passes really ran.
    const double expected = triad ? 2.0 + scalar * 0.5 : 1.0;
    const double seen = triad ? pa[kElements / 2] : pc[kElements / 2];
    if (seen != expected) {
        std::fprintf(stderr, "bench_bandwidth: wrong result %g\n", seen);
        return 1;
    }
    const double bytes = static_cast<double>(kElements) * (triad ? 24.0 : 16.0);
    mb::print_result(args.job, args.impl, ms,
                     {{"bytes", bytes},
                      {"gb_per_s", bytes / (mb::min_of(ms) * 1e6)},
                      {"gb_per_s_median", bytes / (mb::median_of(ms) * 1e6)},
                      {"array_mib", kElements * sizeof(double) / 1048576.0}});
    return 0;
}
