// Filling holes, attributes through the steps, the whole sequence and its idempotence
// (repair.h).

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <tuple>

#include "meshedit/core/attributes.h"
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

// ------------------------------------------------------------------ holes

TEST(RepairHoles, AHoleOfFourEdgesIsFilledAndOneOfTenIsLeftAtFive) {
    // A 10 × 10 grid without square (2, 2) (a hole of 4 edges) and squares (5..8, 6) (a hole
    // of 10 edges, its long sides straight: a fan from any corner would have flat triangles).
    const MeshSoup soup = grid_soup(10, 10, {22, 65, 66, 67, 68});
    Mesh mesh = build_mesh(soup.soup);
    ASSERT_EQ(count_boundary_loops(mesh), 3u);
    const std::size_t faces = mesh.n_faces();

    const RepairResult r = fill_holes(mesh, 5);
    ASSERT_VALID(mesh);
    EXPECT_EQ(r.count, 1u);
    EXPECT_EQ(r.left, 2u);  // the 10 edges, and the grid's own border of 40
    EXPECT_EQ(mesh.n_faces(), faces + 2);
    EXPECT_TRUE(mesh.is_triangle_mesh());
    EXPECT_EQ(count_boundary_loops(mesh), 2u);
    EXPECT_TRUE(has(r.sentence, "filled 1 hole of at most 5 edges (4 edges in all, with triangles"))
        << r.sentence;
    EXPECT_TRUE(has(r.sentence,
                    "left 2 holes of more than 5 edges (40, 10 edges; the largest at "
                    "vertex 1)"))
        << r.sentence;
    EXPECT_EQ(fill_holes(mesh, 5).count, 0u);  // again: nothing more to fill

    // At ten edges the long hole is filled too, with no flat triangle (flips from the fan).
    const RepairResult r10 = fill_holes(mesh, 10);
    ASSERT_VALID(mesh);
    EXPECT_EQ(r10.count, 1u);
    EXPECT_EQ(r10.left, 1u);
    EXPECT_EQ(mesh.n_faces(), faces + 2 + 8);
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
    for (const Face f : mesh.faces()) {
        EXPECT_GT(norm(face_area_vector(mesh, f)), 0.1) << "face " << f.idx();
    }
    MeshSoup again;
    again.soup = to_polygon_soup(mesh);
    EXPECT_FALSE(repair(again).changed());
}

TEST(RepairHoles, APolygonMeshGetsOnePolygonPerHole) {
    // The open cube (the top quad gone): one hole of 4 edges, filled by one quad, and the
    // cube is closed and outward.
    MeshSoup soup = cube_soup(false);
    soup.soup.indices.resize(4 * 5);
    soup.soup.face_offsets.resize(6);
    Mesh mesh = build_mesh(soup.soup);
    const RepairResult r = fill_holes(mesh, 4);
    ASSERT_VALID(mesh);
    EXPECT_EQ(r.count, 1u);
    EXPECT_EQ(mesh.n_faces(), 6u);
    EXPECT_FALSE(mesh.is_triangle_mesh());
    EXPECT_TRUE(is_closed_and_outward(mesh));
}

TEST(RepairHoles, APartAFillClosesTurnsOutward) {
    // The inside-out cube without one face: open, its winding is kept by orientation; once
    // the hole is filled it is closed, and turned outward with its corner values.
    MeshSoup soup = cube_soup(true);
    soup.soup.indices.resize(4 * 5);
    soup.soup.face_offsets.resize(6);
    LoadedMesh loaded = build_loaded_mesh(soup, "cube");
    auto uv = loaded.mesh.property<Halfedge, Vec2>(kTexCoordProperty);
    for (const Halfedge h : loaded.mesh.halfedges()) {
        uv[h] = {static_cast<double>(loaded.mesh.to_vertex(h).idx()), 0};
    }
    const RepairResult r = fill_holes(loaded.mesh, 4);
    ASSERT_VALID(loaded.mesh);
    EXPECT_EQ(r.count, 1u);
    EXPECT_TRUE(is_closed_and_outward(loaded.mesh));
    EXPECT_TRUE(
        has(r.sentence, "turned over 6 faces so that 1 part the fills closed faces outward"))
        << r.sentence;
    // Each face corner still holds the value of its own vertex.
    for (const Halfedge h : loaded.mesh.halfedges()) {
        if (!loaded.mesh.is_boundary(h)) {
            EXPECT_EQ(uv[h].x, static_cast<double>(loaded.mesh.to_vertex(h).idx()));
        }
    }
}

