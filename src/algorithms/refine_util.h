#pragma once
// Private to meshedit_core: what the fast subdivision paths (Loop in subdivision.cpp,
// Catmull-Clark and linear in quad_subdivision.cpp) share: chunked parallel passes with
// progress, moving arrays out of a mesh and freeing them early, the overflow guard, and the
// "does level k fit" check of the plans.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "algorithms/loop_rules.h"
#include "mesh/mesh_arrays.h"
#include "mesh/parallel.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/memory.h"
#include "meshedit/core/subdivision.h"

namespace meshedit::refine {

// Below this many faces everything runs on the calling thread.
inline constexpr std::size_t kParallelFaces = 100'000;
// Elements per chunk of work handed to a thread (small enough to balance two threads on a
// 100,000-face mesh), and at least this many between two progress reports.
inline constexpr std::size_t kChunk = std::size_t{1} << 14;
inline constexpr std::size_t kReportEvery = std::size_t{1} << 16;

/// Runs body(begin, end) over [0, n) in chunks on `threads` threads, reporting a fraction
/// that goes from `lo` to `hi` from the calling thread.
template <class Body>
void chunked(std::size_t n, unsigned threads, loop_rules::Progress& progress, double lo, double hi,
             const Body& body) {
    std::size_t reported = 0;
    parallel::for_chunks(n, kChunk, threads, body, [&](std::size_t done) {
        if (done - reported >= kReportEvery) {
            reported = done;
            progress(lo + (hi - lo) * static_cast<double>(done) / static_cast<double>(n));
        }
    });
    progress(hi);
}

/// Moves the contents out of a property array, leaving it empty (and unallocated).
template <class A>
A take(A& v) {
    A out;
    out.swap(v);
    return out;
}

/// Frees an array's storage now (clear() keeps it).
template <class A>
void release(A& v) {
    A().swap(v);
}

/// `a`, resized to `n` elements that the pass that follows writes, every one of them.
template <class A>
A& sized(A& a, std::size_t n) {
    a.resize_for_overwrite(n);
    return a;
}

constexpr std::uint32_t u32(std::size_t i) {
    return static_cast<std::uint32_t>(i);
}

/// The subdivision rules' points are convex combinations of old points, but the sums inside
/// them (A + B, a vertex's neighbours, a face's corners) are not, and overflow near the top
/// of the double range. A mesh whose largest coordinate exceeds 2^990 (a sum of 2^32 of them
/// still fits) is subdivided at a power-of-two scale and scaled back, which changes no bit
/// of any other mesh's result. Returns the exponent to scale by, 0 for every ordinary mesh.
inline int overflow_exponent(const memory::Array<Vec3>& p) {
    double largest = 0.0;
    for (const Vec3& q : p) {
        largest = std::max({largest, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    }
    if (!(largest > std::ldexp(1.0, 990))) {
        return 0;
    }
    int exponent = 0;
    std::frexp(largest, &exponent);
    return exponent;
}

inline void scale_by_power_of_two(memory::Array<Vec3>& p, int exponent) {
    for (Vec3& q : p) {
        q = Vec3{std::ldexp(q.x, exponent), std::ldexp(q.y, exponent), std::ldexp(q.z, exponent)};
    }
}

/// The old mesh's connectivity, moved out of the mesh before the new arrays are allocated;
/// each array is freed as soon as no later pass reads it.
struct OldMesh {
    memory::Array<Halfedge> next;
    memory::Array<Halfedge> prev;  // empty unless asked for (Loop's passes do not read it)
    memory::Array<Vertex> to;
    memory::Array<Face> face;
    memory::Array<Halfedge> face_halfedge;
    memory::Array<Halfedge> vertex_halfedge;
    memory::Array<std::uint8_t> crease;  // empty when the mesh has no crease flags

    bool is_sharp(std::size_t e) const {
        const bool boundary = !face[2 * e].is_valid() || !face[2 * e + 1].is_valid();
        return loop_rules::is_sharp(boundary, crease.empty() ? 0 : crease[e]);
    }
};

/// Moves the connectivity and the crease flags out of `mesh` into `old` and shrinks the
/// edge, halfedge and face arrays to 0, which resets every user property on them to its
/// default (their old values would describe the wrong elements) and frees their storage.
/// The vertices keep their positions and properties. \return the crease property (null if
/// the mesh has none), emptied, for give_crease_halves().
inline EdgeProperty<std::uint8_t> take_connectivity(Mesh& mesh, OldMesh& old, bool keep_prev) {
    old.next = take(MeshArrays::next(mesh));
    if (keep_prev) {
        old.prev = take(MeshArrays::prev(mesh));
    } else {
        release(MeshArrays::prev(mesh));
    }
    old.to = take(MeshArrays::to_vertex(mesh));
    old.face = take(MeshArrays::face(mesh));
    old.face_halfedge = take(MeshArrays::face_halfedge(mesh));
    old.vertex_halfedge = take(MeshArrays::vertex_halfedge(mesh));
    EdgeProperty<std::uint8_t> crease = loop_rules::crease_property(mesh);
    if (crease) {
        old.crease = take(crease.vector());
    }
    mesh.resize(mesh.vertices_size(), 0, 0);
    release(MeshArrays::edge_deleted(mesh));
    release(MeshArrays::face_deleted(mesh));
    return crease;
}

/// Both halves of an old crease edge are creases (new edge g < 2E is half of old edge g/2);
/// the other `new_ne` - 2E edges, inside the old faces, are not.
inline void give_crease_halves(EdgeProperty<std::uint8_t>& crease, const OldMesh& old,
                               std::size_t new_ne) {
    if (!crease) {
        return;
    }
    memory::Array<std::uint8_t>& flags = crease.vector();
    flags.assign(new_ne, 0);
    for (std::size_t g = 0; g < 2 * old.crease.size(); ++g) {
        flags[g] = old.crease[g / 2];
    }
}

/// Replaces the mesh's positions with `n` new ones that `compute(out, old_positions)` writes,
/// every one of them, under the overflow guard of overflow_exponent().
template <class Compute>
void replace_positions(Mesh& mesh, std::size_t n, const Compute& compute);

/// Writes the new prev array of `mesh` as the inverse of its new next array: every halfedge
/// is the next of exactly one, so chunks of halfedges write disjoint entries.
inline void write_prev_from_next(Mesh& mesh, unsigned threads, loop_rules::Progress& progress,
                                 double lo, double hi) {
    const memory::Array<Halfedge>& next = MeshArrays::next(mesh);
    auto& prev = sized(MeshArrays::prev(mesh), next.size());
    chunked(next.size(), threads, progress, lo, hi, [&](std::size_t begin, std::size_t end) {
        for (std::size_t x = begin; x < end; ++x) {
            prev[next[x].idx()] = Halfedge(u32(x));
        }
    });
}

/// Records level `level`'s counts in `plan` and refuses it (false, with plan.status) when
/// they exceed 32-bit handles or the memory budget: `per_face` bytes per face, four times
/// over (the level's own temporaries, an undo snapshot or a writer's copy, normals, file
/// buffers).
inline bool plan_level(SubdivisionPlan& plan, int level, double v, double e, double f,
                       double per_face) {
    plan.vertices = v, plan.edges = e, plan.faces = f;
    plan.bytes = 4.0 * per_face * f;
    const std::string what = "cannot subdivide: level " + std::to_string(level) + " (" +
                             std::to_string(static_cast<unsigned long long>(f)) + " faces) ";
    if (2.0 * e >= static_cast<double>(kInvalidIndex) || v >= static_cast<double>(kInvalidIndex)) {
        plan.status = OpStatus::composed(
            what + "would exceed the 2^32 - 1 elements 32-bit handles can number");
        return false;
    }
    if (const auto over = over_budget(plan.bytes)) {
        plan.status = OpStatus::composed(what + *over);
        return false;
    }
    return true;
}

template <class Compute>
void replace_positions(Mesh& mesh, std::size_t n, const Compute& compute) {
    memory::Array<Vec3> position;
    position.resize_for_overwrite(n);
    const int exponent = overflow_exponent(mesh.position_vector());
    if (exponent != 0) {
        scale_by_power_of_two(mesh.position_vector(), -exponent);
    }
    compute(position, mesh.position_vector());
    if (exponent != 0) {
        scale_by_power_of_two(position, exponent);
    }
    mesh.position_vector().swap(position);
}

}  // namespace meshedit::refine
