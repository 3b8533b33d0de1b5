// add_scene_marks(): the overlay of a frame besides feature edges (overlay.h). GL-free.

#include "meshedit/overlay/overlay.h"

namespace meshedit {

void add_scene_marks(const SceneContent& scene, const OverlayStyle& style, OverlayBatch& out) {
    if (scene.mesh != nullptr) {
        const Mesh& mesh = *scene.mesh;
        if (scene.show_nets) {
            add_control_nets(scene.patches, style, out);
        }
        if (scene.steps >= 0 && scene.steps_patch < scene.patches.size()) {
            add_patch_steps(scene.patches[scene.steps_patch], scene.steps_u, scene.steps_v,
                            scene.steps, style, out);
        }
        if (scene.problems != nullptr) {
            add_problem_marks(mesh, *scene.problems, style, out);
        }
        if (scene.hovered != scene.selected) {
            add_element_highlight(mesh, scene.hovered, style.hovered, style, out);
        }
        add_element_highlights(mesh, scene.also_selected, style.selected, style, out);
        add_element_highlight(mesh, scene.selected, style.selected, style, out);
        if (scene.stencil) {
            const ElementRef element = scene.hovered.is_none() ? scene.selected : scene.hovered;
            if (!element.is_none()) {
                add_stencil_marks(mesh, subdivision_stencil(mesh, element, *scene.stencil), style,
                                  out);
            }
        }
        return;
    }
    if (scene.curve == nullptr) {
        return;
    }
    const BezierCurve& curve = *scene.curve;
    add_unit_square(style, out);
    add_bezier_curve(curve, scene.t, scene.level, scene.show_curve, style, out);
    const auto mark = [&](const ElementRef& e, const Color& color) {
        if (e.kind == ElementRef::Kind::Vertex && e.index < curve.control_points.size()) {
            out.points.push_back({curve.control_points[e.index], color, style.control_point_px});
        }
    };
    mark(scene.hovered, style.hovered);
    mark(scene.selected, style.selected);
}

}  // namespace meshedit
