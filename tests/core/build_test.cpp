// build_mesh(): polygon soup -> halfedge mesh, with every repair reported.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "meshedit/core/build.h"
#include "meshedit/core/topology.h"
#include "meshedit/core/validate.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using test::soup_from_faces;

const std::vector<Vec3> kTetPositions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::vector<std::vector<std::uint32_t>> kTetFaces{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

//     3 ----- 2
//     |     / |      Two triangles: 4 vertices, 5 edges (4 on the boundary), 1 loop.
//     |   /   |
//     0 ----- 1
TEST(BuildMesh, TwoTrianglesKeepVertexOrderAndFaces) {
    BuildReport report;
    const PolygonSoup soup =
        soup_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
    const Mesh mesh = build_mesh(soup, &report);
    ASSERT_VALID(mesh);
    EXPECT_FALSE(report.repaired());
    EXPECT_EQ(mesh.n_vertices(), 4u);
    EXPECT_EQ(mesh.n_edges(), 5u);
    EXPECT_EQ(mesh.n_faces(), 2u);
    for (std::uint32_t i = 0; i < 4; ++i) {
        EXPECT_EQ(mesh.position(Vertex(i)), soup.positions[i]);  // vertex i = input i
        EXPECT_TRUE(mesh.is_boundary(Vertex(i)));
    }
    const std::vector<std::vector<std::uint32_t>> expected{{0, 1, 2}, {0, 2, 3}};
    EXPECT_EQ(test::canonical_faces(mesh), expected);
    EXPECT_FALSE(mesh.is_boundary(mesh.find_edge(Vertex(0), Vertex(2))));
    EXPECT_TRUE(mesh.is_boundary(mesh.find_edge(Vertex(0), Vertex(1))));
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
}

TEST(BuildMesh, FacesKeepTheirOrderAndCornerOrder) {
    const Mesh mesh = build_mesh(soup_from_faces(kTetPositions, kTetFaces));
    ASSERT_VALID(mesh);
    for (std::uint32_t f = 0; f < 4; ++f) {
        std::vector<std::uint32_t> corners;
        Halfedge h = mesh.halfedge(Face(f));
        for (int i = 0; i < 3; ++i) {
            corners.push_back(mesh.from_vertex(h).idx());
            h = mesh.next(h);
        }
        EXPECT_EQ(corners, kTetFaces[f]) << "face " << f;
    }
    EXPECT_EQ(mesh.n_edges(), 6u);
    EXPECT_EQ(count_boundary_loops(mesh), 0u);
}

TEST(BuildMesh, PolygonsAreKept) {
    // A pyramid with a square base: one quad and four triangles.
    const Mesh mesh =
        build_mesh(soup_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}},
                                   {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}));
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.valence(Face(0)), 4u);
    EXPECT_FALSE(mesh.is_triangle_mesh());
    EXPECT_EQ(euler_characteristic(mesh), 2);
}

TEST(BuildMesh, DegenerateFacesAreDroppedAndReported) {
    PolygonSoup soup = soup_from_faces(kTetPositions, kTetFaces);
    soup.add_face({0, 1});        // face 4: two corners
    soup.add_face({0, 1, 1});     // face 5: repeated corner
    soup.add_face({2, 3, 2, 1});  // face 6: repeated corner
    BuildReport report;
    const Mesh mesh = build_mesh(soup, &report);
    ASSERT_VALID(mesh);
    EXPECT_EQ(report.dropped_faces, (std::vector<std::uint32_t>{4, 5, 6}));
    EXPECT_EQ(mesh.n_faces(), 4u);
    EXPECT_NE(report.summary().find("dropped 3 degenerate faces"), std::string::npos)
        << report.summary();
}

