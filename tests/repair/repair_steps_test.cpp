// Each repair step on small hand-built soups (repair.h): the exact soup it leaves, what it
// says it changed, and a valid mesh built from it.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "meshedit/core/normals.h"
#include "meshedit/core/topology.h"
#include "meshedit/repair/repair.h"
#include "repair/repair_test_util.h"
#include "support/mesh_compare.h"

namespace meshedit::test {
namespace {

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// ------------------------------------------------------------------ merge

TEST(RepairMerge, UnweldedTrianglesBecomeFourVerticesSharingOneEdge) {
    // Two triangles of a unit square, each with its own three vertices (an STL-style soup):
    //   2,5 ---- 4          2 ---- 3
    //    |  \    |          |  \   |
    //    |    \  |   →      |    \ |
    //    0 ---- 1,3         0 ---- 1
    MeshSoup soup = soup_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                            {{0, 1, 2}, {3, 4, 5}});
    const RepairResult r = merge_vertices(soup);
    EXPECT_EQ(r.count, 2u);
    EXPECT_EQ(r.first, (std::vector<std::uint32_t>{3, 5}));
    EXPECT_EQ(soup.soup.positions, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}));
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 2}, {1, 3, 2}}));
    EXPECT_TRUE(has(r.sentence, "merged 2 vertices into others within")) << r.sentence;
    EXPECT_TRUE(has(r.sentence, "6 → 4 vertices: 3, 5")) << r.sentence;

    BuildReport report;
    const Mesh mesh = build_mesh(soup.soup, &report);
    ASSERT_VALID(mesh);
    EXPECT_FALSE(report.repaired());
    EXPECT_EQ(mesh.n_vertices(), 4u);
    EXPECT_EQ(mesh.n_edges(), 5u);
    const Edge shared = mesh.find_edge(Vertex(1), Vertex(2));
    ASSERT_TRUE(shared.is_valid());
    EXPECT_FALSE(mesh.is_boundary(shared));
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
}

TEST(RepairMerge, StitchesAnUnweldedNoisyCubeIntoOneClosedMesh) {
    // Every triangle of the cube with its own corners, each moved by up to 1e-9.
    const MeshSoup cube = cube_soup(false);
    MeshSoup soup;
    double noise = 1e-9;
    for (std::size_t f = 0; f < cube.soup.n_faces(); ++f) {
        const std::uint32_t* c = cube.soup.indices.data() + cube.soup.face_offsets[f];
        for (const auto& tri : {std::array{c[0], c[1], c[2]}, std::array{c[0], c[2], c[3]}}) {
            std::vector<std::uint32_t> corners;
            for (const std::uint32_t v : tri) {
                corners.push_back(static_cast<std::uint32_t>(soup.soup.positions.size()));
                soup.soup.positions.push_back(cube.soup.positions[v] + Vec3{noise, -noise, 0});
                noise = -noise * 0.9;
            }
            soup.soup.add_face_range(corners);
        }
    }
    ASSERT_EQ(soup.soup.positions.size(), 36u);
    const RepairResult r = merge_vertices(soup);
    EXPECT_EQ(r.count, 28u);
    EXPECT_EQ(soup.soup.positions.size(), 8u);
    const Mesh mesh = build_mesh(soup.soup);
    ASSERT_VALID(mesh);
    EXPECT_TRUE(is_closed(mesh));
    EXPECT_EQ(euler_characteristic(mesh), 2);
    EXPECT_GT(signed_volume(mesh), 7.99);
}

TEST(RepairMerge, RelativeAndAbsoluteTolerances) {
    // Vertex 3 is 0.01 from vertex 1; the diagonal is sqrt(2).
    const MeshSoup base =
        soup_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1.01, 0, 0}, {1, 1, 0}}, {{0, 1, 2}, {3, 4, 2}});
    const auto merged = [&](MergeTolerance tolerance) {
        MeshSoup soup = base;
        return merge_vertices(soup, tolerance).count;
    };
    EXPECT_EQ(merged({}), 0u);              // 1e-6 of the diagonal
    EXPECT_EQ(merged({0.02, false}), 1u);   // absolute
    EXPECT_EQ(merged({0.005, false}), 0u);  // absolute, too small
    EXPECT_EQ(merged({0.01, true}), 1u);    // 0.0141 of the diagonal
    EXPECT_EQ(merged({0.005, true}), 0u);   // 0.0071
    EXPECT_EQ(merged({0.0, false}), 0u);    // equal positions only
    MeshSoup equal =
        soup_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0, 1, 0}, {1, 1, 0}}, {{0, 1, 2}, {1, 4, 3}});
    EXPECT_EQ(merge_vertices(equal, {0.0, false}).count, 1u);  // 0 and -0 are equal
    EXPECT_EQ(faces_of(equal.soup), (Faces{{0, 1, 2}, {1, 3, 2}}));
}

