#pragma once
// Private: the last drawn 3D view, kept as a texture while an operation runs in the
// background. Drawing a million triangles on a software GL takes about 0.3 s of the two cores
// the operation needs; a progress frame shows this copy instead and costs almost nothing.

namespace meshedit::viewer {

class StillFrame {
public:
    StillFrame() = default;
    StillFrame(const StillFrame&) = delete;
    StillFrame& operator=(const StillFrame&) = delete;
    ~StillFrame();

    /// Copies the default framebuffer's colour (resolving its multisampling) into the texture.
    void capture(int width, int height);
    /// Whether a capture of this size is held.
    bool holds(int width, int height) const {
        return texture_ != 0 && width == width_ && height == height_;
    }
    /// Draws the capture behind ImGui's windows (call between ImGui::NewFrame and Render).
    void draw_behind_panels() const;

private:
    unsigned fbo_ = 0, texture_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace meshedit::viewer