//   3           1        A bow tie: two triangles share vertex 0 only. Vertex 0 is
//   | \       / |        split: the second fan gets copy 5 at the same position.
//   |   \   /   |
//   |     0     |
//   |   /   \   |
//   4           2
TEST(BuildMesh, NonManifoldVertexIsSplit) {
    BuildReport report;
    const Mesh mesh = build_mesh(test::bowtie_soup(), &report);
    ASSERT_VALID(mesh);
    EXPECT_EQ(report.split_vertices, (std::vector<std::uint32_t>{0}));
    EXPECT_EQ(report.added_vertices, 1u);
    EXPECT_EQ(mesh.n_vertices(), 6u);
    EXPECT_EQ(mesh.position(Vertex(5)), mesh.position(Vertex(0)));
    EXPECT_EQ(count_components(mesh), 2u);
    EXPECT_EQ(count_boundary_loops(mesh), 2u);
    EXPECT_EQ(test::canonical_faces(mesh),
              (std::vector<std::vector<std::uint32_t>>{{0, 1, 2}, {3, 4, 5}}));
    EXPECT_NE(report.summary().find("split 1 non-manifold vertex (0) by adding 1 copy"),
              std::string::npos);
}

// Three triangles on edge 0-1 (a "book"): the edge is cut into boundaries.
TEST(BuildMesh, EdgeWithThreeFacesIsCut) {
    BuildReport report;
    const Mesh mesh =
        build_mesh(soup_from_faces({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}},
                                   {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}),
                   &report);
    ASSERT_VALID(mesh);
    ASSERT_EQ(report.nonmanifold_edges.size(), 1u);
    EXPECT_EQ(report.nonmanifold_edges[0], (std::pair<std::uint32_t, std::uint32_t>{0, 1}));
    EXPECT_EQ(mesh.n_faces(), 3u);
    EXPECT_TRUE(report.repaired());
}

// Two triangles using edge 0-1 in the same direction disagree on orientation: cut.
TEST(BuildMesh, InconsistentOrientationIsCut) {
    BuildReport report;
    const Mesh mesh = build_mesh(
        soup_from_faces({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}}, {{0, 1, 2}, {0, 1, 3}}),
        &report);
    ASSERT_VALID(mesh);
    EXPECT_EQ(report.nonmanifold_edges.size(), 1u);
    EXPECT_EQ(mesh.n_edges(), 6u);
}

// Faces (0,1,2), (0,2,1), (0,1,3): edge 0-1 has three faces and is cut; the third face gets
// copies of 1 and 0 (4 and 5, in the order its corners are met). The first two still share
// 0 and 1, and their two sides of 0-1 are glued back: a closed pillow and a separate
// triangle, and no doubled edge (a slit of two boundary edges 0-1 once made collapse() leave
// a self-loop).
TEST(BuildMesh, CutEdgeWhoseSidesStillJoinTheSameVerticesIsGlued) {
    BuildReport report;
    const Mesh mesh = build_mesh(test::pillow_and_ear_soup(), &report);
    ASSERT_VALID(mesh);
    EXPECT_EQ(report.nonmanifold_edges,
              (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, 1}}));
    EXPECT_EQ(report.split_vertices, (std::vector<std::uint32_t>{0, 1}));
    EXPECT_EQ(mesh.n_vertices(), 6u);
    EXPECT_EQ(mesh.n_edges(), 6u);
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
    EXPECT_EQ(count_components(mesh), 2u);
    EXPECT_EQ(test::canonical_faces(mesh),
              (std::vector<std::vector<std::uint32_t>>{{0, 1, 2}, {0, 2, 1}, {3, 5, 4}}));
    EXPECT_TRUE(test::identical(build_mesh(to_polygon_soup(mesh)), mesh));
}

TEST(BuildMesh, DuplicateFaceBecomesSeparateComponent) {
    BuildReport report;
    const Mesh mesh = build_mesh(
        soup_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 1, 2}}), &report);
    ASSERT_VALID(mesh);
    EXPECT_EQ(report.nonmanifold_edges.size(), 3u);
    EXPECT_EQ(mesh.n_vertices(), 6u);
    EXPECT_EQ(count_components(mesh), 2u);
}

