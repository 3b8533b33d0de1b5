// OSMesa context creation (osmesa_context.h). libOSMesa is opened with dlopen, not linked: it
// exports the GL entry points itself, and this program takes them from OSMesaGetProcAddress
// into gl_dispatch, like EGL's.

#include "osmesa_context.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "gl_dispatch.h"

namespace meshedit::headless {

namespace {

struct OsMesaLibrary {
    decltype(&OSMesaCreateContextAttribs) create_context = nullptr;
    decltype(&OSMesaMakeCurrent) make_current = nullptr;
    decltype(&OSMesaDestroyContext) destroy_context = nullptr;
    decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
};

// Opened once and never closed, as libEGL (egl_context.cpp).
const OsMesaLibrary& osmesa() {
    static const OsMesaLibrary library = [] {
        void* handle = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr) {
            handle = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
        }
        if (handle == nullptr) {
            throw ContextError(std::string("osmesa: cannot open libOSMesa.so.8 (") + dlerror() +
                               ")");
        }
        OsMesaLibrary l;
        auto load = [&](auto& pointer, const char* name) {
            pointer =
                reinterpret_cast<std::remove_reference_t<decltype(pointer)>>(dlsym(handle, name));
            if (pointer == nullptr) {
                throw ContextError(std::string("osmesa: libOSMesa lacks ") + name);
            }
        };
        load(l.create_context, "OSMesaCreateContextAttribs");
        load(l.make_current, "OSMesaMakeCurrent");
        load(l.destroy_context, "OSMesaDestroyContext");
        load(l.get_proc_address, "OSMesaGetProcAddress");
        return l;
    }();
    return library;
}

void* resolve_gl(const char* name) {
    return reinterpret_cast<void*>(osmesa().get_proc_address(name));
}

class OsMesaContext : public GlContext {
public:
    OsMesaContext(OSMesaContext context, std::vector<std::uint8_t> buffer)
        : context_(context), buffer_(std::move(buffer)) {}
    ~OsMesaContext() override { osmesa().destroy_context(context_); }
    std::string backend() const override { return "osmesa"; }

private:
    OSMesaContext context_;
    std::vector<std::uint8_t> buffer_;  ///< the default buffer OSMesa draws nothing into
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context(const ContextRequest& request) {
    const OsMesaLibrary& l = osmesa();
    const int width = request.width;
    const int height = request.height;
    std::vector<std::uint8_t> buffer(static_cast<std::size_t>(width) *
                                     static_cast<std::size_t>(height) * 4);
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
    OSMesaContext context = l.create_context(attributes, nullptr);
    if (context == nullptr) {
        throw ContextError("osmesa: cannot create an OpenGL 3.3 core context");
    }
    if (l.make_current(context, buffer.data(), GL_UNSIGNED_BYTE, width, height) == 0) {
        l.destroy_context(context);
        throw ContextError("osmesa: cannot make the context current (" + std::to_string(width) +
                           "x" + std::to_string(height) + ")");
    }
    auto result = std::make_unique<OsMesaContext>(context, std::move(buffer));
    load_gl_functions(resolve_gl);
    check_gl_version("osmesa");
    return result;
}

}  // namespace meshedit::headless
