// When the renderer may cull back faces: only for closed, outward surfaces that the near plane
// cannot cut open (the image would otherwise lose the inside it shows through the cut).
#include "meshedit/overlay/camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace meshedit {
namespace {

BoundingBox unit_box() {
    BoundingBox box;
    box.add(Vec3(-1, -1, -1));
    box.add(Vec3(1, 1, 1));
    return box;
}

// The opening view of the box: framed, so its nearest point is well beyond the near plane.
Camera framed_camera() {
    Camera camera;
    camera.frame(unit_box(), 1.6f);
    return camera;
}

TEST(BackFaces, HiddenForAClosedOutwardSurfaceSeenFromOutside) {
    EXPECT_TRUE(back_faces_hidden(framed_camera(), true, unit_box()));
}

TEST(BackFaces, ShownForOpenOrInsideOutSurfaces) {
    EXPECT_FALSE(back_faces_hidden(framed_camera(), false, unit_box()));
}

TEST(BackFaces, ShownInOrthographicViewsAndForEmptyBoxes) {
    Camera ortho = framed_camera();
    ortho.orthographic = true;
    EXPECT_FALSE(back_faces_hidden(ortho, true, unit_box()));
    EXPECT_FALSE(back_faces_hidden(framed_camera(), true, BoundingBox()));
}

TEST(BackFaces, ShownWhenTheEyeIsInsideTheBox) {
    Camera camera = framed_camera();
    camera.target = glm::vec3(0.0f);
    camera.distance = 0.5f;  // the eye sits inside [-1, 1]^3
    EXPECT_FALSE(back_faces_hidden(camera, true, unit_box()));
}

TEST(BackFaces, ShownWhenTheNearPlaneCanReachTheBox) {
    // The eye on +Z walks towards the box's front face at z = 1, with scene radii that put
    // the near plane in front of the box or into it: culling is allowed exactly while the
    // box lies beyond the near plane.
    Camera camera = framed_camera();
    camera.target = glm::vec3(0.0f);
    camera.azimuth_deg = 0.0f;
    camera.elevation_deg = 0.0f;
    int hidden_count = 0;
    int shown_count = 0;
    for (const float radius : {0.5f, 1.0f, 2.0f}) {
        camera.scene_radius = radius;
        for (float d = 20.0f; d > 1.0f; d -= 0.01f) {
            camera.distance = d;
            const float front_depth = d - 1.0f;
            const bool hidden = back_faces_hidden(camera, true, unit_box());
            if (front_depth > 1.02f * camera.near_plane()) {
                EXPECT_TRUE(hidden) << "radius " << radius << ", distance " << d;
            } else if (front_depth < camera.near_plane()) {
                EXPECT_FALSE(hidden) << "radius " << radius << ", distance " << d;
            }
            (hidden ? hidden_count : shown_count)++;
        }
    }
    EXPECT_GT(hidden_count, 1000);
    EXPECT_GT(shown_count, 1000);
}

// The up axis: with +Z up, the front view (azimuth 0) looks along +Y from −Y, and the screen's
// up is +Z; with +Y up as before, from +Z.
TEST(CameraUp, FrontViewOfEachUpAxis) {
    Camera camera;
    camera.azimuth_deg = 0.0f;
    camera.elevation_deg = 0.0f;
    camera.distance = 2.0f;
    EXPECT_NEAR(camera.eye().z, 2.0f, 1e-6f);
    camera.up = UpAxis::Z;
    EXPECT_NEAR(camera.eye().y, -2.0f, 1e-6f);
    EXPECT_NEAR(camera.eye().z, 0.0f, 1e-6f);
    const glm::mat4 view = camera.view();
    // The view's second row is the screen's up in world space.
    EXPECT_NEAR(view[2][1], 1.0f, 1e-6f);
    camera.elevation_deg = 30.0f;
    EXPECT_NEAR(camera.eye().z, 2.0f * std::sin(glm::radians(30.0f)), 1e-5f);
}

// The trackball keeps the view it starts from and turns freely past the poles; back on the
// turntable the view is levelled again, with the same eye.
TEST(CameraUp, TrackballStartsAndEndsWhereTheTurntableIs) {
    Camera camera;
    camera.azimuth_deg = 40.0f;
    camera.elevation_deg = 25.0f;
    camera.distance = 3.0f;
    const glm::vec3 eye = camera.eye();
    camera.set_trackball(true);
    EXPECT_LT(glm::length(camera.eye() - eye), 1e-5f);
    camera.set_trackball(false);
    EXPECT_NEAR(camera.azimuth_deg, 40.0f, 1e-3f);
    EXPECT_NEAR(camera.elevation_deg, 25.0f, 1e-3f);

    camera.set_trackball(true);
    for (int i = 0; i < 4; ++i) {
        camera.orbit(0.0f, 45.0f);  // 180° over the top: the turntable clamps at 89°
    }
    EXPECT_NEAR(glm::length(camera.eye() - camera.target), 3.0f, 1e-4f);
    const glm::vec3 d = glm::normalize(camera.eye() - camera.target);
    EXPECT_LT(d.y, -0.3f) << "went over the pole to below";
}

}  // namespace
}  // namespace meshedit
