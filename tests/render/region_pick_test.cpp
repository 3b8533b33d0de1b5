// Box selection (region_pick.h): what a rectangle selects in each mode, through the mesh and
// only where the view shows it, on a cube seen straight from the front.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "meshedit/core/face_bvh.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"
#include "meshedit/overlay/region_pick.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

// The cube [-1,1]³ from the front (+Z, azimuth and elevation 0), 200 × 200 pixels.
Camera front() {
    Camera camera;
    camera.azimuth_deg = 0.0f;
    camera.elevation_deg = 0.0f;
    camera.distance = 6.0f;
    camera.scene_radius = 2.0f;
    return camera;
}

const ScreenBox kWhole{{0, 0}, {200, 200}, 200, 200};

TEST(BoxSelect, ThroughTheMeshTakesEverythingInside) {
    const Mesh cube = test::quad_cube();
    EXPECT_EQ(elements_in_box(cube, front(), kWhole, ElementRef::Kind::Face).size(), 6u);
    EXPECT_EQ(elements_in_box(cube, front(), kWhole, ElementRef::Kind::Vertex).size(), 8u);
    EXPECT_EQ(elements_in_box(cube, front(), kWhole, ElementRef::Kind::Edge).size(), 12u);
    // The left half of the image: the vertices with x = -1, and the edges between them.
    const ScreenBox left{{0, 0}, {100, 200}, 200, 200};
    const auto vertices = elements_in_box(cube, front(), left, ElementRef::Kind::Vertex);
    ASSERT_EQ(vertices.size(), 4u);
    for (const ElementRef& v : vertices) {
        EXPECT_EQ(cube.position(Vertex(v.index)).x, -1.0);
    }
    EXPECT_EQ(elements_in_box(cube, front(), left, ElementRef::Kind::Edge).size(), 4u);
    // Corners given either way round select the same.
    const ScreenBox flipped{{100, 200}, {0, 0}, 200, 200};
    EXPECT_EQ(elements_in_box(cube, front(), flipped, ElementRef::Kind::Vertex), vertices);
}

// A box (and a lasso) decides most faces from a byte per corner (all beyond one side: out;
// all well inside: in) and only the rest by their centre. Through the mesh that must be
// what the rule says of every face, taken here face by face: the average of its corners in
// clip space, divided, inside the box; visible only, the box must agree with a lasso of the
// same rectangle (which skips the "all inside" shortcut).
TEST(BoxSelect, CornerCodesDecideAsTheCentresDo) {
    const Mesh torus = shapes::torus(300, 150);  // faces of a few pixels
    Camera camera;
    camera.azimuth_deg = 30.0f;
    camera.elevation_deg = 25.0f;
    camera.frame_mesh(torus, 1.6f);
    const glm::mat4 m = camera.projection(1.6f) * camera.view();
    std::size_t total = 0;
    for (const auto& [a, b] : {std::pair<glm::vec2, glm::vec2>{{320, 200}, {960, 600}},
                               {{0, 0}, {1280, 800}},
                               {{101.3f, 57.9f}, {402.6f, 701.1f}},
                               {{640, 400}, {641, 401}},
                               {{-50, -50}, {20, 900}}}) {
        std::vector<ElementRef> expected;
        for (const Face f : torus.faces()) {
            glm::vec4 sum(0.0f);
            for (const Vertex v : torus.vertices(f)) {
                const Vec3& x = torus.position(v);
                sum += m * glm::vec4(float(x.x), float(x.y), float(x.z), 1.0f);
            }
            const float px = (sum.x / sum.w + 1.0f) * 0.5f * 1280.0f;
            const float py = (1.0f - sum.y / sum.w) * 0.5f * 800.0f;
            if (px >= a.x && px <= b.x && py >= a.y && py <= b.y) {
                expected.push_back(ElementRef::face(f));
            }
        }
        const ScreenBox box{a, b, 1280, 800};
        const std::string where = std::to_string(a.x) + "," + std::to_string(a.y) + " to " +
                                  std::to_string(b.x) + "," + std::to_string(b.y);
        EXPECT_EQ(elements_in_box(torus, camera, box, ElementRef::Kind::Face), expected) << where;
        const std::vector<glm::vec2> outline = {a, {b.x, a.y}, b, {a.x, b.y}};
        EXPECT_EQ(elements_in_box(torus, camera, box, ElementRef::Kind::Face, Reach::Visible),
                  elements_in_lasso(torus, camera, outline, 1280, 800, ElementRef::Kind::Face,
                                    Reach::Visible))
            << where;
        total += expected.size();
    }
    EXPECT_GT(total, 50000u);  // the boxes hold faces: the comparison is not of empty lists
}

