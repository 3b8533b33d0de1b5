// Storage of big arrays (memory.h): big buffers start on a 2 MiB boundary, small ones come
// from operator new, and arrays behave as std::vector whichever path their buffer took.
#include "meshedit/core/memory.h"
#include "meshedit/core/pod_array.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;

TEST(Memory, BigBuffersStartOnAHugePageBoundary) {
    memory::Allocator<double> allocator;
    for (const std::size_t n :
         {memory::kBigBytes / 8, memory::kBigBytes / 8 + 1, std::size_t{3} << 20}) {
        double* p = allocator.allocate(n);
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % kHuge, 0u) << n;
        p[0] = 1.0;
        p[n - 1] = 2.0;  // the whole range is writable
        EXPECT_EQ(p[0] + p[n - 1], 3.0);
        allocator.deallocate(p, n);
    }
}

TEST(Memory, SmallBuffersKeepTheirTypesAlignment) {
    memory::Allocator<Vec3> allocator;
    Vec3* p = allocator.allocate(3);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % alignof(Vec3), 0u);
    allocator.deallocate(p, 3);
}

TEST(Memory, ArraysGrowCopyAndShrinkAcrossTheThreshold) {
    // Growing by push_back crosses from operator new to mapped buffers; contents survive.
    memory::Array<std::uint32_t> a;
    const std::size_t n = 3 * memory::kBigBytes / sizeof(std::uint32_t);
    for (std::uint32_t i = 0; i < n; ++i) {
        a.push_back(i);
    }
    memory::Array<std::uint32_t> expected(n);
    std::iota(expected.begin(), expected.end(), 0u);
    EXPECT_EQ(a, expected);
    const memory::Array<std::uint32_t> copy = a;
    EXPECT_EQ(copy, expected);
    a.resize(10);
    a.shrink_to_fit();
    EXPECT_EQ(a, memory::Array<std::uint32_t>(expected.begin(), expected.begin() + 10));
}

// A big buffer grows by moving its pages (grow_big), not by copying: the contents survive,
// the new buffer starts on a 2 MiB boundary, and the old address is given up. Where the
// system cannot move (AddressSanitizer's builds map nothing), it copies, with the same result.
TEST(Memory, BigBuffersGrowWithTheirContents) {
    memory::PodArray<std::uint64_t> a;
    const std::size_t n = 3 * memory::kBigBytes / sizeof(std::uint64_t) + 7;
    a.resize_for_overwrite(n);
    for (std::size_t i = 0; i < n; ++i) {
        a[i] = i * 2654435761u;
    }
    a.shrink_to_fit();
    ASSERT_EQ(a.capacity(), n);
    a.push_back(42);  // doubles: a move of 6 MiB of pages
    EXPECT_EQ(a.capacity(), 2 * n);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % kHuge, 0u);
    for (std::size_t i = 0; i < n; ++i) {
        ASSERT_EQ(a[i], i * 2654435761u) << i;
    }
    EXPECT_EQ(a[n], 42u);
    a.resize(2 * n, 5);  // the grown part is writable to its end
    EXPECT_EQ(a[2 * n - 1], 5u);
}

TEST(PodArray, BehavesAsAVector) {
    memory::PodArray<int> a{1, 2, 3};
    a.resize(5);  // value-initialised, as std::vector
    EXPECT_EQ(a, (memory::PodArray<int>{1, 2, 3, 0, 0}));
    a.resize(2);
    a.resize(4, 7);
    EXPECT_EQ(a, (memory::PodArray<int>{1, 2, 7, 7}));
    a.push_back(a[0]);  // an element of itself, across a reallocation
    a.append(3, a.back());
    EXPECT_EQ(a, (memory::PodArray<int>{1, 2, 7, 7, 1, 1, 1, 1}));
    const std::vector<int> more{5, 6};
    a.insert(a.end(), more.begin(), more.end());
    EXPECT_EQ(a.size(), 10u);
    EXPECT_EQ(a.back(), 6);
    memory::PodArray<int> copy = a;
    memory::PodArray<int> moved = std::move(copy);
    EXPECT_EQ(moved, a);
    EXPECT_TRUE(copy.empty());  // NOLINT(bugprone-use-after-move): moved-from is empty
    moved.assign(3, 9);
    EXPECT_EQ(moved, (memory::PodArray<int>{9, 9, 9}));
    moved.clear();
    moved.shrink_to_fit();
    EXPECT_EQ(moved.capacity(), 0u);
    EXPECT_EQ(moved.data(), nullptr);
}

TEST(PodArray, GrowsByDoublingAndResizesForOverwriteWithoutTouchingOldElements) {
    memory::PodArray<std::uint32_t> a;
    std::size_t reallocations = 0;
    const std::uint32_t* data = a.data();
    for (std::uint32_t i = 0; i < 100'000; ++i) {
        a.append(1, i);
        reallocations += a.data() != data;
        data = a.data();
    }
    EXPECT_LE(reallocations, 20u);  // log2(100,000) + 1
    a.resize_for_overwrite(200'000);
    EXPECT_EQ(a.size(), 200'000u);
    for (std::uint32_t i = 0; i < 100'000; ++i) {
        ASSERT_EQ(a[i], i);
    }
}

TEST(Memory, MeshesAreTheSameWithAndWithoutHugePages) {
    // The hint changes where memory comes from, never what is in it.
    ASSERT_TRUE(memory::huge_pages_enabled());
    Mesh with = shapes::torus(200, 120);  // arrays of several MB
    loop_subdivide(with);
    memory::set_huge_pages_enabled(false);
    Mesh without = shapes::torus(200, 120);
    loop_subdivide(without);
    memory::set_huge_pages_enabled(true);
    EXPECT_TRUE(test::identical(with, without));
}

// The warm benchmark protocol: a freed big buffer comes back for the next request of the same
// size (under ASan big buffers come from operator new, and reuse is the allocator's business).
TEST(Memory, ReuseKeepsFreedBigBuffersForTheSameSize) {
#if !defined(__SANITIZE_ADDRESS__)
    const std::size_t bytes = 3 * memory::kBigBytes + 12345;
    memory::set_reuse_freed(true);
    void* a = memory::map_big(bytes);
    static_cast<char*>(a)[bytes - 1] = 7;
    memory::unmap_big(a, bytes);
    void* b = memory::map_big(bytes);
    EXPECT_EQ(a, b);
    EXPECT_EQ(static_cast<char*>(b)[bytes - 1], 7);  // the same pages, not fresh ones
    void* c = memory::map_big(bytes);                // none kept now: a new mapping
    EXPECT_NE(c, b);
    memory::unmap_big(b, bytes);
    memory::unmap_big(c, bytes);
    memory::set_reuse_freed(false);  // releases both
    void* d = memory::map_big(bytes);
    EXPECT_EQ(static_cast<char*>(d)[bytes - 1], 0);  // fresh pages are zero
    memory::unmap_big(d, bytes);
#endif
}

}  // namespace
}  // namespace meshedit
