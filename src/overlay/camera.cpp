// Orbit camera (camera.h).

#include "meshedit/overlay/camera.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace meshedit {

glm::vec3 Camera::world_up() const {
    if (trackball && !orthographic) {
        return orientation * glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return up == UpAxis::Z && !orthographic ? glm::vec3(0.0f, 0.0f, 1.0f)
                                            : glm::vec3(0.0f, 1.0f, 0.0f);
}

glm::vec3 Camera::eye() const {
    if (orthographic) {
        return target + glm::vec3(0.0f, 0.0f, distance);
    }
    if (trackball) {
        return target + distance * (orientation * glm::vec3(0.0f, 0.0f, 1.0f));
    }
    const float az = glm::radians(azimuth_deg);
    const float el = glm::radians(std::clamp(elevation_deg, -89.0f, 89.0f));
    // In a Y-up frame; a Z-up world maps (x, y, z) to (x, −z, y), so the front eye is on −Y.
    const glm::vec3 offset(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
    const glm::vec3 world = up == UpAxis::Z ? glm::vec3(offset.x, -offset.z, offset.y) : offset;
    return target + distance * world;
}

glm::mat4 Camera::view() const {
    return glm::lookAt(eye(), target, world_up());
}

void Camera::orbit(float dx_deg, float dy_deg) {
    if (!trackball) {
        azimuth_deg -= dx_deg;
        elevation_deg = std::clamp(elevation_deg + dy_deg, -89.0f, 89.0f);
        return;
    }
    // Dragging right turns the scene right: the eye goes left about the screen's up axis;
    // dragging down tips it towards the viewer: the eye goes up about the screen's right.
    const glm::vec3 screen_up = orientation * glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 screen_right = orientation * glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::quat turn = glm::angleAxis(glm::radians(-dx_deg), screen_up) *
                           glm::angleAxis(glm::radians(-dy_deg), screen_right);
    orientation = glm::normalize(turn * orientation);
}

void Camera::set_trackball(bool on) {
    if (on == trackball) {
        return;
    }
    if (on) {
        // The camera's axes in world space are the rows of the view rotation.
        orientation = glm::quat_cast(glm::transpose(glm::mat3(view())));
        trackball = true;
        return;
    }
    // Back to azimuth and elevation of the current eye direction about the up axis.
    const glm::vec3 d = glm::normalize(eye() - target);
    trackball = false;
    const glm::vec3 frame = up == UpAxis::Z ? glm::vec3(d.x, d.z, -d.y) : d;  // to Y-up
    elevation_deg = glm::degrees(std::asin(std::clamp(frame.y, -1.0f, 1.0f)));
    azimuth_deg = glm::degrees(std::atan2(frame.x, frame.z));
}

// Near and far hug the scene's bounding sphere: depth precision where it matters.
float Camera::far_plane() const {
    return orthographic ? distance + 2.0f * scene_radius : distance + 1.5f * scene_radius;
}

float Camera::near_plane() const {
    return orthographic ? 0.01f * distance
                        : std::max(distance - 1.5f * scene_radius, far_plane() * 1e-3f);
}

glm::mat4 Camera::projection(float aspect) const {
    glm::mat4 p;
    if (orthographic) {
        const float h = 0.5f * ortho_height;
        const float w = h * aspect;
        p = glm::ortho(-w, w, -h, h, near_plane(), far_plane());
    } else {
        p = glm::perspective(glm::radians(fov_y_deg), aspect, near_plane(), far_plane());
    }
    if (lens_shift_x != 0.0f) {
        // x_ndc += shift, applied in clip space (x += shift · w).
        p = glm::translate(glm::mat4(1.0f), glm::vec3(lens_shift_x, 0.0f, 0.0f)) * p;
    }
    return p;
}

void Camera::frame_mesh(const Mesh& mesh, float aspect, std::span<const Vec3> extra) {
    // Fitting the points themselves is tighter than fitting the box corners.
    std::vector<Vec3> points;
    points.reserve(mesh.n_vertices() + extra.size());
    for (Vertex v : mesh.vertices()) {
        points.push_back(mesh.position(v));
    }
    points.insert(points.end(), extra.begin(), extra.end());
    BoundingBox box;
    for (const Vec3& p : points) {
        box.add(p);
    }
    if (points.empty()) {
        box.add({-1, -1, -1});
        box.add({1, 1, 1});
    }
    frame(box, aspect, points);
}

void Camera::frame(const BoundingBox& box, float aspect, std::span<const Vec3> points) {
    orthographic = false;
    if (box.is_empty()) {
        target = glm::vec3(0.0f);
        scene_radius = 1.0f;
        distance = 3.0f;
        return;
    }
    const Vec3 c = box.center();
    target = glm::vec3(static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z));
    scene_radius = std::max(0.5f * static_cast<float>(box.diagonal()), 1e-6f);

    // Fit the eight box corners, not the bounding sphere: the sphere wastes a third of the
    // picture on a long object. In camera axes (looking down −z, the eye at +distance on z),
    // a corner (x, y, z) is inside when |x| ≤ (d − z)·tan(half_x), so d ≥ |x|/tan + z.
    const float tan_y = std::tan(0.5f * glm::radians(fov_y_deg));
    const float tan_x = tan_y * aspect;
    distance = 1.0f;
    const glm::mat3 rotation(view());  // world → camera rotation (translation dropped)
    float needed = 0.0f;
    auto fit = [&](const glm::vec3& point) {
        const glm::vec3 p = rotation * (point - target);
        needed = std::max(needed, std::abs(p.x) / tan_x + p.z);
        needed = std::max(needed, std::abs(p.y) / tan_y + p.z);
    };
    if (points.empty()) {
        for (int i = 0; i < 8; ++i) {
            fit(glm::vec3((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                          (i & 4) ? box.max.z : box.min.z));
        }
    } else {
        for (const Vec3& p : points) {
            fit(glm::vec3(static_cast<float>(p.x), static_cast<float>(p.y),
                          static_cast<float>(p.z)));
        }
    }
    distance = std::max(needed * 1.08f, 1e-5f);  // a small margin around the model
}

void Camera::frame_2d(glm::vec2 min, glm::vec2 max, float aspect, float margin) {
    orthographic = true;
    const glm::vec2 size = max - min;
    target = glm::vec3(0.5f * (min + max), 0.0f);
    ortho_height = std::max(size.y, size.x / aspect) * (1.0f + 2.0f * margin);
    distance = 1.0f;
    scene_radius = 0.5f * glm::length(size) + 1.0f;
}

std::optional<glm::vec2> project_to_pixels(const Camera& camera, const Vec3& p, int width,
                                           int height) {
    const float w = static_cast<float>(std::max(width, 1));
    const float h = static_cast<float>(std::max(height, 1));
    const glm::vec4 clip =
        camera.projection(w / h) * camera.view() *
        glm::vec4(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z), 1.0f);
    if (clip.w <= 0.0f || clip.z < -clip.w || clip.z > clip.w) {
        return std::nullopt;
    }
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return glm::vec2((ndc.x + 1.0f) * 0.5f * w, (1.0f - ndc.y) * 0.5f * h);
}

bool back_faces_hidden(const Camera& camera, bool closed_and_outward, const BoundingBox& bounds) {
    if (!closed_and_outward || camera.orthographic || bounds.is_empty()) {
        return false;
    }
    // View depth is linear, so over the box it is smallest at a corner. A box wholly beyond
    // the near plane (1 % margin for float rounding) cannot be cut open by it.
    const glm::mat4 view = camera.view();
    float nearest = std::numeric_limits<float>::max();
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 corner(static_cast<float>((i & 1) != 0 ? bounds.max.x : bounds.min.x),
                               static_cast<float>((i & 2) != 0 ? bounds.max.y : bounds.min.y),
                               static_cast<float>((i & 4) != 0 ? bounds.max.z : bounds.min.z),
                               1.0f);
        nearest = std::min(nearest, -(view * corner).z);
    }
    return nearest > 1.01f * camera.near_plane();
}

}  // namespace meshedit
