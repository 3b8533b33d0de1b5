// EGL context creation (egl_context.h). libEGL is opened with dlopen, not linked, so that
// meshedit-render starts (and can fall back to OSMesa, or say what to install) where it is
// missing; glvnd's libEGL then routes eglGetProcAddress("glFoo") to the vendor of the current
// context, which fills gl_dispatch.

#include "egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "gl_dispatch.h"

namespace meshedit::headless {

namespace {

struct EglLibrary {
    PFNEGLGETPROCADDRESSPROC get_proc_address = nullptr;
    PFNEGLGETERRORPROC get_error = nullptr;
    PFNEGLQUERYSTRINGPROC query_string = nullptr;
    PFNEGLINITIALIZEPROC initialize = nullptr;
    PFNEGLTERMINATEPROC terminate = nullptr;
    PFNEGLBINDAPIPROC bind_api = nullptr;
    PFNEGLCHOOSECONFIGPROC choose_config = nullptr;
    PFNEGLCREATECONTEXTPROC create_context = nullptr;
    PFNEGLDESTROYCONTEXTPROC destroy_context = nullptr;
    PFNEGLMAKECURRENTPROC make_current = nullptr;
    // Extensions (nullptr when libEGL lacks them).
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display = nullptr;
    PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;
    PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string = nullptr;
};

// Opened once and never closed: unloading a GL driver while the process runs is asking for
// trouble, and the process is short-lived.
const EglLibrary& egl() {
    static const EglLibrary library = [] {
        void* handle = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr) {
            throw ContextError(std::string("egl: cannot open libEGL.so.1 (") + dlerror() + ")");
        }
        EglLibrary l;
        auto core = [&](auto& pointer, const char* name) {
            pointer =
                reinterpret_cast<std::remove_reference_t<decltype(pointer)>>(dlsym(handle, name));
            if (pointer == nullptr) {
                throw ContextError(std::string("egl: libEGL.so.1 lacks ") + name);
            }
        };
        core(l.get_proc_address, "eglGetProcAddress");
        core(l.get_error, "eglGetError");
        core(l.query_string, "eglQueryString");
        core(l.initialize, "eglInitialize");
        core(l.terminate, "eglTerminate");
        core(l.bind_api, "eglBindAPI");
        core(l.choose_config, "eglChooseConfig");
        core(l.create_context, "eglCreateContext");
        core(l.destroy_context, "eglDestroyContext");
        core(l.make_current, "eglMakeCurrent");
        auto extension = [&](auto& pointer, const char* name) {
            pointer = reinterpret_cast<std::remove_reference_t<decltype(pointer)>>(
                l.get_proc_address(name));
        };
        extension(l.get_platform_display, "eglGetPlatformDisplayEXT");
        extension(l.query_devices, "eglQueryDevicesEXT");
        extension(l.query_device_string, "eglQueryDeviceStringEXT");
        return l;
    }();
    return library;
}

void* resolve_gl(const char* name) {
    return reinterpret_cast<void*>(egl().get_proc_address(name));
}

// Whether the space-separated `list` (which may be null) holds `name`.
bool has_extension(const char* list, std::string_view name) {
    if (list == nullptr) {
        return false;
    }
    std::string_view rest(list);
    while (!rest.empty()) {
        const std::size_t end = rest.find(' ');
        if (rest.substr(0, end) == name) {
            return true;
        }
        rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    }
    return false;
}

std::string error_name() {
    const EGLint code = egl().get_error();
    switch (code) {
        case EGL_NOT_INITIALIZED:
            return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS:
            return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC:
            return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE:
            return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG:
            return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT:
            return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY:
            return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH:
            return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER:
            return "EGL_BAD_PARAMETER";
        default: {
            char hex[16];
            std::snprintf(hex, sizeof hex, "0x%04x", static_cast<unsigned>(code));
            return std::string("EGL error ") + hex;
        }
    }
}

// One place an EGL display can come from.
struct Candidate {
    std::string name;  ///< "surfaceless", "device 1 (/dev/dri/renderD128)"
    EGLenum platform;
    void* native;  ///< the EGLDeviceEXT, or nullptr for surfaceless
};

class EglContext : public GlContext {
public:
    EglContext(std::string name, EGLDisplay display, EGLContext context)
        : name_(std::move(name)), display_(display), context_(context) {}
    ~EglContext() override {
        egl().make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        egl().destroy_context(display_, context_);
        egl().terminate(display_);
    }
    std::string backend() const override { return "egl (" + name_ + ")"; }

private:
    std::string name_;
    EGLDisplay display_;
    EGLContext context_;
};

// A context on `candidate`, or nullptr with the reason in `failure`.
std::unique_ptr<GlContext> try_candidate(const Candidate& candidate, std::string& failure) {
    const EglLibrary& l = egl();
    EGLDisplay display = l.get_platform_display(candidate.platform, candidate.native, nullptr);
    if (display == EGL_NO_DISPLAY) {
        failure = candidate.name + ": no display (" + error_name() + ")";
        return nullptr;
    }
    EGLint major = 0, minor = 0;
    if (l.initialize(display, &major, &minor) == EGL_FALSE) {
        failure = candidate.name + ": eglInitialize fails (" + error_name() + ")";
        return nullptr;
    }
    auto give_up = [&](const std::string& why) {
        failure = candidate.name + ": " + why;
        l.terminate(display);
        return nullptr;
    };
    const char* extensions = l.query_string(display, EGL_EXTENSIONS);
    if (!has_extension(extensions, "EGL_KHR_surfaceless_context")) {
        return give_up("no EGL_KHR_surfaceless_context");
    }
    if (major * 10 + minor < 15 && !has_extension(extensions, "EGL_KHR_create_context")) {
        return give_up("EGL " + std::to_string(major) + "." + std::to_string(minor) +
                       " without EGL_KHR_create_context cannot ask for a core profile");
    }
    if (l.bind_api(EGL_OPENGL_API) == EGL_FALSE) {
        return give_up("no desktop OpenGL API (" + error_name() + ")");
    }
    // No surface is ever made, so any config that renders OpenGL will do; none at all where
    // EGL_KHR_no_config_context allows it.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!has_extension(extensions, "EGL_KHR_no_config_context")) {
        const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                 EGL_PBUFFER_BIT, EGL_NONE};
        EGLint count = 0;
        if (l.choose_config(display, wanted, &config, 1, &count) == EGL_FALSE || count < 1) {
            return give_up("no config renders OpenGL");
        }
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    EGLContext context = l.create_context(display, config, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        return give_up("the driver refuses an OpenGL 3.3 core context (" + error_name() + ")");
    }
    if (l.make_current(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) == EGL_FALSE) {
        const std::string why =
            "cannot make the context current without a surface (" + error_name() + ")";
        l.destroy_context(display, context);
        return give_up(why);
    }
    auto result = std::make_unique<EglContext>(candidate.name, display, context);
    load_gl_functions(resolve_gl);
    try {
        check_gl_version("egl (" + candidate.name + ")");
    } catch (const ContextError& e) {
        failure = e.what();
        return nullptr;
    }
    return result;
}

}  // namespace

