// Undo history: whole-document snapshots and recorded changes, bounded in steps and bytes,
// redo cleared by a new edit, at least one undo step always kept.

#include "meshedit/viewer/history.h"

#include <gtest/gtest.h>

#include "meshedit/core/shapes.h"
#include "support/mesh_compare.h"
#include "viewer/editor_test_util.h"

namespace meshedit::viewer {
namespace {

/// A document told apart by its revision (and, for byte tests, its size).
Document doc(std::uint64_t revision, Mesh mesh = {}) {
    Document d;
    d.mesh = std::move(mesh);
    d.revision = revision;
    return d;
}

TEST(History, DocumentBytesCountEverything) {
    Document d;
    const std::size_t empty = d.bytes();
    EXPECT_GE(empty, sizeof(Document));
    d.mesh = shapes::icosphere(2);
    EXPECT_EQ(d.bytes(), empty - Mesh().bytes() + d.mesh.bytes());
    const std::size_t with_mesh = d.bytes();
    d.curve.control_points.assign(100, Vec3{});
    EXPECT_GE(d.bytes(), with_mesh + 100 * sizeof(Vec3));
    const std::size_t with_curve = d.bytes();
    d.patches.resize(2);
    d.patches[0].control_points.assign(16, Vec3{});
    d.patches[1].control_points.assign(16, Vec3{});
    EXPECT_GE(d.bytes(), with_curve + 2 * sizeof(BezierPatch) + 32 * sizeof(Vec3));
}

TEST(History, UndoRedoSwapDocuments) {
    History h;
    Document current = doc(1);
    EXPECT_FALSE(h.undo(current));
    EXPECT_FALSE(h.redo(current));
    h.push(current);  // edit 1 -> 2
    current = doc(2);
    h.push(current);  // edit 2 -> 3
    current = doc(3);
    EXPECT_EQ(h.undo_steps(), 2u);

    ASSERT_TRUE(h.undo(current));
    EXPECT_EQ(current.revision, 2u);
    ASSERT_TRUE(h.undo(current));
    EXPECT_EQ(current.revision, 1u);
    EXPECT_FALSE(h.undo(current));
    EXPECT_EQ(current.revision, 1u);
    EXPECT_EQ(h.redo_steps(), 2u);

    ASSERT_TRUE(h.redo(current));
    EXPECT_EQ(current.revision, 2u);
    ASSERT_TRUE(h.redo(current));
    EXPECT_EQ(current.revision, 3u);
    EXPECT_FALSE(h.redo(current));
}

TEST(History, PushClearsRedo) {
    History h;
    Document current = doc(1);
    h.push(current);
    current = doc(2);
    h.push(current);
    current = doc(3);
    ASSERT_TRUE(h.undo(current));
    ASSERT_TRUE(h.undo(current));
    EXPECT_EQ(h.redo_steps(), 2u);
    h.push(current);  // a new edit from revision 1
    current = doc(4);
    EXPECT_EQ(h.redo_steps(), 0u);
    EXPECT_EQ(h.undo_steps(), 1u);
    EXPECT_FALSE(h.redo(current));
    EXPECT_EQ(h.bytes(), doc(1).bytes());
}

TEST(History, StepLimitDropsOldestFirst) {
    History h(HistoryLimits{std::size_t{1} << 40, 3});
    Document current = doc(0);
    for (std::uint64_t r = 1; r <= 10; ++r) {
        h.push(current);
        current = doc(r);
        EXPECT_LE(h.undo_steps() + h.redo_steps(), 3u);
    }
    EXPECT_EQ(h.undo_steps(), 3u);
    // The three newest survive: 9, 8, 7.
    for (std::uint64_t r : {9u, 8u, 7u}) {
        ASSERT_TRUE(h.undo(current));
        EXPECT_EQ(current.revision, r);
    }
    EXPECT_FALSE(h.undo(current));
}

TEST(History, ByteBudgetKeepsAtLeastOneStep) {
    const Mesh big = shapes::icosphere(3);
    const std::size_t one = doc(0, big).bytes();
    // Room for two big snapshots, not three.
    History h(HistoryLimits{2 * one + one / 2, 3});
    Document current = doc(0, big);
    for (std::uint64_t r = 1; r <= 5; ++r) {
        h.push(current);
        current = doc(r, big);
        EXPECT_LE(h.bytes(), h.limits().max_bytes);
        EXPECT_GE(h.undo_steps(), 1u);
    }
    EXPECT_EQ(h.undo_steps(), 2u);
    EXPECT_EQ(h.bytes(), 2 * one);

    // A budget smaller than one snapshot still keeps the last step (then the bound is one
    // snapshot).
    History tiny(HistoryLimits{16, 3});
    Document cur = doc(0, big);
    for (std::uint64_t r = 1; r <= 3; ++r) {
        tiny.push(cur);
        cur = doc(r, big);
        EXPECT_EQ(tiny.undo_steps(), 1u);
        EXPECT_EQ(tiny.bytes(), one);
    }
    ASSERT_TRUE(tiny.undo(cur));
    EXPECT_EQ(cur.revision, 2u);
    EXPECT_TRUE(test::identical(cur.mesh, big));
    EXPECT_EQ(tiny.redo_steps(), 1u);
    EXPECT_EQ(tiny.bytes(), one);
    ASSERT_TRUE(tiny.redo(cur));
    EXPECT_EQ(cur.revision, 3u);
}

TEST(History, BytesFollowTheStacks) {
    const Mesh small = shapes::cube();
    const Mesh large = shapes::icosphere(2);
    History h;
    Document current = doc(1, small);
    h.push(current);
    current = doc(2, large);
    EXPECT_EQ(h.bytes(), doc(1, small).bytes());
    ASSERT_TRUE(h.undo(current));  // large goes to redo
    EXPECT_EQ(h.bytes(), doc(2, large).bytes());
    ASSERT_TRUE(h.redo(current));
    EXPECT_EQ(h.bytes(), doc(1, small).bytes());
    h.clear();
    EXPECT_EQ(h.bytes(), 0u);
    EXPECT_EQ(h.undo_steps(), 0u);
    EXPECT_EQ(h.redo_steps(), 0u);
}

TEST(History, UndoIsBitExact) {
    History h;
    Document current = doc(1, shapes::torus(6, 5));
    const Mesh before = current.mesh;
    h.push(current);
    current.mesh.position(Vertex(3)).x += 1.0;
    current.mesh.property<Edge, std::uint8_t>("e:crease", 0)[Edge(2)] = 1;
    current.revision = 2;
    ASSERT_TRUE(h.undo(current));
    EXPECT_TRUE(test::identical(current.mesh, before));
}

// A local edit's undo step holds what it touched: a flip costs the same few hundred bytes on a
// 20,000-face torus as on a 200-face one, and 200 of them fit in well under a megabyte.
TEST(History, AFlipsUndoStepDoesNotGrowWithTheMesh) {
    std::vector<std::size_t> bytes;
    for (const int n : {10, 100}) {
        Editor ed = editor_with(shapes::torus(n, n));
        std::size_t before = ed.history().bytes();
        const auto n_edges = static_cast<std::uint32_t>(ed.mesh().edges_size());
        for (std::uint32_t e = 0; ed.history().undo_steps() < 200; ++e) {
            ed.select(ElementRef::edge(Edge(7 * e % n_edges)));
            if (!ed.run(edit("flip")).refused) {
                ASSERT_TRUE(ed.history().last_is_change());
            }
        }
        bytes.push_back(ed.history().bytes() - before);
        for (int i = 0; i < 200; ++i) {
            ASSERT_FALSE(ed.run({Command::Undo}).refused);
        }
        EXPECT_TRUE(test::identical(ed.mesh(), shapes::torus(n, n)));
    }
    EXPECT_LE(bytes[1], bytes[0] + 200 * 16);  // indices print longer in the session step
    EXPECT_LE(bytes[1], 200u * 1024u);
}

}  // namespace
}  // namespace meshedit::viewer
