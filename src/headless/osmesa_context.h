#pragma once
// An OSMesa GL 3.3 core context (Mesa's software rasteriser, llvmpipe). OSMesa left Mesa in
// 25.1; it stays the fallback while distributions ship it.

#include <memory>

#include "gl_context.h"

namespace meshedit::headless {

/// Opens libOSMesa.so.8 and makes a core-profile 3.3 context current with a
/// `request.width` × `request.height` RGBA default buffer (the renderer draws into its own
/// FBO; the buffer only makes the context current). \throws ContextError.
std::unique_ptr<GlContext> make_osmesa_context(const ContextRequest& request);

}  // namespace meshedit::headless
