#pragma once
// The OpenGL 3.3 core context meshedit-render draws in, made by EGL or OSMesa
// (docs/rendering.md, "Backends"). Both libraries are opened at run time (dlopen) and GL is
// called through gl_dispatch.h, so one binary holds both and runs when only one is installed.

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshedit::headless {

enum class Backend { Auto, Egl, OsMesa };

/// The name messages start with: "meshedit" when `meshedit render` ran this program (it sets
/// MESHEDIT_CALLED_AS), else "meshedit-render".
const char* program_name();

/// No context could be made (exit 2). The message says what was tried and what to install.
class ContextError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ContextRequest {
    Backend backend = Backend::Auto;
    std::optional<int> device;  ///< --device N: an EGL device, as eglQueryDevicesEXT orders them
    int width = 1, height = 1;  ///< OSMesa's default buffer (the renderer draws into its FBO)
    bool verbose = false;       ///< report devices and failed attempts on stderr
};

/// A current context; destroying it releases it.
class GlContext {
public:
    GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;
    virtual ~GlContext() = default;

    /// What made it: "egl (surfaceless)", "egl (device 1: /dev/dri/card0)", "osmesa".
    virtual std::string backend() const = 0;
    /// Waits until every GL command has finished (glFinish), for timings.
    void finish() const;
};

/// Makes a context current and loads GL through its backend: EGL or OSMesa as asked, or
/// with Backend::Auto EGL and then OSMesa. \throws ContextError saying what each attempt
/// met and what to install.
std::unique_ptr<GlContext> make_context(const ContextRequest& request);

/// The backends this build holds, in the order auto tries them ("egl", "osmesa").
std::vector<std::string> compiled_backends();

/// GL_RENDERER and GL_VERSION of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits),
/// OpenGL 4.5 (Core Profile) Mesa 22.3.6".
std::string gl_description();

/// Checks that the current context is OpenGL 3.3 or newer. \throws ContextError.
void check_gl_version(const std::string& backend);

}  // namespace meshedit::headless
