#include "meshedit/render/labels.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <string>

#include "meshedit/files/files.h"

namespace meshedit {

void draw_labels(Image& image, std::span<const OverlayBatch::Label> labels, const Camera& camera) {
    if (labels.empty()) {
        return;
    }
    if (!std::filesystem::exists(kLabelFont)) {
        throw IoError(kLabelFont, "",
                      "the labels' font is missing (apt-get install fonts-dejavu-core)");
    }
    namespace OIIO = OIIO_NAMESPACE;
    const OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf buffer(spec, image.rgba.data());  // wraps the pixels: drawn in place
    const int font_px = std::max(12, image.height / 32);
    for (const OverlayBatch::Label& label : labels) {
        const auto at = project_to_pixels(camera, label.at, image.width, image.height);
        if (!at) {
            continue;
        }
        // Light text on a translucent dark box: readable on any shading.
        const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(label.text, font_px, kLabelFont);
        const int gap = font_px / 2;
        const int x = static_cast<int>(std::lround(at->x)) +
                      (label.left && box.defined() ? -gap - box.xend : gap);
        const int y = static_cast<int>(std::lround(at->y)) - font_px / 3;
        const int pad = std::max(2, font_px / 6);
        const std::array<float, 4> shade{0.05f, 0.05f, 0.08f, 0.7f};
        const std::array<float, 4> color{0.5f + 0.5f * label.color[0], 0.5f + 0.5f * label.color[1],
                                         0.5f + 0.5f * label.color[2], 1.0f};
        if (!box.defined() ||
            !OIIO::ImageBufAlgo::render_box(buffer, x + box.xbegin - pad, y + box.ybegin - pad,
                                            x + box.xend + pad, y + box.yend + pad, shade, true) ||
            !OIIO::ImageBufAlgo::render_text(buffer, x, y, label.text, font_px, kLabelFont,
                                             color)) {
            throw IoError(kLabelFont, "", "cannot draw text: " + buffer.geterror());
        }
    }
}

}  // namespace meshedit
