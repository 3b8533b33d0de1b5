#include "meshedit/overlay/colormap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace meshedit {
namespace {

using Anchor = std::array<float, 3>;

// Anchor colours, evenly spaced in t (sRGB, 0-255 / 255).
constexpr Anchor kViridis[] = {
    {0.267f, 0.005f, 0.329f}, {0.283f, 0.141f, 0.458f}, {0.254f, 0.265f, 0.530f},
    {0.207f, 0.372f, 0.553f}, {0.164f, 0.471f, 0.558f}, {0.128f, 0.567f, 0.551f},
    {0.135f, 0.659f, 0.518f}, {0.267f, 0.749f, 0.441f}, {0.478f, 0.821f, 0.318f},
    {0.741f, 0.873f, 0.150f}, {0.993f, 0.906f, 0.144f}};
constexpr Anchor kMagma[] = {
    {0.001f, 0.000f, 0.014f}, {0.110f, 0.063f, 0.267f}, {0.310f, 0.071f, 0.483f},
    {0.506f, 0.145f, 0.506f}, {0.710f, 0.212f, 0.478f}, {0.898f, 0.349f, 0.392f},
    {0.984f, 0.529f, 0.380f}, {0.996f, 0.761f, 0.529f}, {0.987f, 0.991f, 0.749f}};
constexpr Anchor kDiverging[] = {{0.230f, 0.299f, 0.754f},
                                 {0.552f, 0.690f, 0.996f},
                                 {0.865f, 0.865f, 0.865f},
                                 {0.958f, 0.604f, 0.483f},
                                 {0.706f, 0.016f, 0.150f}};

Color through(std::span<const Anchor> anchors, double t) {
    const double x = std::clamp(t, 0.0, 1.0) * static_cast<double>(anchors.size() - 1);
    const auto i = std::min(static_cast<std::size_t>(x), anchors.size() - 2);
    const auto f = static_cast<float>(x - static_cast<double>(i));
    const Anchor& a = anchors[i];
    const Anchor& b = anchors[i + 1];
    return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]), 1.0f};
}

}  // namespace

std::string_view colormap_name(ColorMap map) {
    switch (map) {
        case ColorMap::Viridis:
            return "viridis";
        case ColorMap::Magma:
            return "magma";
        case ColorMap::Diverging:
            break;
    }
    return "diverging";
}

std::optional<ColorMap> find_colormap(std::string_view name) {
    for (const ColorMap map : {ColorMap::Viridis, ColorMap::Magma, ColorMap::Diverging}) {
        if (colormap_name(map) == name) {
            return map;
        }
    }
    return std::nullopt;
}

Color colormap_color(ColorMap map, double t) {
    switch (map) {
        case ColorMap::Viridis:
            return through(kViridis, t);
        case ColorMap::Magma:
            return through(kMagma, t);
        case ColorMap::Diverging:
            break;
    }
    return through(kDiverging, t);
}

Color FieldColoring::color_of(double value) const {
    if (std::isnan(value)) {
        return missing;
    }
    const double span = hi - lo;
    return colormap_color(map, span > 0.0 ? (value - lo) / span : 0.5);
}

FieldColoring default_coloring(const FieldInfo& info, std::span<const double> values, double clip) {
    FieldColoring c;
    const double lo = field_percentile(values, clip);
    const double hi = field_percentile(values, 1.0 - clip);
    if (info.name == "valence") {
        // Diverging about the commonest valence (6 on triangles, 4 on quads): regular
        // vertices grey, the extraordinary ones blue (fewer edges) or red (more),
        std::map<double, std::size_t> counts;
        for (const double x : values) {
            if (std::isfinite(x)) {
                ++counts[x];
            }
        }
        double regular = 0.0;
        std::size_t most = 0;
        for (const auto& [x, n] : counts) {
            if (n > most) {
                regular = x;
                most = n;
            }
        }
        // ±1 to ±3 about it: beyond 3, a pole's 32 would grey out the valence-5 and -7 ones.
        const double m = counts.empty() ? 1.0
                                        : std::clamp(std::max(regular - counts.begin()->first,
                                                              counts.rbegin()->first - regular),
                                                     1.0, 3.0);
        c.map = ColorMap::Diverging;
        c.lo = regular - m;
        c.hi = regular + m;
    } else if (info.is_signed) {
        // Symmetric about 0, up to the (1 − clip) quantile of |value|.
        std::vector<double> magnitude;
        for (const double x : values) {
            magnitude.push_back(std::abs(x));
        }
        const double m = field_percentile(magnitude, 1.0 - clip);
        c.map = ColorMap::Diverging;
        c.lo = -m;
        c.hi = m;
    } else {
        c.lo = lo;
        c.hi = hi;
    }
    return c;
}

}  // namespace meshedit
