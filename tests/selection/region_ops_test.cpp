// Extrude and subdivide a region of faces as one (region_ops.h), on quad grids and triangle
// meshes whose answers are known by construction, and against whole-mesh linear subdivision.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/smoothing.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/selection/region_ops.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

FaceSet faces(const Mesh& mesh, const std::vector<std::uint32_t>& indices) {
    FaceSet out(mesh.faces_size());
    for (const std::uint32_t f : indices) {
        out.insert(Face(f));
    }
    return out;
}

// The middle 3 × 3 quads of a 5 × 5 grid: quad (i, j) is face 5 j + i.
std::vector<std::uint32_t> middle_nine() {
    std::vector<std::uint32_t> out;
    for (std::uint32_t j = 1; j <= 3; ++j) {
        for (std::uint32_t i = 1; i <= 3; ++i) {
            out.push_back(5 * j + i);
        }
    }
    return out;
}

double face_area(const Mesh& mesh, Face f) {
    Vec3 n{0, 0, 0};
    for (const Halfedge h : mesh.halfedges(f)) {
        n += cross(mesh.position(mesh.from_vertex(h)), mesh.position(mesh.to_vertex(h)));
    }
    return 0.5 * norm(n);
}

// The expected extrusion of the middle 3 × 3 of a 5 × 5 grid by `h`: the 16 quads around it
// on the floor, the 9 on top, and 12 walls.
Mesh expected_extrusion(double h) {
    std::vector<Vec3> positions;
    std::vector<std::vector<std::uint32_t>> polygons;
    std::map<std::array<double, 3>, std::uint32_t> index;
    const auto at = [&](double x, double y, double z) {
        const auto [it, made] =
            index.emplace(std::array<double, 3>{x, y, z}, std::uint32_t(positions.size()));
        if (made) {
            positions.push_back({x, y, z});
        }
        return it->second;
    };
    const auto inside = [](int i, int j) { return i >= 1 && i <= 3 && j >= 1 && j <= 3; };
    for (int j = 0; j < 5; ++j) {
        for (int i = 0; i < 5; ++i) {
            const double z = inside(i, j) ? h : 0.0;
            polygons.push_back(
                {at(i, j, z), at(i + 1, j, z), at(i + 1, j + 1, z), at(i, j + 1, z)});
        }
    }
    // Walls along the region's border, counter-clockwise seen from outside.
    for (int k = 1; k <= 3; ++k) {
        polygons.push_back({at(k, 1, 0), at(k + 1, 1, 0), at(k + 1, 1, h), at(k, 1, h)});
        polygons.push_back({at(4, k, 0), at(4, k + 1, 0), at(4, k + 1, h), at(4, k, h)});
        polygons.push_back({at(k + 1, 4, 0), at(k, 4, 0), at(k, 4, h), at(k + 1, 4, h)});
        polygons.push_back({at(1, k + 1, 0), at(1, k, 0), at(1, k, h), at(1, k + 1, h)});
    }
    return test::mesh_from_faces(positions, polygons);
}

TEST(ExtrudeRegion, NineQuadsRiseAsOneWithTwelveWalls) {
    Mesh mesh = shapes::quad_grid(5, 5);
    RegionExtrude made;
    ASSERT_TRUE(extrude_region(mesh, faces(mesh, middle_nine()), 0.5, &made));
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.n_vertices(), 36u + 12u);
    EXPECT_EQ(mesh.n_edges(), 60u + 24u);
    EXPECT_EQ(mesh.n_faces(), 25u + 12u);
    EXPECT_EQ(made.sides.size(), 12u);
    EXPECT_EQ(made.moved.size(), 16u);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected_extrusion(0.5)));
    // The region's faces are the top and still share their inner edges.
    for (const std::uint32_t f : middle_nine()) {
        for (const Halfedge h : mesh.halfedges(Face(f))) {
            EXPECT_EQ(mesh.position(mesh.to_vertex(h)).z, 0.5);
        }
    }
}

TEST(ExtrudeRegion, MovingTheTopAgainEqualsExtrudingThere) {
    Mesh moved = shapes::quad_grid(5, 5);
    RegionExtrude made;
    ASSERT_TRUE(extrude_region(moved, faces(moved, middle_nine()), 0.0, &made));
    ASSERT_TRUE(extrude_region_positions(moved, made, -0.25));
    Mesh direct = shapes::quad_grid(5, 5);
    ASSERT_TRUE(extrude_region(direct, faces(direct, middle_nine()), -0.25));
    EXPECT_TRUE(test::identical(moved, direct));
}

