// add_stencil_marks() and weight_label() (overlay.h): a subdivision stencil drawn on the
// mesh. GL-free.

#include <cmath>
#include <cstdio>

#include "meshedit/overlay/overlay.h"

namespace meshedit {

std::string weight_label(double weight) {
    // The smallest denominator that gives the weight exactly (to rounding): Loop's and
    // Catmull-Clark's weights are fractions like 3/8, 1/16, 3/40, 1/36.
    for (long long denominator = 1; denominator <= 4096; ++denominator) {
        const double numerator = std::round(weight * static_cast<double>(denominator));
        if (std::abs(numerator / static_cast<double>(denominator) - weight) <= 1e-12 &&
            std::abs(numerator) < 1e9) {
            char buffer[48];
            if (denominator == 1) {
                std::snprintf(buffer, sizeof buffer, "%.0f", numerator);
            } else {
                std::snprintf(buffer, sizeof buffer, "%.0f/%lld", numerator, denominator);
            }
            return buffer;
        }
    }
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", weight);
    return buffer;
}

void add_stencil_marks(const Mesh& mesh, const Stencil& stencil, const OverlayStyle& style,
                       OverlayBatch& out) {
    if (!stencil.ok()) {
        return;
    }
    for (const StencilTerm& term : stencil.terms) {
        const Vec3& p = mesh.position(term.vertex);
        out.lines.push_back({p, stencil.position, style.stencil, 1.5f, true});
        out.points.push_back({p, style.stencil, style.control_point_px * 0.75f, true});
        out.labels.push_back({p, weight_label(term.weight), style.stencil});
    }
    out.points.push_back({stencil.position, style.loop_target, style.control_point_px, true});
    out.labels.push_back({stencil.position, "p' (" + stencil.rule + ")", style.loop_target,
                          OverlayBatch::Label::Side::Left});
}

}  // namespace meshedit
