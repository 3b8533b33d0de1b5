// Big-buffer mapping and huge-page hints (memory.h). The only core file that calls the
// operating system directly: mmap/madvise have no standard-library counterpart. Elsewhere,
// and under AddressSanitizer (which guards operator new's buffers, not mmap's), big buffers
// come from aligned operator new, without the hint.

#include "meshedit/core/memory.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#if defined(__linux__) && !defined(__SANITIZE_ADDRESS__)
#define MESHEDIT_MAP_BIG 1
#include <sys/mman.h>
#else
#define MESHEDIT_MAP_BIG 0
#endif

namespace meshedit::memory {
namespace {

constexpr std::size_t kHuge = std::size_t{2} << 20;
constexpr std::size_t kPage = std::size_t{4} << 10;

std::atomic<bool> g_enabled{true};

std::size_t round_up(std::size_t bytes, std::size_t unit) {
    return (bytes + unit - 1) / unit * unit;
}

}  // namespace

bool huge_pages_enabled() {
    return g_enabled.load(std::memory_order_relaxed);
}

void set_huge_pages_enabled(bool enabled) {
    g_enabled.store(enabled, std::memory_order_relaxed);
}

#if MESHEDIT_MAP_BIG

namespace {

// Freed big buffers kept for reuse (set_reuse_freed), with their mapped length.
struct Kept {
    void* data;
    std::size_t length;
};
std::mutex g_kept_mutex;
std::vector<Kept> g_kept;
std::atomic<bool> g_reuse{false};

// A fresh mapping of `length` bytes (a multiple of kPage) at a 2 MiB boundary.
void* map_aligned(std::size_t length) {
    // Map 2 MiB more than needed, then unmap the ends so that the buffer starts on a 2 MiB
    // boundary (the kernel places a mapping on any 4 KiB boundary).
    void* raw =
        ::mmap(nullptr, length + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) {
        throw std::bad_alloc();
    }
    const auto start = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = round_up(start, kHuge);
    if (aligned > start) {
        ::munmap(raw, aligned - start);
    }
    const std::uintptr_t end = start + length + kHuge;
    if (end > aligned + length) {
        ::munmap(reinterpret_cast<void*>(aligned + length), end - (aligned + length));
    }
    return reinterpret_cast<void*>(aligned);
}

// The hint on the whole mapping: the kernel backs only the 2 MiB pages that lie wholly
// inside it with huge pages, so the tail keeps small ones and no memory is wasted on it. (A
// hint on the whole pages alone would split the mapping in two, and mremap cannot grow a
// range that spans two mappings: grow_big would fail and copy.)
void advise_whole(void* data, std::size_t length) {
    if (length >= kHuge && huge_pages_enabled()) {
        ::madvise(data, length, MADV_HUGEPAGE);
    }
}

}  // namespace

void* map_big(std::size_t bytes) {
    const std::size_t length = round_up(bytes, kPage);
    if (g_reuse.load(std::memory_order_relaxed)) {
        const std::lock_guard lock(g_kept_mutex);
        for (std::size_t i = 0; i < g_kept.size(); ++i) {
            if (g_kept[i].length == length) {
                void* data = g_kept[i].data;
                g_kept.erase(g_kept.begin() + static_cast<std::ptrdiff_t>(i));
                return data;
            }
        }
    }
    void* data = map_aligned(length);
    advise_whole(data, length);
    return data;
}

void* grow_big(void* data, std::size_t bytes, std::size_t new_bytes) {
    // Reusing kept buffers (the warm protocol) copies into memory written once already;
    // moving would write fresh pages instead.
    if (g_reuse.load(std::memory_order_relaxed) || new_bytes < bytes) {
        return nullptr;
    }
    const std::size_t length = round_up(bytes, kPage);
    const std::size_t new_length = round_up(new_bytes, kPage);
    // Move the pages onto a fresh 2 MiB-aligned range (which mremap unmaps first), so that
    // huge pages move whole and the grown buffer can have them too.
    void* target = map_aligned(new_length);
    void* moved = ::mremap(data, length, new_length, MREMAP_MAYMOVE | MREMAP_FIXED, target);
    if (moved == MAP_FAILED) {
        ::munmap(target, new_length);
        return nullptr;
    }
    advise_whole(moved, new_length);
    return moved;
}

void unmap_big(void* data, std::size_t bytes) noexcept {
    if (g_reuse.load(std::memory_order_relaxed)) {
        try {
            const std::lock_guard lock(g_kept_mutex);
            g_kept.push_back({data, round_up(bytes, kPage)});
            return;
        } catch (...) {  // no room to remember it: give it back
        }
    }
    ::munmap(data, round_up(bytes, kPage));
}

void set_reuse_freed(bool reuse) {
    g_reuse.store(reuse, std::memory_order_relaxed);
    if (!reuse) {
        const std::lock_guard lock(g_kept_mutex);
        for (const Kept& k : g_kept) {
            ::munmap(k.data, k.length);
        }
        g_kept.clear();
    }
}

void advise_huge_pages(const void* data, std::size_t bytes) {
    if (data == nullptr || !huge_pages_enabled()) {
        return;
    }
    const auto begin = round_up(reinterpret_cast<std::uintptr_t>(data), kHuge);
    const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) / kHuge * kHuge;
    if (begin + kHuge < end) {
        ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    }
}

#else

void* map_big(std::size_t bytes) {
    return ::operator new (bytes, std::align_val_t{kHuge});
}

void unmap_big(void* data, std::size_t /*bytes*/) noexcept {
    ::operator delete (data, std::align_val_t{kHuge});
}

void* grow_big(void* /*data*/, std::size_t /*bytes*/, std::size_t /*new_bytes*/) {
    return nullptr;  // operator new's buffers cannot move: the caller copies
}

void advise_huge_pages(const void* /*data*/, std::size_t /*bytes*/) {}

void set_reuse_freed(bool /*reuse*/) {}  // operator new's buffers: the allocator decides

#endif

}  // namespace meshedit::memory
