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

/// The silhouette's bounding box in a screenshot: pixels that differ from the background
/// (the gradient is constant along a row, so the row's last pixel stands for it).
struct Extent {
    int width = 0;
    int height = 0;
};
/// Only pixels right of `left` and above the last `bottom` rows count (a window's capture:
/// the info panel and the status line are not the model).
inline Extent silhouette(const RgbImage& image, int left = 0, int bottom = 0) {
    int x0 = image.width, y0 = image.height, x1 = -1, y1 = -1;
    for (int y = 0; y < image.height - bottom; ++y) {
        for (int x = left; x < image.width - 3; ++x) {
            if (channel_difference(image, x, y, image, image.width - 1, y) > 40) {
                x0 = std::min(x0, x);
                x1 = std::max(x1, x);
                y0 = std::min(y0, y);
                y1 = std::max(y1, y);
            }
        }
    }
    return x1 < 0 ? Extent{} : Extent{x1 - x0 + 1, y1 - y0 + 1};
}

}  // namespace meshedit::test::e2e
