#pragma once
/// \file
/// The random operation sweep (geometry-central's HalfedgeMutationSuite, at scale): random
/// flips, splits and collapses on a mesh, with validate() after every op and after every
/// garbage collection, exact element-count deltas and the Euler characteristic after every
/// success, and a bit-for-bit unchanged mesh after every refusal. Used by the op sweep tests
/// and the long soak.

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <string_view>

#include "core/op_test_util.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/validate.h"
#include "support/fixtures.h"

namespace meshedit::test {

struct Counts {
    long v, e, f;
    explicit Counts(const Mesh& m)
        : v(static_cast<long>(m.n_vertices())),
          e(static_cast<long>(m.n_edges())),
          f(static_cast<long>(m.n_faces())) {}
};

struct Tally {
    long ops = 0;
    long applied[3] = {0, 0, 0};
    long refused[3] = {0, 0, 0};
};

enum Op { kFlip, kSplit, kCollapse };

// Runs one op on a live edge and checks its contract; returns false on a failed assertion.
inline ::testing::AssertionResult run_op(Mesh& mesh, Op op, Edge e, Tally& tally) {
    const Counts before(mesh);
    const bool boundary = mesh.is_boundary(e);
    const OpStatus ok = op == kFlip    ? is_flip_ok(mesh, e)
                        : op == kSplit ? is_split_ok(mesh, e)
                                       : is_collapse_ok(mesh, e);
    if (!ok) {
        const Mesh snapshot = mesh;
        std::string_view reason;
        bool done = false;
        if (op == kFlip) {
            const auto r = flip(mesh, e);
            done = r.ok(), reason = r.reason();
        } else if (op == kSplit) {
            const auto r = split(mesh, e);
            done = r.ok(), reason = r.reason();
        } else {
            const auto r = collapse(mesh, e);
            done = r.ok(), reason = r.reason();
        }
        ++tally.refused[op];
        if (done || reason != ok.reason()) {
            return ::testing::AssertionFailure() << "op disagrees with its predicate";
        }
        return test::identical(mesh, snapshot);
    }
    ++tally.applied[op];
    long dv = 0, de = 0, df = 0;
    if (op == kFlip) {
        const auto r = flip(mesh, e);
        if (!r || *r != e) {
            return ::testing::AssertionFailure() << "flip failed after its predicate passed";
        }
    } else if (op == kSplit) {
        const auto r = split(mesh, e);
        if (!r || Mesh::edge(mesh.halfedge(*r)) != e) {
            return ::testing::AssertionFailure() << "split failed or lost its documented halfedge";
        }
        dv = 1, de = boundary ? 2 : 3, df = boundary ? 1 : 2;
    } else {
        const Vertex v0 = mesh.vertex(e, 0), v1 = mesh.vertex(e, 1);
        const auto r = collapse(mesh, e);
        if (!r || *r != std::min(v0, v1)) {
            return ::testing::AssertionFailure() << "collapse failed or kept the wrong vertex";
        }
        dv = -1, de = boundary ? -2 : -3, df = boundary ? -1 : -2;
    }
    const Counts after(mesh);
    if (after.v - before.v != dv || after.e - before.e != de || after.f - before.f != df) {
        return ::testing::AssertionFailure() << "element counts changed wrongly";
    }
    return ::testing::AssertionSuccess();
}

// Random ops on one mesh. The mix leans towards splits while the mesh is smaller than it
// started and towards collapses while it is larger; leaving [F/4, 4F] restarts from the shape.
// validate() runs after every op (O(n): on big meshes the op count is kept small).
inline void sweep(const NamedMesh& shape, unsigned seed, long n_ops, Tally& tally) {
    SCOPED_TRACE(shape.name + ", seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    Mesh mesh = shape.mesh;
    const std::size_t f0 = shape.mesh.n_faces();
    const long chi = test::euler(mesh);
    for (long k = 0; k < n_ops; ++k) {
        if (mesh.n_faces() > 4 * f0 || 4 * mesh.n_faces() < f0) {
            mesh = shape.mesh;
        }
        const bool small = mesh.n_faces() < f0;
        std::discrete_distribution<int> mix(small ? std::initializer_list<double>{3, 4, 2}
                                                  : std::initializer_list<double>{3, 2, 4});
        const Op op = static_cast<Op>(mix(rng));
        std::uniform_int_distribution<std::uint32_t> pick(
            0, static_cast<std::uint32_t>(mesh.edges_size() - 1));
        Edge e(pick(rng));
        while (mesh.is_deleted(e)) {
            e = Edge(pick(rng));
        }
        ++tally.ops;
        ASSERT_TRUE(run_op(mesh, op, e, tally)) << "op " << op << " on edge " << e.idx();
        ASSERT_VALID(mesh) << "after op " << op << " on edge " << e.idx() << ", step " << k;
        ASSERT_EQ(test::euler(mesh), chi);
        if (k % 97 == 0) {
            mesh.garbage_collection();
            ASSERT_VALID(mesh) << "after garbage collection";
        }
    }
}

}  // namespace meshedit::test
