#pragma once
/// \file
/// The array that mesh properties are stored in. For trivially copyable elements (every
/// connectivity array, positions, flags) it is PodArray: a std::vector look-alike over
/// memory.h's huge-page buffers that can also
///   - grow by k elements with one fill (`append`): a local op that adds a vertex, three edges
///     and two faces grows ten arrays, and std::vector's per-element construction through a
///     custom allocator cost more instructions than the op itself (callgrind: ~800 per split);
///   - resize without writing the new elements (`resize_for_overwrite`), for arrays that a
///     pass writes whole right after (Loop subdivision), so that fresh memory is touched once,
///     by the threads that fill it, not first by a serial zeroing pass.
/// Other element types use std::vector with the same allocator.

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <iterator>
#include <type_traits>
#include <utility>
#include <vector>

#include "meshedit/core/assert.h"
#include "meshedit/core/memory.h"

namespace meshedit::memory {

template <class T>
class PodArray {
    static_assert(std::is_trivially_copyable_v<T>, "PodArray holds trivially copyable types");

public:
    using value_type = T;
    using size_type = std::size_t;
    using difference_type = std::ptrdiff_t;
    using reference = T&;
    using const_reference = const T&;
    using pointer = T*;
    using const_pointer = const T*;
    using iterator = T*;
    using const_iterator = const T*;

    PodArray() noexcept = default;
    explicit PodArray(size_type n) { resize(n); }
    PodArray(size_type n, const T& value) { resize(n, value); }
    template <std::input_iterator It>
    PodArray(It first, It last) {
        assign(first, last);
    }
    PodArray(std::initializer_list<T> values) { assign(values.begin(), values.end()); }
    PodArray(const PodArray& other) { assign(other.begin(), other.end()); }
    PodArray(PodArray&& other) noexcept { swap(other); }
    PodArray& operator=(const PodArray& other) {
        if (this != &other) {
            assign(other.begin(), other.end());
        }
        return *this;
    }
    PodArray& operator=(PodArray&& other) noexcept {
        PodArray(std::move(other)).swap(*this);
        return *this;
    }
    ~PodArray() { release(); }

    size_type size() const noexcept { return size_; }
    size_type capacity() const noexcept { return capacity_; }
    bool empty() const noexcept { return size_ == 0; }
    T* data() noexcept { return data_; }
    const T* data() const noexcept { return data_; }
    iterator begin() noexcept { return data_; }
    iterator end() noexcept { return data_ + size_; }
    const_iterator begin() const noexcept { return data_; }
    const_iterator end() const noexcept { return data_ + size_; }
    const_iterator cbegin() const noexcept { return data_; }
    const_iterator cend() const noexcept { return data_ + size_; }
    T& operator[](size_type i) { return data_[i]; }
    const T& operator[](size_type i) const { return data_[i]; }
    T& front() { return data_[0]; }
    const T& front() const { return data_[0]; }
    T& back() { return data_[size_ - 1]; }
    const T& back() const { return data_[size_ - 1]; }

