#pragma once
/// \file
/// Where the viewer's opening camera shows a mesh's faces and edges, in window pixels, so that
/// the end-to-end tests click what the mesh holds rather than hard-coded places.

#include <cmath>
#include <optional>
#include <string>

#include "viewer_fixture.h"

namespace meshedit::test::e2e {

inline Vec3 centroid(const Mesh& mesh, Face f) {
    Vec3 sum{0, 0, 0};
    int n = 0;
    for (Vertex v : mesh.vertices(f)) {
        sum = sum + mesh.position(v);
        ++n;
    }
    return sum * (1.0 / n);
}

/// The viewer's opening view of the input mesh; edits keep this camera.
struct View {
    Camera camera;
    Vec3 eye;
    float aspect;
    int width;
    int height;

    View(const Mesh& mesh, int window_width, int window_height)
        : camera(opening_camera(mesh, window_width, window_height)),
          aspect(static_cast<float>(window_width) / static_cast<float>(window_height)),
          width(window_width),
          height(window_height) {
        const glm::vec3 e = camera.eye();
        eye = {e.x, e.y, e.z};
    }

    glm::vec2 pixel(const Vec3& p) const { return project(camera, aspect, p, width, height); }

    /// Cosine between f's normal and the ray from its centroid to the eye: 1 faces us.
    double facing(const Mesh& mesh, Face f) const {
        const Vec3 to_eye = eye - centroid(mesh, f);
        return dot(face_normal(mesh, f), to_eye) / norm(to_eye);
    }
};

/// A window pixel to click, clear of the info panel (left) and the status line (bottom).
struct Pixel {
    int x = 0;
    int y = 0;
};

inline std::optional<Pixel> clickable(const View& view, const glm::vec2& p) {
    const Pixel px{static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y))};
    const bool inside = px.x > info_panel_pixels(view.width) + 20 && px.x < view.width - 10 &&
                        px.y > 10 && px.y < view.height - 60;
    return inside ? std::optional<Pixel>(px) : std::nullopt;
}

/// Face f picked at its centroid, when it looks at the camera.
inline std::optional<Pixel> face_pixel(const View& view, const Mesh& mesh, Face f) {
    if (view.facing(mesh, f) < 0.3) {
        return std::nullopt;
    }
    return clickable(view, view.pixel(centroid(mesh, f)));
}

/// Boundary-to-be edge a-b picked 2 px inside `inside` (the face that stays beside it), so
/// the ID pass sees the edge band of that face rather than the hole.
inline std::optional<Pixel> edge_pixel(const View& view, const Mesh& mesh, Vertex a, Vertex b,
                                       Face inside) {
    const glm::vec2 mid = view.pixel((mesh.position(a) + mesh.position(b)) * 0.5);
    const glm::vec2 toward = view.pixel(centroid(mesh, inside)) - mid;
    if (glm::length(toward) < 8.0f || view.facing(mesh, inside) < 0.3) {
        return std::nullopt;
    }
    return clickable(view, mid + glm::normalize(toward) * 2.0f);
}

/// The face beside a-b other than `not_this`.
inline Face other_face(const Mesh& mesh, Vertex a, Vertex b, Face not_this) {
    for (Halfedge h : mesh.halfedges(a)) {
        if (mesh.to_vertex(h) == b) {
            const Face f = mesh.face(h);
            return f == not_this ? mesh.face(Mesh::twin(h)) : f;
        }
    }
    return Face();
}

/// "V n E n F n" of a mesh, as the title shows it.
inline std::string counts(const Mesh& mesh) {
    return "V " + std::to_string(mesh.n_vertices()) + " E " + std::to_string(mesh.n_edges()) +
           " F " + std::to_string(mesh.n_faces());
}

}  // namespace meshedit::test::e2e
