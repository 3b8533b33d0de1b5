#pragma once
/// \file
/// Environment maps for shading mode 7 (mirror reflection): an equirectangular image,
/// longitude θ along x (u = θ/2π) and polar angle φ from +Y down along y (v = φ/π), as in
/// the CS184 handout. The default is made here, by code: a studio sky with a horizon, a
/// ground and three soft lights. Any image OpenImageIO reads (PNG, JPEG, HDR, EXR) can
/// replace it; values are linear, and HDR ones above 1 are tone-mapped by the shader.

#include <filesystem>
#include <vector>

namespace meshedit {

struct EnvironmentImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  ///< width × height × 3, row 0 at the top (+Y), linear

    const float* at(int x, int y) const { return rgb.data() + 3 * (y * width + x); }
};

/// The default environment, `width` × width/2 pixels: blue-grey sky to a bright horizon, a
/// darker ground below it, a warm key light (up to 6× white), a cool fill and a long soft
/// box overhead.
EnvironmentImage default_environment(int width = 512);

/// The six faces of a cube map (+X, −X, +Y, −Y, +Z, −Z, in GL's order and orientation),
/// each `size` × `size` RGB, resampled bilinearly from `image` at each texel's direction
/// through the same θ/2π, φ/π mapping: what mode 7 samples, since a cube lookup costs a
/// software rasteriser far less than the arc tangent and arc cosine per pixel.
std::vector<std::vector<float>> cube_faces(const EnvironmentImage& image, int size);

/// Reads an equirectangular image. 8-bit images are sRGB and are made linear; float images
/// (HDR, EXR) are taken as they are. \throws IoError naming the file (unreadable, not about
/// twice as wide as high, larger than 16384 pixels a side).
EnvironmentImage read_environment(const std::filesystem::path& path);

}  // namespace meshedit
