// stitch_borders() (repair.h) on hand-built cracks: the exact faces it leaves, the corner
// attributes it gives the new corners, what it refuses, and a valid mesh built from it.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "meshedit/core/topology.h"
#include "meshedit/repair/repair.h"
#include "repair/repair_test_util.h"
#include "support/mesh_compare.h"

namespace meshedit::test {
namespace {

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A crack as two tessellations leave it: the lower triangle's top side b → a, the upper
// part's two triangles meeting at m on it, their corners a', b' apart from a, b:
//
//   a',3 ───── m,5 ───── b',4
//    |  ╲       |       ╱ |        upper: (3 5 6), (5 4 6); d = 6 above m
//   a,0 ─────────────── b,1
//          ╲         ╱
//              c,2                 lower: (0 2 1)
//
// `lift` moves m off the line a b (a curve's bulge between the two tessellations).
MeshSoup crack(double lift) {
    MeshSoup soup =
        soup_of({{0, 0, 0}, {2, 0, 0}, {1, -1, 0}, {0, 0, 0}, {2, 0, 0}, {1, lift, 0}, {1, 1, 0}},
                {{0, 2, 1}, {3, 5, 6}, {5, 4, 6}});
    // The lower triangle's texture coordinates run along x; the upper ones are their own.
    soup.corner_texcoords = {{0, 0},   {0.5, 0.5}, {1, 0}, {0, 0},  {0.5, 0},
                             {0.5, 1}, {0.5, 0},   {1, 0}, {0.5, 1}};
    soup.face_materials = {7, 8, 8};
    soup.materials.resize(9);
    return soup;
}

TEST(RepairStitch, AVertexOnAnotherSidesEdgeSplitsItAndTheCrackCloses) {
    MeshSoup soup = crack(0.0);
    // The merge alone keeps a' and b' apart: the faces would touch only at a point.
    EXPECT_EQ(merge_vertices(soup).count, 0u);
    const RepairResult r = stitch_borders(soup);
    EXPECT_EQ(r.count, 1u);
    EXPECT_EQ(r.first, (std::vector<std::uint32_t>{5}));
    EXPECT_EQ(r.left, 0u);
    // The lower triangle is a fan from c, its side b → a split at m; then a' and b' merge
    // into a and b and the numbering closes up (m is 3, d is 4).
    EXPECT_EQ(faces_of(soup.soup), (Faces{{1, 3, 2}, {3, 0, 2}, {0, 3, 4}, {3, 1, 4}}));
    EXPECT_EQ(soup.soup.positions,
              (std::vector<Vec3>{{0, 0, 0}, {2, 0, 0}, {1, -1, 0}, {1, 0, 0}, {1, 1, 0}}));
    // The corners at m on the lower side are blended halfway from b's to a's.
    EXPECT_EQ(soup.corner_texcoords, (std::vector<Vec2>{{1, 0},
                                                        {0.5, 0},
                                                        {0.5, 0.5},
                                                        {0.5, 0},
                                                        {0, 0},
                                                        {0.5, 0.5},
                                                        {0, 0},
                                                        {0.5, 0},
                                                        {0.5, 1},
                                                        {0.5, 0},
                                                        {1, 0},
                                                        {0.5, 1}}));
    EXPECT_EQ(soup.face_materials, (std::vector<std::uint32_t>{7, 7, 8, 8}));
    EXPECT_TRUE(has(r.sentence, "stitched 1 boundary vertex into the boundary edges"))
        << r.sentence;
    EXPECT_TRUE(has(r.sentence, "3 → 4 faces: 5")) << r.sentence;
    EXPECT_TRUE(has(r.sentence, "then merged 2 vertices")) << r.sentence;

    BuildReport report;
    const Mesh mesh = build_mesh(soup.soup, &report);
    ASSERT_VALID(mesh);
    EXPECT_FALSE(report.repaired());
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
    EXPECT_EQ(mesh.n_edges(), 8u);  // the outline's 4 and the inside's 4

    // Nothing is left to stitch.
    const MeshSoup once = soup;
    EXPECT_FALSE(stitch_borders(soup).changed());
    EXPECT_EQ(faces_of(soup.soup), faces_of(once.soup));
}

TEST(RepairStitch, ACurvesBulgeWithinTheRatioIsStitchedBeyondItIsNot) {
    // m 0.04 of the side's length (2) off it: within 0.05.
    MeshSoup near = crack(0.08);
    EXPECT_EQ(stitch_borders(near).count, 1u);
    // 0.06 of it off: left as it is, bit for bit.
    MeshSoup far = crack(0.12);
    const MeshSoup before = far;
    const RepairResult r = stitch_borders(far);
    EXPECT_EQ(r.count, 0u);
    EXPECT_TRUE(r.sentence.empty());
    EXPECT_EQ(far.soup.positions, before.soup.positions);
    EXPECT_EQ(far.soup.indices, before.soup.indices);
    EXPECT_EQ(far.corner_texcoords, before.corner_texcoords);
    // A larger ratio takes it.
    StitchOptions wide;
    wide.ratio = 0.1;
    EXPECT_EQ(stitch_borders(far, wide).count, 1u);
}

TEST(RepairStitch, LeavesABorderRunningTheSameWayAndVerticesAtAnEnd) {
    // The upper part turned over: its bottom runs b' → a' as the lower side does, so it is
    // not the other side of this crack (a flap folded onto it).
    MeshSoup same =
        soup_of({{0, 0, 0}, {2, 0, 0}, {1, -1, 0}, {0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, 1, 0}},
                {{0, 2, 1}, {3, 6, 5}, {5, 6, 4}});
    EXPECT_EQ(stitch_borders(same).count, 0u);
    // m within the merge distance of a: the merge's to join, not the stitch's.
    MeshSoup end = soup_of({{0, 0, 0}, {2, 0, 0}, {1, -1, 0}, {1e-9, 0, 0}, {1, 1, 0}},
                           {{0, 2, 1}, {3, 1, 4}});
    EXPECT_EQ(stitch_borders(end).count, 0u);
}

TEST(RepairStitch, TwoVerticesOnOneSideMakeAFanAndACreaseFollowsThem) {
    //   3 ── 5 ── 6 ── 4      upper: (3 5 7), (5 6 7), (6 4 7); 7 above
    //   0 ──────────── 1      lower: (0 2 1), crease 1-0 along its top
    MeshSoup soup = soup_of({{0, 0, 0},
                             {3, 0, 0},
                             {1.5, -1, 0},
                             {0, 0, 0},
                             {3, 0, 0},
                             {1, 0, 0},
                             {2, 0, 0},
                             {1.5, 1, 0}},
                            {{0, 2, 1}, {3, 5, 7}, {5, 6, 7}, {6, 4, 7}});
    soup.creases = {{1, 0}};
    const RepairResult r = stitch_borders(soup);
    EXPECT_EQ(r.count, 2u);
    // 5, 6 became 3, 4 (a', b' merged away); the fan runs from b to a.
    EXPECT_EQ(faces_of(soup.soup),
              (Faces{{1, 4, 2}, {4, 3, 2}, {3, 0, 2}, {0, 3, 5}, {3, 4, 5}, {4, 1, 5}}));
    EXPECT_EQ(soup.creases,
              (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{1, 4}, {4, 3}, {3, 0}}));
    const Mesh mesh = build_mesh(soup.soup);
    ASSERT_VALID(mesh);
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
}

TEST(RepairStitch, AFarAwayTriangleDoesNotOverflowTheGrid) {
    // Edges of length 1 beside a triangle near the largest double (whose sides' lengths and
    // the box's diagonal overflow): the cells are clamped. The merge distance is absolute: a
    // share of that diagonal would take in the whole crack.
    MeshSoup soup = crack(0.0);
    const auto n = static_cast<std::uint32_t>(soup.soup.positions.size());
    soup.soup.positions.insert(soup.soup.positions.end(),
                               {{1e300, 0, 0}, {1e300, 1e299, 0}, {-1e300, 0, 1e300}});
    soup.soup.add_face({n, n + 1, n + 2});
    soup.corner_texcoords.insert(soup.corner_texcoords.end(), 3, Vec2{0, 0});
    soup.face_materials.push_back(0);
    const RepairResult r = stitch_borders(soup, {}, MergeTolerance{1e-9, false});
    EXPECT_EQ(r.count, 1u);
    EXPECT_TRUE(has(r.sentence, "then merged 2 vertices")) << r.sentence;
}

TEST(RepairStitch, RefusesARatioOutsideItsRange) {
    MeshSoup soup = crack(0.0);
    for (const double ratio : {0.0, -1.0, 0.5, std::nan("")}) {
        StitchOptions options;
        options.ratio = ratio;
        EXPECT_THROW(stitch_borders(soup, options), std::invalid_argument) << ratio;
    }
}

TEST(RepairStitch, TheRepairSequenceStitchesAndASecondRepairChangesNothing) {
    MeshSoup soup = crack(0.0);
    const RepairReport first = repair(soup);
    EXPECT_TRUE(first.changed());
    EXPECT_EQ(soup.soup.n_faces(), 4u);
    const MeshSoup once = soup;
    EXPECT_FALSE(repair(soup).changed());
    EXPECT_EQ(faces_of(soup.soup), faces_of(once.soup));
    // Off, the crack stays.
    MeshSoup off = crack(0.0);
    RepairOptions options;
    options.stitch = false;
    repair(off, options);
    EXPECT_EQ(off.soup.n_faces(), 3u);
}

}  // namespace
}  // namespace meshedit::test
