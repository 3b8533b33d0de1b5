// Invariant sweep (geometry-central's HalfedgeMutationSuite, at scale): random flips, splits
// and collapses on every corpus mesh, with validate() after every op and after every garbage
// collection, exact element-count deltas and the Euler characteristic after every success,
// and a bit-for-bit unchanged mesh after every refusal.

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string_view>

#include "core/op_sweep.h"
#include "core/op_test_util.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/validate.h"

namespace meshedit {
namespace {

using test::sweep;
using test::Tally;

// The three triangle operations the first sweeps were written for.
constexpr std::string_view kTriangleOps[] = {"flip", "split", "collapse"};

// is_flip_ok() and is_split_ok() written plainly: whole faces through is_triangle(face), the
// a-d search through find_halfedge() from halfedge(a), a face's corners by its circulator.
// The optimised predicates (which start from the edge's own halfedges) must refuse exactly
// the same edges for the same reasons.
bool has_corner(const Mesh& mesh, Face f, Vertex v) {
    for (const Vertex w : mesh.vertices(f)) {
        if (w == v) {
            return true;
        }
    }
    return false;
}

std::string_view reference_flip_refusal(const Mesh& mesh, Edge e) {
    if (mesh.is_deleted(e)) {
        return "cannot flip: the edge is deleted";
    }
    if (mesh.is_boundary(e)) {
        return "cannot flip: boundary edge";
    }
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge t0 = Mesh::halfedge(e, 1);
    const Vertex a = mesh.to_vertex(mesh.next(h0));
    const Vertex d = mesh.to_vertex(mesh.next(t0));
    if (a == d) {
        return "cannot flip: the new edge already exists";
    }
    // A polygon beside e gains a corner it may already have (triangles: only when a == d).
    if (has_corner(mesh, mesh.face(h0), d) || has_corner(mesh, mesh.face(t0), a)) {
        return "cannot flip: a face would visit a vertex twice";
    }
    if (mesh.find_halfedge(a, d).is_valid()) {
        return "cannot flip: the new edge already exists";
    }
    return {};
}

std::string_view reference_split_refusal(const Mesh& mesh, Edge e) {
    if (mesh.is_deleted(e)) {
        return "cannot split: the edge is deleted";
    }
    const Face f0 = mesh.face(e, 0);
    const Face f1 = mesh.face(e, 1);
    if (!f0.is_valid() && !f1.is_valid()) {
        return "cannot split: the edge has no face";
    }
    if (f0.is_valid() && f1.is_valid() && mesh.is_triangle(f0) && mesh.is_triangle(f1) &&
        mesh.to_vertex(mesh.next(Mesh::halfedge(e, 0))) ==
            mesh.to_vertex(mesh.next(Mesh::halfedge(e, 1)))) {
        return "cannot split: the new edges would coincide";
    }
    return {};
}

::testing::AssertionResult predicates_match_reference(const Mesh& mesh) {
    for (std::uint32_t i = 0; i < mesh.edges_size(); ++i) {
        const Edge e(i);
        if (is_flip_ok(mesh, e).reason() != reference_flip_refusal(mesh, e)) {
            return ::testing::AssertionFailure() << "is_flip_ok differs on edge " << i;
        }
        if (is_split_ok(mesh, e).reason() != reference_split_refusal(mesh, e)) {
            return ::testing::AssertionFailure() << "is_split_ok differs on edge " << i;
        }
    }
    return ::testing::AssertionSuccess();
}

// Every edge, deleted ones included, of meshes with a wide range of valences (fans of 3 to
// 12 triangles; random flips, splits and collapses of the corpus, which also adds polygons'
// neighbours, boundaries and tombstones).
TEST(OpSweep, PredicatesMatchReference) {
    for (int n = 3; n <= 12; ++n) {
        EXPECT_TRUE(predicates_match_reference(test::one_ring(n))) << "one_ring " << n;
    }
    auto corpus = test::sweep_corpus();
    corpus.push_back({"quad grid", test::mesh_from_faces(
                                       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0.5, 0}},
                                       {{0, 1, 2, 3}, {0, 3, 4}})});
    for (const auto& shape : test::pillow_family()) {
        corpus.push_back(shape);
    }
    for (const auto& shape : corpus) {
        SCOPED_TRACE(shape.name);
        std::mt19937 rng(17);
        Mesh mesh = shape.mesh;
        for (int k = 0; k < 300; ++k) {
            ASSERT_TRUE(predicates_match_reference(mesh)) << "step " << k;
            std::uniform_int_distribution<std::uint32_t> pick(
                0, static_cast<std::uint32_t>(mesh.edges_size() - 1));
            const Edge e(pick(rng));
            switch (k % 3) {
                case 0:
                    flip(mesh, e);
                    break;
                case 1:
                    split(mesh, e);
                    break;
                default:
                    if (mesh.n_faces() > shape.mesh.n_faces() / 2) {
                        collapse(mesh, e);
                    }
            }
        }
    }
}