TEST(ExtrudeRegion, AtTheBorderTheWallsHangFromIt) {
    Mesh mesh = shapes::quad_grid(3, 3);
    ASSERT_TRUE(extrude_region(mesh, faces(mesh, {0, 1}), 1.0));  // two quads in a corner
    ASSERT_VALID(mesh);
    // Border of the two quads: 6 sides, all walls (two of them along the grid's edge).
    EXPECT_EQ(mesh.n_faces(), 9u + 6u);
    EXPECT_EQ(mesh.n_vertices(), 16u + 6u);
}

TEST(ExtrudeRegion, CarriesCornerValuesToTheWallsAndTheTop) {
    Mesh mesh = shapes::quad_grid(5, 5);
    auto corner = mesh.add_property<Halfedge, double>("h:u");
    auto value = mesh.add_property<Vertex, double>("v:u");
    const auto u = [](const Vec3& p) { return p.x + 10.0 * p.y; };
    for (const Halfedge h : mesh.halfedges()) {
        corner[h] = u(mesh.position(mesh.to_vertex(h)));
    }
    for (const Vertex v : mesh.vertices()) {
        value[v] = u(mesh.position(v));
    }
    ASSERT_TRUE(extrude_region(mesh, faces(mesh, middle_nine()), 2.0));
    // A corner copies the corner at the same vertex below it: x and y are unchanged.
    for (const Halfedge h : mesh.halfedges()) {
        if (mesh.face(h).is_valid()) {
            EXPECT_EQ(corner[h], u(mesh.position(mesh.to_vertex(h)))) << h.idx();
        }
    }
    for (const Vertex v : mesh.vertices()) {
        EXPECT_EQ(value[v], u(mesh.position(v))) << v.idx();
    }
}

TEST(ExtrudeRegion, RefusesWithItsReasonAndTouchesNothing) {
    const Mesh grid = shapes::quad_grid(5, 5);
    const Mesh cube = test::quad_cube();
    const auto refused = [](const Mesh& before, const FaceSet& region, double height,
                            const std::string& reason) {
        Mesh mesh = before;
        const auto r = extrude_region(mesh, region, height);
        EXPECT_FALSE(r);
        EXPECT_NE(std::string(r.reason()).find(reason), std::string::npos) << r.reason();
        EXPECT_TRUE(test::identical(mesh, before));
    };
    refused(cube, faces(cube, {0, 1, 2, 3, 4, 5}), 1.0, "whole closed surface");
    refused(grid, faces(grid, {0, 6}), 1.0, "touches itself at vertex 7");
    refused(grid, faces(grid, {}), 1.0, "select one or more live faces");
    refused(grid, faces(grid, {3}), std::nan(""), "finite");
    refused(grid, faces(grid, {3}), 1e308, "range of numbers");
}

// The expected inset of the middle 3 × 3 of a 5 × 5 grid by `t`: the 16 quads around it as
// they were, a ring of 12 quads from the square [1, 4]² in to [1 + t, 4 - t]², and inside it
// the 9 quads, whose border vertices moved in by t (the corners diagonally) and whose four
// inner vertices stayed.
Mesh expected_inset(double t) {
    std::vector<Vec3> positions;
    std::vector<std::vector<std::uint32_t>> polygons;
    std::map<std::array<double, 2>, std::uint32_t> index;
    const auto at = [&](double x, double y) {
        const auto [it, made] =
            index.emplace(std::array<double, 2>{x, y}, std::uint32_t(positions.size()));
        if (made) {
            positions.push_back({x, y, 0.0});
        }
        return it->second;
    };
    const auto inside = [](int i, int j) { return i >= 1 && i <= 3 && j >= 1 && j <= 3; };
    const auto in = [&](int k) { return k == 1 ? 1 + t : k == 4 ? 4 - t : double(k); };
    for (int j = 0; j < 5; ++j) {
        for (int i = 0; i < 5; ++i) {
            if (inside(i, j)) {
                polygons.push_back({at(in(i), in(j)), at(in(i + 1), in(j)),
                                    at(in(i + 1), in(j + 1)), at(in(i), in(j + 1))});
            } else {
                polygons.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    }
    for (int k = 1; k <= 3; ++k) {  // the ring, counter-clockwise seen from +z
        polygons.push_back({at(k, 1), at(k + 1, 1), at(in(k + 1), in(1)), at(in(k), in(1))});
        polygons.push_back({at(4, k), at(4, k + 1), at(in(4), in(k + 1)), at(in(4), in(k))});
        polygons.push_back({at(k + 1, 4), at(k, 4), at(in(k), in(4)), at(in(k + 1), in(4))});
        polygons.push_back({at(1, k + 1), at(1, k), at(in(1), in(k)), at(in(1), in(k + 1))});
    }
    return test::mesh_from_faces(positions, polygons);
}

TEST(InsetRegion, NineQuadsGetOneRingOfTwelve) {
    Mesh mesh = shapes::quad_grid(5, 5);
    RegionInset made;
    ASSERT_TRUE(inset_region(mesh, faces(mesh, middle_nine()), 0.25, &made));
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.n_vertices(), 36u + 12u);
    EXPECT_EQ(mesh.n_edges(), 60u + 24u);
    EXPECT_EQ(mesh.n_faces(), 25u + 12u);
    EXPECT_EQ(made.border.size(), 12u);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected_inset(0.25)));
    // The region keeps its handles: its faces are the inner nine, each inside the ring.
    double area = 0;
    for (const std::uint32_t f : middle_nine()) {
        area += face_area(mesh, Face(f));
    }
    EXPECT_NEAR(area, 2.5 * 2.5, 1e-12);
}

