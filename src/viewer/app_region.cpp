// The window's box select (B): the next left press starts a rectangle, drawn over the frame
// as the cursor moves; the release selects what it holds (overlay/region_pick.h) in the
// selection's kind, only what the view shows unless Alt is held; Shift adds to the selection;
// a right press cancels.

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <chrono>

#include "app.h"
#include "meshedit/overlay/region_pick.h"

namespace meshedit::viewer {

bool App::box_mouse_button(int button, int action, int mods) {
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
    } else if (action == GLFW_RELEASE && drag_ == DragMode::Box) {
        drag_ = DragMode::None;
        finish_box((mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_ALT) != 0);
    }
    redraw_frames_ = kSettleFrames;
    return true;
}

void App::draw_box() {
    if (drag_ != DragMode::Box) {
        return;
    }
    // Framebuffer pixels to ImGui's window coordinates.
    const glm::ivec2 fb = framebuffer_size();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float sx = display.x / static_cast<float>(fb.x),
                sy = display.y / static_cast<float>(fb.y);
    const glm::vec2 to = cursor_pixels();
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImVec2 a(box_from_.x * sx, box_from_.y * sy), b(to.x * sx, to.y * sy);
    draw->AddRectFilled(a, b, IM_COL32(255, 160, 40, 40));
    draw->AddRect(a, b, IM_COL32(255, 160, 40, 220), 0.0f, 0, 1.5f);
}

void App::finish_box(bool add, bool through) {
    if (!mesh_mode() || !scene_->has_mesh()) {
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    const glm::ivec2 size = framebuffer_size();
    const Mesh& mesh = editor_.mesh();
    const FaceBvh* visible =
        through ? nullptr : &display_.picking_tree(mesh, editor_.document().revision);
    const ScreenBox box{box_from_, cursor_pixels(), size.x, size.y};
    const std::vector<ElementRef> inside =
        elements_in_box(mesh, camera_, box, editor_.region_kind(), visible);
    // The info panel's "pick" time: a box is a pick of many elements.
    last_pick_ms_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    apply(editor_.select_elements(inside, add, through ? "box (through)" : "box"));
}

}  // namespace meshedit::viewer
