#include "meshedit/core/threads.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <thread>

namespace meshedit {
namespace {

constexpr unsigned kUnset = std::numeric_limits<unsigned>::max();
std::atomic<unsigned> g_set{kUnset};

struct Environment {
    std::optional<unsigned> count;  // nullopt: unset or bad
    std::optional<std::string> problem;
};

// Read once: a pass in the middle of its work must not see the setting change under it.
const Environment& environment() {
    static const Environment env = [] {
        Environment e;
        const char* text = std::getenv("MESHEDIT_THREADS");
        if (text == nullptr || *text == '\0') {
            return e;
        }
        e.count = parse_thread_count(text);
        if (!e.count) {
            e.problem = "MESHEDIT_THREADS: " + bad_thread_count(text);
        }
        return e;
    }();
    return env;
}

unsigned resolve(unsigned n) {
    return n == 0 ? hardware_threads() : n;
}

}  // namespace

unsigned hardware_threads() {
    return std::max(1u, std::thread::hardware_concurrency());
}

unsigned thread_count() {
    if (const unsigned set = g_set.load(std::memory_order_relaxed); set != kUnset) {
        return resolve(set);
    }
    const Environment& env = environment();
    return resolve(env.count.value_or(0));
}

void set_thread_count(unsigned n) {
    if (n > kMaxThreads) {
        throw std::invalid_argument("set_thread_count: " + bad_thread_count(std::to_string(n)));
    }
    g_set.store(n, std::memory_order_relaxed);
}

void reset_thread_count() {
    g_set.store(kUnset, std::memory_order_relaxed);
}

std::optional<unsigned> parse_thread_count(std::string_view text) {
    if (text.empty() || text.size() > 5) {
        return std::nullopt;
    }
    unsigned n = 0;
    for (const char c : text) {
        if (c < '0' || c > '9') {
            return std::nullopt;
        }
        n = n * 10 + static_cast<unsigned>(c - '0');
    }
    if (n > kMaxThreads) {
        return std::nullopt;
    }
    return n;
}

std::optional<std::string> thread_environment_problem() {
    return environment().problem;
}

std::string bad_thread_count(std::string_view text) {
    return "'" + std::string(text) +
           "' is not a thread count (a whole number from 0, meaning all cores, to " +
           std::to_string(kMaxThreads) + ")";
}

}  // namespace meshedit
