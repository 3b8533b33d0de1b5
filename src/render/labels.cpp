#include "meshedit/render/labels.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

#include "meshedit/files/files.h"

namespace meshedit {
namespace {

// OpenImageIO 2.4's render_text() garbles every byte past ASCII (it draws "·" as "7"): the
// labels' few other characters as ASCII, anything else as '?'.
std::string oiio_safe(const std::string& text) {
    static const std::pair<std::string_view, std::string_view> kAscii[] = {
        {"→", "->"}, {"–", "-"}, {"·", "*"}, {"…", "..."}, {"²", "^2"}};
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte < 0x80) {
            out += text[i++];
            continue;
        }
        bool known = false;
        for (const auto& [utf8, ascii] : kAscii) {
            if (std::string_view(text).substr(i, utf8.size()) == utf8) {
                out += ascii;
                i += utf8.size();
                known = true;
                break;
            }
        }
        if (!known) {
            out += '?';
            ++i;
            while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) {
                ++i;
            }
        }
    }
    return out;
}

}  // namespace

void draw_labels(Image& image, std::span<const OverlayBatch::Label> labels, const Camera& camera,
                 int font_px) {
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
    if (font_px <= 0) {
        font_px = std::max(12, image.height / 32);
    }
    for (const OverlayBatch::Label& label : labels) {
        const auto at = project_to_pixels(camera, label.at, image.width, image.height);
        if (!at) {
            continue;
        }
        // Light text on a translucent dark box: readable on any shading.
        const std::string text = oiio_safe(label.text);
        const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(text, font_px, kLabelFont);
        if (!box.defined()) {
            throw IoError(kLabelFont, "", "cannot measure text: " + OIIO::geterror());
        }
        const int gap = font_px / 2;
        const int ax = static_cast<int>(std::lround(at->x));
        const int ay = static_cast<int>(std::lround(at->y));
        int x = ax + gap;
        int y = ay - font_px / 3;
        if (label.side == OverlayBatch::Label::Side::Left) {
            x = ax - gap - box.xend;
        } else if (label.side == OverlayBatch::Label::Side::Centre) {
            x = ax - (box.xbegin + box.xend) / 2;
            y = ay - (box.ybegin + box.yend) / 2;
        }
        const int pad = std::max(2, font_px / 6);
        const std::array<float, 4> shade{0.05f, 0.05f, 0.08f, 0.7f};
        const std::array<float, 4> color{0.5f + 0.5f * label.color[0], 0.5f + 0.5f * label.color[1],
                                         0.5f + 0.5f * label.color[2], 1.0f};
        if (!OIIO::ImageBufAlgo::render_box(buffer, x + box.xbegin - pad, y + box.ybegin - pad,
                                            x + box.xend + pad, y + box.yend + pad, shade, true) ||
            !OIIO::ImageBufAlgo::render_text(buffer, x, y, text, font_px, kLabelFont, color)) {
            throw IoError(kLabelFont, "", "cannot draw text: " + buffer.geterror());
        }
    }
}

}  // namespace meshedit
