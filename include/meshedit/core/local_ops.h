#pragma once
/// \file
/// Local operations on the halfedge mesh. Contract (as Scotty3D's halfedge-local.cpp states
/// it): each op either succeeds, or returns a refusal with a reason and leaves the mesh
/// exactly as it was. Each has a pure predicate (`is_*_ok`) the UI can call to grey out a
/// command; the op calls the same predicate first. Diagrams: docs/halfedge.md and above each
/// op in src/core/local_ops.cpp.

#include <string_view>

#include "meshedit/core/mesh.h"

namespace meshedit {

/// Whether an operation is allowed; when not, a short reason for a status line
/// ("cannot flip a boundary edge"). The reason is a string literal: no allocation.
class OpStatus {
public:
    static constexpr OpStatus ok() { return OpStatus(); }
    static constexpr OpStatus refused(std::string_view reason) { return OpStatus(reason); }

    explicit constexpr operator bool() const { return reason_.empty(); }
    constexpr std::string_view reason() const { return reason_; }

private:
    constexpr OpStatus() = default;
    explicit constexpr OpStatus(std::string_view reason) : reason_(reason) {}
    std::string_view reason_;
};

/// The outcome of an op: the handle it documents on success, or the refusal reason.
template <class H>
class OpResult {
public:
    constexpr OpResult(H value) : value_(value) {}  // NOLINT: implicit on purpose
    constexpr OpResult(OpStatus refusal) : reason_(refusal.reason()) {}  // NOLINT

    explicit constexpr operator bool() const { return reason_.empty(); }
    constexpr bool ok() const { return reason_.empty(); }
    /// The handle; \pre ok().
    constexpr H value() const { return value_; }
    constexpr H operator*() const { return value_; }
    constexpr std::string_view reason() const { return reason_; }

private:
    H value_{};
    std::string_view reason_;
};

/// \return ok if `e` is a live interior edge between two triangles whose flipped edge would
/// not already exist (and would not join a vertex to itself).
OpStatus is_flip_ok(const Mesh& mesh, Edge e);
/// Flips `e` inside its two triangles: (a,b,c),(c,b,d) → (a,d,c),(a,b,d) where b-c is `e`.
/// O(1), no allocation. \return the same edge handle, now joining a and d.
OpResult<Edge> flip(Mesh& mesh, Edge e);

/// \return ok if `e` is live and every face beside it is a triangle.
OpStatus is_split_ok(const Mesh& mesh, Edge e);
/// Splits `e` at its midpoint. An interior edge's two triangles become four; a boundary
/// edge's one triangle becomes two and the boundary gains the vertex. O(1), no allocation.
/// \return the new vertex m; `halfedge(m)` runs along the original edge, from m towards
/// `to_vertex(halfedge(e, 0))`, and `edge(halfedge(m))` is `e` itself (shortened).
OpResult<Vertex> split(Mesh& mesh, Edge e);

/// \return ok if collapsing `e` keeps the mesh a valid manifold: the link condition holds,
/// no face would lose its last edges (a boundary-spanning edge, a triangle with both other
/// edges on the boundary), and the mesh would not shrink below a tetrahedron.
OpStatus is_collapse_ok(const Mesh& mesh, Edge e);
/// Collapses `e` to its midpoint. The endpoint with the smaller index survives (so CLI edge
/// names stay predictable); the other endpoint, `e`, and the faces degenerating with it are
/// deleted (garbage collection is left to the caller). \return the surviving vertex.
OpResult<Vertex> collapse(Mesh& mesh, Edge e);

/// \return ok if `f` is live (a triangle is ok: triangulating it changes nothing).
OpStatus is_triangulate_ok(const Mesh& mesh, Face f);
/// Splits polygon `f` into triangles by diagonals inside it, never adding an edge that
/// already exists. \return `f` (now one of the triangles).
OpResult<Face> triangulate(Mesh& mesh, Face f);
/// Triangulates every non-triangle face. \return how many faces were triangulated.
std::size_t triangulate(Mesh& mesh);

}  // namespace meshedit
