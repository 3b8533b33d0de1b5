// The memory budget (budget.h).

#include "meshedit/core/budget.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace meshedit {
namespace {

constexpr std::size_t kMinimum = std::size_t{64} << 20;

std::atomic<std::size_t> g_budget{0};  // 0: not set
std::atomic<bool> g_floor{true};       // false: g_budget may be below kMinimum

}  // namespace

std::size_t physical_memory() {
    // /proc/meminfo rather than sysconf(): the core uses the standard library only.
    std::ifstream in("/proc/meminfo");
    std::string key;
    std::size_t kilobytes = 0;
    std::string unit;
    while (in >> key >> kilobytes >> unit) {
        if (key == "MemTotal:") {
            return kilobytes * 1024;
        }
    }
    return 0;
}

std::optional<std::size_t> parse_byte_size(const std::string& text) {
    std::istringstream in(text);
    double value = 0.0;
    if (!(in >> value) || !(value > 0.0) || !std::isfinite(value)) {
        return std::nullopt;
    }
    std::string suffix;
    in >> suffix;
    double scale = 1.0;
    if (suffix == "K" || suffix == "k" || suffix == "KB" || suffix == "KiB") {
        scale = 1024.0;
    } else if (suffix == "M" || suffix == "MB" || suffix == "MiB") {
        scale = 1024.0 * 1024.0;
    } else if (suffix == "G" || suffix == "GB" || suffix == "GiB") {
        scale = 1024.0 * 1024.0 * 1024.0;
    } else if (suffix == "T" || suffix == "TB" || suffix == "TiB") {
        scale = 1024.0 * 1024.0 * 1024.0 * 1024.0;
    } else if (!suffix.empty()) {
        return std::nullopt;
    }
    std::string rest;
    if (in >> rest) {
        return std::nullopt;
    }
    const double bytes = value * scale;
    if (bytes > 1e18) {
        return std::nullopt;
    }
    return static_cast<std::size_t>(bytes);
}

std::size_t memory_budget() {
    if (const std::size_t set = g_budget.load(std::memory_order_relaxed); set != 0) {
        return g_floor.load(std::memory_order_relaxed) ? std::max(set, kMinimum) : set;
    }
    if (const char* env = std::getenv("MESHEDIT_MEMORY_BUDGET"); env != nullptr && *env != 0) {
        if (const auto bytes = parse_byte_size(env)) {
            return std::max(*bytes, kMinimum);
        }
    }
    const std::size_t physical = physical_memory();
    // Unknown physical memory: assume a small machine rather than none at all.
    return physical == 0 ? std::size_t{4} << 30 : std::max(physical / 2, kMinimum);
}

void set_memory_budget(std::size_t bytes) {
    g_floor.store(true, std::memory_order_relaxed);
    g_budget.store(bytes, std::memory_order_relaxed);
}

void set_memory_budget_without_floor(std::size_t bytes) {
    g_floor.store(false, std::memory_order_relaxed);
    g_budget.store(bytes, std::memory_order_relaxed);
}

std::string format_bytes(double bytes) {
    char text[32];
    if (bytes >= 1e9) {
        std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
    } else if (bytes >= 1e6) {
        std::snprintf(text, sizeof text, "%.1f MB", bytes / 1e6);
    } else {
        std::snprintf(text, sizeof text, "%.0f KB", std::ceil(bytes / 1e3));
    }
    return text;
}

std::optional<std::string> over_budget(double bytes) {
    const double budget = static_cast<double>(memory_budget());
    if (bytes <= budget) {
        return std::nullopt;
    }
    return "would need about " + format_bytes(bytes) + " of memory, over the budget of " +
           format_bytes(budget) + " (--memory-budget or MESHEDIT_MEMORY_BUDGET sets it)";
}

void check_budget(double bytes, const std::string& what) {
    if (const auto over = over_budget(bytes)) {
        throw BudgetError(what + " " + *over);
    }
}

}  // namespace meshedit
