// Choosing and making the headless context (gl_context.h).

#include "gl_context.h"

#include <cstdlib>

#include <GL/glcorearb.h>

#include <algorithm>
#include <cstdio>

#if MESHEDIT_HAVE_EGL
#include "egl_context.h"
#endif
#if MESHEDIT_HAVE_OSMESA
#include "osmesa_context.h"
#endif

namespace meshedit::headless {

const char* program_name() {
    static const std::string name = [] {
        const char* called = std::getenv("MESHEDIT_CALLED_AS");
        return std::string(called != nullptr && *called != '\0' ? called : "meshedit-render");
    }();
    return name.c_str();
}

namespace {

// What to install, per backend (Debian package names; docs/building.md has the others).
constexpr const char* kInstallEgl = "Mesa's EGL (Debian: libegl1 libegl-mesa0) or a GPU driver's";
constexpr const char* kInstallOsMesa = "OSMesa (Debian: libosmesa6)";

std::unique_ptr<GlContext> try_backend(Backend backend, const ContextRequest& request,
                                       std::string& failures) {
    try {
#if MESHEDIT_HAVE_EGL
        if (backend == Backend::Egl) {
            return make_egl_context(request);
        }
#endif
#if MESHEDIT_HAVE_OSMESA
        if (backend == Backend::OsMesa) {
            return make_osmesa_context(request);
        }
#endif
        failures += std::string(failures.empty() ? "" : "; ") +
                    (backend == Backend::Egl
                         ? "egl: not in this build (libegl-dev was missing when it was configured)"
                         : "osmesa: not in this build (libosmesa6-dev was missing when it was "
                           "configured)");
    } catch (const ContextError& e) {
        if (request.verbose) {
            std::fprintf(stderr, "%s: %s\n", headless::program_name(), e.what());
        }
        failures += std::string(failures.empty() ? "" : "; ") + e.what();
    }
    return nullptr;
}

}  // namespace

void GlContext::finish() const {
    glFinish();
}

std::unique_ptr<GlContext> make_context(const ContextRequest& request) {
    std::string failures;
    const bool auto_choice = request.backend == Backend::Auto;
    if (request.backend == Backend::OsMesa && request.device) {
        throw ContextError("--device picks an EGL device; --backend osmesa has none");
    }
    // Installing a library cannot help a backend this binary was built without.
    if (request.backend != Backend::Auto) {
        const std::string name = request.backend == Backend::Egl ? "egl" : "osmesa";
        const std::vector<std::string> built = compiled_backends();
        if (std::find(built.begin(), built.end(), name) == built.end()) {
            throw ContextError("--backend " + name + ": not in this build (" +
                               (name == "egl" ? "libegl-dev" : "libosmesa6-dev") +
                               " was missing when it was configured; --version lists the "
                               "backends it has)");
        }
    }
    if (auto_choice || request.backend == Backend::Egl) {
        if (auto context = try_backend(Backend::Egl, request, failures)) {
            return context;
        }
        // A device was asked for by number: falling back to OSMesa would hide the mistake.
        if (request.device) {
            throw ContextError(failures);
        }
    }
    if (auto_choice || request.backend == Backend::OsMesa) {
        if (auto context = try_backend(Backend::OsMesa, request, failures)) {
            return context;
        }
    }
    const std::string install = request.backend == Backend::Egl ? kInstallEgl
                                : request.backend == Backend::OsMesa
                                    ? kInstallOsMesa
                                    : std::string(kInstallEgl) + ", or " + kInstallOsMesa;
    throw ContextError("no OpenGL 3.3 core context (" + failures + "); install " + install);
}

std::vector<std::string> compiled_backends() {
    std::vector<std::string> names;
#if MESHEDIT_HAVE_EGL
    names.emplace_back("egl");
#endif
#if MESHEDIT_HAVE_OSMESA
    names.emplace_back("osmesa");
#endif
    return names;
}

std::string gl_description() {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return std::string(renderer != nullptr ? renderer : "?") + ", OpenGL " +
           (version != nullptr ? version : "?");
}

void check_gl_version(const std::string& backend) {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < 33) {
        throw ContextError(backend + ": the driver gives OpenGL " + std::to_string(major) + "." +
                           std::to_string(minor) + " (" + gl_description() +
                           "), MeshEdit needs 3.3 core");
    }
}

}  // namespace meshedit::headless
