#include "meshedit/render/labels.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "meshedit/files/files.h"
#include "meshedit/overlay/label_layout.h"

namespace meshedit {
namespace {

// OpenImageIO 2.4's render_text() garbles every byte past ASCII (it draws "·" as "7"): the
// labels' few other characters as ASCII, anything else as '?'.
std::string oiio_safe(const std::string& text) {
    static const std::pair<std::string_view, std::string_view> kAscii[] = {
        {"→", "->"}, {"–", "-"}, {"·", "*"}, {"…", "..."}, {"²", "^2"}, {"°", " deg"}};
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

std::filesystem::path label_font() {
    std::vector<std::filesystem::path> candidates;
    if (const char* env = std::getenv("MESHEDIT_FONT"); env != nullptr && *env != '\0') {
        candidates.emplace_back(env);
    }
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        candidates.push_back(self.parent_path().parent_path() / "share" / "meshedit" / "fonts" /
                             "DejaVuSans.ttf");
    }
    candidates.emplace_back("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
    for (const auto& path : candidates) {
        if (std::filesystem::is_regular_file(path, ec)) {
            return path;
        }
    }
    return candidates.back();
}

void draw_labels(Image& image, std::span<const OverlayBatch::Label> labels, const Camera& camera,
                 int font_px) {
    if (labels.empty()) {
        return;
    }
    const std::string font = label_font().string();
    if (!std::filesystem::exists(font)) {
        throw IoError(font, "", "the labels' font is missing (apt-get install fonts-dejavu-core)");
    }
    namespace OIIO = OIIO_NAMESPACE;
    const OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf buffer(spec, image.rgba.data());  // wraps the pixels: drawn in place
    if (font_px <= 0) {
        font_px = std::max(12, image.height / 32);
    }
    // First where each would go alone (its text box about the baseline origin x, y), then
    // where it goes among the others (label_layout.h), then drawn there.
    struct Measured {
        const OverlayBatch::Label* label;
        std::string text;
        OIIO::ROI box;
        int x, y;  // the baseline origin, alone
    };
    std::vector<Measured> measured;
    std::vector<LabelSpot> spots;
    const int gap = font_px / 2;
    const int pad = std::max(2, font_px / 6);
    for (const OverlayBatch::Label& label : labels) {
        const auto at = project_to_pixels(camera, label.at, image.width, image.height);
        if (!at) {
            continue;
        }
        const std::string text = oiio_safe(label.text);
        const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(text, font_px, font);
        if (!box.defined()) {
            throw IoError(font, "", "cannot measure text: " + OIIO::geterror());
        }
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
        measured.push_back({&label, text, box, x, y});
        spots.push_back(
            {{static_cast<float>(x + box.xbegin - pad), static_cast<float>(y + box.ybegin - pad),
              static_cast<float>(box.xend - box.xbegin + 2 * pad),
              static_cast<float>(box.yend - box.ybegin + 2 * pad)},
             label.side,
             label.fixed});
    }
    const std::vector<std::optional<LabelRect>> placed =
        place_labels(spots, static_cast<float>(gap), -2.0f, static_cast<float>(image.width),
                     static_cast<float>(image.height));
    for (std::size_t i = 0; i < measured.size(); ++i) {
        if (!placed[i]) {
            continue;  // no free place near its point
        }
        const Measured& m = measured[i];
        const int x = m.x + static_cast<int>(std::lround(placed[i]->x - spots[i].box.x));
        const int y = m.y + static_cast<int>(std::lround(placed[i]->y - spots[i].box.y));
        // Light text on a translucent dark box: readable on any shading.
        // A label the surface hides (hide_labels_behind()) is drawn faded.
        const float fade = m.label->hidden ? 0.4f : 1.0f;
        const std::array<float, 4> shade{0.05f, 0.05f, 0.08f, 0.7f * fade};
        const Color& c = m.label->color;
        // render_text() ignores alpha: a hidden label's text is mixed towards grey instead.
        const auto ink = [&](float x) { return fade * (0.5f + 0.5f * x) + (1.0f - fade) * 0.55f; };
        const std::array<float, 4> color{ink(c[0]), ink(c[1]), ink(c[2]), 1.0f};
        if (!OIIO::ImageBufAlgo::render_box(buffer, x + m.box.xbegin - pad, y + m.box.ybegin - pad,
                                            x + m.box.xend + pad, y + m.box.yend + pad, shade,
                                            true) ||
            !OIIO::ImageBufAlgo::render_text(buffer, x, y, m.text, font_px, font, color)) {
            throw IoError(font, "", "cannot draw text: " + buffer.geterror());
        }
    }
}

void draw_legend(Image& image, const FieldColoring& coloring, const std::string& title) {
    const std::string font = label_font().string();
    if (!std::filesystem::exists(font)) {
        throw IoError(font, "", "the legend's font is missing (apt-get install fonts-dejavu-core)");
    }
    namespace OIIO = OIIO_NAMESPACE;
    const OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf buffer(spec, image.rgba.data());
    const int font_px = std::max(12, image.height / 32);
    const OIIO::ROI title_box = OIIO::ImageBufAlgo::text_size(oiio_safe(title), font_px, font);
    const int bar_w = std::max({60, image.width / 4, title_box.defined() ? title_box.xend : 0});
    const int bar_h = std::max(8, font_px * 2 / 3);
    const int margin = font_px;
    const int x0 = image.width - margin - bar_w;
    const int y0 = image.height - margin - font_px - bar_h;  // the bar's top; values below it
    const std::array<float, 4> panel{0.97f, 0.97f, 0.98f, 0.85f};
    const std::array<float, 4> ink{0.12f, 0.12f, 0.16f, 1.0f};
    OIIO::ImageBufAlgo::render_box(buffer, x0 - font_px / 2, y0 - 2 * font_px,
                                   image.width - margin / 2, image.height - margin / 3, panel,
                                   true);
    for (int x = 0; x < bar_w; ++x) {
        const Color c = colormap_color(coloring.map, (x + 0.5) / bar_w);
        for (int y = 0; y < bar_h; ++y) {
            std::uint8_t* p = image.pixel(x0 + x, y0 + y);
            for (int k = 0; k < 3; ++k) {
                p[k] =
                    static_cast<std::uint8_t>(std::lround(255.0f * c[static_cast<std::size_t>(k)]));
            }
            p[3] = 255;
        }
    }
    const double scale = std::max(std::abs(coloring.lo), std::abs(coloring.hi));
    const auto value = [scale](double x) {
        if (std::abs(x) < 1e-9 * scale) {
            x = 0.0;  // rounding noise of a value that is 0 (a flat dihedral: "9e-15")
        }
        char text[32];
        std::snprintf(text, sizeof text, "%.3g", x);
        return std::string(text);
    };
    const std::string lo = value(coloring.lo), hi = value(coloring.hi);
    const OIIO::ROI hi_box = OIIO::ImageBufAlgo::text_size(hi, font_px, font);
    const int below = y0 + bar_h + font_px;
    if (!OIIO::ImageBufAlgo::render_text(buffer, x0, y0 - font_px / 2, oiio_safe(title), font_px,
                                         font, ink) ||
        !OIIO::ImageBufAlgo::render_text(buffer, x0, below, lo, font_px, font, ink) ||
        !OIIO::ImageBufAlgo::render_text(buffer, x0 + bar_w - (hi_box.defined() ? hi_box.xend : 0),
                                         below, hi, font_px, font, ink)) {
        throw IoError(font, "", "cannot draw text: " + buffer.geterror());
    }
}

}  // namespace meshedit