// ------------------------------------------------------------------ attributes

// Per face, each corner's position and texture coordinate.
using Corners = std::vector<std::map<std::tuple<double, double, double>, Vec2>>;

Corners corners_of(const MeshSoup& soup) {
    Corners out(soup.soup.n_faces());
    for (std::size_t f = 0; f < soup.soup.n_faces(); ++f) {
        for (std::uint32_t c = soup.soup.face_offsets[f]; c < soup.soup.face_offsets[f + 1]; ++c) {
            const Vec3& p = soup.soup.positions[soup.soup.indices[c]];
            out[f][{p.x, p.y, p.z}] = soup.corner_texcoords[c];
        }
    }
    return out;
}

TEST(RepairAttributes, EveryCornerKeepsItsTextureCoordinateThroughMergeAndFlip) {
    // A strip of three unit quads, each with its own four vertices; the middle one turned.
    MeshSoup soup;
    for (int i = 0; i < 3; ++i) {
        const double x = i;
        std::vector<Vec3> quad{{x, 0, 0}, {x + 1, 0, 0}, {x + 1, 1, 0}, {x, 1, 0}};
        if (i == 1) {
            std::reverse(quad.begin() + 1, quad.end());
        }
        std::vector<std::uint32_t> corners;
        for (const Vec3& p : quad) {
            corners.push_back(static_cast<std::uint32_t>(soup.soup.positions.size()));
            soup.soup.positions.push_back(p);
            soup.corner_texcoords.push_back({10.0 * i + p.x, p.y});  // a seam between quads
        }
        soup.soup.add_face_range(corners);
    }
    soup.face_materials = {0, 1, 2};
    soup.materials.resize(3);
    const Corners before = corners_of(soup);

    const RepairReport report = repair(soup);
    ASSERT_EQ(report.lines.size(), 2u);
    EXPECT_TRUE(has(report.lines[0], "merged 4 vertices")) << report.lines[0];
    EXPECT_EQ(report.lines[1], "turned over 1 face to agree with its neighbours: 1");
    EXPECT_EQ(soup.soup.positions.size(), 8u);
    EXPECT_EQ(corners_of(soup), before);
    EXPECT_EQ(soup.face_materials, (std::vector<std::uint32_t>{0, 1, 2}));

    // Built, each face halfedge holds the value of the corner it arrives at.
    const LoadedMesh loaded = build_loaded_mesh(soup, "strip");
    ASSERT_VALID(loaded.mesh);
    EXPECT_FALSE(loaded.repairs.repaired());
    const auto uv = loaded.mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    ASSERT_TRUE(uv);
    for (const Face f : loaded.mesh.faces()) {
        for (const Halfedge h : loaded.mesh.halfedges(f)) {
            const Vec3& p = loaded.mesh.position(loaded.mesh.to_vertex(h));
            EXPECT_EQ(uv[h], before[f.idx()].at({p.x, p.y, p.z})) << "face " << f.idx();
        }
    }
}

// ------------------------------------------------------------------ the sequence

// An inside-out cube, unwelded, with a duplicate face, a zero-area face, a repeated corner and
// a tiny floating triangle, every corner with its own texture coordinate.
MeshSoup hostile_soup() {
    const MeshSoup cube = cube_soup(true);
    MeshSoup soup;
    const auto add = [&](const std::vector<Vec3>& corners) {
        std::vector<std::uint32_t> face;
        for (const Vec3& p : corners) {
            face.push_back(static_cast<std::uint32_t>(soup.soup.positions.size()));
            soup.soup.positions.push_back(p);
            soup.corner_texcoords.push_back(
                {p.x + p.z, p.y + static_cast<double>(soup.soup.n_faces())});
        }
        soup.soup.add_face_range(face);
    };
    for (std::size_t f = 0; f < cube.soup.n_faces(); ++f) {
        std::vector<Vec3> corners;
        for (std::uint32_t c = cube.soup.face_offsets[f]; c < cube.soup.face_offsets[f + 1]; ++c) {
            corners.push_back(cube.soup.positions[cube.soup.indices[c]]);
        }
        add(corners);
        if (f == 2) {
            add(corners);  // a duplicate
        }
    }
    add({{-1, -1, -1}, {0, -1, -1}, {1, -1, -1}});            // zero area, on an edge
    add({{5, 5, 5}, {5.1, 5, 5}, {5.1, 5, 5}, {5, 5.1, 5}});  // a repeated corner
    soup.face_materials.assign(soup.soup.n_faces(), 0);
    return soup;
}

