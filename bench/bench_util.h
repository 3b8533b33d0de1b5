#pragma once
/// \file
/// Shared by every benchmark program: repeated timing, peak RSS, and the RESULT line that
/// bench/run_bench.py collects (see bench/README.md).

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "meshedit/core/memory.h"
#include "meshedit/core/threads.h"

namespace meshedit::bench {

/// MeshEdit with its huge-page hint off, reported under this name (a reference, not an anchor).
inline constexpr const char* kNoHugePagesImpl = "meshedit_no_huge_pages";

/// The warm protocol (`--warm`): every implementation reuses its memory across repetitions,
/// as a long-running program does, so the times show the algorithm without the page faults
/// of fresh memory. One untimed repetition first; no malloc_trim between repetitions; glibc
/// serves every allocation from its heap and keeps what is freed (M_MMAP_MAX 0, no trimming)
/// for the anchors, and MeshEdit's big-buffer mapper keeps freed buffers for reuse
/// (memory::set_reuse_freed). Results are reported under the job's name + "_warm".
inline bool& warm_protocol() {
    static bool warm = false;
    return warm;
}
inline void use_warm_protocol() {
    warm_protocol() = true;
    memory::set_reuse_freed(true);
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
}

/// Takes the flags every program shares out of the arguments: `--warm`; `--no-huge-pages`,
/// which turns MeshEdit's huge-page hint off (core/memory.h), as `--impl
/// meshedit_no_huge_pages` does (which then runs as `meshedit`), to measure what the hint is
/// worth; and `--threads N`, MeshEdit's thread count (core/threads.h; MESHEDIT_THREADS does
/// the same, run_bench.py uses it). A bad count exits 2. read_command_line() calls it first.
inline void take_common_flags(int& argc, char** argv) {
    static char meshedit_impl[] = "meshedit";
    if (const auto problem = thread_environment_problem()) {
        std::fprintf(stderr, "%s\n", problem->c_str());
        std::exit(2);
    }
    int out = 1;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
            const auto n = parse_thread_count(argv[i + 1]);
            if (!n) {
                std::fprintf(stderr, "--threads: %s\n", bad_thread_count(argv[i + 1]).c_str());
                std::exit(2);
            }
            set_thread_count(*n);
            ++i;
            continue;
        }
        if (std::strcmp(argv[i], "--warm") == 0) {
            use_warm_protocol();
            continue;
        }
        if (std::strcmp(argv[i], "--no-huge-pages") == 0) {
            memory::set_huge_pages_enabled(false);
            continue;
        }
        if (std::strcmp(argv[i], kNoHugePagesImpl) == 0 && i > 1 &&
            std::strcmp(argv[i - 1], "--impl") == 0) {
            memory::set_huge_pages_enabled(false);
            argv[out++] = meshedit_impl;
            continue;
        }
        argv[out++] = argv[i];
    }
    argc = out;
}

/// The command line of every bench program but bench_io_draw (after take_common_flags()):
/// `--list`, or `--job JOB --impl IMPL [--runs N] [--data DIR]`. `--data` is where the real
/// meshes are unpacked (bench_real_meshes.h), by default loop_data beside the executable.
struct JobArgs {
    bool list = false;
    std::string job;
    std::string impl;
    int runs = 5;
    std::filesystem::path data =
        std::filesystem::canonical("/proc/self/exe").parent_path() / "loop_data";
};
/// False on anything else (print the usage).
inline bool parse_job_args(int argc, char** argv, JobArgs& out) {
    if (argc == 2 && std::strcmp(argv[1], "--list") == 0) {
        out.list = true;
        return true;
    }
    if (argc % 2 != 1) {
        return false;
    }
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i];
        if (key == "--job") {
            out.job = argv[i + 1];
        } else if (key == "--impl") {
            out.impl = argv[i + 1];
        } else if (key == "--runs") {
            out.runs = std::atoi(argv[i + 1]);
        } else if (key == "--data") {
            out.data = argv[i + 1];
        } else {
            return false;
        }
    }
    return out.runs >= 1;
}

/// The answer to --list: every "JOB IMPL" pair of `jobs` × `impls`, one a line.
template <class Jobs, class Impls>
void print_pairs(const Jobs& jobs, const Impls& impls) {
    for (const auto& job : jobs) {
        for (const auto& impl : impls) {
            std::printf("%s %s\n", std::string(job).c_str(), std::string(impl).c_str());
        }
    }
}

/// Whether `name` is one of `names`.
template <class Names>
bool one_of(const Names& names, const std::string& name) {
    for (const auto& n : names) {
        if (name == n) {
            return true;
        }
    }
    return false;
}

/// A bench program's whole command line: take_common_flags(), then `--job J --impl I [--runs
/// N] [--data DIR]` naming one of `jobs` × `impls`, or `--list`, which prints every pair.
/// \return the status to exit with now (0 after --list; 2, the usage printed, for anything
/// else), or nullopt when `args` names a pair to run.
template <class Jobs, class Impls>
std::optional<int> read_command_line(int& argc, char** argv, const Jobs& jobs, const Impls& impls,
                                     JobArgs& args) {
    take_common_flags(argc, argv);
    const bool parsed = parse_job_args(argc, argv, args);
    if (parsed && args.list) {
        print_pairs(jobs, impls);
        return 0;
    }
    if (!parsed || !one_of(jobs, args.job) || !one_of(impls, args.impl)) {
        const std::string name = std::filesystem::path(argv[0]).filename().string();
        std::fprintf(stderr,
                     "usage: %s --job JOB --impl IMPL [--runs N] [--data DIR] [--threads N]\n"
                     "       %s --list   (every JOB IMPL pair)\n",
                     name.c_str(), name.c_str());
        return 2;
    }
    return std::nullopt;
}

