#pragma once
/// \file
/// Colour maps for scalar fields (core/fields.h) and the mapping of a field's values to
/// colours, shared by the viewer, meshedit-render and the legend. GL-free.
///
/// The maps are piecewise-linear through a few anchor colours written down here (to about
/// three digits): viridis and magma through colours near the ten-step anchors of Smith and
/// van der Walt's perceptually uniform maps, the diverging map through Moreland's cool-warm
/// end points and a neutral grey middle.

#include <optional>
#include <span>
#include <string_view>

#include "meshedit/core/fields.h"
#include "meshedit/overlay/overlay.h"

namespace meshedit {

enum class ColorMap { Viridis, Magma, Diverging };

/// "viridis", "magma", "diverging".
std::string_view colormap_name(ColorMap map);
std::optional<ColorMap> find_colormap(std::string_view name);

/// The colour at `t` (clamped to [0, 1]), opaque.
Color colormap_color(ColorMap map, double t);

/// How a field's values become colours: [lo, hi] mapped onto the map, values outside it
/// clamped to its ends; NaN (no value) in `missing`.
struct FieldColoring {
    ColorMap map = ColorMap::Viridis;
    double lo = 0.0, hi = 1.0;
    Color missing{0.55f, 0.55f, 0.57f, 1.0f};

    Color color_of(double value) const;
};

/// The colouring a field gets by default: its values between the `clip` and 1 − `clip`
/// percentiles on viridis (outliers such as a cone tip's curvature do not wash the rest
/// out); a signed field on the diverging map, symmetric about 0 up to the 1 − `clip`
/// quantile of |value|; valence on the diverging map about its commonest value, so the
/// extraordinary vertices stand out.
FieldColoring default_coloring(const FieldInfo& info, std::span<const double> values,
                               double clip = 0.05);

}  // namespace meshedit
