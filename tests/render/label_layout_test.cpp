// Labels without overlaps (label_layout.h): a free label keeps its place, a crowd moves up
// and down and across, none covers another, and what finds no place near its point is left
// out rather than drawn far away.

#include "meshedit/overlay/label_layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <vector>
#include "meshedit/core/face_bvh.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

using Side = OverlayBatch::Label::Side;

bool overlap(const LabelRect& a, const LabelRect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

TEST(LabelLayout, AFreeLabelKeepsItsPlace) {
    const std::vector<LabelSpot> spots{{{10, 10, 30, 12}, Side::Right},
                                       {{100, 50, 30, 12}, Side::Left}};
    const auto placed = place_labels(spots, 4, 1, 200, 100);
    ASSERT_TRUE(placed[0] && placed[1]);
    EXPECT_EQ(placed[0]->x, 10);
    EXPECT_EQ(placed[0]->y, 10);
    EXPECT_EQ(placed[1]->x, 100);
    EXPECT_EQ(placed[1]->y, 50);
}

TEST(LabelLayout, ACrowdAtOnePointSpreadsWithoutOverlapsAndTheRestIsLeftOut) {
    // Twenty labels that would all sit on one spot (a dense diagram's corner).
    const std::vector<LabelSpot> spots(20, LabelSpot{{100, 100, 40, 12}, Side::Right});
    const auto placed = place_labels(spots, 4, 1, 400, 300);
    std::vector<LabelRect> shown;
    for (const auto& p : placed) {
        if (p) {
            shown.push_back(*p);
        }
    }
    // Five rows on the right and five on the left (the box moved across the point).
    EXPECT_EQ(shown.size(), 10u);
    EXPECT_TRUE(placed[0] && placed[0]->x == 100 && placed[0]->y == 100) << "the first stays";
    for (std::size_t i = 0; i < shown.size(); ++i) {
        for (std::size_t j = i + 1; j < shown.size(); ++j) {
            EXPECT_FALSE(overlap(shown[i], shown[j])) << i << " " << j;
        }
        // Near its point: within two rows up or down, on either side.
        EXPECT_LE(std::abs(shown[i].y - 100), 2 * 13 + 1e-3);
    }
}

TEST(LabelLayout, LabelsStayInsideTheImage) {
    // At the right edge the box goes to the point's left; at the bottom, a row up.
    const std::vector<LabelSpot> spots{{{190, 40, 30, 12}, Side::Right},
                                       {{50, 95, 30, 12}, Side::Centre}};
    const auto placed = place_labels(spots, 4, 1, 200, 100);
    ASSERT_TRUE(placed[0] && placed[1]);
    EXPECT_EQ(placed[0]->x, 190 - 38);
    EXPECT_EQ(placed[1]->y, 95 - 13);
    for (const auto& p : placed) {
        EXPECT_GE(p->x, 0);
        EXPECT_LE(p->x + p->w, 200);
        EXPECT_LE(p->y + p->h, 100);
    }
}

TEST(LabelLayout, FixedLabelsStayAndTheOthersMakeRoom) {
    // A title where a name would go: the title keeps its box even though it comes second,
    // and the name moves; rows of a list stay even where they touch.
    const std::vector<LabelSpot> spots{{{50, 20, 40, 12}, Side::Right},
                                       {{40, 20, 80, 12}, Side::Centre, true},
                                       {{10, 60, 60, 13}, Side::Right, true},
                                       {{10, 72, 60, 13}, Side::Right, true}};
    const auto placed = place_labels(spots, 4, 0, 200, 100);
    ASSERT_TRUE(placed[1] && placed[2] && placed[3]);
    EXPECT_EQ(placed[1]->x, 40);
    EXPECT_EQ(placed[1]->y, 20);
    EXPECT_EQ(placed[3]->y, 72);
    ASSERT_TRUE(placed[0]);
    EXPECT_FALSE(overlap(*placed[0], *placed[1]));
    EXPECT_EQ(placed[0]->x, 50);
}

}  // namespace
// Labels the surface hides from the eye are marked and moved after the others: on the cube
// seen from +z, a front corner's label stays, a back corner's is hidden, a point in front of
// the cube stays, and a fixed label (a title) is never hidden.
TEST(LabelLayout, LabelsBehindTheSurfaceAreMarkedAndPlacedLast) {
    const Mesh cube = shapes::cube();  // corners at ±1
    const FaceBvh tree(cube);
    std::vector<OverlayBatch::Label> labels = {
        {Vec3(1, 1, -1), "back", {}, OverlayBatch::Label::Side::Right, false},
        {Vec3(1, 1, 1), "front", {}, OverlayBatch::Label::Side::Right, false},
        {Vec3(0, 0, 0), "inside", {}, OverlayBatch::Label::Side::Right, false},
        {Vec3(0, 0, 3), "outside", {}, OverlayBatch::Label::Side::Right, false},
        {Vec3(-1, -1, -1), "title", {}, OverlayBatch::Label::Side::Right, true},
    };
    hide_labels_behind(labels, Vec3(0.3, 0.2, 10), cube, tree);
    std::vector<std::string> order;
    for (const OverlayBatch::Label& label : labels) {
        order.push_back(label.text + (label.hidden ? " (hidden)" : ""));
    }
    EXPECT_EQ(order, (std::vector<std::string>{"front", "outside", "title", "back (hidden)",
                                               "inside (hidden)"}));
}

}  // namespace meshedit
