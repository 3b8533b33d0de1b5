#pragma once
/// \file
/// An orbit camera: the eye circles a target at an azimuth and elevation in degrees and a
/// distance, around the world's +Y or +Z axis (a turntable), or turns freely (a trackball).
/// Perspective by default; orthographic for 2D views (Bezier curves). Shared by the headless
/// renderer and the interactive viewer.

#include <optional>
#include <span>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "meshedit/core/math.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

/// Which world axis points up on the screen.
enum class UpAxis {
    Y,  ///< glTF's and OBJ's convention, and what COLLADA files are converted to on reading
    Z,  ///< the CS184 course's models (tagged Y_UP, but their data is Z-up), CAD, Blender
};

class Camera {
public:
    glm::vec3 target{0.0f};
    /// Around the up axis; 0 puts the eye on +Z (up +Y) or on −Y (up +Z): the front view.
    float azimuth_deg = 30.0f;
    float elevation_deg = 20.0f;  ///< above the ground plane, clamped to ±89°
    UpAxis up = UpAxis::Y;
    /// Free rotation: `orientation` (camera axes in world space) replaces azimuth and
    /// elevation, and orbit() turns about the screen's axes with no clamp.
    bool trackball = false;
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
    float distance = 3.0f;
    float fov_y_deg = 40.0f;
    /// Radius of the scene around `target`, for the near and far planes.
    float scene_radius = 1.0f;

    /// Orthographic: shows `ortho_height` world units vertically around `target`, looking
    /// down −Z (azimuth and elevation ignored).
    bool orthographic = false;
    float ortho_height = 1.0f;

    /// Moves the picture sideways without turning the camera: the target appears at this
    /// normalised x (−1 left edge … 1 right edge) instead of the centre. The viewer uses
    /// it to centre the model in the space its info panel leaves free; orbits still turn
    /// about the target.
    float lens_shift_x = 0.0f;

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

    /// Turns the view by a mouse drag of (dx, dy) degrees: azimuth and elevation on the
    /// turntable, rotation about the screen's up and right axes on the trackball.
    void orbit(float dx_deg, float dy_deg);
    /// Switches to or from the trackball keeping the current view (back on the turntable,
    /// the view is levelled to the up axis).
    void set_trackball(bool on);
    /// The world direction that is up on the screen.
    glm::vec3 world_up() const;

    glm::vec3 eye() const;
    glm::mat4 view() const;
    /// \param aspect width / height of the viewport.
    glm::mat4 projection(float aspect) const;
    /// View-space distance of the near clipping plane (perspective and orthographic).
    float near_plane() const;
    float far_plane() const;
};

/// Where `p` lands in a `width` × `height` image seen through `camera`, in pixels from the
/// top-left corner; nothing when it lies behind the eye or outside the depth range.
std::optional<glm::vec2> project_to_pixels(const Camera& camera, const Vec3& p, int width,
                                           int height);

/// True when no back face of a surface can be seen from `camera` (perspective): every part of the
/// surface is closed with its faces pointing outwards
/// (`closed_and_outward`, see is_closed_and_outward() in core/normals.h) and its bounding box
/// `bounds` lies wholly beyond the near plane, which so cannot cut it open. Only a
/// self-intersecting surface breaks this. MeshRenderer culls back faces then, which halves the
/// triangles a software rasteriser shades. Orthographic views answer false.
bool back_faces_hidden(const Camera& camera, bool closed_and_outward, const BoundingBox& bounds);

}  // namespace meshedit
