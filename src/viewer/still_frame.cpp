// The 3D view kept as a texture during a background operation (still_frame.h).

#include "still_frame.h"

#include <GL/glcorearb.h>
#include <imgui.h>

#include <cstdint>

namespace meshedit::viewer {

StillFrame::~StillFrame() {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteTextures(1, &texture_);
}

void StillFrame::capture(int width, int height) {
    if (!holds(width, height)) {
        glDeleteFramebuffers(1, &fbo_);
        glDeleteTextures(1, &texture_);
        glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glGenFramebuffers(1, &fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
        width_ = width;
        height_ = height;
    }
    // Same size, multisampled to single: a resolve, which GL allows in a blit.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void StillFrame::draw_behind_panels() const {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    // GL's rows start at the bottom: the texture is drawn upside down to stand upright.
    ImGui::GetBackgroundDrawList()->AddImage(
        reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(texture_)), ImVec2(0, 0), size,
        ImVec2(0, 1), ImVec2(1, 0));
}

}  // namespace meshedit::viewer
