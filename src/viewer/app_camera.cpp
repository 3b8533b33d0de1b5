// The window's camera: framing the document (at the start and after Space; edits and undo
// keep the user's view), the selection (.), and the room the info panel takes.

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

#include "app.h"

namespace meshedit::viewer {

void App::fit_depth_range() {
    if (!mesh_mode() || camera_.orthographic || editor_.mesh().n_vertices() == 0) {
        return;
    }
    // The sphere Camera::frame() takes: the box's centre and half its diagonal (one pass, no
    // copy: undo on a million faces passes here).
    const Mesh& mesh = editor_.mesh();
    BoundingBox box;
    for (const Vertex v : mesh.vertices()) {
        box.add(mesh.position(v));
    }
    const Vec3 c = box.center();
    scene_center_ = {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)};
    scene_radius_ = std::max(0.5f * static_cast<float>(box.diagonal()), 1e-6f);
    update_camera_planes();
}

void App::frame_selection() {
    const auto box = editor_.selection_bounds();
    if (!box) {
        return;
    }
    const Vec3 c = (box->first + box->second) * 0.5;
    const double r = std::max(0.5 * norm(box->second - box->first), 0.02 * scene_radius_);
    camera_.target = {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)};
    if (camera_.orthographic) {
        camera_.ortho_height = static_cast<float>(3.0 * r);
    } else {
        const double half_fov = glm::radians(camera_.fov_y_deg) / 2.0;
        camera_.distance = static_cast<float>(1.5 * r / std::sin(half_fov));
    }
    update_camera_planes();
}

int App::covered_pixels() const {
    if (!editor_.view().show_info) {
        return 0;
    }
    int w = 1, h = 1;
    glfwGetWindowSize(window_, &w, &h);
    const int fb = framebuffer_size().x;
    // Window coordinates to framebuffer pixels (HiDPI); at most half the view.
    const float px = panels_.info_right_edge() * static_cast<float>(fb) / static_cast<float>(w);
    return std::clamp(static_cast<int>(std::lround(px)), 0, fb / 2);
}

int App::covered_right_pixels() const {
    const float left = panels_.diagram_left_edge();
    if (left <= 0.0f) {
        return 0;
    }
    int w = 1, h = 1;
    glfwGetWindowSize(window_, &w, &h);
    const int fb = framebuffer_size().x;
    const float px =
        (static_cast<float>(w) - left) * static_cast<float>(fb) / static_cast<float>(w);
    // At most what leaves half the view beside the info panel's room.
    return std::clamp(static_cast<int>(std::lround(px)), 0, fb / 2 - covered_pixels() / 2);
}

void App::keep_room_for_panels() {
    // The free part's centre, in NDC: shifted right by the info panel, left by the Rewiring
    // panel.
    camera_.lens_shift_x = static_cast<float>(covered_pixels() - covered_right_pixels()) /
                           static_cast<float>(framebuffer_size().x);
}

void App::reset_camera() {
    // Framed into the part of the window the info panel leaves free, and centred there: the
    // same picture as `meshedit render` at that part's size.
    const glm::ivec2 size = framebuffer_size();
    const float a = static_cast<float>(size.x - covered_pixels()) / static_cast<float>(size.y);
    camera_ = Camera();
    keep_room_for_panels();
    camera_.up = editor_.view().up;
    if (!mesh_mode()) {
        camera_.frame_2d({0.0f, 0.0f}, {1.0f, 1.0f}, a);
    } else {
        camera_.frame_mesh(editor_.mesh(), a);  // as `meshedit render`, in the free part
    }
    camera_.set_trackball(editor_.view().trackball && !camera_.orthographic);
    scene_center_ = camera_.target;
    scene_radius_ = camera_.orthographic ? 1.0f : camera_.scene_radius;
    cursor_moved_ = true;
    redraw_frames_ = kSettleFrames;
}

void App::update_camera_planes() {
    // Near and far planes follow the scene's sphere even when the target has wandered off
    // its centre (pan, zoom to cursor).
    if (!camera_.orthographic) {
        camera_.scene_radius = scene_radius_ + glm::length(camera_.target - scene_center_);
    }
    cursor_moved_ = true;
}

glm::dmat4 App::clip_of_world() const {
    return glm::dmat4(camera_.projection(aspect())) * glm::dmat4(camera_.view());
}

Vec3 App::world_at(glm::dvec2 p, double ndc_z) const {
    const glm::ivec2 size = framebuffer_size();
    const glm::dvec4 ndc(2.0 * p.x / size.x - 1.0, 1.0 - 2.0 * p.y / size.y, ndc_z, 1.0);
    const glm::dvec4 world = glm::inverse(clip_of_world()) * ndc;
    return {world.x / world.w, world.y / world.w, world.z / world.w};
}

glm::ivec2 App::framebuffer_size() const {
    int w = 1, h = 1;
    glfwGetFramebufferSize(window_, &w, &h);
    return {std::max(w, 1), std::max(h, 1)};
}

float App::aspect() const {
    const glm::ivec2 s = framebuffer_size();
    return static_cast<float>(s.x) / static_cast<float>(s.y);
}

glm::vec2 App::cursor_pixels() const {
    int ww = 1, wh = 1;
    glfwGetWindowSize(window_, &ww, &wh);
    const glm::ivec2 fb = framebuffer_size();
    return {static_cast<float>(cursor_.x * fb.x / std::max(ww, 1)),
            static_cast<float>(cursor_.y * fb.y / std::max(wh, 1))};
}

glm::vec3 App::unproject(glm::vec2 p, float ndc_z) const {
    const glm::ivec2 size = framebuffer_size();
    const glm::vec4 ndc(2.0f * (p.x + 0.5f) / static_cast<float>(size.x) - 1.0f,
                        1.0f - 2.0f * (p.y + 0.5f) / static_cast<float>(size.y), ndc_z, 1.0f);
    const glm::vec4 world = glm::inverse(camera_.projection(aspect()) * camera_.view()) * ndc;
    return glm::vec3(world) / world.w;
}

}  // namespace meshedit::viewer