std::unique_ptr<GlContext> make_egl_context(const ContextRequest& request) {
    const EglLibrary& l = egl();
    const char* client = l.query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (l.get_platform_display == nullptr || !has_extension(client, "EGL_EXT_platform_base")) {
        // glvnd's libEGL without a vendor library (no Mesa EGL, no GPU driver) ends here.
        throw ContextError(
            "egl: libEGL.so.1 offers no EGL_EXT_platform_base (is an EGL driver installed?)");
    }
    // The devices, as eglQueryDevicesEXT orders them (what --device N counts).
    std::vector<Candidate> hardware, software;
    const bool has_devices = has_extension(client, "EGL_EXT_platform_device") &&
                             l.query_devices != nullptr && l.query_device_string != nullptr;
    std::vector<EGLDeviceEXT> devices;
    if (has_devices) {
        EGLint count = 0;
        if (l.query_devices(0, nullptr, &count) == EGL_TRUE && count > 0) {
            devices.resize(static_cast<std::size_t>(count));
            l.query_devices(count, devices.data(), &count);
            devices.resize(static_cast<std::size_t>(count));
        }
    }
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const char* extensions = l.query_device_string(devices[i], EGL_EXTENSIONS);
        const bool is_software = has_extension(extensions, "EGL_MESA_device_software");
        std::string what = is_software ? "software" : "hardware";
        if (has_extension(extensions, "EGL_EXT_device_drm")) {
            if (const char* file = l.query_device_string(devices[i], EGL_DRM_DEVICE_FILE_EXT)) {
                what += std::string(", ") + file;
            }
        }
        Candidate candidate{"device " + std::to_string(i) + ": " + what, EGL_PLATFORM_DEVICE_EXT,
                            devices[i]};
        if (request.verbose) {
            std::fprintf(stderr, "%s: EGL %s\n", headless::program_name(), candidate.name.c_str());
        }
        (is_software ? software : hardware).push_back(candidate);
    }
    std::vector<Candidate> candidates;
    if (request.device) {
        const int n = static_cast<int>(devices.size());
        if (!has_devices) {
            throw ContextError("egl: --device needs EGL_EXT_platform_device, which libEGL lacks");
        }
        if (*request.device < 0 || *request.device >= n) {
            throw ContextError("egl: --device " + std::to_string(*request.device) +
                               " is out of range: EGL lists " + std::to_string(n) +
                               " device(s), numbered from 0 (--verbose names them)");
        }
        for (const auto* list : {&hardware, &software}) {
            for (const Candidate& c : *list) {
                if (c.native == devices[static_cast<std::size_t>(*request.device)]) {
                    candidates.push_back(c);
                }
            }
        }
    } else {
        // A GPU first; then Mesa's surfaceless platform (its GPU driver if it has a render
        // node it can use, else llvmpipe); then the software devices.
        candidates = hardware;
        if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
            candidates.push_back({"surfaceless", EGL_PLATFORM_SURFACELESS_MESA, nullptr});
        }
        candidates.insert(candidates.end(), software.begin(), software.end());
    }
    if (candidates.empty()) {
        throw ContextError(
            "egl: neither EGL_EXT_platform_device nor EGL_MESA_platform_surfaceless is offered");
    }
    std::string failures;
    for (const Candidate& candidate : candidates) {
        std::string failure;
        if (auto context = try_candidate(candidate, failure)) {
            return context;
        }
        if (request.verbose) {
            std::fprintf(stderr, "%s: EGL %s\n", headless::program_name(), failure.c_str());
        }
        failures += (failures.empty() ? "" : ", ") + failure;
    }
    throw ContextError("egl: " + failures);
}

}  // namespace meshedit::headless
