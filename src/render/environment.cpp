#include "meshedit/render/environment.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "meshedit/core/budget.h"
#include "meshedit/files/io_error.h"

namespace meshedit {
namespace {

constexpr double kPi = std::numbers::pi;

struct Direction {
    double x, y, z;
};

// The direction of pixel centre (x, y) of a w × h equirectangular image.
Direction direction_of(int x, int y, int w, int h) {
    const double theta = 2.0 * kPi * ((x + 0.5) / w - 0.5);  // −π … π, atan2(z, x)
    const double phi = kPi * (y + 0.5) / h;                  // 0 at +Y
    return {std::sin(phi) * std::cos(theta), std::cos(phi), std::sin(phi) * std::sin(theta)};
}

// A soft light: intensity × a Gaussian of the angle to its direction.
double light(const Direction& d, double theta_deg, double elevation_deg, double radius_deg) {
    const double t = theta_deg * kPi / 180.0, e = elevation_deg * kPi / 180.0;
    const Direction c{std::cos(e) * std::cos(t), std::sin(e), std::cos(e) * std::sin(t)};
    const double cosine = std::clamp(d.x * c.x + d.y * c.y + d.z * c.z, -1.0, 1.0);
    const double angle = std::acos(cosine) / (radius_deg * kPi / 180.0);
    return std::exp(-0.5 * angle * angle);
}

double srgb_to_linear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

EnvironmentImage default_environment(int width) {
    EnvironmentImage env;
    env.width = std::max(width, 8);
    env.height = env.width / 2;
    env.rgb.resize(static_cast<std::size_t>(3 * env.width * env.height));
    for (int y = 0; y < env.height; ++y) {
        for (int x = 0; x < env.width; ++x) {
            const Direction d = direction_of(x, y, env.width, env.height);
            double r, g, b;
            if (d.y >= 0.0) {
                // Sky: bright at the horizon, blue-grey overhead.
                const double s = std::pow(d.y, 0.6);
                r = 0.85 + s * (0.32 - 0.85);
                g = 0.88 + s * (0.42 - 0.88);
                b = 0.93 + s * (0.62 - 0.93);
            } else {
                // Ground: warm grey, darker straight down; a soft step at the horizon.
                const double s = std::pow(-d.y, 0.5);
                r = 0.30 + s * (0.10 - 0.30);
                g = 0.27 + s * (0.09 - 0.27);
                b = 0.24 + s * (0.08 - 0.24);
            }
            const double key = 6.0 * light(d, 40.0, 35.0, 9.0);
            const double fill = 1.6 * light(d, 215.0, 18.0, 16.0);
            // A long soft box overhead: a band of constant longitude width near the zenith.
            const double box = 2.5 * std::exp(-std::pow((d.y - 0.93) / 0.035, 2.0)) *
                               std::exp(-std::pow(d.x / 0.25, 2.0));
            // The sky and ground were chosen as display colours: linear, as images are.
            float* p = env.rgb.data() + 3 * (y * env.width + x);
            p[0] = static_cast<float>(srgb_to_linear(r) + key * 1.0 + fill * 0.75 + box);
            p[1] = static_cast<float>(srgb_to_linear(g) + key * 0.93 + fill * 0.85 + box);
            p[2] = static_cast<float>(srgb_to_linear(b) + key * 0.82 + fill * 1.0 + box);
        }
    }
    return env;
}

namespace {

// Bilinear sample of `image` at direction d (unit): u = θ/2π + ½, v = φ/π; wraps in θ.
void sample(const EnvironmentImage& image, double x, double y, double z, float* out) {
    const double u = std::atan2(z, x) / (2.0 * kPi) + 0.5;
    const double v = std::acos(std::clamp(y, -1.0, 1.0)) / kPi;
    const double fx = u * image.width - 0.5,
                 fy = std::clamp(v * image.height - 0.5, 0.0, image.height - 1.0);
    const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
    const double tx = fx - x0, ty = fy - y0;
    const int y1 = std::min(y0 + 1, image.height - 1);
    const auto wrap = [&](int i) { return ((i % image.width) + image.width) % image.width; };
    const float* a = image.at(wrap(x0), y0);
    const float* b = image.at(wrap(x0 + 1), y0);
    const float* c = image.at(wrap(x0), y1);
    const float* d = image.at(wrap(x0 + 1), y1);
    for (int k = 0; k < 3; ++k) {
        out[k] = static_cast<float>((1 - ty) * ((1 - tx) * a[k] + tx * b[k]) +
                                    ty * ((1 - tx) * c[k] + tx * d[k]));
    }
}

}  // namespace

std::vector<std::vector<float>> cube_faces(const EnvironmentImage& image, int size) {
    std::vector<std::vector<float>> faces(
        6, std::vector<float>(static_cast<std::size_t>(3 * size * size)));
    for (int face = 0; face < 6; ++face) {
        for (int j = 0; j < size; ++j) {
            for (int i = 0; i < size; ++i) {
                // GL's cube map table: the texel's (sc, tc) in [−1, 1] and its major axis.
                const double sc = 2.0 * (i + 0.5) / size - 1.0, tc = 2.0 * (j + 0.5) / size - 1.0;
                double x = 0, y = 0, z = 0;
                switch (face) {
                    case 0:
                        x = 1;
                        y = -tc;
                        z = -sc;
                        break;
                    case 1:
                        x = -1;
                        y = -tc;
                        z = sc;
                        break;
                    case 2:
                        x = sc;
                        y = 1;
                        z = tc;
                        break;
                    case 3:
                        x = sc;
                        y = -1;
                        z = -tc;
                        break;
                    case 4:
                        x = sc;
                        y = -tc;
                        z = 1;
                        break;
                    default:
                        x = -sc;
                        y = -tc;
                        z = -1;
                        break;
                }
                const double n = std::sqrt(x * x + y * y + z * z);
                sample(image, x / n, y / n, z / n,
                       faces[static_cast<std::size_t>(face)].data() + 3 * (j * size + i));
            }
        }
    }
    return faces;
}

EnvironmentImage read_environment(const std::filesystem::path& path) {
    namespace OIIO = OIIO_NAMESPACE;
    // A FIFO or a device would block or never end: only regular files, as the mesh readers.
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) {
        throw IoError(path.string(), "", "no such file");
    }
    if (!std::filesystem::is_regular_file(status)) {
        throw IoError(path.string(), "", "is not a regular file (a FIFO, a device or a folder)");
    }
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) {
        throw IoError(path.string(), "", "cannot read the environment image: " + OIIO::geterror());
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width < 8 || spec.height < 4 || spec.width > 16384 || spec.height > 16384) {
        throw IoError(path.string(), "",
                      "an environment image is 8 to 16384 pixels a side, this one " +
                          std::to_string(spec.width) + " × " + std::to_string(spec.height));
    }
    if (std::abs(spec.width - 2 * spec.height) > spec.height / 10) {
        throw IoError(path.string(), "",
                      "not equirectangular: it should be twice as wide as high, it is " +
                          std::to_string(spec.width) + " × " + std::to_string(spec.height));
    }
    const int channels = spec.nchannels;
    if (channels < 1 || channels > 64) {
        throw IoError(path.string(), "",
                      "an image of " + std::to_string(channels) + " channels is not a picture");
    }
    // What the header promises, checked against the budget before anything is allocated: the
    // linear RGB kept (12 bytes a pixel) and the cube map made from it (as much again).
    const double pixels = static_cast<double>(spec.width) * spec.height;
    if (const auto over = over_budget(24.0 * pixels)) {
        throw IoError(path.string(), "",
                      "an environment image of " + std::to_string(spec.width) + " × " +
                          std::to_string(spec.height) + " pixels " + *over);
    }
    EnvironmentImage env;
    env.width = spec.width;
    env.height = spec.height;
    const bool srgb = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                      spec.format.basetype == OIIO::TypeDesc::UINT16;
    // Row by row, the kept pixels growing with the rows read: a header that promises more
    // than the file holds fails at its end instead of allocating gigabytes first.
    const auto width = static_cast<std::size_t>(spec.width);
    std::vector<float> row(width * static_cast<std::size_t>(channels));
    for (int y = 0; y < spec.height; ++y) {
        if (!in->read_scanline(y + spec.y, spec.z, OIIO::TypeDesc::FLOAT, row.data())) {
            throw IoError(path.string(), "",
                          "cannot read row " + std::to_string(y) +
                              " of the environment image: " + in->geterror());
        }
        for (std::size_t x = 0; x < width; ++x) {
            for (int k = 0; k < 3; ++k) {
                const float c = row[x * static_cast<std::size_t>(channels) +
                                    static_cast<std::size_t>(std::min(k, channels - 1))];
                env.rgb.push_back(!std::isfinite(c) ? 0.0f
                                  : srgb            ? static_cast<float>(srgb_to_linear(c))
                                                    : std::max(c, 0.0f));
            }
        }
    }
    return env;
}

}  // namespace meshedit
