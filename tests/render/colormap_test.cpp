// Colour maps and the default colouring of fields: the maps' ends and monotone lightness,
// NaN shown as missing, signed fields symmetric about 0, valence centred on the regular one.

#include "meshedit/overlay/colormap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace meshedit {
namespace {

float luminance(const Color& c) {
    return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

TEST(Colormap, SequentialMapsGetLighterAndClamp) {
    for (const ColorMap map : {ColorMap::Viridis, ColorMap::Magma}) {
        SCOPED_TRACE(std::string(colormap_name(map)));
        float previous = -1.0f;
        for (int i = 0; i <= 20; ++i) {
            const float l = luminance(colormap_color(map, i / 20.0));
            EXPECT_GT(l, previous);
            previous = l;
        }
        EXPECT_EQ(colormap_color(map, -3.0), colormap_color(map, 0.0));
        EXPECT_EQ(colormap_color(map, 7.0), colormap_color(map, 1.0));
        EXPECT_EQ(find_colormap(colormap_name(map)), map);
    }
    // The diverging map: blue, grey in the middle, red.
    const Color mid = colormap_color(ColorMap::Diverging, 0.5);
    EXPECT_NEAR(mid[0], mid[2], 1e-6);
    EXPECT_GT(colormap_color(ColorMap::Diverging, 0.0)[2], 0.7f);
    EXPECT_GT(colormap_color(ColorMap::Diverging, 1.0)[0], 0.7f);
    EXPECT_FALSE(find_colormap("jet").has_value());
}

TEST(Colormap, DefaultColourings) {
    const FieldInfo& gauss = *find_field("gauss");
    const std::vector<double> signed_values{-1.0, -0.5, 0.0, 0.25, 3.0, std::nan("")};
    const FieldColoring c = default_coloring(gauss, signed_values, 0.0);
    EXPECT_EQ(c.map, ColorMap::Diverging);
    EXPECT_EQ(c.lo, -3.0);
    EXPECT_EQ(c.hi, 3.0);
    EXPECT_EQ(c.color_of(std::nan("")), c.missing);
    EXPECT_EQ(c.color_of(0.0), colormap_color(ColorMap::Diverging, 0.5));

    const FieldInfo& valence = *find_field("valence");
    const std::vector<double> valences{6, 6, 6, 6, 5, 7, 4, 32};
    const FieldColoring v = default_coloring(valence, valences);
    EXPECT_EQ(v.lo, 3.0);  // 6 ± 3: a pole's 32 is clamped, not the range
    EXPECT_EQ(v.hi, 9.0);

    const FieldInfo& area = *find_field("face_area");
    std::vector<double> areas;
    for (int i = 0; i <= 100; ++i) {
        areas.push_back(i);
    }
    const FieldColoring a = default_coloring(area, areas, 0.05);
    EXPECT_EQ(a.map, ColorMap::Viridis);
    EXPECT_EQ(a.lo, 5.0);
    EXPECT_EQ(a.hi, 95.0);
}

}  // namespace
}  // namespace meshedit
