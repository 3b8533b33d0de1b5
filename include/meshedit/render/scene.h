#pragma once
/// \file
/// One frame, the same in every GL context: the viewer's window and meshedit-render's
/// OSMesa buffer both describe what they show as a SceneContent (overlay.h), turn it into
/// overlay geometry with add_scene_marks() (plus add_feature_edges(), which the viewer
/// caches), and draw it with a SceneRenderer. (polyscope's render engine is the model: one
/// drawing path, several contexts.)

#include "meshedit/core/mesh.h"
#include "meshedit/overlay/camera.h"
#include "meshedit/overlay/overlay.h"
#include "meshedit/render/mesh_renderer.h"
#include "meshedit/render/overlay_renderer.h"

namespace meshedit {

/// The flat background behind curves (paper), and the gradient behind meshes.
inline constexpr float kPaper[3] = {0.97f, 0.97f, 0.96f};

/// The renderers of one frame, drawn in order: background, shaded mesh, overlay. Needs a
/// current GL 3.3 core context for everything but construction.
class SceneRenderer {
public:
    MeshRenderer& mesh() { return mesh_; }
    const MeshRenderer& mesh() const { return mesh_; }
    OverlayRenderer& overlay() { return overlay_; }

    /// Uploads `mesh` to draw (or nothing, for a curve: nullptr).
    void upload(const Mesh* mesh);
    bool has_mesh() const { return has_mesh_; }

    /// Draws the frame into the current framebuffer, `width` × `height` pixels: paper behind
    /// a curve (no mesh uploaded), the gradient and the shaded mesh otherwise, then the
    /// overlay.
    void draw(const Camera& camera, int width, int height, const RenderOptions& options);
    /// The gradient and the mesh's triangles with a trivial shader and no overlay: what a
    /// bare glDrawElements costs, for the draw benchmark.
    void draw_bare(const Camera& camera, int width, int height);

private:
    BackgroundRenderer background_;
    MeshRenderer mesh_;
    OverlayRenderer overlay_;
    bool has_mesh_ = false;
};

}  // namespace meshedit
