// OSMesa context creation (osmesa_context.h).

#include "osmesa_context.h"

#include <GL/osmesa.h>

#include <string>

#include "meshedit/render/shader_program.h"

namespace meshedit::headless {

OsMesaContext::OsMesaContext(int width, int height)
    : buffer_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    // Depth and stencil live in the renderer's FBO, so the default buffer needs none.
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context == nullptr) {
        throw GlError("OSMesa cannot create an OpenGL 3.3 core context");
    }
    if (OSMesaMakeCurrent(context, buffer_.data(), GL_UNSIGNED_BYTE, width, height) == 0) {
        OSMesaDestroyContext(context);
        throw GlError("OSMesa cannot make the context current (" + std::to_string(width) + "x" +
                      std::to_string(height) + ")");
    }
    context_ = context;
}

OsMesaContext::~OsMesaContext() {
    OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void OsMesaContext::finish() const {
    glFinish();
}

}  // namespace meshedit::headless
