#pragma once
// Private: the GL 3.3 core prototypes. GL_GLEXT_PROTOTYPES (set on meshedit_render) makes
// glcorearb.h declare the functions, which libOSMesa and glvnd's libOpenGL both export, so
// no loader is needed. Never included from public headers.

#include <GL/glcorearb.h>
