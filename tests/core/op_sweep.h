#pragma once
/// \file
/// The random operation sweep (geometry-central's HalfedgeMutationSuite, at scale): random
/// local operations on random elements of a mesh, with validate() after every op and after
/// every garbage collection, the op's documented result, exact element-count deltas and so
/// the Euler characteristic after every success, and a bit-for-bit unchanged mesh after every
/// refusal. Used by the op sweep tests and the long soak. An operation joins the sweep with
/// one row in sweep_ops().

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/op_test_util.h"
#include "meshedit/core/element_ref.h"
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
    Counts(long v_, long e_, long f_) : v(v_), e(e_), f(f_) {}
};

/// The kind of element an operation acts on; None for an operation on the whole mesh.
using Target = ElementRef::Kind;

/// One operation of the sweep.
struct SweepOp {
    std::string_view name;
    Target target;
    /// 1 if it adds elements, -1 if it removes them, 0 if neither: the sweep leans towards
    /// growing ops while the mesh is smaller than it started, and towards shrinking ones
    /// while it is larger.
    int grows;
    double weight;
    OpStatus (*check)(const Mesh&, std::uint32_t);
    /// Runs the op on element `i`: its refusal reason, or empty after a success whose
    /// documented result was checked (`wrong` says what was not as documented).
    std::string_view (*run)(Mesh&, std::uint32_t i, std::string& wrong);
    /// The change of V, E and F that a success makes, read from the mesh before it.
    Counts (*delta)(const Mesh&, std::uint32_t i);
};

// How many of the two sides of `e` are triangles (not polygons, not boundary gaps): those
// split() divides and collapse() removes.
inline long triangles_beside(const Mesh& m, Edge e) {
    long triangles = 0;
    for (unsigned k = 0; k < 2; ++k) {
        const Halfedge h = Mesh::halfedge(e, k);
        triangles += !m.is_boundary(h) && m.is_triangle(m.face(h)) ? 1 : 0;
    }
    return triangles;
}

inline Counts no_change(const Mesh&, std::uint32_t) {
    return {0, 0, 0};
}

// make_boundary(f): f goes, so do its sides already on the boundary and the corners both of
// whose sides go.
inline Counts make_boundary_delta(const Mesh& m, std::uint32_t i) {
    long edges = 0, vertices = 0;
    for (const Halfedge h : m.halfedges(Face(i))) {
        const bool goes = m.is_boundary(Mesh::twin(h));
        edges += goes ? 1 : 0;
        vertices += goes && m.is_boundary(Mesh::twin(m.next(h))) ? 1 : 0;
    }
    return {-vertices, -edges, -1};
}

// The first boundary edge from index i on, for the ops that need one (weld, fill_hole), so
// that the sweep applies them often enough; on a closed mesh edge i itself, which they refuse.
inline Edge first_boundary_edge(const Mesh& m, std::uint32_t i) {
    const std::size_t n = m.edges_size();
    for (std::size_t k = 0; k < n; ++k) {
        const Edge e(static_cast<std::uint32_t>((i + k) % n));
        if (!m.is_deleted(e) && m.is_boundary(e)) {
            return e;
        }
    }
    return Edge(i);
}

// The second edge of a weld with `e1` (a boundary edge): for even indices the next edge along
// its boundary loop (the two meet at a vertex: a zip), for odd ones the first boundary edge
// from a scattered index on. `e1` itself when there is none.
inline Edge weld_partner(const Mesh& m, Edge e1) {
    if (!m.is_boundary(e1)) {
        return e1;
    }
    const Halfedge g1 =
        m.is_boundary(Mesh::halfedge(e1, 0)) ? Mesh::halfedge(e1, 0) : Mesh::halfedge(e1, 1);
    if (e1.idx() % 2 == 0) {
        return Mesh::edge(m.next(g1));
    }
    const std::size_t n = m.edges_size();
    for (std::size_t k = 0; k < n; ++k) {
        const Edge e(static_cast<std::uint32_t>((e1.idx() * 7919u + k) % n));
        if (e != e1 && !m.is_deleted(e) && m.is_boundary(e)) {
            return e;
        }
    }
    return e1;
}

