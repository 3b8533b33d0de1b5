// The drawing path of one frame (scene.h).

#include "meshedit/render/scene.h"

namespace meshedit {

void SceneRenderer::upload(const Mesh* mesh) {
    has_mesh_ = mesh != nullptr;
    if (mesh != nullptr) {
        mesh_.upload(*mesh);
    }
}

void SceneRenderer::draw(const Camera& camera, int width, int height,
                         const RenderOptions& options) {
    if (has_mesh_) {
        background_.draw(kBackgroundTop, kBackgroundBottom);
        mesh_.draw(camera, static_cast<float>(width) / static_cast<float>(height), options);
    } else {
        background_.draw(kPaper, kPaper);
    }
    overlay_.draw(camera, width, height);
}

void SceneRenderer::draw_bare(const Camera& camera, int width, int height) {
    background_.draw(kBackgroundTop, kBackgroundBottom);
    mesh_.draw_bare(camera, static_cast<float>(width) / static_cast<float>(height));
}

}  // namespace meshedit
