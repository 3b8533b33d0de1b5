/// \file
/// Polygon triangulation by diagonals, never duplicating an edge that exists elsewhere (a
/// quad on a coarse torus can have one diagonal already present as a mesh edge). A fan from
/// some corner is tried first; if every fan hits an existing edge, a dynamic program over
/// sub-polygons finds any valid triangulation, or proves there is none.

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "meshedit/core/local_ops.h"

namespace meshedit {
namespace {

// How to cut polygon `f`: its corners and, for every sub-polygon (i..j), the third corner k
// of the triangle on its closing side (i, j). A fan from corner 0 is k = j - 1.
struct Plan {
    std::vector<Halfedge> sides;  // sides[i] runs corner i -> corner i+1
    std::vector<Vertex> corners;
    std::vector<std::uint32_t> apex_table;  // n*n table of k; empty for a fan
    std::size_t size() const { return corners.size(); }
    std::uint32_t apex(std::uint32_t i, std::uint32_t j) const {
        return apex_table.empty() ? j - 1 : apex_table[i * size() + j];
    }
};

// Fills `chord[i*n + j]` (i < j) with 1 where corners i and j are joined by a mesh edge that
// is not a side of the polygon.
std::vector<std::uint8_t> existing_chords(const Mesh& mesh, const Plan& plan) {
    const std::size_t n = plan.size();
    std::vector<std::pair<Vertex, std::uint32_t>> index;  // corner -> position, sorted
    for (std::uint32_t i = 0; i < n; ++i) {
        index.emplace_back(plan.corners[i], i);
    }
    std::sort(index.begin(), index.end());
    std::vector<std::uint8_t> chord(n * n, 0);
    for (std::uint32_t i = 0; i < n; ++i) {
        for (const Vertex w : mesh.vertices(plan.corners[i])) {
            auto it = std::lower_bound(index.begin(), index.end(),
                                       std::pair<Vertex, std::uint32_t>(w, 0));
            for (; it != index.end() && it->first == w; ++it) {
                const std::uint32_t j = it->second;
                chord[std::min(i, j) * n + std::max(i, j)] = 1;
            }
        }
    }
    return chord;
}

// Chooses the triangulation; rotates the corners so that a fan apex, if any, is corner 0.
OpStatus make_plan(const Mesh& mesh, Face f, Plan& plan) {
    MESHEDIT_ASSERT(mesh.is_valid(f));
    if (mesh.is_deleted(f)) {
        return OpStatus::refused("cannot triangulate: the face is deleted");
    }
    for (const Halfedge h : mesh.halfedges(f)) {
        plan.sides.push_back(h);
        plan.corners.push_back(mesh.from_vertex(h));
    }
    const std::size_t n = plan.size();
    if (n == 3) {
        return OpStatus::ok();
    }
    const std::vector<std::uint8_t> chord = existing_chords(mesh, plan);
    auto blocked = [&](std::size_t i, std::size_t j) {  // a diagonal, not a side
        return j - i > 1 && j - i < n - 1 && chord[i * n + j] != 0;
    };
    for (std::size_t p = 0; p < n; ++p) {
        bool fan = true;
        for (std::size_t q = 0; q < n && fan; ++q) {
            fan = !blocked(std::min(p, q), std::max(p, q));
        }
        if (fan) {
            std::rotate(plan.sides.begin(), plan.sides.begin() + p, plan.sides.end());
            std::rotate(plan.corners.begin(), plan.corners.begin() + p, plan.corners.end());
            return OpStatus::ok();
        }
    }
    // ok[i*n+j]: sub-polygon i..j (closed by i-j) can be cut; apex_table holds the witness.
    std::vector<std::uint8_t> ok(n * n, 0);
    plan.apex_table.assign(n * n, 0);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        ok[i * n + i + 1] = 1;
    }
    for (std::size_t len = 2; len < n; ++len) {
        for (std::size_t i = 0; i + len < n; ++i) {
            const std::size_t j = i + len;
            for (std::size_t k = i + 1; k < j && !ok[i * n + j]; ++k) {
                if (ok[i * n + k] && ok[k * n + j] && !blocked(i, k) && !blocked(k, j)) {
                    ok[i * n + j] = 1;
                    plan.apex_table[i * n + j] = static_cast<std::uint32_t>(k);
                }
            }
        }
    }
    if (!ok[n - 1]) {
        return OpStatus::refused(
            "cannot triangulate: every triangulation would duplicate an existing edge");
    }
    return OpStatus::ok();
}

}  // namespace

