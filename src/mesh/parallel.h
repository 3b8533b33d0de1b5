#pragma once
// Private to meshedit_core: loops over [0, n) cut into chunks that several threads take in
// order (std::jthread only; the core stays standard-library only). Every element belongs to
// exactly one chunk and chunk boundaries do not depend on the number of threads, so a pass
// that writes each element from its own chunk gives the same bits on any number of threads.

#include "meshedit/core/threads.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace meshedit::parallel {

/// Tests only: when nonzero, replaces every pass's `serial_below`, so that a small mesh runs
/// its chunks on several threads too (the chunks stay the same; see ScopedSerialBelow).
inline std::atomic<std::size_t> g_serial_below_for_tests{0};

/// Threads worth using for `n` items: 1 below `serial_below` items (starting threads would
/// cost more than they save), else meshedit::thread_count() (threads.h: set_thread_count(),
/// MESHEDIT_THREADS or all cores), capped by `max_threads` when that is nonzero.
inline unsigned thread_count(std::size_t n, std::size_t serial_below, unsigned max_threads = 0) {
    const std::size_t for_tests = g_serial_below_for_tests.load(std::memory_order_relaxed);
    if (n < (for_tests != 0 ? for_tests : serial_below)) {
        return 1;
    }
    const unsigned setting = meshedit::thread_count();
    return max_threads == 0 ? setting : std::min(setting, max_threads);
}

/// Tests only: every pass of at least `n` items goes parallel while this lives.
class ScopedSerialBelow {
public:
    explicit ScopedSerialBelow(std::size_t n) { g_serial_below_for_tests.store(n); }
    ~ScopedSerialBelow() { g_serial_below_for_tests.store(0); }
    ScopedSerialBelow(const ScopedSerialBelow&) = delete;
    ScopedSerialBelow& operator=(const ScopedSerialBelow&) = delete;
};

/// Runs `body(begin, end)` over [0, n) in chunks of `chunk` elements (the last may be
/// shorter), which `threads` threads, the calling one included, take in increasing order.
/// After each chunk it ran itself, the calling thread calls `report(done)` with the number of
/// elements finished so far by all threads (non-decreasing), so a progress callback that is
/// not thread-safe is only ever called from the caller's thread. If a chunk throws, no new
/// chunks start and the first exception is rethrown once every thread has stopped.
template <class Body, class Report>
void for_chunks(std::size_t n, std::size_t chunk, unsigned threads, const Body& body,
                const Report& report) {
    chunk = std::max<std::size_t>(chunk, 1);
    const std::size_t n_chunks = (n + chunk - 1) / chunk;
    threads = static_cast<unsigned>(std::clamp<std::size_t>(n_chunks, 1, std::max(threads, 1u)));
    std::atomic<std::size_t> next_chunk{0};
    std::atomic<std::size_t> done{0};
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto work = [&](bool caller) {
        for (;;) {
            const std::size_t c = next_chunk.fetch_add(1);
            if (c >= n_chunks || failed.load()) {
                return;
            }
            const std::size_t begin = c * chunk;
            const std::size_t end = std::min(n, begin + chunk);
            try {
                body(begin, end);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(error_mutex);
                if (!failed.exchange(true)) {
                    error = std::current_exception();
                }
                return;
            }
            const std::size_t finished = done.fetch_add(end - begin) + (end - begin);
            if (caller) {
                report(finished);
            }
        }
    };
    {
        std::vector<std::jthread> workers;
        workers.reserve(threads - 1);
        for (unsigned t = 1; t < threads; ++t) {
            workers.emplace_back(work, false);
        }
        work(true);
    }  // the workers join here
    if (error) {
        std::rethrow_exception(error);
    }
}

/// for_chunks() without progress.
template <class Body>
void for_chunks(std::size_t n, std::size_t chunk, unsigned threads, const Body& body) {
    for_chunks(n, chunk, threads, body, [](std::size_t) {});
}

}  // namespace meshedit::parallel
