// The repair verbs through the edit language: an unwelded cube is welded whole, flipped faces
// are turned back, holes are filled, attributes and creases survive the trip through the soup,
// a second repair changes nothing bit for bit, and a refused step leaves the mesh bit for bit.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/smoothing.h"
#include "meshedit/core/topology.h"
#include "meshedit/io/io.h"
#include "meshedit/ops/ops.h"
#include "meshedit/repair/repair.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit::ops {
namespace {

const std::vector<Vec3> kCorners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
// The unit cube as 12 outward triangles.
const std::vector<std::array<std::uint32_t, 3>> kTriangles = {
    {0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
    {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};

// The cube as a file of 12 separate triangles holds it (36 vertices), each corner with its
// own texture coordinate, built as a loaded file is.
Mesh unwelded_cube() {
    MeshSoup soup;
    for (const auto& t : kTriangles) {
        for (const std::uint32_t c : t) {
            soup.corner_texcoords.push_back({kCorners[c].x, kCorners[c].y + kCorners[c].z});
            soup.soup.indices.push_back(static_cast<std::uint32_t>(soup.soup.positions.size()));
            soup.soup.positions.push_back(kCorners[c]);
        }
        soup.soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.soup.indices.size()));
    }
    soup.soup.face_offsets.insert(soup.soup.face_offsets.begin(), 0);
    soup.creases.emplace_back(0, 1);  // the first triangle's edge from (0,0,0) to (1,1,0)
    return build_loaded_mesh(std::move(soup), "cube").mesh;
}

// The welded cube with `flipped` triangles wound backwards, built as a loaded file is (the
// builder cuts the edges where neighbours disagree).
Mesh cube_with_flipped(const std::vector<std::size_t>& flipped) {
    std::vector<std::vector<std::uint32_t>> faces;
    for (std::size_t i = 0; i < kTriangles.size(); ++i) {
        const auto& t = kTriangles[i];
        faces.push_back({t[0], t[1], t[2]});
        if (std::find(flipped.begin(), flipped.end(), i) != flipped.end()) {
            std::swap(faces.back()[1], faces.back()[2]);
        }
    }
    MeshSoup soup;
    soup.soup = test::soup_from_faces(kCorners, faces);
    return build_loaded_mesh(std::move(soup), "cube").mesh;
}

bool closed(const Mesh& mesh) {
    for (const Edge e : mesh.edges()) {
        if (mesh.is_boundary(e)) {
            return false;
        }
    }
    return true;
}

// The closed cube of 12 triangles, valid, facing outward.
void expect_outward_cube(const Mesh& mesh) {
    EXPECT_EQ(mesh.n_vertices(), 8u);
    EXPECT_EQ(mesh.n_edges(), 18u);
    EXPECT_EQ(mesh.n_faces(), 12u);
    EXPECT_VALID(mesh);
    EXPECT_TRUE(closed(mesh));
    EXPECT_GT(enclosed_volume(mesh), 0.0);
}

std::string refusal(Mesh& mesh, const std::string& text) {
    const Mesh before = mesh;
    try {
        run_steps(mesh, parse(text), OnRefusal::Stop);
    } catch (const OpError& e) {
        EXPECT_TRUE(e.refused()) << text;
        EXPECT_TRUE(test::identical(mesh, before)) << text;
        return e.what();
    }
    ADD_FAILURE() << text << " ran";
    return {};
}

TEST(RepairVerbs, MergeByDistanceWeldsAnUnweldedCubeKeepingItsAttributes) {
    Mesh mesh = unwelded_cube();
    ASSERT_EQ(mesh.n_vertices(), 36u);
    mesh.add_property<Vertex, double>("v:weight", 1.0);
    const StepResult result = run_step(mesh, parse_step("merge_by_distance"));
    expect_outward_cube(mesh);
    EXPECT_TRUE(result.renumbers);
    EXPECT_EQ(result.message.rfind("merged 28 vertices into others within ", 0), 0u)
        << result.message;
    EXPECT_NE(result.message.find("dropped what a soup cannot carry: the property v:weight"),
              std::string::npos)
        << result.message;
    // Every corner keeps its texture coordinate; the crease is still marked.
    const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    ASSERT_TRUE(uv);
    for (const Halfedge h : mesh.halfedges()) {
        if (!mesh.is_boundary(h)) {
            const Vec3 p = mesh.position(mesh.to_vertex(h));
            EXPECT_EQ(uv[h].x, p.x);
            EXPECT_EQ(uv[h].y, p.y + p.z);
        }
    }
    EXPECT_EQ(test::crease_count(mesh), 1u);
    EXPECT_FALSE(mesh.has_property<Vertex>("v:weight"));
}

TEST(RepairVerbs, MergeByAnAbsoluteDistance) {
    Mesh mesh = unwelded_cube();
    run_step(mesh, parse_step("merge_by_distance:0.5,1"));  // the cube's edges are 1 long
    EXPECT_EQ(mesh.n_vertices(), 8u);
    Mesh apart = unwelded_cube();
    apart.position(Vertex(0)) += Vec3{1e-3, 0, 0};
    // 1e-4 apart is not 1e-3: vertex 0 stays apart, the rest merge.
    run_step(apart, parse_step("merge_by_distance:1e-4,1"));
    EXPECT_EQ(apart.n_vertices(), 9u);
}

TEST(RepairVerbs, OrientTurnsFlippedFacesOutward) {
    Mesh mesh = cube_with_flipped({2, 7});
    EXPECT_GT(mesh.n_vertices(), 8u);  // the builder cut the disagreeing edges
    const StepResult result = run_step(mesh, parse_step("orient"));
    expect_outward_cube(mesh);
    EXPECT_NE(result.message.find("turned over 2 faces"), std::string::npos) << result.message;

    Mesh inward = cube_with_flipped({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
    EXPECT_LT(enclosed_volume(inward), 0.0);
    run_step(inward, parse_step("orient"));
    EXPECT_GT(enclosed_volume(inward), 0.0);
}

TEST(RepairVerbs, FillHolesFillsThoseUpToItsSize) {
    Mesh mesh = shapes::icosphere(2);
    const std::size_t faces = mesh.n_faces();
    run_steps(mesh, parse("make_boundary:f0"), OnRefusal::Stop);
    const StepResult filled = run_step(mesh, parse_step("fill_holes:3"));
    EXPECT_EQ(mesh.n_faces(), faces);
    EXPECT_TRUE(closed(mesh));
    EXPECT_VALID(mesh);
    EXPECT_EQ(filled.message.rfind("filled 1 hole", 0), 0u) << filled.message;
    const StepResult again = run_step(mesh, parse_step("fill_holes:3"));
    EXPECT_EQ(again.message, "nothing to fill: no hole");

    Mesh cube = test::quad_cube();
    run_steps(cube, parse("make_boundary:f0"), OnRefusal::Stop);
    const Mesh open = cube;
    const StepResult large = run_step(cube, parse_step("fill_holes:3"));
    EXPECT_TRUE(test::identical(cube, open));
    EXPECT_EQ(large.message.rfind("nothing to fill: ", 0), 0u) << large.message;
    run_step(cube, parse_step("fill_holes:4"));
    EXPECT_EQ(cube.n_faces(), 6u);
    EXPECT_TRUE(closed(cube));
    EXPECT_VALID(cube);
}

TEST(RepairVerbs, FillHolesFairIsTheLibrarysFill) {
    Mesh mesh = shapes::icosphere(3);
    run_steps(mesh, parse("make_boundary:f0,make_boundary:f100,make_boundary:f700"),
              OnRefusal::Stop);
    Mesh by_library = mesh;
    const RepairResult expected = fill_holes_fair(by_library, {});
    ASSERT_GT(expected.count, 0u);
    const StepResult filled = run_step(mesh, parse_step("fill_holes_fair"));
    EXPECT_EQ(filled.message, expected.sentence);
    EXPECT_TRUE(test::identical(mesh, by_library));
    EXPECT_TRUE(closed(mesh));
    EXPECT_EQ(run_step(mesh, parse_step("fill_holes_fair")).message, "nothing to fill: no hole");
    EXPECT_NE(refusal(mesh, "fill_holes_fair:2").find("whole number from 3"), std::string::npos);
}

TEST(RepairVerbs, RepairTwiceIsRepairOnce) {
    Mesh mesh = cube_with_flipped({5});
    run_step(mesh, parse_step("repair"));
    EXPECT_EQ(mesh.n_vertices(), 8u);
    EXPECT_VALID(mesh);
    const Mesh once = mesh;
    const StepResult second = run_step(mesh, parse_step("repair"));
    EXPECT_EQ(second.message, "nothing to repair");
    EXPECT_FALSE(second.topology);
    EXPECT_TRUE(test::identical(mesh, once));
    for (const char* step : {"merge_by_distance", "stitch", "remove_degenerate", "orient",
                             "remove_small:2", "fill_holes:10"}) {
        run_step(mesh, parse_step(step));
        EXPECT_TRUE(test::identical(mesh, once)) << step;
    }
}

TEST(RepairVerbs, StitchClosesACrackBetweenTwoTessellations) {
    // The lower triangle's top side runs from (2,0) to (0,0); the upper part's two triangles
    // meet at (1,0) on it, with their own corners at its ends (repair/stitch_test.cpp).
    Mesh mesh = test::mesh_from_faces(
        {{0, 0, 0}, {2, 0, 0}, {1, -1, 0}, {0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, 1, 0}},
        {{0, 2, 1}, {3, 5, 6}, {5, 4, 6}});
    EXPECT_EQ(count_boundary_loops(mesh), 2u);
    const StepResult result = run_step(mesh, parse_step("stitch"));
    EXPECT_VALID(mesh);
    EXPECT_TRUE(result.topology);
    EXPECT_EQ(result.message.rfind("stitched 1 boundary vertex", 0), 0u) << result.message;
    EXPECT_EQ(mesh.n_vertices(), 5u);
    EXPECT_EQ(mesh.n_faces(), 4u);
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
    const Mesh once = mesh;
    EXPECT_EQ(run_step(mesh, parse_step("stitch")).message, "nothing to repair");
    EXPECT_TRUE(test::identical(mesh, once));
}

TEST(RepairVerbs, FillFairFillsTheOneHoleItsEdgeBorders) {
    // Two holes cut from a sphere, far apart; the edge names the first.
    Mesh mesh = shapes::icosphere(2);
    run_step(mesh, parse_step("make_boundary:f0"));
    run_step(mesh, parse_step("make_boundary:f200"));
    ASSERT_EQ(count_boundary_loops(mesh), 2u);
    Halfedge border;
    for (const Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h) && !border.is_valid()) {
            border = h;
        }
    }
    const Vertex a = mesh.from_vertex(border), b = mesh.to_vertex(border);
    const std::string step = "fill_fair:" + std::to_string(a.idx()) + "-" + std::to_string(b.idx());
    Mesh by_library = mesh;
    const RepairResult expected = fill_hole_fair(by_library, border, FairFillOptions{});
    ASSERT_EQ(expected.count, 1u);

    const StepResult result = run_step(mesh, parse_step(step));
    EXPECT_VALID(mesh);
    EXPECT_TRUE(result.topology);
    EXPECT_EQ(result.message, expected.sentence);
    EXPECT_EQ(count_boundary_loops(mesh), 1u);
    EXPECT_TRUE(test::identical(mesh, by_library));

    // An edge that is not on a hole: refused, the mesh as it was.
    const Mesh before = mesh;
    EXPECT_NE(refusal(mesh, step).find("not on a hole"), std::string::npos);
    EXPECT_TRUE(test::identical(mesh, before));
}

TEST(RepairVerbs, RemoveSmallAndRemoveDegenerate) {
    Mesh mesh = test::two_copies(shapes::icosphere(1), {5, 0, 0});
    const std::size_t faces = mesh.n_faces();
    const StepResult kept = run_step(mesh, parse_step("remove_small:10"));
    EXPECT_EQ(mesh.n_faces(), faces);
    EXPECT_EQ(kept.message.rfind("nothing to repair", 0), 0u) << kept.message;

    Mesh flat = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}},
                                      {{0, 1, 2}, {0, 3, 1}});  // the second has no area
    const StepResult removed = run_step(flat, parse_step("remove_degenerate"));
    EXPECT_EQ(flat.n_faces(), 1u);
    EXPECT_VALID(flat);
    EXPECT_EQ(removed.message.rfind("removed 1 degenerate face", 0), 0u) << removed.message;
}

