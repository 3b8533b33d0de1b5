#pragma once
/// \file
/// An orbit camera (Y up): the eye circles a target at an azimuth and elevation in degrees
/// and a distance. Perspective by default; orthographic for 2D views (Bezier curves). Shared
/// by the headless renderer and the interactive viewer.

#include <span>

#include <glm/glm.hpp>

#include "meshedit/core/math.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

class Camera {
public:
    glm::vec3 target{0.0f};
    float azimuth_deg = 30.0f;    ///< around +Y, 0 looks along −Z (eye on +Z)
    float elevation_deg = 20.0f;  ///< above the XZ plane, clamped to ±89°
    float distance = 3.0f;
    float fov_y_deg = 40.0f;
    /// Radius of the scene around `target`, for the near and far planes.
    float scene_radius = 1.0f;

    /// Orthographic: shows `ortho_height` world units vertically around `target`, looking
    /// down −Z (azimuth and elevation ignored).
    bool orthographic = false;
    float ortho_height = 1.0f;

    /// Perspective view of `box` from the current azimuth and elevation: the target becomes
    /// the box centre and the distance the smallest at which all eight box corners fit a
    /// viewport of `aspect` (width / height), plus a small margin. If `points` is given (the
    /// mesh's positions, say), those are fitted instead of the corners: a tighter picture.
    void frame(const BoundingBox& box, float aspect = 1.0f, std::span<const Vec3> points = {});
    /// frame() on the live vertices of `mesh` plus `extra` points (e.g. control points): the
    /// opening view of `meshedit render` and of the viewer. An empty mesh frames [-1, 1]³.
    void frame_mesh(const Mesh& mesh, float aspect, std::span<const Vec3> extra = {});
    /// Orthographic view of the rectangle [min, max] (x, y) with `margin` around it, fitted
    /// to `aspect` (width / height).
    void frame_2d(glm::vec2 min, glm::vec2 max, float aspect, float margin = 0.05f);

    glm::vec3 eye() const;
    glm::mat4 view() const;
    /// \param aspect width / height of the viewport.
    glm::mat4 projection(float aspect) const;
    /// View-space distance of the near clipping plane (perspective and orthographic).
    float near_plane() const;
    float far_plane() const;
};

/// True when no back face of a surface can be seen from `camera` (perspective): every part of the
/// surface is closed with its faces pointing outwards
/// (`closed_and_outward`, see is_closed_and_outward() in core/normals.h) and its bounding box
/// `bounds` lies wholly beyond the near plane, which so cannot cut it open. Only a
/// self-intersecting surface breaks this. MeshRenderer culls back faces then, which halves the
/// triangles a software rasteriser shades. Orthographic views answer false.
bool back_faces_hidden(const Camera& camera, bool closed_and_outward, const BoundingBox& bounds);

}  // namespace meshedit
