// Loop one phase at a time: the four phases are the classic Loop exactly (the same mesh, bit
// for bit) and L's mesh (the same positions bit for bit, the same faces); each phase does what it
// says and no more; the mesh stays valid after every phase; refusals name their reason and change
// nothing.

#include <gtest/gtest.h>

#include "core/subdivision_test_util.h"
#include "meshedit/core/loop_steps.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using test::creased_cube;

std::vector<test::NamedMesh> teaching_meshes() {
    std::vector<test::NamedMesh> meshes;
    meshes.push_back({"cube", shapes::cube()});
    meshes.push_back({"icosahedron", shapes::icosahedron()});
    meshes.push_back({"torus", shapes::torus(5, 4)});
    meshes.push_back({"creased cube", creased_cube()});
    meshes.push_back({"open disk", shapes::disk(6)});
    meshes.push_back({"open grid", shapes::grid(3, 2)});
    return meshes;
}

TEST(LoopSteps, FourPhasesAreTheClassicLoopAndLBitForBit) {
    for (const auto& [name, input] : teaching_meshes()) {
        SCOPED_TRACE(name);
        for (const LoopWeights w : {LoopWeights::Warren, LoopWeights::Loop}) {
            LoopOptions options;
            options.weights = w;
            Mesh phased = input;
            for (int phase = 1; phase <= 4; ++phase) {
                ASSERT_EQ(next_loop_phase(phased), phase);
                ASSERT_EQ(check_loop_step(phased), "");
                EXPECT_EQ(loop_step(phased, options).phase, phase);
                ASSERT_VALID(phased);
            }
            EXPECT_EQ(next_loop_phase(phased), 1) << "finished: the next press starts again";
            Mesh classic = input;
            loop_subdivide_classic(classic, options);
            EXPECT_TRUE(test::identical(phased, classic));
            // L (the fast path): the same vertices, bit for bit (both sum each one-ring
            // clockwise from the anchor), the same faces and creases; only the numbering of
            // edges and faces differs.
            Mesh fast = input;
            loop_subdivide(fast, options);
            ASSERT_EQ(fast.n_vertices(), phased.n_vertices());
            for (Vertex v : fast.vertices()) {
                ASSERT_EQ(fast.position(v), phased.position(v)) << "vertex " << v.idx();
            }
            EXPECT_EQ(test::canonical_faces(fast), test::canonical_faces(phased));
            EXPECT_EQ(test::crease_pairs(fast), test::crease_pairs(phased));
        }
    }
}

TEST(LoopSteps, EachPhaseDoesWhatItSays) {
    Mesh mesh = shapes::cube();  // 8 vertices, 18 edges, 12 triangles
    const Mesh input = mesh;
    const LoopStepReport positions = loop_step(mesh);
    EXPECT_EQ(positions.count, 8u);
    EXPECT_EQ(positions.message,
              "Loop 1/4: computed the new position of 8 vertices and 18 edge points (nothing "
              "moved yet)");
    EXPECT_EQ(mesh.position_vector(), input.position_vector()) << "nothing moves in phase 1";
    EXPECT_EQ(test::canonical_faces(mesh), test::canonical_faces(input));

    const LoopStepReport split = loop_step(mesh);
    EXPECT_EQ(split.message, "Loop 2/4: split 18 edges");
    EXPECT_EQ(mesh.n_vertices(), 26u);
    EXPECT_EQ(mesh.n_faces(), 48u) << "each split divides the two triangles beside it: 12 + 2·18";
    EXPECT_FALSE(mesh.has_property<Edge>(kLoopEdgePoint)) << "the edge points became vertices";

    const LoopStepReport flip = loop_step(mesh);
    EXPECT_EQ(flip.message, "Loop 3/4: flipped 12 new edges that join an old and a new vertex");
    EXPECT_EQ(mesh.n_faces(), 48u) << "flips turn edges, they add no faces";
    const auto flipped = mesh.get_property<Edge, std::uint8_t>(kLoopFlippedEdge);
    const auto is_new = mesh.get_property<Vertex, std::uint8_t>(kLoopNewVertex);
    ASSERT_TRUE(flipped && is_new);
    for (Edge e : mesh.edges()) {
        if (flipped[e] != 0) {
            EXPECT_TRUE(is_new[mesh.vertex(e, 0)] != 0 && is_new[mesh.vertex(e, 1)] != 0)
                << "a flipped edge joins two new vertices";
        }
    }

    const LoopStepReport move = loop_step(mesh);
    EXPECT_EQ(move.message, "Loop 4/4: moved 26 vertices to their new positions");
    for (const char* name : {kLoopTarget, kLoopHasTarget, kLoopNewVertex}) {
        EXPECT_FALSE(mesh.has_property<Vertex>(name)) << name;
    }
    for (const char* name : {kLoopNewEdge, kLoopFlippedEdge, kLoopEdgePoint}) {
        EXPECT_FALSE(mesh.has_property<Edge>(name)) << name;
    }
}

TEST(LoopSteps, PolygonsAndPillowsAreRefusedAtTheFirstPhase) {
    const Mesh quads = shapes::quad_sphere(1);
    EXPECT_EQ(check_loop_step(quads),
              "cannot step Loop: the phases are shown on triangles (Ctrl+T or triangulate "
              "first)");
    Mesh half = shapes::cube();
    loop_step(half);
    EXPECT_EQ(check_loop_step(half), "") << "later phases always run";
}

}  // namespace
}  // namespace meshedit
