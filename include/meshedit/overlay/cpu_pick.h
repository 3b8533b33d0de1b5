#pragma once
/// \file
/// Picking on the CPU: the element under a pixel by the rules of the ID pass (shaders/
/// pick.frag, MeshRenderer::pick()), found with one ray into a FaceBvh instead of drawing
/// every triangle. On a million triangles that is microseconds instead of the ID pass's
/// vertex stage (hundreds of milliseconds on llvmpipe).
///
/// The ray runs through the pixel's centre from the near to the far plane (so what the GPU
/// clips away is not hit) and meets the nearest triangle, front sides only when the renderer
/// culls back faces (MeshRenderer::culls_back_faces()): then, as on the GPU, a back face is
/// never reported and whatever front face lies behind it is. The triangle's perspective-
/// correct barycentrics at the pixel and their screen-space rate of change then go through
/// pick.frag's rules unchanged: the nearest corner within the vertex radius, else the nearest
/// real side within the edge radius, else the band just inside it (its halfedge in this face),
/// else the face. fwidth() is taken as the GPU takes it, from the pixel's 2×2 quad: the
/// difference to the horizontal and to the vertical neighbour in the same quad (quads start
/// at even columns and rows, counted from the top; from the bottom, as GL counts, they are
/// the same pairs whenever the height is even).

#include <array>
#include <optional>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/face_bvh.h"
#include "meshedit/core/mesh.h"
#include "meshedit/overlay/camera.h"

namespace meshedit {

/// pick.frag's uniforms: radii in pixels, the halfedge band as a barycentric.
struct PickRadii {
    float vertex_px = 6.0f;
    float edge_px = 4.0f;
    float halfedge_band = 0.15f;
};

/// The answer and what it was decided from.
struct PickDetail {
    ElementRef element;
    std::optional<FaceBvh::Hit> hit;  ///< the triangle under the sample, if any
    /// fwidth() of the barycentric of each corner, per pixel (before pick.frag's 1e-7 floor).
    std::array<double, 3> fwidth{};
};

/// Picks at the sample (x, y), in pixels from the top-left corner of a `width` × `height`
/// viewport (a pixel's centre is at +0.5); `bvh` must be current for `mesh` (face_bvh.h).
PickDetail pick_sample(const FaceBvh& bvh, const Mesh& mesh, const Camera& camera, int width,
                       int height, double x, double y, bool cull_back_faces,
                       const PickRadii& radii = {});

/// What MeshRenderer::pick() answers for pixel (x, y) (origin top-left): pick_sample() at the
/// pixel's centre; nothing outside the viewport.
ElementRef cpu_pick(const FaceBvh& bvh, const Mesh& mesh, const Camera& camera, int width,
                    int height, int x, int y, bool cull_back_faces, float vertex_radius_px = 6.0f,
                    float edge_radius_px = 4.0f);

}  // namespace meshedit
