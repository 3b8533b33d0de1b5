#pragma once
// Private to the mesh renderer's .cpp files: how a triangle corner is packed, and how a GL
// buffer grows.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "gl.h"
#include "meshedit/core/math.h"

namespace meshedit {

// Packs a unit vector as GL_INT_2_10_10_10_REV (x in the low bits, signed normalised).
inline std::uint32_t pack_normal(const Vec3& n) {
    auto component = [](double v) {
        const long q = std::lround(std::clamp(v, -1.0, 1.0) * 511.0);
        return static_cast<std::uint32_t>(q) & 0x3ffu;
    };
    return component(n.x) | (component(n.y) << 10) | (component(n.z) << 20);
}

// Grows `buffer` (bound to `target`) to at least `bytes`, keeping its size otherwise, then
// uploads `data`. Growth doubles, so a slowly growing mesh does not reallocate every edit, and
// a first upload leaves 1/16 room: otherwise the first split after loading grew the buffer
// and sent it whole (1.8 s at 10M faces on llvmpipe, against 0.06 ms for an update in place).
inline void upload_buffer(GLenum target, std::size_t& capacity, const void* data,
                          std::size_t bytes) {
    if (bytes > capacity) {
        capacity = std::max(bytes + bytes / 16, capacity * 2);
        glBufferData(target, static_cast<GLsizeiptr>(capacity), nullptr, GL_STATIC_DRAW);
    }
    if (bytes > 0) {
        glBufferSubData(target, 0, static_cast<GLsizeiptr>(bytes), data);
    }
}

}  // namespace meshedit