TEST(RepairSequence, TheSafeSequenceOnAHostileSoup) {
    MeshSoup soup = hostile_soup();
    RepairOptions options;
    options.components.min_faces = 2;
    const RepairReport report = repair(soup, options);
    ASSERT_EQ(report.lines.size(), 5u);
    EXPECT_TRUE(has(report.lines[0], "merged")) << report.lines[0];
    EXPECT_TRUE(has(report.lines[1], "removed 1 degenerate face (1 of zero area): 7"))
        << report.lines[1];
    EXPECT_TRUE(has(report.lines[1], "dropped 1 repeated corner from 1 face")) << report.lines[1];
    EXPECT_EQ(report.lines[2],
              "removed 1 duplicate face (the same vertices as an earlier face): 3");
    EXPECT_TRUE(has(report.lines[3], "so that 1 closed part faces outward")) << report.lines[3];
    EXPECT_TRUE(has(report.lines[4], "removed 1 component of fewer than 2 faces"))
        << report.lines[4];
    EXPECT_EQ(soup.soup.n_faces(), 6u);
    EXPECT_EQ(soup.soup.positions.size(), 8u);
    EXPECT_EQ(soup.corner_texcoords.size(), 24u);
    EXPECT_EQ(soup.face_materials.size(), 6u);

    const LoadedMesh loaded = build_loaded_mesh(soup, "hostile");
    ASSERT_VALID(loaded.mesh);
    EXPECT_FALSE(loaded.repairs.repaired());
    EXPECT_TRUE(is_closed_and_outward(loaded.mesh));
}

TEST(RepairSequence, RepairingARepairedSoupChangesNothing) {
    for (const bool merge : {true, false}) {
        SCOPED_TRACE(merge ? "merged" : "not merged");
        MeshSoup soup = hostile_soup();
        RepairOptions options;
        options.merge = merge;
        options.components.min_faces = 2;
        repair(soup, options);
        const MeshSoup once = soup;
        const RepairReport again = repair(soup, options);
        EXPECT_FALSE(again.changed());
        EXPECT_TRUE(again.lines.empty()) << again.lines.front();
        EXPECT_EQ(soup.soup.positions, once.soup.positions);
        EXPECT_EQ(soup.soup.indices, once.soup.indices);
        EXPECT_EQ(soup.soup.face_offsets, once.soup.face_offsets);
        EXPECT_EQ(soup.corner_texcoords, once.corner_texcoords);
        EXPECT_EQ(soup.face_materials, once.face_materials);
        EXPECT_VALID(build_mesh(soup.soup));
    }
}

TEST(RepairSequence, RepairAndBuildReportsWhatTheBuilderStillCut) {
    // Three triangles on one edge 0-1: a non-manifold edge no repair step removes.
    MeshSoup soup = soup_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                            {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    const RepairedMesh repaired = repair_and_build(soup, {}, "fin");
    ASSERT_VALID(repaired.loaded.mesh);
    ASSERT_FALSE(repaired.report.lines.empty());
    EXPECT_TRUE(has(repaired.report.lines.back(), "the builder ")) << repaired.report.lines.back();
    MeshSoup nan = soup_of({{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}}, {{0, 1, 2}});
    try {
        repair_and_build(nan, {}, "nan.obj");
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_TRUE(has(e.what(), "nan.obj")) << e.what();
        EXPECT_TRUE(has(e.what(), "vertex 2 has a non-finite coordinate")) << e.what();
    }
}

TEST(RepairSequence, HolesAreFilledOnlyWhenAsked) {
    const MeshSoup soup = grid_soup(4, 4, {5});
    EXPECT_EQ(count_boundary_loops(repair_and_build(soup, {}, "grid").loaded.mesh), 2u);
    RepairOptions options;
    options.fill_holes = 4;
    const RepairedMesh filled = repair_and_build(soup, options, "grid");
    ASSERT_VALID(filled.loaded.mesh);
    EXPECT_EQ(count_boundary_loops(filled.loaded.mesh), 1u);
    ASSERT_EQ(filled.report.lines.size(), 1u);
    EXPECT_TRUE(has(filled.report.lines[0], "filled 1 hole")) << filled.report.lines[0];
}

}  // namespace
}  // namespace meshedit::test