TEST(InsetRegion, MovingTheRingAgainEqualsInsettingThere) {
    Mesh moved = shapes::quad_grid(5, 5);
    RegionInset made;
    ASSERT_TRUE(inset_region(moved, faces(moved, middle_nine()), 0.0, &made));
    ASSERT_TRUE(inset_region_positions(moved, made, 0.4));
    Mesh direct = shapes::quad_grid(5, 5);
    ASSERT_TRUE(inset_region(direct, faces(direct, middle_nine()), 0.4));
    EXPECT_TRUE(test::identical(moved, direct));
    // The base taken before equals what the run made.
    Mesh fresh = shapes::quad_grid(5, 5);
    const RegionInset base = inset_region_base(fresh, faces(fresh, middle_nine()));
    EXPECT_EQ(base.border, made.border);
    EXPECT_EQ(base.inward, made.inward);
}

TEST(InsetRegion, RefusesWithItsReasonAndTouchesNothing) {
    const Mesh grid = shapes::quad_grid(5, 5);
    const Mesh cube = test::quad_cube();
    const auto refused = [](const Mesh& before, const FaceSet& region, double thickness,
                            const std::string& reason) {
        Mesh mesh = before;
        const auto r = inset_region(mesh, region, thickness);
        EXPECT_FALSE(r);
        EXPECT_NE(std::string(r.reason()).find(reason), std::string::npos) << r.reason();
        EXPECT_EQ(std::string(r.reason()).rfind("cannot inset the region: ", 0), 0u);
        EXPECT_TRUE(test::identical(mesh, before));
    };
    refused(cube, faces(cube, {0, 1, 2, 3, 4, 5}), 0.1, "whole closed surface");
    refused(grid, faces(grid, {0, 6}), 0.1, "touches itself at vertex 7");
    refused(grid, faces(grid, {}), 0.1, "select one or more live faces");
    refused(grid, faces(grid, {3}), -0.1, "at least 0");
    refused(grid, faces(grid, {3}), std::nan(""), "finite");
    refused(grid, faces(grid, {3}), 1e308, "range of numbers");
}

TEST(SubdivideRegion, OneQuadSplitsAndItsNeighboursFan) {
    Mesh mesh = shapes::quad_grid(3, 3);
    std::vector<Face> inside;
    ASSERT_TRUE(subdivide_region(mesh, faces(mesh, {4}), &inside));
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.n_vertices(), 16u + 4u + 1u);
    // The middle quad is four; its four edge neighbours are three triangles each.
    EXPECT_EQ(mesh.n_faces(), 8u - 4u + 4u + 12u);
    ASSERT_EQ(inside.size(), 4u);
    for (const Face f : inside) {
        EXPECT_EQ(mesh.valence(f), 4u);
        EXPECT_DOUBLE_EQ(face_area(mesh, f), 0.25);
    }
    double total = 0;
    std::size_t triangles = 0;
    for (const Face f : mesh.faces()) {
        total += face_area(mesh, f);
        triangles += mesh.valence(f) == 3 ? 1 : 0;
        // No corner in the middle of a straight side: every corner turns.
        for (const Halfedge h : mesh.halfedges(f)) {
            const Vec3 a = mesh.position(mesh.from_vertex(h));
            const Vec3 b = mesh.position(mesh.to_vertex(h));
            const Vec3 c = mesh.position(mesh.to_vertex(mesh.next(h)));
            EXPECT_GT(norm(cross(b - a, c - b)), 1e-12) << "face " << f.idx();
        }
    }
    EXPECT_EQ(triangles, 12u);
    EXPECT_DOUBLE_EQ(total, 9.0);
}

