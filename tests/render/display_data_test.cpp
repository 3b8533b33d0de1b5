// DisplayData, the one owner of what the window and meshedit-render derive from a document:
// each part is recomputed when a change makes it stale and kept otherwise, and the picking
// tree follows a recorded change in the time of what it touched.

#include <gtest/gtest.h>

#include <cmath>

#include "meshedit/core/attributes.h"
#include "meshedit/core/fields.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/core/shapes.h"
#include "meshedit/overlay/display_data.h"

namespace meshedit {
namespace {

std::size_t lines(const OverlayBatch& batch) {
    return batch.lines.size();
}

TEST(DisplayData, FeaturesAreKeptUntilAChangeMakesThemStale) {
    Mesh mesh = shapes::grid(2, 2);  // a square of 4 quads: 8 boundary edges
    DisplayData display;
    const std::size_t boundary = lines(display.features(mesh, true, true));
    EXPECT_EQ(boundary, 8u);
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    for (const Edge e : mesh.edges()) {
        if (!mesh.is_boundary(e)) {
            crease[e] = 1;
            break;
        }
    }
    EXPECT_EQ(lines(display.features(mesh, true, true)), boundary);  // not told: kept
    display.follow(mesh, {.features = true});
    EXPECT_EQ(lines(display.features(mesh, true, true)), boundary + 1);
    EXPECT_EQ(lines(display.features(mesh, false, true)), 0u);  // edges left out
}

TEST(DisplayData, TheFieldIsRecomputedOnlyWhenItsInputsChange) {
    Mesh mesh = shapes::icosphere(1);
    DisplayData display;
    FieldRequest request;
    request.info = find_field("valence");
    ASSERT_NE(request.info, nullptr);
    bool recomputed = false;
    display.field(mesh, request, &recomputed);
    EXPECT_TRUE(recomputed);
    recomputed = false;
    display.field(mesh, request, &recomputed);
    EXPECT_FALSE(recomputed);  // a click, a hover: nothing to do
    request.clip = 0.2f;
    display.field(mesh, request, &recomputed);
    EXPECT_TRUE(recomputed);
    recomputed = false;
    ASSERT_TRUE(split(mesh, Edge(0)));
    display.follow(mesh, {.mesh = true});
    const FieldDisplay& field = display.field(mesh, request, &recomputed);
    EXPECT_TRUE(recomputed);
    EXPECT_EQ(field.values.size(), mesh.vertices_size());
    request.info = nullptr;
    EXPECT_EQ(display.field(mesh, request).info, nullptr);
}

// `tree` and `fresh` meet the same first triangle at the same t along `rays` rays from the
// centre of `mesh`, spread over the sphere.
void expect_same_hits(const FaceBvh& tree, const FaceBvh& fresh, const Mesh& mesh, int rays) {
    for (int i = 0; i < rays; ++i) {
        const double a = 0.1 * i, b = 0.37 * i;
        const FaceBvh::Ray ray{{0, 0, 0},
                               {std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)}};
        const auto x = tree.intersect(mesh, ray);
        const auto y = fresh.intersect(mesh, ray);
        ASSERT_EQ(x.has_value(), y.has_value());
        if (x) {
            EXPECT_EQ(x->face, y->face);
            EXPECT_EQ(x->t, y->t);
        }
    }
}

// The tree follows a recorded flip and answers as a tree built afresh.
TEST(DisplayData, ThePickingTreeFollowsARecordedChange) {
    Mesh mesh = shapes::icosphere(2);
    DisplayData display;
    display.picking_tree(mesh, 1);
    MeshRecorder recorder(mesh);
    ASSERT_TRUE(flip(mesh, Edge(7)));
    const MeshChange change = recorder.finish();
    const MeshChange::Region region = change.region();
    DisplayData::Change followed;
    followed.mesh = true;
    followed.region = &region;
    followed.before = 1;
    followed.after = 2;
    display.follow(mesh, followed);
    FaceBvh fresh;
    fresh.build(mesh);
    const FaceBvh& tree = display.picking_tree(mesh, 2);
    expect_same_hits(tree, fresh, mesh, 200);
}

// A tree built ahead on the worker answers as one built when first asked, and is taken, not
// built again, by the pick at its revision; one for another revision is built afresh.
TEST(DisplayData, ThePrebuiltTreeIsTheTreeOfItsRevision) {
    const Mesh mesh = shapes::icosphere(4);
    DisplayData display;
    display.prebuild(mesh, 5);
    display.settle();
    const FaceBvh fresh(mesh);
    const FaceBvh& tree = display.picking_tree(mesh, 5);
    EXPECT_EQ(tree.tree_size(), fresh.tree_size());
    EXPECT_EQ(tree.rebuilds(), 0u);
    expect_same_hits(tree, fresh, mesh, 100);
    // picking_tree() waits for a build under way itself.
    const Mesh small = shapes::icosphere(1);
    display.prebuild(small, 6);
    EXPECT_EQ(display.picking_tree(small, 6).tree_size(), small.n_faces());
    EXPECT_EQ(display.picking_tree(mesh, 7).tree_size(), mesh.n_faces());
}

}  // namespace
}  // namespace meshedit