TEST(BoxSelect, VisibleOnlyTakesWhatTheViewShows) {
    const Mesh cube = test::quad_cube();
    const Reach visible = Reach::Visible;
    const auto faces = elements_in_box(cube, front(), kWhole, ElementRef::Kind::Face, visible);
    ASSERT_EQ(faces.size(), 1u);  // the front face; the others' centres lie behind it
    EXPECT_GT(face_normal(cube, Face(faces[0].index)).z, 0.0);
    const auto vertices = elements_in_box(cube, front(), kWhole, ElementRef::Kind::Vertex, visible);
    ASSERT_EQ(vertices.size(), 4u);
    for (const ElementRef& v : vertices) {
        EXPECT_EQ(cube.position(Vertex(v.index)).z, 1.0);
    }
    EXPECT_EQ(elements_in_box(cube, front(), kWhole, ElementRef::Kind::Edge, visible).size(), 4u);
    // With back faces culled, as the renderer does for this closed cube: the same answers.
    const Reach front_only = Reach::VisibleFrontOnly;
    EXPECT_EQ(elements_in_box(cube, front(), kWhole, ElementRef::Kind::Face, front_only), faces);
    EXPECT_EQ(elements_in_box(cube, front(), kWhole, ElementRef::Kind::Vertex, front_only),
              vertices);
}

// The depth buffer agrees with rays from the eye into the picking tree (the independent way
// to ask what the view shows) on a torus seen from above at an angle, but for centres within
// a pixel of a silhouette (where the surface turns away from the eye).
TEST(BoxSelect, VisibleOnlyAgreesWithRaysIntoTheTree) {
    const Mesh torus = shapes::torus(60, 30);
    Camera camera;
    camera.azimuth_deg = 30.0f;
    camera.elevation_deg = 35.0f;
    camera.frame_mesh(torus, 400.0f / 300.0f);
    FaceBvh tree;
    tree.build(torus);
    const ScreenBox whole{{0, 0}, {400, 300}, 400, 300};
    const auto through = elements_in_box(torus, camera, whole, ElementRef::Kind::Face);
    ASSERT_EQ(through.size(), torus.n_faces());
    const glm::vec3 e = camera.eye();
    const Vec3 eye{e.x, e.y, e.z};
    std::vector<bool> by_ray(torus.faces_size(), false);
    std::size_t shown = 0;
    for (const Face f : torus.faces()) {
        FaceBvh::Ray ray;
        ray.origin = eye;
        ray.direction = face_centroid(torus, f) - eye;
        ray.t_max = 1.0 - 1e-6;
        by_ray[f.idx()] = !tree.intersect(torus, ray).has_value();
        shown += by_ray[f.idx()] ? 1 : 0;
    }
    EXPECT_GT(shown, torus.n_faces() / 3);
    EXPECT_LT(shown, torus.n_faces() * 3 / 4);
    // Both with back faces drawn and culled (the torus is closed, outward, seen from outside).
    for (const Reach reach : {Reach::Visible, Reach::VisibleFrontOnly}) {
        std::vector<bool> by_depth(torus.faces_size(), false);
        for (const ElementRef& f :
             elements_in_box(torus, camera, whole, ElementRef::Kind::Face, reach)) {
            by_depth[f.index] = true;
        }
        std::size_t differ = 0;
        for (const Face f : torus.faces()) {
            if (by_ray[f.idx()] != by_depth[f.idx()]) {
                ++differ;
                // Only where the surface turns away: the silhouette, within a pixel.
                const Vec3 to_eye = eye - face_centroid(torus, f);
                EXPECT_LT(std::abs(dot(face_normal(torus, f), to_eye)) / norm(to_eye), 0.2)
                    << "face " << f.idx() << ": ray says " << by_ray[f.idx()];
            }
        }
        EXPECT_LE(differ, torus.n_faces() / 20) << shown << " shown by rays";
    }
}

// A circle (the brush) round the image's centre: the front and back faces' centres both land
// there; only the front one is seen. A circle off the cube selects nothing.
TEST(CircleSelect, SelectsInsideTheCircle) {
    const Mesh cube = test::quad_cube();
    EXPECT_EQ(
        elements_in_circle(cube, front(), {100, 100}, 10, 200, 200, ElementRef::Kind::Face).size(),
        2u);
    const auto seen = elements_in_circle(cube, front(), {100, 100}, 10, 200, 200,
                                         ElementRef::Kind::Face, Reach::Visible);
    ASSERT_EQ(seen.size(), 1u);
    EXPECT_GT(face_normal(cube, Face(seen[0].index)).z, 0.0);
    EXPECT_TRUE(
        elements_in_circle(cube, front(), {5, 5}, 4, 200, 200, ElementRef::Kind::Vertex).empty());
    // The top-left front corner lands at about (45, 45).
    EXPECT_EQ(
        elements_in_circle(cube, front(), {45, 45}, 6, 200, 200, ElementRef::Kind::Vertex).size(),
        1u);
}

