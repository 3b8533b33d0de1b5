// Shading-mode lookup (shading.h).

#include "meshedit/overlay/shading.h"

#include <charconv>

namespace meshedit {

std::optional<ShadingMode> find_shading_mode(std::string_view name_or_number) {
    int number = -1;
    const char* end = name_or_number.data() + name_or_number.size();
    const auto [ptr, ec] = std::from_chars(name_or_number.data(), end, number);
    const bool is_number = ec == std::errc() && ptr == end;
    for (const ShadingMode& mode : kShadingModes) {
        if ((is_number && mode.number == number) || (!is_number && mode.name == name_or_number)) {
            return mode;
        }
    }
    // Common synonyms, so `--shading blinn-phong` or `--shading flat-grey` work.
    if (name_or_number == "blinn-phong" || name_or_number == "blinn") {
        return kShadingModes[1];
    }
    if (name_or_number == "flat-grey" || name_or_number == "gray") {
        return kShadingModes[2];
    }
    return std::nullopt;
}

std::optional<SurfaceColorMode> find_surface_color(std::string_view name) {
    for (const SurfaceColorMode& mode : kSurfaceColors) {
        if (mode.name == name) {
            return mode;
        }
    }
    if (name == "colors" || name == "colours" || name == "attribute") {
        return kSurfaceColors[3];
    }
    return std::nullopt;
}

}  // namespace meshedit