    /// Capacity for at least `n` elements (exactly `n` when it grows, as std::vector).
    void reserve(size_type n) {
        if (n > capacity_) {
            reallocate(n);
        }
    }
    /// `n` elements; new ones value-initialised (T{}), as std::vector::resize.
    void resize(size_type n) { resize(n, T{}); }
    void resize(size_type n, const T& value) {
        if (n > size_) {
            append(n - size_, value);
        } else {
            size_ = n;
        }
    }
    /// `n` elements; new ones are left unwritten (indeterminate) for the caller to fill.
    void resize_for_overwrite(size_type n) {
        reserve(n);
        size_ = n;
    }
    /// Appends `k` copies of `value`, doubling the capacity when it grows.
    void append(size_type k, const T& value) {
        const T copy = value;  // `value` may live in this array, which may move
        grow_for(k);
        std::fill_n(data_ + size_, k, copy);
        size_ += k;
    }
    void push_back(const T& value) {
        const T copy = value;  // `value` may live in this array, which may move
        if (size_ == capacity_) {
            grow_for(1);
        }
        data_[size_++] = copy;
    }
    void pop_back() { --size_; }
    void clear() noexcept { size_ = 0; }
    void shrink_to_fit() {
        if (capacity_ > size_) {
            if (size_ == 0) {
                release();
            } else {
                reallocate(size_);
            }
        }
    }
    void assign(size_type n, const T& value) {
        clear();
        append(n, value);
    }
    template <std::input_iterator It>
    void assign(It first, It last) {
        clear();
        insert(end(), first, last);
    }
    /// Inserts [first, last) at the end (`at` must be end()).
    template <std::input_iterator It>
    iterator insert(const_iterator at, It first, It last) {
        MESHEDIT_ASSERT(at == cend());
        (void)at;
        const auto k = static_cast<size_type>(std::distance(first, last));
        grow_for(k);
        std::copy(first, last, data_ + size_);
        size_ += k;
        return data_ + size_ - k;
    }
    iterator insert(const_iterator at, std::initializer_list<T> values) {
        return insert(at, values.begin(), values.end());
    }
    void swap(PodArray& other) noexcept {
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(capacity_, other.capacity_);
    }

    friend bool operator==(const PodArray& a, const PodArray& b) {
        return a.size_ == b.size_ && std::equal(a.begin(), a.end(), b.begin());
    }

private:
    // Room for `k` more: at least double the old capacity, as push_back does.
    void grow_for(size_type k) {
        if (capacity_ - size_ < k) {
            reallocate(std::max(size_ + k, 2 * capacity_));
        }
    }
    void reallocate(size_type n) {
        // A big buffer growing moves its pages instead of copying them: the first element
        // added to a copied 1M-face mesh (a hole's fill) copied ~100 MB, most of the fill.
        if (n > capacity_ && capacity_ * sizeof(T) >= kBigBytes) {
            if (void* moved = grow_big(data_, capacity_ * sizeof(T), n * sizeof(T))) {
                data_ = static_cast<T*>(moved);
                capacity_ = n;
                return;
            }
        }
        Allocator<T> allocator;
        T* fresh = allocator.allocate(n);
        if (size_ > 0) {
            std::memcpy(static_cast<void*>(fresh), data_, size_ * sizeof(T));
        }
        release_buffer();
        data_ = fresh;
        capacity_ = n;
    }
    void release_buffer() noexcept {
        if (data_ != nullptr) {
            Allocator<T>().deallocate(data_, capacity_);
        }
    }
    void release() noexcept {
        release_buffer();
        data_ = nullptr;
        size_ = 0;
        capacity_ = 0;
    }

    T* data_ = nullptr;
    size_type size_ = 0;
    size_type capacity_ = 0;
};

/// The array mesh properties are stored in: PodArray for trivially copyable elements,
/// std::vector with the huge-page allocator otherwise.
template <class T>
using Array =
    std::conditional_t<std::is_trivially_copyable_v<T>, PodArray<T>, std::vector<T, Allocator<T>>>;

/// Resizes `v` to `n` elements, writing new ones only where the array type must (std::vector).
template <class T>
void resize_for_overwrite(PodArray<T>& v, std::size_t n) {
    v.resize_for_overwrite(n);
}
template <class T>
void resize_for_overwrite(std::vector<T, Allocator<T>>& v, std::size_t n) {
    v.resize(n);
}

/// Appends `k` copies of `value` (doubling the capacity when it grows).
template <class T>
void append(PodArray<T>& v, std::size_t k, const T& value) {
    v.append(k, value);
}
template <class T>
void append(std::vector<T, Allocator<T>>& v, std::size_t k, const T& value) {
    reserve_more(v, k);
    v.insert(v.end(), k, value);
}

}  // namespace meshedit::memory