// extrude and inset: a corner, a rung, an inner side and a quad per side of the face.
inline Counts ring_delta(const Mesh& m, std::uint32_t i) {
    const auto n = static_cast<long>(m.valence(Face(i)));
    return Counts{n, 2 * n, n};
}

// The boundary halfedge of `e`, or halfedge 0 of an interior edge.
inline Halfedge boundary_side(const Mesh& m, Edge e) {
    return m.is_boundary(Mesh::halfedge(e, 1)) ? Mesh::halfedge(e, 1) : Mesh::halfedge(e, 0);
}

// clang-format off
inline const SweepOp kSweepOps[] = {
    {"flip", Target::Edge, 0, 3,
     [](const Mesh& m, std::uint32_t i) { return is_flip_ok(m, Edge(i)); },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const auto r = flip(m, Edge(i));
         if (r && *r != Edge(i)) { wrong = "flip returned another edge"; }
         return r.reason();
     },
     no_change},
    {"split", Target::Edge, 1, 3,
     [](const Mesh& m, std::uint32_t i) { return is_split_ok(m, Edge(i)); },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const auto r = split(m, Edge(i));
         if (r && Mesh::edge(m.halfedge(*r)) != Edge(i)) {
             wrong = "split lost its documented halfedge";
         }
         return r.reason();
     },
     [](const Mesh& m, std::uint32_t i) {
         // One new edge along e, and one edge and one face per triangle beside it.
         const long triangles = triangles_beside(m, Edge(i));
         return Counts{1, 1 + triangles, triangles};
     }},
    {"collapse", Target::Edge, -1, 3,
     [](const Mesh& m, std::uint32_t i) { return is_collapse_ok(m, Edge(i)); },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const Vertex survivor = std::min(m.vertex(Edge(i), 0), m.vertex(Edge(i), 1));
         const auto r = collapse(m, Edge(i));
         if (r && *r != survivor) { wrong = "collapse kept the wrong vertex"; }
         return r.reason();
     },
     [](const Mesh& m, std::uint32_t i) {
         // The edge, and per triangle beside it the triangle and one of its other edges.
         const long triangles = triangles_beside(m, Edge(i));
         return Counts{-1, -1 - triangles, -triangles};
     }},
    {"bisect", Target::Edge, 1, 1,
     [](const Mesh& m, std::uint32_t i) { return is_bisect_ok(m, Edge(i)); },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const auto r = bisect(m, Edge(i));
         if (r && (Mesh::edge(m.halfedge(*r)) != Edge(i) || m.valence(*r) != 2)) {
             wrong = "bisect's vertex is not on the old edge with two edges";
         }
         return r.reason();
     },
     [](const Mesh&, std::uint32_t) { return Counts{1, 1, 0}; }},
    {"poke", Target::Face, 1, 1,
     [](const Mesh& m, std::uint32_t i) { return is_poke_ok(m, Face(i)); },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const Halfedge h = m.halfedge(Face(i));
         const std::size_t n = m.valence(Face(i));
         const auto r = poke(m, Face(i));
         if (r && (m.face(h) != Face(i) || m.valence(*r) != n)) {
             wrong = "poke did not keep f on its halfedge or join every corner";
         }
         return r.reason();
     },
     [](const Mesh& m, std::uint32_t i) {
         const auto n = static_cast<long>(m.valence(Face(i)));
         return Counts{1, n, n - 1};
     }},
    {"make_boundary", Target::Face, -1, 0.5,
     [](const Mesh& m, std::uint32_t i) { return is_make_boundary_ok(m, Face(i)); },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const auto r = make_boundary(m, Face(i));
         if (r && r.value().is_valid() && !m.is_boundary(*r)) {
             wrong = "make_boundary returned a halfedge off the boundary";
         }
         return r.reason();
     },
     make_boundary_delta},
    {"fill_hole", Target::Edge, 1, 0.5,
     [](const Mesh& m, std::uint32_t i) {
         return is_fill_hole_ok(m, boundary_side(m, first_boundary_edge(m, i)));
     },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const Halfedge h = boundary_side(m, first_boundary_edge(m, i));
         const auto r = fill_hole(m, h);
         if (r && m.face(h) != *r) {
             wrong = "fill_hole's face is not on the hole's halfedge";
         }
         return r.reason();
     },
     [](const Mesh&, std::uint32_t) { return Counts{0, 0, 1}; }},
    {"dissolve_edge", Target::Edge, -1, 1,
     [](const Mesh& m, std::uint32_t i) { return is_dissolve_edge_ok(m, Edge(i)); },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const Face kept = m.face(Mesh::halfedge(Edge(i), 0));
         const bool boundary = m.is_boundary(Edge(i));
         const auto r = dissolve_edge(m, Edge(i));
         if (r && !boundary && *r != kept) {
             wrong = "dissolve_edge kept the wrong face";
         }
         return r.reason();
     },
     [](const Mesh& m, std::uint32_t i) {
         const Halfedge h = Mesh::halfedge(Edge(i), 0);
         if (!m.is_boundary(Edge(i))) {
             return Counts{0, -1, -1};
         }
         return make_boundary_delta(m, m.face(m.is_boundary(h) ? Mesh::twin(h) : h).idx());
     }},
    {"dissolve_vertex", Target::Vertex, -1, 1,
     [](const Mesh& m, std::uint32_t i) { return is_dissolve_vertex_ok(m, Vertex(i)); },
     [](Mesh& m, std::uint32_t i, std::string&) -> std::string_view {
         return dissolve_vertex(m, Vertex(i)).reason();
     },
     [](const Mesh& m, std::uint32_t i) {
         const auto n = static_cast<long>(m.valence(Vertex(i)));
         return m.is_boundary(Vertex(i)) ? Counts{-1, -(n - 1), -(n - 2)}
                                         : Counts{-1, -n, -(n - 1)};
     }},
    {"weld", Target::Edge, -1, 1,
     [](const Mesh& m, std::uint32_t i) {
         const Edge e1 = first_boundary_edge(m, i);
         return is_weld_ok(m, e1, weld_partner(m, e1));
     },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const Edge e1 = first_boundary_edge(m, i);
         const auto r = weld(m, e1, weld_partner(m, e1));
         if (r && (*r != e1 || m.is_boundary(*r))) {
             wrong = "weld did not return e1 as an interior edge";
         }
         return r.reason();
     },
     [](const Mesh& m, std::uint32_t i) {
         // Two vertices merge into two, one less where the edges meet (a zip); e2 goes.
         const Edge e1 = first_boundary_edge(m, i);
         const Edge e2 = weld_partner(m, e1);
         long shared = 0;
         for (unsigned x = 0; x < 2; ++x) {
             for (unsigned y = 0; y < 2; ++y) {
                 shared += m.vertex(e1, x) == m.vertex(e2, y) ? 1 : 0;
             }
         }
         return Counts{-(2 - shared), -1, 0};
     }},
    {"extrude", Target::Face, 1, 0.5,
     [](const Mesh& m, std::uint32_t i) { return is_extrude_ok(m, Face(i), 0.1 * (i % 3), 0.25); },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const std::size_t n = m.valence(Face(i));
         const auto r = extrude_face(m, Face(i), 0.1 * (i % 3), 0.25);
         if (r && (*r != Face(i) || m.valence(*r) != n)) {
             wrong = "extrude did not keep f as the inner face";
         }
         return r.reason();
     },
     ring_delta},
    {"inset", Target::Face, 1, 0.5,
     [](const Mesh& m, std::uint32_t i) { return is_inset_ok(m, Face(i), 0.3); },
     [](Mesh& m, std::uint32_t i, std::string&) -> std::string_view {
         return inset_face(m, Face(i), 0.3).reason();
     },
     ring_delta},
    {"bevel_vertex", Target::Vertex, 1, 0.5,
     [](const Mesh& m, std::uint32_t i) { return is_bevel_vertex_ok(m, Vertex(i), 0.2); },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         const std::size_t n = m.valence(Vertex(i));
         const auto r = bevel_vertex(m, Vertex(i), 0.2);
         if (r && m.valence(*r) != n) {
             wrong = "bevel_vertex's face does not have a corner per edge";
         }
         return r.reason();
     },
     [](const Mesh& m, std::uint32_t i) {
         const auto n = static_cast<long>(m.valence(Vertex(i)));
         return Counts{n - 1, n, 1};
     }},
    {"bevel_edge", Target::Edge, 1, 0.5,
     [](const Mesh& m, std::uint32_t i) { return is_bevel_edge_ok(m, Edge(i), 0.2); },
     [](Mesh& m, std::uint32_t i, std::string&) -> std::string_view {
         return bevel_edge(m, Edge(i), 0.2).reason();
     },
     [](const Mesh& m, std::uint32_t i) {
         const auto n = static_cast<long>(m.valence(m.vertex(Edge(i), 0)) +
                                          m.valence(m.vertex(Edge(i), 1))) - 2;
         return Counts{n - 2, n - 1, 1};
     }},
    {"collapse_face", Target::Face, -1, 0.5,
     [](const Mesh& m, std::uint32_t i) { return is_collapse_face_ok(m, Face(i)); },
     [](Mesh& m, std::uint32_t i, std::string& wrong) -> std::string_view {
         Vertex smallest;
         for (const Vertex v : m.vertices(Face(i))) {
             smallest = smallest.is_valid() ? std::min(smallest, v) : v;
         }
         const auto r = collapse_face(m, Face(i));
         if (r && *r != smallest) {
             wrong = "collapse_face kept another corner than the smallest";
         }
         return r.reason();
     },
     [](const Mesh& m, std::uint32_t i) {
         // f's corners become one, its sides go, and so does each triangle across a side
         // with one more edge.
         long n = 0, triangles = 0;
         for (const Halfedge h : m.halfedges(Face(i))) {
             ++n;
             const Halfedge r = Mesh::twin(h);
             triangles += !m.is_boundary(r) && m.is_triangle(m.face(r)) ? 1 : 0;
         }
         return Counts{-(n - 1), -n - triangles, -1 - triangles};
     }},
    {"flip_orientation", Target::None, 0, 0.02,
     [](const Mesh&, std::uint32_t) { return OpStatus::ok(); },
     [](Mesh& m, std::uint32_t, std::string&) -> std::string_view {
         flip_orientation(m);
         return {};
     },
     no_change},
};
// clang-format on

