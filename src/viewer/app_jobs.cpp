// Long operations seen from the window: the progress of an operation running in the
// background (Editor::set_background) and of one running in place, both over a still of the
// 3D view, so that showing progress does not take the cores the operation runs on.

#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>

#include "app.h"

namespace meshedit::viewer {

void App::show_progress(std::string_view verb, double fraction) {
    const double now = glfwGetTime();
    if (fraction <= 0.0 || progress_started_ < 0.0) {
        progress_started_ = now;  // a new operation
        progress_drawn_ = now;
    }
    if (now - progress_started_ < 0.3 || now - progress_drawn_ < 0.1) {
        return;
    }
    const bool first = progress_drawn_ == progress_started_;
    progress_drawn_ = now;
    const glm::ivec2 size = framebuffer_size();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, size.x, size.y);
    if (first || !still_.holds(size.x, size.y)) {
        draw_scene(size.x, size.y);  // the GPU still holds the mesh as it was
        still_.capture(size.x, size.y);
    }
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    still_.draw_behind_panels();  // a frame of the scene costs what the operation needs
    panels_.draw_progress(std::string(verb), fraction, now - progress_started_);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window_);
}

void App::follow_job() {
    display_.settle();  // the result replaces the mesh a picking tree may be read from
    if (const std::optional<Outcome> done = editor_.finish_job()) {
        apply(*done);
        ++view_events_;
        return;
    }
    if (glfwGetTime() - job_drawn_ >= 0.25) {
        job_drawn_ = glfwGetTime();
        redraw_frames_ = std::max(redraw_frames_, 1);
    }
}

}  // namespace meshedit::viewer
