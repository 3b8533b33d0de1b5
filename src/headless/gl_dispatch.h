#pragma once
// meshedit-render's own GL entry points. The renderer calls glFoo() by name (gl.h); this
// program defines every function of glcorearb.h as a jump through a pointer, filled from the
// backend that made the context current (eglGetProcAddress or OSMesaGetProcAddress). So
// neither libOpenGL nor libOSMesa is linked: both are opened at run time, and their GL symbols
// never meet in one process (docs/rendering.md, "Backends").

namespace meshedit::headless {

/// Looks a GL function up by name in the backend that made the current context.
using GlResolver = void* (*)(const char* name);

/// Fills every GL entry point through `resolve`. Call it once a context is current.
/// \return the number of functions the backend does not provide (they stay unset).
int load_gl_functions(GlResolver resolve);

}  // namespace meshedit::headless
