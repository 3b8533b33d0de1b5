#pragma once
/// \file
/// Storage for big arrays. A mesh of a million faces holds tens of MB per array, and every
/// 4 KiB page of a new array costs a page fault when it is first written; on a virtual
/// machine those faults can be most of the time of building, copying or subdividing a mesh
/// (measured here: 133 ms to first write 48 MB in 4 KiB pages, 6 ms in 2 MiB pages). Linux can
/// back memory with 2 MiB transparent huge pages, but in its default "madvise" mode only
/// where the program asks, and only on 2 MiB-aligned ranges.
///
/// `Allocator<T>` therefore maps buffers of kBigBytes or more directly, 2 MiB-aligned, and
/// asks for huge pages on every whole 2 MiB page of the buffer (the tail keeps small pages, so
/// no memory is wasted); freeing unmaps them at once; growing moves their pages (mremap)
/// instead of copying them. Smaller buffers come from operator new.
/// pod_array.h builds the arrays that mesh properties are stored in on it.

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <new>
#include <type_traits>
#include <vector>

namespace meshedit::memory {

/// Buffers at least this big are mapped directly (one huge page).
inline constexpr std::size_t kBigBytes = std::size_t{2} << 20;

/// `bytes` of memory at a 2 MiB boundary, with the huge-page hint when enabled.
/// \throws std::bad_alloc when the system has no memory for it.
void* map_big(std::size_t bytes);
/// Returns what map_big(bytes) gave.
void unmap_big(void* data, std::size_t bytes) noexcept;
/// Grows a buffer that map_big(bytes) gave to `new_bytes` without copying it: the system
/// moves its pages to a new address, which is returned (the old one is then invalid). Gives
/// nullptr, and leaves the buffer as it was, where it cannot (no mremap, kept buffers being
/// reused, a shrink, or the system refused): the caller then copies.
void* grow_big(void* data, std::size_t bytes, std::size_t new_bytes);

/// Whether map_big() asks for huge pages (default: yes). Off lets a benchmark measure what
/// the hint is worth. Thread-safe.
bool huge_pages_enabled();
void set_huge_pages_enabled(bool enabled);

/// Whether unmap_big() keeps what it frees for the next map_big() of the same size instead of
/// returning it to the system (default: no). A benchmark's warm protocol turns it on, so that
/// repetitions reuse memory already faulted in, as a long-running program's allocator would;
/// turning it off releases what is kept. Thread-safe.
void set_reuse_freed(bool reuse);

/// Asks for huge pages on the whole 2 MiB pages inside [data, data + bytes) of a buffer this
/// module did not map (a std::string, say), when it spans at least two. Refusals are ignored.
void advise_huge_pages(const void* data, std::size_t bytes);

/// A stateless std::allocator replacement: big buffers from map_big(), small ones from
/// operator new.
template <class T>
class Allocator {
public:
    using value_type = T;
    using is_always_equal = std::true_type;
    using propagate_on_container_move_assignment = std::true_type;

    Allocator() noexcept = default;
    template <class U>
    Allocator(const Allocator<U>& /*other*/) noexcept {}  // NOLINT(google-explicit-constructor)

    T* allocate(std::size_t n) {
        if (n > max_size()) {
            throw std::bad_array_new_length();
        }
        const std::size_t bytes = n * sizeof(T);
        if (bytes >= kBigBytes) {
            return static_cast<T*>(map_big(bytes));
        }
        return static_cast<T*>(::operator new (bytes, std::align_val_t{alignof(T)}));
    }
    void deallocate(T* p, std::size_t n) noexcept {
        const std::size_t bytes = n * sizeof(T);
        if (bytes >= kBigBytes) {
            unmap_big(p, bytes);
        } else {
            ::operator delete (p, std::align_val_t{alignof(T)});
        }
    }
    static constexpr std::size_t max_size() noexcept {
        return static_cast<std::size_t>(-1) / 2 / sizeof(T);
    }

    template <class U>
    bool operator==(const Allocator<U>& /*other*/) const noexcept {
        return true;
    }
};

/// Room for `extra` more elements, doubling the capacity when it grows (as push_back does), so
/// that repeated calls stay amortised O(1) per element.
template <class V>
void reserve_more(V& v, std::size_t extra) {
    if (v.capacity() - v.size() < extra) {
        v.reserve(std::max(v.size() + extra, 2 * v.capacity()));
    }
}

}  // namespace meshedit::memory
