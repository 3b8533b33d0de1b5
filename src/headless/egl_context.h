#pragma once
// An EGL context without a surface: on a GPU's EGL device (EGL_EXT_platform_device, e.g.
// NVIDIA's) or on Mesa's surfaceless platform (llvmpipe, or the GPU's Mesa driver).

#include <memory>

#include "gl_context.h"

namespace meshedit::headless {

/// Opens libEGL.so.1 and makes a GL 3.3 core context current, trying in order: hardware EGL
/// devices, the surfaceless platform, software devices (EGL_MESA_device_software); only
/// `request.device` when it is set. \throws ContextError naming what each attempt met.
std::unique_ptr<GlContext> make_egl_context(const ContextRequest& request);

}  // namespace meshedit::headless