TEST(OpSweep, RandomOpsOnCorpus) {
    const auto corpus = test::sweep_corpus();
    ASSERT_GE(corpus.size(), 5u);
    constexpr long kOpsPerRun = 6500;
    Tally tally;
    for (const auto& shape : corpus) {
        for (unsigned seed : {1u, 2u}) {
            sweep(shape, seed * 7919u + static_cast<unsigned>(shape.name.size()), kOpsPerRun,
                  tally);
            if (HasFatalFailure()) {
                return;
            }
        }
    }
    EXPECT_GE(tally.ops, 100000);
    // Each op succeeds in at least a tenth of its share of the mix, so that the sweep means
    // something for it, and the ops that can be refused on these meshes are refused often.
    double total_weight = 0;
    for (const test::SweepOp& op : test::sweep_ops()) {
        total_weight += op.weight;
    }
    for (std::size_t k = 0; k < test::sweep_ops().size(); ++k) {
        const double share = test::sweep_ops()[k].weight / total_weight;
        EXPECT_GT(static_cast<double>(tally.applied[k]),
                  share * static_cast<double>(tally.ops) / 10)
            << test::sweep_ops()[k].name;
        RecordProperty(std::string(test::sweep_ops()[k].name), std::to_string(tally.applied[k]));
    }
    EXPECT_GT(tally.refused_of("flip"), tally.ops / 100);
    EXPECT_GT(tally.refused_of("collapse"), tally.ops / 100);
    RecordProperty("ops", std::to_string(tally.ops));
}

// Only flips, splits and collapses: on triangle meshes these three must keep succeeding,
// with no polygon to refuse them.
TEST(OpSweep, TriangleOpsOnCorpus) {
    Tally tally;
    for (const auto& shape : test::sweep_corpus()) {
        sweep(shape, 5u, 4000, tally, kTriangleOps);
        if (HasFatalFailure()) {
            return;
        }
    }
    for (const std::string_view op : kTriangleOps) {
        EXPECT_GT(tally.applied_of(op), tally.ops / 20) << op;
    }
}

// The meshes at the edge of what the operations accept (pillows, a valence-2 interior
// vertex, faces sharing two edges, lone triangles): every op either works and leaves a valid
// mesh or is refused and changes nothing. Most ops are refused here; no ratio is asked.
TEST(OpSweep, RandomOpsOnPillowFamily) {
    Tally tally;
    for (const auto& shape : test::pillow_family()) {
        for (unsigned seed : {3u, 4u, 5u}) {
            sweep(shape, seed, 2000, tally);
            if (HasFatalFailure()) {
                return;
            }
        }
    }
    EXPECT_GT(tally.applied_of("split"), 0);
    EXPECT_GT(tally.refused_of("flip") + tally.refused_of("collapse"), 0);
}

// A doubled edge linked by hand (build_mesh never makes one): no op may turn it into a
// self-loop or any other broken link; whatever the op does, the only invariant still broken
// afterwards may be the doubled edge itself.
TEST(OpSweep, OpsNeverCorruptAMeshWithADoubledEdge) {
    const Mesh slit = test::slit_pillow();
    for (const test::SweepOp& op : test::sweep_ops()) {
        const auto n = static_cast<std::uint32_t>(test::element_count(slit, op.target));
        for (std::uint32_t i = 0; i < n; ++i) {
            Mesh mesh = slit;
            std::string wrong;
            const bool done = op.run(mesh, i, wrong).empty();
            const auto error = validate(mesh);
            if (!done) {
                EXPECT_TRUE(test::identical(mesh, slit)) << op.name << " on element " << i;
            }
            if (error) {
                EXPECT_EQ(error->invariant, "multi-edge")
                    << op.name << " on element " << i << ": " << error->message;
            }
        }
    }
}

// Meshes of 5,000 to 40,000 faces: long valence chains, big boundaries, many GCs. validate()
// is O(n) per op; unoptimised sanitizer builds run a tenth of the ops.
TEST(OpSweep, RandomOpsOnBigMeshes) {
#ifdef NDEBUG
    constexpr long kOpsPerMesh = 1500;
#else
    constexpr long kOpsPerMesh = 150;
#endif
    Tally tally;
    for (const auto& shape : test::big_corpus()) {
        sweep(shape, 11u, kOpsPerMesh, tally);
        if (HasFatalFailure()) {
            return;
        }
    }
    for (const std::string_view op : kTriangleOps) {
        EXPECT_GT(tally.applied_of(op), tally.ops / 40) << op;
    }
}

}  // namespace
}  // namespace meshedit