TEST(SubdivideRegion, NineQuadsBecomeThirtySixLiveQuads) {
    Mesh mesh = shapes::quad_grid(5, 5);
    std::vector<Face> inside;
    const auto first = subdivide_region(mesh, faces(mesh, middle_nine()), &inside);
    ASSERT_TRUE(first);
    ASSERT_VALID(mesh);
    ASSERT_EQ(inside.size(), 36u);
    EXPECT_EQ(*first, inside.front());
    for (const Face f : inside) {
        ASSERT_FALSE(mesh.is_deleted(f));
        EXPECT_DOUBLE_EQ(face_area(mesh, f), 0.25);
    }
    // 12 neighbours across the border, each cut into 3 triangles; 4 corner quads untouched.
    EXPECT_EQ(mesh.n_faces(), 36u + 36u + 4u);
}

TEST(SubdivideRegion, ATriangleBecomesFourAndItsNeighbourTwo) {
    Mesh mesh = test::two_triangles();
    std::vector<Face> inside;
    ASSERT_TRUE(subdivide_region(mesh, faces(mesh, {0}), &inside));
    ASSERT_VALID(mesh);
    EXPECT_EQ(inside.size(), 4u);
    EXPECT_EQ(mesh.n_faces(), 6u);
    for (const Face f : mesh.faces()) {
        EXPECT_EQ(mesh.valence(f), 3u);
    }
}

TEST(SubdivideRegion, TheWholeQuadMeshEqualsLinearSubdivision) {
    for (Mesh mesh : {shapes::quad_grid(3, 2), test::quad_cube()}) {
        Mesh expected = mesh;
        QuadSubdivisionOptions linear;
        linear.scheme = QuadScheme::Linear;
        quad_subdivide(expected, linear);
        FaceSet all(mesh.faces_size());
        for (const Face f : mesh.faces()) {
            all.insert(f);
        }
        ASSERT_TRUE(subdivide_region(mesh, all));
        ASSERT_VALID(mesh);
        EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
    }
}

// Over every face of a closed mesh the smooth schemes are the whole-mesh ones: Loop on the
// icosphere equals loop_subdivide() (Warren's weights), Catmull-Clark on the quad cube and on
// the icosphere's triangles equals catmull_clark(), positions to 1e-12.
TEST(SubdivideRegion, TheSmoothSchemesOverAWholeMeshAreTheWholeMeshOnes) {
    const auto everything = [](const Mesh& mesh) {
        FaceSet all(mesh.faces_size());
        for (const Face f : mesh.faces()) {
            all.insert(f);
        }
        return all;
    };
    {
        Mesh mesh = shapes::icosphere(1);
        Mesh expected = mesh;
        loop_subdivide(expected);
        ASSERT_TRUE(subdivide_region(mesh, everything(mesh), nullptr, RegionScheme::Loop));
        ASSERT_VALID(mesh);
        EXPECT_TRUE(test::same_faces_by_position(mesh, expected, 1e-12));
    }
    for (Mesh mesh : {test::quad_cube(), shapes::icosphere(1)}) {
        Mesh expected = mesh;
        quad_subdivide(expected);  // Catmull-Clark
        ASSERT_TRUE(subdivide_region(mesh, everything(mesh), nullptr, RegionScheme::CatmullClark));
        ASSERT_VALID(mesh);
        EXPECT_TRUE(test::same_faces_by_position(mesh, expected, 1e-12));
    }
}