TEST(RepairMerge, BadTolerancesAndSoupsAreRefusedWithTheirReason) {
    MeshSoup soup = soup_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    EXPECT_THROW(merge_vertices(soup, {-1.0, false}), std::invalid_argument);
    EXPECT_THROW(merge_vertices(soup, {std::nan(""), true}), std::invalid_argument);
    EXPECT_THROW(merge_vertices(soup, {INFINITY, false}), std::invalid_argument);
    try {
        merge_vertices(soup, {-1.0, false});
    } catch (const std::invalid_argument& e) {
        EXPECT_TRUE(has(e.what(), "not -1")) << e.what();
    }
    MeshSoup nan = soup_of({{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}, {{0, 1, 2}});
    EXPECT_THROW(repair(nan), TopologyError);
    MeshSoup out_of_range = soup_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 7}});
    EXPECT_THROW(repair(out_of_range), TopologyError);
}

TEST(RepairMerge, HugeCoordinatesAndHugeTolerancesStayFinite) {
    // Near the top of the double range the diagonal overflows when taken plainly.
    MeshSoup soup = soup_of({{-1e308, 0, 0}, {1e308, 0, 0}, {0, 1e308, 0}, {1e308, 0, 0}},
                            {{0, 1, 2}, {3, 2, 0}});
    const RepairResult r = merge_vertices(soup);
    EXPECT_EQ(r.count, 1u);
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 2}, {1, 2, 0}}));
    // A distance larger than the mesh merges every vertex: every face collapses.
    MeshSoup small = soup_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    EXPECT_EQ(merge_vertices(small, {10.0, true}).count, 2u);
    EXPECT_EQ(small.soup.positions.size(), 1u);
    EXPECT_EQ(remove_degenerate_faces(small).count, 1u);
    EXPECT_EQ(small.soup.n_faces(), 0u);
    EXPECT_TRUE(small.soup.positions.empty());
}

TEST(RepairMerge, KeepsVerticesApartWhereTheFacesWouldOnlyTouch) {
    // Two triangles tip to tip, each with its own tip vertex at the same place: merged, the
    // tip would be a vertex the builder splits again.
    MeshSoup soup = soup_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {-1, 0, 0}, {-1, -1, 0}},
                            {{0, 1, 2}, {3, 4, 5}});
    const MeshSoup before = soup;
    const RepairResult r = merge_vertices(soup);
    EXPECT_EQ(r.count, 0u);
    EXPECT_EQ(r.left, 1u);
    EXPECT_TRUE(has(r.sentence, "kept 1 vertex within")) << r.sentence;
    EXPECT_EQ(soup.soup.positions, before.soup.positions);
    EXPECT_EQ(soup.soup.indices, before.soup.indices);
}

TEST(RepairMerge, AMergedVertexKeepsTheValuesOfTheVertexItJoins) {
    MeshSoup soup = soup_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                            {{0, 1, 2}, {3, 4, 5}});
    soup.normals = {{0, 0, 1}, {0, 0, 2}, {0, 0, 3}, {0, 0, 4}, {0, 0, 5}, {0, 0, 6}};
    soup.vertex_properties.push_back(
        {"quality", UserProperty::Type::F32, {10, 11, 12, 13, 14, 15}});
    soup.creases = {{3, 4}, {1, 3}, {4, 5}};  // 1-3 becomes one vertex: dropped
    const RepairResult r = merge_vertices(soup);
    EXPECT_EQ(r.count, 2u);
    EXPECT_EQ(soup.normals, (std::vector<Vec3>{{0, 0, 1}, {0, 0, 2}, {0, 0, 3}, {0, 0, 5}}));
    EXPECT_EQ(soup.vertex_properties[0].values, (std::vector<double>{10, 11, 12, 14}));
    EXPECT_EQ(soup.creases, (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{1, 3}, {3, 2}}));
    EXPECT_TRUE(has(r.sentence, "dropped 1 crease mark whose ends merged")) << r.sentence;
}

// ------------------------------------------------------------------ degenerate, duplicate

TEST(RepairDegenerate, AZeroAreaFaceGoesWithTheVertexOnlyItUsed) {
    //   3 ---- 2
    //   |   /  |
    //   0 ---- 1 ---- 4     face (0, 1, 4): three corners on one line
    MeshSoup soup = soup_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}},
                            {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}});
    soup.face_materials = {0, 1, 2};
    soup.face_properties.push_back({"label", UserProperty::Type::I32, {7, 8, 9}});
    const RepairResult r = remove_degenerate_faces(soup);
    EXPECT_EQ(r.count, 1u);
    EXPECT_EQ(r.first, std::vector<std::uint32_t>{2});
    EXPECT_EQ(r.removed_vertices, 1u);
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(soup.soup.positions.size(), 4u);
    EXPECT_EQ(soup.face_materials, (std::vector<std::uint32_t>{0, 1}));
    EXPECT_EQ(soup.face_properties[0].values, (std::vector<double>{7, 8}));
    EXPECT_EQ(r.sentence,
              "removed 1 degenerate face (1 of zero area): 2; removed 1 vertex only they used");
}

