#pragma once
// The headless GL context of the in-process render tests: the backend named by
// MESHEDIT_RENDER_BACKEND (ctest runs these tests once per backend), else auto.

#include <cstdlib>
#include <memory>
#include <string>

#include "gl_context.h"

namespace meshedit::test {

inline std::unique_ptr<headless::GlContext> make_test_context(int width, int height) {
    headless::ContextRequest request;
    request.width = width;
    request.height = height;
    const char* env = std::getenv("MESHEDIT_RENDER_BACKEND");
    const std::string name = env != nullptr ? env : "";
    request.backend = name == "egl"      ? headless::Backend::Egl
                      : name == "osmesa" ? headless::Backend::OsMesa
                                         : headless::Backend::Auto;
    return headless::make_context(request);
}

}  // namespace meshedit::test