OpStatus is_triangulate_ok(const Mesh& mesh, Face f) {
    Plan plan;
    return make_plan(mesh, f, plan);
}

// The sub-polygon i..j is closed by halfedge c (corner j -> corner i, in the part being cut).
// Its triangle (i, k, j) gets sides[i] or a new chord i -> k, sides[k] or a new chord
// k -> j, then c; the chords' twins close the sub-polygons i..k and k..j, cut next. The
// first triangle keeps f; every chord is interior, so no vertex anchor changes.
//
//      corners i+1 .. k-1               corners k+1 .. j-1
//                  .         k         .
//                    .     ^   \     .
//                      ik    g    kj
//                     /             v
//                    i <-----c----- j
OpResult<Face> triangulate(Mesh& mesh, Face f) {
    Plan plan;
    if (const OpStatus ok = make_plan(mesh, f, plan); !ok) {
        return ok;
    }
    const auto n = static_cast<std::uint32_t>(plan.size());
    if (n == 3) {
        return f;
    }
    struct Part {
        std::uint32_t i, j;
        Halfedge c;
    };
    // Carry: a chord's halfedge is its face's corner at its head, which the side arriving at
    // that corner of f was; the chords are new, the triangles parts of f.
    const auto corner = [&](std::uint32_t m) { return plan.sides[(m + n - 1) % n]; };
    const auto carry_chord = [&](Halfedge chord, std::uint32_t from, std::uint32_t to) {
        mesh.carry(chord, corner(to));
        mesh.carry(Mesh::twin(chord), corner(from));
        mesh.carry_default(Mesh::edge(chord));
    };
    std::vector<Part> todo{{0, n - 1, plan.sides[n - 1]}};
    while (!todo.empty()) {
        const auto [i, j, c] = todo.back();
        todo.pop_back();
        const Face g = (c == plan.sides[n - 1]) ? f : mesh.new_face();
        if (g != f) {
            mesh.carry(g, f);
        }
        const std::uint32_t k = plan.apex(i, j);
        Halfedge ik = plan.sides[i];
        if (k != i + 1) {
            ik = mesh.new_edge(plan.corners[i], plan.corners[k]);
            carry_chord(ik, i, k);
            todo.push_back({i, k, Mesh::twin(ik)});
        }
        Halfedge kj = plan.sides[k];
        if (j != k + 1) {
            kj = mesh.new_edge(plan.corners[k], plan.corners[j]);
            carry_chord(kj, k, j);
            todo.push_back({k, j, Mesh::twin(kj)});
        }
        mesh.set_next(ik, kj);
        mesh.set_next(kj, c);
        mesh.set_next(c, ik);
        for (const Halfedge h : {ik, kj, c}) {
            mesh.set_face(h, g);
        }
        mesh.set_halfedge(g, c);
    }
    return f;
}

std::size_t triangulate(Mesh& mesh) {
    std::vector<Face> polygons;  // snapshot: triangulating adds faces
    for (const Face f : mesh.faces()) {
        if (!mesh.is_triangle(f)) {
            polygons.push_back(f);
        }
    }
    std::size_t count = 0;
    for (const Face f : polygons) {
        count += triangulate(mesh, f).ok() ? 1 : 0;
    }
    return count;
}

}  // namespace meshedit