inline double min_of(std::vector<double> v);
inline double median_of(std::vector<double> v);

/// Short jobs: a job whose median is under kShortJobMs repeats until its timed repetitions add
/// up to kStableTotalMs (at most kMaxRuns of them, and no more once kMaxWallMs of wall time,
/// setups included, have passed), so that its min and median rest on enough samples not to
/// move with one interruption. A 10 ms job gets 50 repetitions, a 1 ms job 500.
inline constexpr double kShortJobMs = 20.0;
inline constexpr double kStableTotalMs = 500.0;
inline constexpr std::size_t kMaxRuns = 2000;
inline constexpr double kMaxWallMs = 30'000.0;

/// Whether time_runs() should add a repetition to `ms`, begun `wall_ms` ago.
inline bool wants_more_runs(const std::vector<double>& ms, double wall_ms) {
    double total = 0;
    for (const double x : ms) {
        total += x;
    }
    return !ms.empty() && median_of(ms) < kShortJobMs && total < kStableTotalMs &&
           ms.size() < kMaxRuns && wall_ms < kMaxWallMs;
}

/// Milliseconds of each of `runs` calls of `body` (more for a short job: wants_more_runs());
/// `setup` runs before each call, untimed. Every run starts cold, as in a fresh process: after
/// the setup, malloc_trim(0) hands the memory that the allocator kept from earlier runs back
/// to the system, so that no implementation's later runs write into pages an earlier run
/// already faulted in.
inline std::vector<double> time_runs(int runs, const std::function<void()>& setup,
                                     const std::function<void()>& body) {
    const auto start = std::chrono::steady_clock::now();
    const auto wall_ms = [&] {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count();
    };
    std::vector<double> ms;
    if (warm_protocol()) {  // one untimed repetition: the memory the timed ones will reuse
        if (setup) {
            setup();
        }
        body();
    }
    for (int i = 0; i < runs || wants_more_runs(ms, wall_ms()); ++i) {
        if (setup) {
            setup();
        }
        if (!warm_protocol()) {
            malloc_trim(0);
        }
        const auto t0 = std::chrono::steady_clock::now();
        body();
        const auto t1 = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    return ms;
}

inline double min_of(std::vector<double> v) {
    return *std::min_element(v.begin(), v.end());
}
inline double median_of(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Peak resident set size of this process so far, in MiB.
inline double peak_rss_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

/// Resident set size of this process now, in MiB (/proc/self/statm).
inline double current_rss_mb() {
    long pages = 0;
    long resident = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) {
            resident = 0;
        }
        std::fclose(f);
    }
    return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) /
           (1024.0 * 1024.0);
}

/// MemAvailable of /proc/meminfo in MiB (0 if unknown): jobs that may not fit are skipped.
inline double mem_available_mb() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    double kib = 0;
    std::string unit;
    while (in >> key >> kib >> unit) {
        if (key == "MemAvailable:") {
            return kib / 1024.0;
        }
    }
    return 0;
}

/// A point for OpenSubdiv's PrimvarRefiner::Interpolate (double coordinates).
struct OsdPoint {
    double x = 0;
    double y = 0;
    double z = 0;
    void Clear(void* = nullptr) { x = y = z = 0; }
    void AddWithWeight(const OsdPoint& p, float w) {
        x += w * p.x;
        y += w * p.y;
        z += w * p.z;
    }
};

/// Prints `RESULT {"job": …, "impl": …, "runs": n, "min_ms": …, "median_ms": …, extras}`.
inline void print_result(const std::string& job, const std::string& impl,
                         const std::vector<double>& ms,
                         const std::map<std::string, double>& extra = {}) {
    const bool no_huge_pages = impl == "meshedit" && !memory::huge_pages_enabled();
    std::printf(
        "RESULT {\"job\": \"%s\", \"impl\": \"%s\", \"runs\": %zu, \"min_ms\": %.3f, "
        "\"median_ms\": %.3f",
        (job + (warm_protocol() ? "_warm" : "")).c_str(),
        no_huge_pages ? kNoHugePagesImpl : impl.c_str(), ms.size(), min_of(ms), median_of(ms));
    for (const auto& [key, value] : extra) {
        std::printf(", \"%s\": %.6g", key.c_str(), value);
    }
    // What MeshEdit's parallel passes could use in this process (anchors ignore it).
    std::printf(", \"meshedit_threads\": %u", thread_count());
    std::printf("}\n");
    std::fflush(stdout);
}

/// Runs `body` (a job's measurement, which prints its RESULT); when it throws, prints `NOTE job
/// impl failed: why` and a RESULT with `"skipped": 1` instead. \return the exit status: 0, or 1
/// when it threw.
template <class Body>
int run_or_skip(const std::string& job, const std::string& impl, const Body& body) {
    try {
        body();
    } catch (const std::exception& e) {
        std::printf("NOTE %s %s failed: %s\n", job.c_str(), impl.c_str(), e.what());
        print_result(job, impl, {0.0}, {{"skipped", 1}});
        return 1;
    }
    return 0;
}

}  // namespace meshedit::bench