inline std::span<const SweepOp> sweep_ops() {
    return kSweepOps;
}

/// The sweep's index of the op called `name`.
inline std::size_t op_index(std::string_view name) {
    for (std::size_t k = 0; k < sweep_ops().size(); ++k) {
        if (sweep_ops()[k].name == name) {
            return k;
        }
    }
    ADD_FAILURE() << "no sweep op " << name;
    return 0;
}

struct Tally {
    long ops = 0;
    std::vector<long> applied = std::vector<long>(sweep_ops().size(), 0);
    std::vector<long> refused = std::vector<long>(sweep_ops().size(), 0);
    long applied_of(std::string_view name) const { return applied[op_index(name)]; }
    long refused_of(std::string_view name) const { return refused[op_index(name)]; }
};

/// How many elements of `target`'s kind the arrays hold, deleted ones included (1 for the
/// whole mesh).
inline std::size_t element_count(const Mesh& mesh, Target target) {
    return target == Target::None ? 1 : elements_size(mesh, target);
}

inline bool is_deleted(const Mesh& mesh, Target target, std::uint32_t i) {
    return target != Target::None && !is_live(mesh, ElementRef{target, i});
}

/// Runs `op` on live element `i` and checks its contract.
inline ::testing::AssertionResult run_op(Mesh& mesh, const SweepOp& op, std::uint32_t i,
                                         Tally& tally) {
    const std::size_t k = static_cast<std::size_t>(&op - sweep_ops().data());
    const OpStatus ok = op.check(mesh, i);
    std::string wrong;
    if (!ok) {
        const Mesh snapshot = mesh;
        const std::string_view reason = op.run(mesh, i, wrong);
        ++tally.refused[k];
        if (reason != ok.reason()) {
            return ::testing::AssertionFailure() << op.name << " disagrees with its predicate: '"
                                                 << reason << "' vs '" << ok.reason() << "'";
        }
        return test::identical(mesh, snapshot);
    }
    ++tally.applied[k];
    const Counts before(mesh);
    const Counts delta = op.delta(mesh, i);
    const std::string_view reason = op.run(mesh, i, wrong);
    if (!reason.empty()) {
        return ::testing::AssertionFailure()
               << op.name << " refused after its predicate passed: " << reason;
    }
    if (!wrong.empty()) {
        return ::testing::AssertionFailure() << wrong;
    }
    const Counts after(mesh);
    if (after.v - before.v != delta.v || after.e - before.e != delta.e ||
        after.f - before.f != delta.f) {
        return ::testing::AssertionFailure()
               << op.name << " changed V/E/F by " << after.v - before.v << "/" << after.e - before.e
               << "/" << after.f - before.f << ", expected " << delta.v << "/" << delta.e << "/"
               << delta.f;
    }
    return ::testing::AssertionSuccess();
}