TEST(RepairDegenerate, RepeatedCornersAreDroppedWithTheirAttributes) {
    // (0, 0, 1, 2) keeps three corners; (1, 1, 2, 1) is left with two and goes.
    MeshSoup soup = soup_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 1, 2}, {1, 1, 2, 1}});
    soup.corner_texcoords = {{0, 0}, {0, 1}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}, {6, 0}};
    const RepairResult r = remove_degenerate_faces(soup);
    EXPECT_EQ(r.count, 1u);
    EXPECT_EQ(r.corners, 1u);
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 2}}));
    EXPECT_EQ(soup.corner_texcoords, (std::vector<Vec2>{{0, 0}, {1, 0}, {2, 0}}));
    EXPECT_EQ(r.sentence,
              "removed 1 degenerate face (1 with fewer than 3 distinct corners): 1; dropped 1 "
              "repeated corner from 1 face: 0");
}

TEST(RepairDuplicates, TheFirstOfFacesOnTheSameVerticesStays) {
    MeshSoup soup = soup_of({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                            {{0, 1, 2}, {0, 2, 3}, {2, 1, 0}, {1, 2, 0}, {3, 0, 2}});
    soup.face_materials = {0, 1, 2, 3, 4};
    soup.corner_texcoords.resize(15);
    for (std::size_t c = 0; c < 15; ++c) {
        soup.corner_texcoords[c] = {static_cast<double>(c), 0};
    }
    const RepairResult r = remove_duplicate_faces(soup);
    EXPECT_EQ(r.count, 3u);
    EXPECT_EQ(r.first, (std::vector<std::uint32_t>{2, 3, 4}));
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(soup.face_materials, (std::vector<std::uint32_t>{0, 1}));
    EXPECT_EQ(soup.corner_texcoords,
              (std::vector<Vec2>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}}));
    EXPECT_EQ(r.sentence,
              "removed 3 duplicate faces (the same vertices as an earlier face): 2, 3, 4");
}

// ------------------------------------------------------------------ orientation

// Three unit quads in a row: 0..3 at y = 0, 4..7 at y = 1.
MeshSoup quad_strip_soup(const Faces& faces) {
    return soup_of(
        {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {3, 1, 0}},
        faces);
}

TEST(RepairOrient, AFlippedQuadInAStripAgreesWithItsNeighbours) {
    MeshSoup soup = quad_strip_soup({{0, 1, 5, 4}, {1, 5, 6, 2}, {2, 3, 7, 6}});
    // Unoriented, the builder cuts the middle quad off along both its shared edges.
    BuildReport cut;
    build_mesh(soup.soup, &cut);
    EXPECT_EQ(cut.nonmanifold_edges.size(), 2u);

    const RepairResult r = orient_faces(soup);
    EXPECT_EQ(r.count, 1u);
    EXPECT_EQ(r.first, std::vector<std::uint32_t>{1});
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}}));
    EXPECT_EQ(r.sentence, "turned over 1 face to agree with its neighbours: 1");
    BuildReport report;
    const Mesh mesh = build_mesh(soup.soup, &report);
    ASSERT_VALID(mesh);
    EXPECT_FALSE(report.repaired());
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
}

TEST(RepairOrient, APartKeepsTheWindingMostOfItsFacesHave) {
    // The first and last quads are turned (normals down): the middle one follows them.
    MeshSoup soup = quad_strip_soup({{0, 4, 5, 1}, {1, 2, 6, 5}, {2, 6, 7, 3}});
    const RepairResult r = orient_faces(soup);
    EXPECT_EQ(r.count, 1u);
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}}));
}

TEST(RepairOrient, AnInsideOutCubeTurnsOutward) {
    MeshSoup outward = cube_soup(false);
    EXPECT_GT(signed_volume(build_mesh(outward.soup)), 0.0);
    EXPECT_EQ(orient_faces(outward).count, 0u);

    MeshSoup soup = cube_soup(true);
    EXPECT_LT(signed_volume(build_mesh(soup.soup)), 0.0);
    const RepairResult r = orient_faces(soup);
    EXPECT_EQ(r.count, 6u);
    EXPECT_EQ(r.sentence,
              "turned over 6 faces so that 1 closed part faces outward: 0, 1, 2, 3, 4, …");
    EXPECT_EQ(faces_of(soup.soup), faces_of(cube_soup(false).soup));
    const Mesh mesh = build_mesh(soup.soup);
    ASSERT_VALID(mesh);
    EXPECT_TRUE(is_closed_and_outward(mesh));
}

