// Framebuffer read-back, PNG through OpenImageIO, and the offscreen RenderTarget.

#include "meshedit/render/image.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>

#include "gl.h"
#include "meshedit/files/files.h"
#include "meshedit/render/render_target.h"
#include "meshedit/render/shader_program.h"

namespace meshedit {

Image read_framebuffer(int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    check_gl("read_framebuffer");
    // GL's row 0 is the bottom; flip in place.
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    std::vector<std::uint8_t> tmp(row);
    for (int y = 0; y < height / 2; ++y) {
        std::uint8_t* a = image.rgba.data() + static_cast<std::size_t>(y) * row;
        std::uint8_t* b = image.rgba.data() + static_cast<std::size_t>(height - 1 - y) * row;
        std::memcpy(tmp.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, tmp.data(), row);
    }
    return image;
}

void write_png(const Image& image, const std::filesystem::path& path) {
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        // The temporary name need not end in .png, so name the format explicitly.
        auto out = OIIO::ImageOutput::create("png");
        if (!out) {
            throw IoError(path.string(), "", "OpenImageIO has no PNG writer: " + OIIO::geterror());
        }
        OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
        // No time stamps or software tags: the same image must give the same bytes.
        if (!out->open(tmp.string(), spec) ||
            !out->write_image(OIIO::TypeDesc::UINT8, image.rgba.data()) || !out->close()) {
            throw IoError(path.string(), "", "cannot write PNG: " + out->geterror());
        }
    });
}

Image read_png(const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) {
        throw IoError(path.string(), "", "cannot read image: " + OIIO::geterror());
    }
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) *
                                     static_cast<std::size_t>(spec.height) *
                                     static_cast<std::size_t>(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data())) {
        throw IoError(path.string(), "", "cannot read image: " + in->geterror());
    }
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    image.rgba.resize(static_cast<std::size_t>(image.width) * image.height * 4);
    const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* s = pixels.data() + i * static_cast<std::size_t>(channels);
        std::uint8_t* d = image.rgba.data() + 4 * i;
        // Grey (1–2 channels) repeats; a missing alpha is opaque.
        d[0] = s[0];
        d[1] = channels >= 3 ? s[1] : s[0];
        d[2] = channels >= 3 ? s[2] : s[0];
        d[3] = channels == 4 ? s[3] : (channels == 2 ? s[1] : 255);
    }
    return image;
}

// ----------------------------------------------------------------------- RenderTarget

namespace {

void make_storage(GLuint renderbuffer, int samples, GLenum format, int width, int height) {
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
    if (samples > 1) {
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    } else {
        glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
}

void require_complete(const char* what) {
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw GlError(std::string(what) + " framebuffer incomplete (status 0x" +
                      std::to_string(status) + ")");
    }
}

}  // namespace

RenderTarget::RenderTarget(int width, int height, int samples)
    : width_(width), height_(height), samples_(samples > 1 ? samples : 1) {
    if (samples_ > 1) {
        GLint max_samples = 1;
        glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
        samples_ = std::min(samples_, static_cast<int>(max_samples));
    }
    glGenFramebuffers(1, &fbo_);
    glGenRenderbuffers(1, &color_);
    glGenRenderbuffers(1, &depth_);
    make_storage(color_, samples_, GL_RGBA8, width, height);
    make_storage(depth_, samples_, GL_DEPTH_COMPONENT24, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    require_complete("render target");
    if (samples_ > 1) {
        glGenFramebuffers(1, &resolve_fbo_);
        glGenRenderbuffers(1, &resolve_color_);
        make_storage(resolve_color_, 1, GL_RGBA8, width, height);
        glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  resolve_color_);
        require_complete("resolve");
    }
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    check_gl("RenderTarget");
}

RenderTarget::~RenderTarget() {
    const GLuint fbos[2] = {fbo_, resolve_fbo_};
    const GLuint rbs[3] = {color_, depth_, resolve_color_};
    glDeleteFramebuffers(2, fbos);
    glDeleteRenderbuffers(3, rbs);
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width_, height_);
}

Image RenderTarget::read() const {
    if (samples_ > 1) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
        glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    }
    Image image = read_framebuffer(width_, height_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    return image;
}

}  // namespace meshedit
