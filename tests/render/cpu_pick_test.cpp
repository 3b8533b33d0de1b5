// The CPU pick's rules on a case worked by hand (no GL): a unit square seen orthographically
// at 100 pixels per unit, where every radius and band lands at a known pixel. Its agreement
// with the ID pass itself is pick_agreement_test.cpp's.

#include "meshedit/overlay/cpu_pick.h"

#include <gtest/gtest.h>

#include "meshedit/core/shapes.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

constexpr int kSize = 200;

// Looks down −z at the origin; 2 units tall in 200 pixels: world (x, y) is pixel
// (100 + 100x, 100 − 100y).
Camera top_view() {
    Camera camera;
    camera.orthographic = true;
    camera.ortho_height = 2.0f;
    camera.distance = 3.0f;
    camera.scene_radius = 2.0f;
    return camera;
}

// The square [−0.5, 0.5]² at z = 0, counter-clockwise from +z, and below it at z = `below`
// (if given) a second one; `flipped` turns the first face down.
Mesh squares(bool flipped = false, double below = 0.0) {
    std::vector<Vec3> points = {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}};
    std::vector<std::vector<std::uint32_t>> faces = {
        flipped ? std::vector<std::uint32_t>{3, 2, 1, 0} : std::vector<std::uint32_t>{0, 1, 2, 3}};
    if (below != 0.0) {
        for (int k = 0; k < 4; ++k) {
            points.push_back(points[static_cast<std::size_t>(k)] + Vec3{0, 0, below});
        }
        faces.push_back({4, 5, 6, 7});
    }
    return test::mesh_from_faces(points, faces);
}

ElementRef at(const Mesh& mesh, double x, double y, bool cull = false) {
    const FaceBvh bvh(mesh);
    return pick_sample(bvh, mesh, top_view(), kSize, kSize, 100.0 + 100.0 * x, 100.0 - 100.0 * y,
                       cull)
        .element;
}

TEST(CpuPick, RadiiAndBandsOfPickFrag) {
    const Mesh mesh = squares();
    // 3 px from the corner (1.5 along each axis): inside the 6 px vertex radius.
    EXPECT_EQ(at(mesh, -0.485, -0.485), ElementRef::vertex(Vertex(0)));
    EXPECT_EQ(at(mesh, 0.485, 0.485), ElementRef::vertex(Vertex(2)));
    // 3 px above the bottom side, far from its ends: the edge (radius 4 px).
    const Edge bottom = mesh.find_edge(Vertex(0), Vertex(1));
    EXPECT_EQ(at(mesh, 0.1, -0.47), ElementRef::edge(bottom));
    // 7 px in: the band (2.5 × 4 = 10 px, or 15% of the triangle's height = 15 px), the
    // halfedge of that side in this face.
    EXPECT_EQ(at(mesh, 0.1, -0.43), ElementRef::halfedge(mesh.find_halfedge(Vertex(0), Vertex(1))));
    EXPECT_EQ(at(mesh, 0.1, -0.37), ElementRef::halfedge(mesh.find_halfedge(Vertex(0), Vertex(1))));
    // 20 px from every side: the face, wherever the fan's diagonal runs.
    EXPECT_EQ(at(mesh, -0.2, -0.3), ElementRef::face(Face(0)));
    EXPECT_EQ(at(mesh, 0.0, 0.0), ElementRef::face(Face(0)));  // on the diagonal: no edge
    // Beside the square: nothing.
    EXPECT_TRUE(at(mesh, 0.7, 0.0).is_none());
}

TEST(CpuPick, FwidthIsTheQuadDifference) {
    // One triangle, legs 100 px along x and y: each barycentric changes by 0.01 per pixel
    // along one axis (the corners at the legs' ends) or along both (the right angle).
    const Mesh mesh =
        test::mesh_from_faces({{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {-0.5, 0.5, 0}}, {{0, 1, 2}});
    const FaceBvh bvh(mesh);
    const PickDetail d = pick_sample(bvh, mesh, top_view(), kSize, kSize, 80.5, 120.5, false);
    ASSERT_TRUE(d.hit);
    for (std::size_t k = 0; k < 3; ++k) {
        const bool right_angle = d.hit->corners[k] == Vertex(0);
        EXPECT_NEAR(d.fwidth[k], right_angle ? 0.02 : 0.01, 1e-9);
    }
}

TEST(CpuPick, CulledBackFacesShowWhatLiesBehind) {
    // The top square faces away from the eye; the one below faces it.
    const Mesh mesh = squares(true, -0.5);
    EXPECT_EQ(at(mesh, -0.2, -0.3), ElementRef::face(Face(0)));
    EXPECT_EQ(at(mesh, -0.2, -0.3, true), ElementRef::face(Face(1)));
    // Culling the only square leaves nothing.
    EXPECT_TRUE(at(squares(true), -0.2, -0.3, true).is_none());
}

TEST(CpuPick, PerspectiveCornersAndTheViewport) {
    const Mesh cube = shapes::cube();
    Camera camera;
    camera.frame_mesh(cube, 1.5f);
    const FaceBvh bvh(cube);
    const int w = 300, h = 200;
    // Vertex 7 (1, 1, 1) faces the default eye (azimuth 30°, elevation 20°).
    const auto p = project_to_pixels(camera, cube.position(Vertex(7)), w, h);
    ASSERT_TRUE(p);
    const ElementRef hit =
        cpu_pick(bvh, cube, camera, w, h, static_cast<int>(p->x), static_cast<int>(p->y), true);
    EXPECT_EQ(hit, ElementRef::vertex(Vertex(7)));
    EXPECT_TRUE(cpu_pick(bvh, cube, camera, w, h, -1, 10, true).is_none());
    EXPECT_TRUE(cpu_pick(bvh, cube, camera, w, h, 10, h, true).is_none());
    EXPECT_TRUE(cpu_pick(bvh, cube, camera, w, h, 2, 2, true).is_none());  // the background
}

}  // namespace
}  // namespace meshedit