// Random ops on one mesh (`ops` restricts the mix to those names; empty: every op). The mix
// leans towards growing ops while the mesh is smaller than it started and towards shrinking
// ones while it is larger; leaving [F/4, 4F] faces or 4E edges restarts from the shape.
// validate() runs after every op (O(n): on big meshes the op count is kept small). The
// exact V/E/F deltas of run_op() fix each op's change of the Euler characteristic.
inline void sweep(const NamedMesh& shape, unsigned seed, long n_ops, Tally& tally,
                  std::span<const std::string_view> ops = {}) {
    SCOPED_TRACE(shape.name + ", seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    Mesh mesh = shape.mesh;
    const std::size_t f0 = shape.mesh.n_faces();
    const std::size_t e0 = shape.mesh.n_edges();
    std::vector<double> small_mix, large_mix;
    for (const SweepOp& op : sweep_ops()) {
        const bool wanted = ops.empty() || std::find(ops.begin(), ops.end(), op.name) != ops.end();
        const double w = wanted ? op.weight : 0.0;
        small_mix.push_back(op.grows > 0 ? 1.5 * w : op.grows < 0 ? 0.75 * w : w);
        large_mix.push_back(op.grows > 0 ? 0.75 * w : op.grows < 0 ? 1.5 * w : w);
    }
    std::discrete_distribution<std::size_t> when_small(small_mix.begin(), small_mix.end());
    std::discrete_distribution<std::size_t> when_large(large_mix.begin(), large_mix.end());
    for (long k = 0; k < n_ops; ++k) {
        if (mesh.n_faces() > 4 * f0 || 4 * mesh.n_faces() < f0 || mesh.n_edges() > 4 * e0) {
            mesh = shape.mesh;
        }
        const SweepOp& op = sweep_ops()[mesh.n_faces() < f0 ? when_small(rng) : when_large(rng)];
        std::uniform_int_distribution<std::uint32_t> pick(
            0, static_cast<std::uint32_t>(element_count(mesh, op.target) - 1));
        std::uint32_t i = pick(rng);
        while (is_deleted(mesh, op.target, i)) {
            i = pick(rng);
        }
        ++tally.ops;
        ASSERT_TRUE(run_op(mesh, op, i, tally)) << op.name << " on element " << i;
        ASSERT_VALID(mesh) << "after " << op.name << " on element " << i << ", step " << k;
        if (k % 97 == 0) {
            mesh.garbage_collection();
            ASSERT_VALID(mesh) << "after garbage collection";
        }
    }
}

}  // namespace meshedit::test