TEST(BuildMesh, UnusedVerticesStayIsolated) {
    BuildReport report;
    std::vector<Vec3> positions = kTetPositions;
    positions.push_back({5, 5, 5});
    const Mesh mesh = build_mesh(soup_from_faces(positions, kTetFaces), &report);
    ASSERT_VALID(mesh);
    EXPECT_EQ(report.isolated_vertices, 1u);
    EXPECT_TRUE(mesh.is_isolated(Vertex(4)));
    EXPECT_EQ(mesh.position(Vertex(4)), (Vec3{5, 5, 5}));
    EXPECT_FALSE(report.repaired());
}

TEST(BuildMesh, IndexOutOfRangeThrowsNamingFaceAndVertex) {
    try {
        build_mesh(soup_from_faces(kTetPositions, {{0, 1, 2}, {0, 1, 9}}));
        FAIL() << "expected TopologyError";
    } catch (const TopologyError& e) {
        EXPECT_STREQ(e.what(), "face 1 uses vertex 9, but there are only 4 vertices");
    }
}

TEST(BuildMesh, NonFinitePositionThrowsNamingVertex) {
    std::vector<Vec3> positions = kTetPositions;
    positions[2].y = std::nan("");
    try {
        build_mesh(soup_from_faces(positions, kTetFaces));
        FAIL() << "expected TopologyError";
    } catch (const TopologyError& e) {
        EXPECT_STREQ(e.what(), "vertex 2 has a non-finite coordinate");
    }
    positions[2].y = INFINITY;
    EXPECT_THROW(build_mesh(soup_from_faces(positions, kTetFaces)), TopologyError);
}

TEST(BuildMesh, EmptySoupGivesEmptyMesh) {
    const Mesh mesh = build_mesh(PolygonSoup{});
    ASSERT_VALID(mesh);
    EXPECT_TRUE(mesh.is_empty());
}

TEST(BuildMesh, RoundTripThroughSoupIsIdentical) {
    const Mesh mesh = build_mesh(soup_from_faces(kTetPositions, kTetFaces));
    const Mesh again = build_mesh(to_polygon_soup(mesh));
    EXPECT_TRUE(test::identical(again, mesh));
}

// Random soups over few vertices are wildly non-manifold; every one must still become a
// valid mesh (never a crash, never an invalid structure).
TEST(BuildMesh, RandomNonManifoldSoupsAlwaysValidate) {
    std::mt19937 rng(12345);
    for (int trial = 0; trial < 3000; ++trial) {
        const int nv = 3 + static_cast<int>(rng() % 8);
        const int nf = 1 + static_cast<int>(rng() % 14);
        PolygonSoup soup;
        for (int v = 0; v < nv; ++v) {
            soup.positions.push_back({double(v), double(v * v % 7), double(v % 3)});
        }
        for (int f = 0; f < nf; ++f) {
            const int k = 3 + static_cast<int>(rng() % 3);
            std::vector<std::uint32_t> corners;
            for (int c = 0; c < k; ++c) {
                corners.push_back(static_cast<std::uint32_t>(rng() % nv));
            }
            soup.add_face_range(corners);
        }
        BuildReport report;
        const Mesh mesh = build_mesh(soup, &report);
        ASSERT_VALID(mesh) << "trial " << trial;
        ASSERT_EQ(mesh.n_faces() + report.dropped_faces.size(), soup.n_faces());
        ASSERT_EQ(mesh.n_vertices(), soup.positions.size() + report.added_vertices);
        // The repaired mesh is a face list's own mesh: written out as one and read back, it
        // is the same mesh and needs no repair (what every file round trip relies on).
        BuildReport again;
        ASSERT_TRUE(test::identical(build_mesh(to_polygon_soup(mesh), &again), mesh))
            << "trial " << trial;
        ASSERT_FALSE(again.repaired()) << "trial " << trial << ": " << again.summary();
    }
}

}  // namespace
}  // namespace meshedit