// A lasso: an outline of the left half selects what a box there would; a triangle over the
// top-left corner takes the two vertices there (front and back project to different pixels).
TEST(LassoSelect, SelectsInsideTheOutline) {
    const Mesh cube = test::quad_cube();
    const std::vector<glm::vec2> left{{0, 0}, {100, 0}, {100, 200}, {0, 200}};
    const ScreenBox box{{0, 0}, {100, 200}, 200, 200};
    EXPECT_EQ(elements_in_lasso(cube, front(), left, 200, 200, ElementRef::Kind::Vertex),
              elements_in_box(cube, front(), box, ElementRef::Kind::Vertex));
    // x + y < 140 pixels: the front corner lands at about (45, 45), the back one at (61, 61).
    const std::vector<glm::vec2> corner{{0, 0}, {140, 0}, {0, 140}};
    const auto top_left =
        elements_in_lasso(cube, front(), corner, 200, 200, ElementRef::Kind::Vertex);
    ASSERT_EQ(top_left.size(), 2u);
    for (const ElementRef& v : top_left) {
        EXPECT_EQ(cube.position(Vertex(v.index)).x, -1.0);
        EXPECT_EQ(cube.position(Vertex(v.index)).y, 1.0);
    }
    EXPECT_TRUE(elements_in_lasso(cube, front(), {{0, 0}, {5, 5}}, 200, 200,
                                  ElementRef::Kind::Vertex)
                    .empty());  // fewer than 3 points: no outline
}

// The view's kept points (ShownPoints) answer every region as the fresh pass over the mesh
// does: boxes on and off the 16-pixel tiles' sides, out of the image, a concave lasso of
// many points and circles, in each kind and reach, on a torus whose faces are a few pixels.
TEST(ShownPoints, AnswerAsTheFreshRegionsDo) {
    const Mesh torus = shapes::torus(240, 120);
    Camera camera;
    camera.azimuth_deg = 30.0f;
    camera.elevation_deg = 35.0f;
    const int w = 640, h = 400;
    camera.frame_mesh(torus, float(w) / float(h));
    const std::vector<std::pair<glm::vec2, glm::vec2>> boxes = {
        {{160, 96}, {480, 304}},  // on the tiles' sides
        {{197.3f, 57.9f}, {402.6f, 251.1f}},
        {{300, 100}, {303, 103}},  // a few pixels
        {{-50, -50}, {250, 900}},  // past the image
        {{0, 0}, {640, 400}}};
    // A star of 40 points round the middle: concave, its edges at every angle.
    std::vector<glm::vec2> star;
    for (int i = 0; i < 40; ++i) {
        const float angle = 6.2831853f * float(i) / 40.0f;
        const float r = i % 2 == 0 ? 190.0f : 80.0f;
        star.push_back({320.0f + r * std::cos(angle), 200.0f + r * 0.9f * std::sin(angle)});
    }
    std::size_t total = 0;
    for (const Reach reach : {Reach::Visible, Reach::VisibleFrontOnly, Reach::Through}) {
        for (const ElementRef::Kind kind :
             {ElementRef::Kind::Face, ElementRef::Kind::Vertex, ElementRef::Kind::Edge}) {
            const ShownPoints shown(torus, camera, w, h, kind, reach);
            EXPECT_TRUE(shown.fits(camera, w, h, kind, reach));
            const std::string what =
                std::to_string(int(reach)) + " kind " + std::to_string(int(kind));
            for (const auto& [a, b] : boxes) {
                const auto fresh =
                    elements_in_box(torus, camera, ScreenBox{a, b, w, h}, kind, reach);
                EXPECT_EQ(shown.in_box(torus, a, b), fresh) << what << " box " << a.x << "," << a.y;
                total += fresh.size();
            }
            const auto fresh_star = elements_in_lasso(torus, camera, star, w, h, kind, reach);
            EXPECT_EQ(shown.in_lasso(torus, star), fresh_star) << what;
            total += fresh_star.size();
            for (const float radius : {3.0f, 40.0f, 150.0f}) {
                const glm::vec2 centre(333.3f, 190.0f);
                const auto fresh =
                    elements_in_circle(torus, camera, centre, radius, w, h, kind, reach);
                EXPECT_EQ(shown.in_circle(torus, centre, radius), fresh) << what << " " << radius;
                total += fresh.size();
            }
        }
    }
    EXPECT_GT(total, 200000u);  // the regions hold elements: not a comparison of empty lists
    // Kept for one view: another camera, image, kind or reach is not this one.
    const ShownPoints faces(torus, camera, w, h, ElementRef::Kind::Face, Reach::Visible);
    Camera turned = camera;
    turned.azimuth_deg += 1.0f;
    EXPECT_FALSE(faces.fits(turned, w, h, ElementRef::Kind::Face, Reach::Visible));
    EXPECT_FALSE(faces.fits(camera, w + 1, h, ElementRef::Kind::Face, Reach::Visible));
    EXPECT_FALSE(faces.fits(camera, w, h, ElementRef::Kind::Vertex, Reach::Visible));
    EXPECT_FALSE(faces.fits(camera, w, h, ElementRef::Kind::Face, Reach::Through));
    const ShownPoints edges(torus, camera, w, h, ElementRef::Kind::Edge, Reach::Visible);
    EXPECT_TRUE(edges.fits(camera, w, h, ElementRef::Kind::Halfedge, Reach::Visible));
}

}  // namespace
}  // namespace meshedit
