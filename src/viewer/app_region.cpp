// The window's box select (B: the next left press starts a rectangle; a right press cancels),
// lasso (Ctrl+right-drag draws an outline) and brush (Alt+B: left drags paint with a circle
// until Esc or a right click), drawn over the frame as the cursor moves. A region selects
// what it holds (overlay/region_pick.h) in the selection's kind, only what the view shows
// unless Alt is held; Shift adds to the selection (the brush: takes away from it).

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>
#include <string>
#include <vector>

#include "app.h"
#include "meshedit/overlay/region_pick.h"

namespace meshedit::viewer {

bool App::region_mouse_button(int button, int action, int mods) {
    if (brush_mode()) {
        if (action == GLFW_PRESS && button == GLFW_MOUSE_BUTTON_RIGHT) {
            drag_ = DragMode::None;
            editor_.end_selection_stroke();
            set_status("brush select ended", false);
            swallow_release_ = true;
        } else if (action == GLFW_PRESS && button == GLFW_MOUSE_BUTTON_LEFT) {
            drag_ = DragMode::Brush;
            editor_.begin_selection_stroke();  // one undo step per drag
            brush_removes_ = (mods & GLFW_MOD_SHIFT) != 0;
            brush_through_ = (mods & GLFW_MOD_ALT) != 0;
            shown_points(brush_through_ ? Reach::Through : visible_reach());
            paint_brush();
        } else if (action == GLFW_RELEASE && button == GLFW_MOUSE_BUTTON_LEFT) {
            drag_ = DragMode::BrushArmed;
            editor_.end_selection_stroke();
        }
        redraw_frames_ = kSettleFrames;
        return true;
    }
    const bool ctrl = (mods & GLFW_MOD_CONTROL) != 0;
    if (drag_ == DragMode::None && action == GLFW_PRESS && button == GLFW_MOUSE_BUTTON_RIGHT &&
        ctrl && mesh_mode()) {
        drag_ = DragMode::Lasso;
        lasso_ = {cursor_pixels()};
        shown_points(visible_reach());  // now, not at the release
        return true;
    }
    if (drag_ == DragMode::Lasso) {
        if (action == GLFW_RELEASE && button == GLFW_MOUSE_BUTTON_RIGHT) {
            drag_ = DragMode::None;
            finish_region((mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_ALT) != 0);
            lasso_.clear();
        }
        redraw_frames_ = kSettleFrames;
        return true;
    }
    if (drag_ != DragMode::BoxArmed && drag_ != DragMode::Box) {
        return false;
    }
    if (action == GLFW_PRESS && button == GLFW_MOUSE_BUTTON_RIGHT) {
        drag_ = DragMode::None;
        set_status("box select cancelled", false);
        swallow_release_ = true;
        return true;
    }
    if (button != GLFW_MOUSE_BUTTON_LEFT) {
        return true;
    }
    if (action == GLFW_PRESS && drag_ == DragMode::BoxArmed) {
        box_from_ = cursor_pixels();
        drag_ = DragMode::Box;
        shown_points(visible_reach());  // now, not at the release
    } else if (action == GLFW_RELEASE && drag_ == DragMode::Box) {
        drag_ = DragMode::None;
        finish_region((mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_ALT) != 0);
    }
    redraw_frames_ = kSettleFrames;
    return true;
}

void App::draw_region() {
    if (drag_ != DragMode::Box && drag_ != DragMode::Lasso && !brush_mode()) {
        return;
    }
    // Framebuffer pixels to ImGui's window coordinates.
    const glm::ivec2 fb = framebuffer_size();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float sx = display.x / static_cast<float>(fb.x),
                sy = display.y / static_cast<float>(fb.y);
    const auto at = [&](glm::vec2 p) { return ImVec2(p.x * sx, p.y * sy); };
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImU32 line = IM_COL32(255, 160, 40, 220);
    if (brush_mode()) {
        draw->AddCircle(at(cursor_pixels()), brush_radius_ * sx, line, 48, 1.5f);
        return;
    }
    if (drag_ == DragMode::Box) {
        draw->AddRectFilled(at(box_from_), at(cursor_pixels()), IM_COL32(255, 160, 40, 40));
        draw->AddRect(at(box_from_), at(cursor_pixels()), line, 0.0f, 0, 1.5f);
        return;
    }
    std::vector<ImVec2> points;
    for (const glm::vec2& p : lasso_) {
        points.push_back(at(p));
    }
    draw->AddPolyline(points.data(), static_cast<int>(points.size()), line, ImDrawFlags_Closed,
                      1.5f);
}

void App::finish_region(bool add, bool through) {
    if (!mesh_mode() || !scene_->has_mesh()) {
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    const glm::ivec2 size = framebuffer_size();
    const Mesh& mesh = editor_.mesh();
    const bool lasso = !lasso_.empty();
    std::vector<ElementRef> inside;
    if (through) {  // one pass over the mesh, as fast as a query: nothing kept
        const ElementRef::Kind kind = editor_.region_kind();
        inside =
            lasso ? elements_in_lasso(mesh, camera_, lasso_, size.x, size.y, kind, Reach::Through)
                  : elements_in_box(mesh, camera_,
                                    ScreenBox{box_from_, cursor_pixels(), size.x, size.y}, kind,
                                    Reach::Through);
    } else {
        const ShownPoints& shown = shown_points(visible_reach());
        inside =
            lasso ? shown.in_lasso(mesh, lasso_) : shown.in_box(mesh, box_from_, cursor_pixels());
    }
    // The info panel's "pick" time: a region is a pick of many elements.
    last_pick_ms_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const std::string what = std::string(lasso ? "lasso" : "box") + (through ? " (through)" : "");
    apply(editor_.select_elements(inside, add, what));
}

Reach App::visible_reach() const {
    // What the view shows: with back faces culled when the renderer culls them.
    return scene_->mesh().culls_back_faces(camera_) ? Reach::VisibleFrontOnly : Reach::Visible;
}

void App::paint_brush() {
    if (!mesh_mode() || !scene_->has_mesh()) {
        return;
    }
    const std::vector<ElementRef> under =
        shown_points(brush_through_ ? Reach::Through : visible_reach())
            .in_circle(editor_.mesh(), cursor_pixels(), brush_radius_);
    if (under.empty()) {
        return;
    }
    apply(brush_removes_ ? editor_.deselect_elements(under, "brush")
                         : editor_.select_elements(under, true, "brush"));
}

const ShownPoints& App::shown_points(Reach reach) {
    const glm::ivec2 size = framebuffer_size();
    const ElementRef::Kind kind = editor_.region_kind();
    const std::uint64_t revision = editor_.document().revision;
    if (!shown_ || shown_revision_ != revision ||
        !shown_->fits(camera_, size.x, size.y, kind, reach)) {
        shown_.emplace(editor_.mesh(), camera_, size.x, size.y, kind, reach);
        shown_revision_ = revision;
    }
    return *shown_;
}

}  // namespace meshedit::viewer