// On part of a mesh the border stays: Loop on a cap of the icosphere moves its inner
// vertices toward the limit surface (inside the sphere, as Loop shrinks) and leaves every
// vertex on the cap's border and outside it where it was; the ring around it is fans.
TEST(SubdivideRegion, LoopOnACapLeavesItsBorderAndTheRest) {
    const Mesh sphere = shapes::icosphere(2);
    std::vector<std::uint32_t> cap;
    for (const Face f : sphere.faces()) {
        bool near = true;
        for (const Vertex v : sphere.vertices(f)) {
            near = near && distance(sphere.position(v), Vec3{0, 0, 1}) < 0.7;
        }
        if (near) {
            cap.push_back(f.idx());
        }
    }
    ASSERT_GT(cap.size(), 10u);
    Mesh mesh = sphere;
    const FaceSet region = faces(mesh, cap);
    const std::vector<Vertex> inner = region_inner_vertices(mesh, region.elements());
    ASSERT_FALSE(inner.empty());
    ASSERT_TRUE(subdivide_region(mesh, region, nullptr, RegionScheme::Loop));
    ASSERT_VALID(mesh);
    std::vector<bool> is_inner(sphere.vertices_size(), false);
    for (const Vertex v : inner) {
        is_inner[v.idx()] = true;
        EXPECT_LT(norm(mesh.position(v)), 1.0 - 1e-6) << v.idx();
    }
    for (const Vertex v : sphere.vertices()) {
        if (!is_inner[v.idx()]) {
            EXPECT_EQ(mesh.position(v), sphere.position(v)) << v.idx();
        }
    }
    Mesh quads = shapes::quad_grid(2, 2);
    const auto refused = subdivide_region(quads, faces(quads, {0}), nullptr, RegionScheme::Loop);
    EXPECT_FALSE(refused);
    EXPECT_EQ(std::string(refused.reason()),
              "cannot subdivide the region with Loop: face 0 has 4 corners (Loop takes "
              "triangles; Catmull-Clark takes any face)");
}

TEST(SubdivideRegion, RefusesAnEmptyRegion) {
    Mesh mesh = shapes::quad_grid(2, 2);
    const Mesh before = mesh;
    EXPECT_FALSE(subdivide_region(mesh, FaceSet(mesh.faces_size())));
    EXPECT_TRUE(test::identical(mesh, before));
}

TEST(DissolveRegion, NineQuadsBecomeOneFaceOfTwelveCorners) {
    Mesh mesh = shapes::quad_grid(5, 5);
    auto corner = mesh.add_property<Halfedge, double>("h:u");
    const auto u = [](const Vec3& p) { return p.x + 10.0 * p.y; };
    for (const Halfedge h : mesh.halfedges()) {
        corner[h] = u(mesh.position(mesh.to_vertex(h)));
    }
    std::vector<Face> merged;
    ASSERT_TRUE(dissolve_region(mesh, faces(mesh, middle_nine()), &merged));
    ASSERT_VALID(mesh);
    ASSERT_EQ(merged.size(), 1u);
    EXPECT_EQ(mesh.valence(merged[0]), 12u);
    EXPECT_EQ(mesh.n_faces(), 25u - 9u + 1u);
    EXPECT_EQ(mesh.n_vertices(), 36u - 4u);
    EXPECT_DOUBLE_EQ(face_area(mesh, merged[0]), 9.0);
    for (const Halfedge h : mesh.halfedges()) {  // every corner kept its value
        if (mesh.face(h).is_valid()) {
            EXPECT_EQ(corner[h], u(mesh.position(mesh.to_vertex(h))));
        }
    }
    // Two pieces at once: two merged faces.
    Mesh two = shapes::quad_grid(5, 5);
    ASSERT_TRUE(dissolve_region(two, faces(two, {0, 1, 23, 24}), &merged));
    ASSERT_VALID(two);
    EXPECT_EQ(merged.size(), 2u);
    EXPECT_EQ(two.n_faces(), 23u);
}

TEST(DissolveRegion, RefusesWhatNoOneFaceCanBeAndTouchesNothing) {
    const Mesh grid = shapes::quad_grid(5, 5);
    const Mesh cube = test::quad_cube();
    const auto refused = [](const Mesh& before, const FaceSet& region, const std::string& reason) {
        Mesh mesh = before;
        const auto r = dissolve_region(mesh, region);
        EXPECT_FALSE(r);
        EXPECT_NE(std::string(r.reason()).find(reason), std::string::npos) << r.reason();
        EXPECT_TRUE(test::identical(mesh, before));
    };
    std::vector<std::uint32_t> ring = middle_nine();
    ring.erase(ring.begin() + 4);  // the middle 3 x 3 without its centre: an annulus
    refused(grid, faces(grid, ring), "is not a disk");
    refused(cube, faces(cube, {0, 1, 2, 3, 4, 5}), "whole closed surface");
    refused(grid, faces(grid, {12}), "one face is merged already");
    refused(grid, faces(grid, {0, 6}), "touches itself at vertex 7");
}

}  // namespace
}  // namespace meshedit