TEST(RepairOrient, ACubeWithOneInwardFaceAndAnInsideOutCubeWithOneOutwardFace) {
    MeshSoup one = cube_soup(false);
    MeshSoup five = cube_soup(true);
    for (MeshSoup* soup : {&one, &five}) {
        std::reverse(soup->soup.indices.begin() + 13, soup->soup.indices.begin() + 16);  // face 3
    }
    const RepairResult r1 = orient_faces(one);
    EXPECT_EQ(r1.count, 1u);
    EXPECT_EQ(r1.first, std::vector<std::uint32_t>{3});
    // Most faces agree inward, then the closed part turns outward: five faces turn.
    const RepairResult r5 = orient_faces(five);
    EXPECT_EQ(r5.count, 5u);
    EXPECT_EQ(r5.first, (std::vector<std::uint32_t>{0, 1, 2, 4, 5}));
    EXPECT_EQ(faces_of(one.soup), faces_of(cube_soup(false).soup));
    EXPECT_EQ(faces_of(five.soup), faces_of(cube_soup(false).soup));
}

TEST(RepairOrient, AMoebiusStripKeepsTheEdgeThatCannotAgree) {
    // Six quads around a loop with half a twist: a_i = p(θ, +w), b_i = p(θ, -w).
    const int n = 6;
    std::vector<Vec3> p;
    for (int i = 0; i < n; ++i) {
        const double t = 2 * std::numbers::pi * i / n;
        for (const double s : {0.3, -0.3}) {
            const double r = 1 + s * std::cos(t / 2);
            p.push_back({r * std::cos(t), r * std::sin(t), s * std::sin(t / 2)});
        }
    }
    Faces faces;
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
        faces.push_back({2 * i, 2 * i + 1, 2 * i + 3, 2 * i + 2});
    }
    faces.push_back({2 * (n - 1), 2 * (n - 1) + 1, 0, 1});  // the twist: a_{n-1} → b_0 side
    MeshSoup soup = soup_of(p, faces);
    const RepairResult r = orient_faces(soup);
    EXPECT_EQ(r.left, 1u);
    EXPECT_TRUE(has(r.sentence, "left 1 edge whose faces cannot agree")) << r.sentence;
    const Mesh mesh = build_mesh(soup.soup);
    EXPECT_VALID(mesh);
}

// ------------------------------------------------------------------ components

TEST(RepairComponents, ATinyFloatingTriangleGoesWithItsVertices) {
    // A 2 × 2 grid (8 triangles, 9 vertices), then a triangle far away.
    MeshSoup soup = grid_soup(2, 2, {});
    for (const Vec3& q : {Vec3{10, 10, 0}, Vec3{10.1, 10, 0}, Vec3{10, 10.1, 0}}) {
        soup.soup.positions.push_back(q);
    }
    soup.soup.add_face({9, 10, 11});
    soup.face_materials.assign(9, 0);
    soup.face_materials.back() = 1;
    MeshSoup by_area = soup;

    const RepairResult r = remove_small_components(soup, {2, 0.0});
    EXPECT_EQ(r.count, 1u);
    EXPECT_EQ(r.first, std::vector<std::uint32_t>{8});
    EXPECT_EQ(r.removed_vertices, 3u);
    EXPECT_EQ(soup.soup.n_faces(), 8u);
    EXPECT_EQ(soup.soup.positions.size(), 9u);
    EXPECT_EQ(soup.face_materials, std::vector<std::uint32_t>(8, 0));
    EXPECT_EQ(r.sentence,
              "removed 1 component of fewer than 2 faces (1 face in all; the first face of "
              "each: 8); removed 3 vertices only they used");

    EXPECT_EQ(remove_small_components(by_area, {0, 0.5}).count, 1u);  // area 0.005
    EXPECT_EQ(by_area.soup.n_faces(), 8u);
}

TEST(RepairComponents, WhenEveryPartIsSmallTheLargestStays) {
    MeshSoup soup = grid_soup(1, 1, {});  // two triangles
    for (const Vec3& q : {Vec3{10, 10, 0}, Vec3{10.1, 10, 0}, Vec3{10, 10.1, 0}}) {
        soup.soup.positions.push_back(q);
    }
    soup.soup.add_face({4, 5, 6});
    const RepairResult r = remove_small_components(soup, {100, 0.0});
    EXPECT_EQ(r.count, 1u);
    EXPECT_EQ(soup.soup.n_faces(), 2u);
    EXPECT_TRUE(has(r.sentence, "kept the largest (2 faces, from face 0)")) << r.sentence;
    EXPECT_THROW(remove_small_components(soup, {0, -1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace meshedit::test
