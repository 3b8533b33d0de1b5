#pragma once
/// \file
/// Where overlay labels go so that no two cover each other (the viewer's ImGui labels and
/// meshedit-render's, render/labels.h, both through this): each label, in order, takes the
/// first free place among its preferred one and a few near it; a label with no free place
/// near its point is left out, as a label far from its point would name the wrong element.

#include <optional>
#include <span>
#include <vector>

#include "meshedit/core/face_bvh.h"
#include "meshedit/overlay/overlay.h"

namespace meshedit {

/// Marks the labels whose point the surface of `mesh` hides from `eye` (the segment from the
/// eye meets a triangle of `tree` before 99.9% of the way, so a label on the surface facing
/// the eye stays shown) and moves them after the others, keeping each group's order: the
/// visible ones get their places first. Fixed labels are never hidden.
void hide_labels_behind(std::vector<OverlayBatch::Label>& labels, const Vec3& eye, const Mesh& mesh,
                        const FaceBvh& tree);

/// A label's box in pixels (top-left corner, size; y grows downward).
struct LabelRect {
    float x = 0, y = 0, w = 0, h = 0;
};

/// A label to place: the box where it would be drawn alone, where it sits beside its point,
/// and whether it is fixed (OverlayBatch::Label::fixed).
struct LabelSpot {
    LabelRect box;
    OverlayBatch::Label::Side side = OverlayBatch::Label::Side::Right;
    bool fixed = false;
};

/// For each label the box it gets. Fixed ones keep theirs. Each other one, in order, takes
/// its preferred box if free, else the first free of it moved one or two rows up or down,
/// then the same on the point's other side (a Centre label: left and right of it), keeping
/// `gap` from the point. Free means clear of every box taken so far by `margin` pixels
/// (negative: their padding may touch by that much, as rows of a list do) and inside the
/// `width` × `height` image. nullopt: no free place. O(n²) for n labels (tens in practice).
std::vector<std::optional<LabelRect>> place_labels(std::span<const LabelSpot> spots, float gap,
                                                   float margin, float width, float height);

}  // namespace meshedit
