#pragma once
/// \file
/// Draws an OverlayBatch (overlay.h) over the shaded mesh, and the background gradient.
///
/// Points become screen-space discs and lines screen-space quads (GL 3.3 core forbids wide
/// lines), both by instancing a 4-vertex strip whose corners the vertex shader pushes out in
/// pixels; arrowheads are triangles sized in pixels the same way; triangles are drawn as
/// they are. All use alpha blending and a small depth bias
/// towards the eye, so edges lying on the surface win the depth test. X-ray points and lines
/// go to a second layer drawn last, faded where the surface hides them.

#include <cstddef>
#include <memory>
#include <vector>

#include "meshedit/overlay/camera.h"
#include "meshedit/overlay/overlay.h"
#include "meshedit/render/shader_program.h"

namespace meshedit {

class OverlayRenderer {
public:
    OverlayRenderer() = default;
    OverlayRenderer(const OverlayRenderer&) = delete;
    OverlayRenderer& operator=(const OverlayRenderer&) = delete;
    ~OverlayRenderer();

    /// Uploads `batch` (reusing buffers and staging arrays). \throws GlError.
    void upload(const OverlayBatch& batch);
    /// Draws the last upload into the current framebuffer, `width` × `height` pixels.
    /// \param depth_bias fraction of clip-space w by which primitives move towards the eye.
    void draw(const Camera& camera, int width, int height, float depth_bias = 1e-4f);

private:
    void ensure_gl_objects();
    void upload_layer(const OverlayBatch& batch);
    void draw_layer(const Camera& camera, int width, int height, float depth_bias);
    template <typename Use>
    void draw_primitives(const Use& use);

    static constexpr float kHiddenAlpha = 0.45f;  ///< x-ray marks behind the surface

    std::unique_ptr<OverlayRenderer> xray_;  ///< the x-ray layer, made on first use
    bool depth_tested_ = true;               ///< false: the x-ray layer

    ShaderProgram point_shader_, line_shader_, tri_shader_, arrow_shader_;
    unsigned point_vao_ = 0, line_vao_ = 0, tri_vao_ = 0, arrow_vao_ = 0;
    unsigned point_vbo_ = 0, line_vbo_ = 0, tri_vbo_ = 0, arrow_vbo_ = 0;
    std::size_t point_capacity_ = 0, line_capacity_ = 0, tri_capacity_ = 0,
                arrow_capacity_ = 0;  ///< bytes
    std::size_t n_points_ = 0, n_lines_ = 0, n_triangles_ = 0, n_arrowheads_ = 0;
    std::vector<float> points_, lines_, triangles_, arrowheads_;  ///< staging
};

/// A vertical background gradient (a full-screen triangle, no vertex buffer).
class BackgroundRenderer {
public:
    BackgroundRenderer() = default;
    BackgroundRenderer(const BackgroundRenderer&) = delete;
    BackgroundRenderer& operator=(const BackgroundRenderer&) = delete;
    ~BackgroundRenderer();

    /// Fills the viewport from `top` to `bottom` colour and clears depth.
    void draw(const float top[3], const float bottom[3]);

private:
    ShaderProgram shader_;
    unsigned vao_ = 0;
};

/// The default background: light grey-blue at the top, nearly white at the bottom.
inline constexpr float kBackgroundTop[3] = {0.70f, 0.76f, 0.84f};
inline constexpr float kBackgroundBottom[3] = {0.95f, 0.96f, 0.97f};

}  // namespace meshedit
