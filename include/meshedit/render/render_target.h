#pragma once
/// \file
/// An offscreen framebuffer (colour RGBA8 + depth 24), optionally multisampled, with
/// read-back into an Image. Headless rendering draws into one, the viewer uses one for
/// screenshots and the pick pass.

#include "meshedit/render/image.h"

namespace meshedit {

class RenderTarget {
public:
    /// Creates the framebuffer. `samples` > 1 asks for MSAA (resolved on read-back); the
    /// driver may clamp it. \throws GlError if the framebuffer is incomplete.
    RenderTarget(int width, int height, int samples = 1);
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;
    ~RenderTarget();

    /// Binds the framebuffer for drawing and sets the viewport to its size.
    void bind() const;
    /// Resolves MSAA (if any) and reads the colour buffer, row 0 at the top.
    Image read() const;

    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }

private:
    int width_, height_, samples_;
    unsigned fbo_ = 0, color_ = 0, depth_ = 0;
    unsigned resolve_fbo_ = 0, resolve_color_ = 0;  ///< only with MSAA
};

}  // namespace meshedit
