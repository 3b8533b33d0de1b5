#pragma once
/// \file
/// Overlay labels (OverlayBatch::Label) on a finished image, for meshedit-render: the window
/// draws the same labels with Dear ImGui. Text is DejaVu Sans (Debian's fonts-dejavu-core)
/// through OpenImageIO, with a dark shadow so it reads on light and dark shading.

#include <filesystem>
#include <span>
#include <string>

#include "meshedit/overlay/camera.h"
#include "meshedit/overlay/colormap.h"
#include "meshedit/overlay/overlay.h"
#include "meshedit/render/image.h"

namespace meshedit {

/// The font labels (and the viewer's panels) are drawn in: DejaVu Sans, looked up in
/// $MESHEDIT_FONT, beside an installed program (<exe>/../share/meshedit/fonts/DejaVuSans.ttf,
/// which `cmake --install` fills), then where Debian's fonts-dejavu-core puts it. The first
/// that exists; the last candidate when none does (the caller's message then names it).
std::filesystem::path label_font();

/// Draws each label a few pixels right of and above where its point lands in `image`, seen
/// through `camera`; labels behind the eye are skipped. Nothing to draw, nothing needed.
/// `font_px` 0: a 32nd of the image's height (at least 12).
/// \throws IoError naming label_font() when it is missing.
void draw_labels(Image& image, std::span<const OverlayBatch::Label> labels, const Camera& camera,
                 int font_px = 0);

/// A field's legend in the image's bottom-right corner: the colour bar from `coloring.lo` to
/// `coloring.hi`, the two values under its ends and `title` (the field's name and unit)
/// above it, on a light panel. \throws IoError naming label_font() when it is missing.
void draw_legend(Image& image, const FieldColoring& coloring, const std::string& title);

/// The font size of labels on a diagram `width` pixels wide (op_diagram.h).
inline int diagram_font_px(int width) {
    return width / 72 > 12 ? width / 72 : 12;
}

}  // namespace meshedit
