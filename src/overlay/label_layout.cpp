// Overlay labels without overlaps (label_layout.h): a greedy placement over a few candidate
// boxes per label, as map labelling does it — cheap and good enough for tens of labels.

#include "meshedit/overlay/label_layout.h"

#include <algorithm>

namespace meshedit {
namespace {

bool overlap(const LabelRect& a, const LabelRect& b, float margin) {
    return a.x < b.x + b.w + margin && b.x < a.x + a.w + margin && a.y < b.y + b.h + margin &&
           b.y < a.y + a.h + margin;
}

bool inside(const LabelRect& r, float width, float height) {
    return r.x >= 0 && r.y >= 0 && r.x + r.w <= width && r.y + r.h <= height;
}

}  // namespace

void hide_labels_behind(std::vector<OverlayBatch::Label>& labels, const Vec3& eye, const Mesh& mesh,
                        const FaceBvh& tree) {
    for (OverlayBatch::Label& label : labels) {
        FaceBvh::Ray ray{eye, label.at - eye, 0.0, 0.999};
        label.hidden = !label.fixed && tree.intersect(mesh, ray).has_value();
    }
    std::stable_partition(labels.begin(), labels.end(),
                          [](const OverlayBatch::Label& label) { return !label.hidden; });
}

std::vector<std::optional<LabelRect>> place_labels(std::span<const LabelSpot> spots, float gap,
                                                   float margin, float width, float height) {
    using Side = OverlayBatch::Label::Side;
    std::vector<std::optional<LabelRect>> out(spots.size());
    std::vector<LabelRect> taken;
    taken.reserve(spots.size());
    for (std::size_t i = 0; i < spots.size(); ++i) {
        if (spots[i].fixed) {
            out[i] = spots[i].box;
            taken.push_back(spots[i].box);
        }
    }
    for (std::size_t i = 0; i < spots.size(); ++i) {
        if (spots[i].fixed) {
            continue;
        }
        const LabelRect& p = spots[i].box;
        // Across to the point's other side: a Right label's box ends `gap` left of the point.
        std::vector<float> across{0.0f};
        if (spots[i].side == Side::Right) {
            across.push_back(-(p.w + 2 * gap));
        } else if (spots[i].side == Side::Left) {
            across.push_back(p.w + 2 * gap);
        } else {
            across.push_back(-(0.5f * p.w + gap));
            across.push_back(0.5f * p.w + gap);
        }
        const float row = p.h + margin;
        for (const float dx : across) {
            for (const float dy : {0.0f, -row, row, -2 * row, 2 * row}) {
                const LabelRect c{p.x + dx, p.y + dy, p.w, p.h};
                if (out[i] || !inside(c, width, height)) {
                    continue;
                }
                bool free = true;
                for (const LabelRect& t : taken) {
                    free = free && !overlap(c, t, margin);
                }
                if (free) {
                    out[i] = c;
                    taken.push_back(c);
                }
            }
        }
    }
    return out;
}

}  // namespace meshedit
