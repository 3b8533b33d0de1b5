#pragma once
/// \file
/// An 8-bit RGBA image in memory (top row first), PNG output through OpenImageIO.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace meshedit {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  ///< width × height × 4 bytes, row 0 at the top

    std::uint8_t* pixel(int x, int y) { return rgba.data() + 4 * (y * width + x); }
    const std::uint8_t* pixel(int x, int y) const { return rgba.data() + 4 * (y * width + x); }
};

/// Reads the current GL framebuffer (viewport origin, `width` × `height`) and flips it so
/// row 0 is the top. Needs a current GL context.
Image read_framebuffer(int width, int height);

/// Writes `image` as PNG, atomically (temp file + rename). \throws IoError naming the file.
void write_png(const Image& image, const std::filesystem::path& path);

/// Reads a PNG (or any format OpenImageIO reads) as 8-bit RGBA. \throws IoError.
Image read_png(const std::filesystem::path& path);

}  // namespace meshedit