TEST(RepairVerbs, RefusalsLeaveTheMeshBitForBit) {
    Mesh mesh = unwelded_cube();
    EXPECT_NE(refusal(mesh, "merge_by_distance:-1").find("finite number of at least 0"),
              std::string::npos);
    EXPECT_NE(refusal(mesh, "merge_by_distance:nan").find("finite number"), std::string::npos);
    EXPECT_NE(refusal(mesh, "merge_by_distance:inf").find("finite number"), std::string::npos);
    EXPECT_NE(refusal(mesh, "merge_by_distance:0.1,2").find("0 (a share"), std::string::npos);
    EXPECT_NE(refusal(mesh, "remove_small:0").find("whole number"), std::string::npos);
    EXPECT_NE(refusal(mesh, "remove_small:1.5").find("whole number"), std::string::npos);
    EXPECT_NE(refusal(mesh, "fill_holes:2").find("whole number from 3"), std::string::npos);
    EXPECT_NE(refusal(mesh, "stitch:0").find("more than 0 and less than 0.5"), std::string::npos);
    EXPECT_NE(refusal(mesh, "stitch:0.5").find("more than 0 and less than 0.5"), std::string::npos);
    // A tolerance larger than the mesh would merge every face away.
    EXPECT_NE(refusal(mesh, "merge_by_distance:2").find("no face of 12 would be left"),
              std::string::npos);
    Mesh empty;
    for (const char* step : {"repair", "merge_by_distance", "stitch", "remove_degenerate", "orient",
                             "remove_small:3", "fill_holes:3"}) {
        EXPECT_NE(refusal(empty, step).find("the mesh has no faces"), std::string::npos) << step;
    }
}

}  // namespace
}  // namespace meshedit::ops
