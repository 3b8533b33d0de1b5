// The thread-count setting (meshedit/core/threads.h): parsing, priority, that the parallel
// loops honour it, and that Loop, Catmull-Clark and vertex normals give the same bits on one
// thread and on many. A white-box test: it includes the core's private mesh/parallel.h to
// watch the threads a loop runs on and to let a 20k-face mesh run its chunks in parallel.
#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "mesh/parallel.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/threads.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

// Restores the process's setting after a test changes it.
struct ThreadSetting {
    ~ThreadSetting() { reset_thread_count(); }
};

TEST(Threads, ParseAcceptsOnlyWholeNumbersUpToTheLimit) {
    EXPECT_EQ(parse_thread_count("0"), 0u);
    EXPECT_EQ(parse_thread_count("1"), 1u);
    EXPECT_EQ(parse_thread_count("16"), 16u);
    EXPECT_EQ(parse_thread_count("1024"), kMaxThreads);
    for (const char* bad : {"", "-1", "+2", "two", "4.5", " 4", "4 ", "1025", "100000",
                            "99999999999999999999", "0x10"}) {
        EXPECT_FALSE(parse_thread_count(bad).has_value()) << bad;
    }
    const std::string sentence = bad_thread_count("-1");
    EXPECT_EQ(sentence.rfind("'-1' is not a thread count", 0), 0u) << sentence;
}

TEST(Threads, SetCountWinsAndZeroMeansAllCores) {
    const ThreadSetting restore;
    set_thread_count(3);
    EXPECT_EQ(thread_count(), 3u);
    set_thread_count(0);
    EXPECT_EQ(thread_count(), hardware_threads());
    EXPECT_THROW(set_thread_count(kMaxThreads + 1), std::invalid_argument);
    EXPECT_EQ(thread_count(), hardware_threads());  // a refused count changes nothing
    reset_thread_count();
    if (std::getenv("MESHEDIT_THREADS") == nullptr) {  // as ctest runs it: all cores again
        EXPECT_EQ(thread_count(), hardware_threads());
    }
    EXPECT_FALSE(thread_environment_problem().has_value());
}

TEST(Threads, ThePerCallCapStillLimits) {
    const ThreadSetting restore;
    set_thread_count(4);
    EXPECT_EQ(parallel::thread_count(1'000'000, 1000), 4u);
    EXPECT_EQ(parallel::thread_count(1'000'000, 1000, 2), 2u);
    EXPECT_EQ(parallel::thread_count(999, 1000), 1u);  // small: the calling thread alone
}

// Each chunk waits until `n` distinct threads have run a chunk, so a loop that starts the `n`
// threads it may use shows all of them, deterministically; one that started more shows more
// than `n`. One that started fewer never gets there: after 5 s nobody waits any more, so it
// fails in 5 s rather than 5 s a chunk.
std::set<std::thread::id> threads_seen(unsigned n) {
    std::mutex mutex;
    std::condition_variable arrived;
    std::set<std::thread::id> seen;
    bool gave_up = false;
    const std::size_t chunks = 64;
    parallel::for_chunks(chunks, 1, parallel::thread_count(chunks, 1),
                         [&](std::size_t, std::size_t) {
                             std::unique_lock<std::mutex> lock(mutex);
                             seen.insert(std::this_thread::get_id());
                             arrived.notify_all();
                             if (!gave_up) {
                                 gave_up = !arrived.wait_for(lock, std::chrono::seconds(5),
                                                             [&] { return seen.size() >= n; });
                             }
                         });
    return seen;
}

TEST(Threads, AParallelLoopRunsOnExactlyTheThreadsSet) {
    const ThreadSetting restore;
    for (const unsigned n : {1u, 2u, 3u, 5u}) {
        set_thread_count(n);
        EXPECT_EQ(threads_seen(n).size(), n) << n << " thread(s) set";
    }
}

// ~20k faces with creases, made to run in parallel below the usual 100,000-face threshold.
Mesh creased_torus() {
    Mesh mesh = shapes::torus(100, 100);
    auto crease = mesh.add_property<Edge, std::uint8_t>(kCreaseProperty, 0);
    for (std::uint32_t e = 0; e < mesh.edges_size(); e += 11) {
        crease[Edge(e)] = 1;
    }
    return mesh;
}

template <class Run>
void expect_same_bits_on_any_count(const Mesh& input, const Run& run) {
    const ThreadSetting restore;
    const parallel::ScopedSerialBelow parallel_from(1000);
    set_thread_count(1);
    Mesh one = input;
    run(one);
    for (const unsigned n : {0u, 3u}) {  // 0: all cores
        set_thread_count(n);
        Mesh many = input;
        run(many);
        EXPECT_TRUE(test::identical(many, one)) << n << " thread(s)";
    }
}

// One level each: every pass of a level runs in chunks (16,384 elements) on the threads, and a
// second level would only run the same passes again, four times slower under the sanitizers.
TEST(ThreadsSameBits, Loop) {
    expect_same_bits_on_any_count(creased_torus(), [](Mesh& m) { loop_subdivide(m); });
}

TEST(ThreadsSameBits, CatmullClarkOnTriangles) {
    expect_same_bits_on_any_count(creased_torus(), [](Mesh& m) { quad_subdivide(m); });
}

TEST(ThreadsSameBits, VertexNormals) {
    // Normals cut faces into chunks of 65,536: 80k faces make two.
    Mesh mesh = creased_torus();
    loop_subdivide(mesh);
    ASSERT_GT(mesh.n_faces(), 65'536u);
    const ThreadSetting restore;
    const parallel::ScopedSerialBelow parallel_from(1000);
    set_thread_count(1);
    std::vector<Vec3> one;
    compute_vertex_normals(mesh, one);
    for (const unsigned n : {0u, 3u}) {
        set_thread_count(n);
        std::vector<Vec3> many;
        compute_vertex_normals(mesh, many);
        ASSERT_EQ(many.size(), one.size());
        EXPECT_EQ(std::memcmp(many.data(), one.data(), one.size() * sizeof(Vec3)), 0)
            << n << " thread(s)";
    }
}

}  // namespace
}  // namespace meshedit
