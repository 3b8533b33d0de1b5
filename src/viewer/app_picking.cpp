// The window's picking: the element under the cursor (a BVH ray cast by the ID pass's rules,
// cpu_pick.h; for curves the nearest control point), hover, and keeping the picking tree and
// the GPU buffers in step with a recorded edit.

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "app.h"
#include "meshedit/overlay/cpu_pick.h"

namespace meshedit::viewer {

namespace {

constexpr float kControlPointPickPixels = 12.0f;

glm::vec3 to_glm(const Vec3& p) {
    return {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
}

// The red line of a boundary edge is drawn half over the hole, where no face is under the
// cursor: a miss there takes the boundary edge picked nearest around it (samples on a ring
// of the edge radius and half of it), so the line itself is pickable (issue 40).
ElementRef boundary_edge_near(const FaceBvh& tree, const Mesh& mesh, const Camera& camera,
                              int width, int height, glm::vec2 at, bool cull, float vertex_px,
                              float edge_px) {
    ElementRef best;
    float best_distance = edge_px + 1.0f;
    for (const float r : {0.5f * edge_px, edge_px}) {
        for (int k = 0; k < 8; ++k) {
            const float a = static_cast<float>(k) * 0.785398f;  // 45° steps
            const glm::vec2 q = at + r * glm::vec2(std::cos(a), std::sin(a));
            const ElementRef e = pick_sample(tree, mesh, camera, width, height, q.x, q.y, cull,
                                             {vertex_px, edge_px, 0.15f})
                                     .element;
            const bool side =
                e.kind == ElementRef::Kind::Edge || e.kind == ElementRef::Kind::Halfedge;
            if (!side) {
                continue;
            }
            const Edge edge =
                e.kind == ElementRef::Kind::Edge ? Edge(e.index) : Mesh::edge(Halfedge(e.index));
            if (mesh.is_boundary(edge) && r < best_distance) {
                best_distance = r;
                best = ElementRef::edge(edge);
            }
        }
    }
    return best;
}

}  // namespace

ElementRef App::pick_at_cursor() {
    const glm::vec2 p = cursor_pixels();
    const glm::ivec2 size = framebuffer_size();
    if (!mesh_mode()) {
        // Control points: the nearest within a few pixels.
        const glm::mat4 clip = camera_.projection(aspect()) * camera_.view();
        const auto& points = editor_.document().curve.control_points;
        ElementRef best;
        float best_distance = kControlPointPickPixels;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const glm::vec4 c = clip * glm::vec4(to_glm(points[i]), 1.0f);
            const glm::vec2 s((c.x / c.w * 0.5f + 0.5f) * static_cast<float>(size.x),
                              (0.5f - c.y / c.w * 0.5f) * static_cast<float>(size.y));
            if (const float d = glm::length(s - p); d < best_distance) {
                best_distance = d;
                best = ElementRef::vertex(Vertex(static_cast<std::uint32_t>(i)));
            }
        }
        return best;
    }
    if (!scene_->has_mesh()) {
        return {};
    }
    const auto start = std::chrono::steady_clock::now();
    // On the CPU, by the ID pass's rules (cpu_pick.h). The BVH is rebuilt on the first pick
    // after the document changes: a new revision, or geometry moved under the same one (a
    // drag, an interactive edit; see apply()).
    const Mesh& mesh = editor_.mesh();
    const FaceBvh& tree = display_.picking_tree(mesh, editor_.document().revision);
    const float scale = static_cast<float>(size.y) / std::max(1.0f, ImGui::GetIO().DisplaySize.y);
    const bool cull = scene_->mesh().culls_back_faces(camera_);
    ElementRef hit = cpu_pick(tree, mesh, camera_, size.x, size.y, static_cast<int>(p.x),
                              static_cast<int>(p.y), cull, 6.0f * scale, 4.0f * scale);
    if (hit.is_none()) {
        const glm::vec2 centre(std::floor(p.x) + 0.5f, std::floor(p.y) + 0.5f);
        hit = boundary_edge_near(tree, mesh, camera_, size.x, size.y, centre, cull, 6.0f * scale,
                                 4.0f * scale);
    }
    last_pick_ms_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return is_live(editor_.mesh(), hit) ? hit : ElementRef{};
}

void App::update_hover() {
    cursor_moved_ = false;
    // Over a panel (or with a prompt open) nothing in the scene is under the cursor.
    const bool over_ui = ImGui::GetIO().WantCaptureMouse || panels_.prompting() ||
                         panels_.contains(glm::vec2(cursor_)) ||
                         glfwGetWindowAttrib(window_, GLFW_HOVERED) == GLFW_FALSE;
    const ElementRef hit = over_ui ? ElementRef{} : pick_at_cursor();
    const ElementRef& old = editor_.hover();
    if (hit.kind != old.kind || hit.index != old.index) {
        editor_.set_hover(hit);
        rebuild_overlay();
    }
}

bool App::follow_mesh_change(const Outcome& outcome) {
    // A recorded local edit (or its undo or redo, a drag's move, an interactive edit's
    // preview) names where it changed the mesh: the GPU buffers and the picking tree follow
    // in the time of what it touched.
    const unsigned changes = outcome.changes;
    const std::optional<MeshChange::Region>& region = outcome.region;
    const bool local = region && (changes & (kTopology | kGeometry | kDocument)) != 0 &&
                       mesh_mode() && scene_->has_mesh();
    if (!local) {
        return false;
    }
    // The tree is brought along only if it showed the document just before this command.
    DisplayData::Change change;
    change.mesh = true;
    change.features = (changes & kDisplay) != 0;
    change.region = &*region;
    change.before = applied_revision_;
    change.after = editor_.document().revision;
    display_.follow(editor_.mesh(), change);
    scene_->mesh().update(editor_.mesh(), region->faces, region->vertices);
    if ((changes & kGeometry) == 0) {
        editor_.set_hover({});  // a drag keeps the hover it has
    }
    cursor_moved_ = true;
    return true;
}

}  // namespace meshedit::viewer
