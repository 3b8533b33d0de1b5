// The GL entry points of meshedit-render (gl_dispatch.h). gl_functions.inc is generated from
// glcorearb.h at configure time (cmake/gl_dispatch.cmake): X(type, name, (parameters),
// (arguments)) for each function, so the definitions below match the header's declarations
// exactly (a mismatch is a compile error).

#include "gl_dispatch.h"

// Hidden: these definitions serve this program only and must never interpose on the GL
// symbols of a library loaded later.
#pragma GCC visibility push(hidden)
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES  // the declarations our definitions are checked against
#endif
#include <GL/glcorearb.h>

namespace {

struct GlFunctions {
#define X(type, name, parameters, arguments) type(APIENTRY* name) parameters = nullptr;
#include "gl_functions.inc"
#undef X
};

GlFunctions gl;

}  // namespace

extern "C" {
#define X(type, name, parameters, arguments) \
    type APIENTRY name parameters {          \
        return gl.name arguments;            \
    }
#include "gl_functions.inc"
#undef X
}
#pragma GCC visibility pop

namespace meshedit::headless {

int load_gl_functions(GlResolver resolve) {
    int missing = 0;
#define X(type, name, parameters, arguments)                       \
    gl.name = reinterpret_cast<decltype(gl.name)>(resolve(#name)); \
    missing += gl.name == nullptr ? 1 : 0;
#include "gl_functions.inc"
#undef X
    return missing;
}

}  // namespace meshedit::headless
