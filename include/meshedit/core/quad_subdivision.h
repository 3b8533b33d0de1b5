#pragma once
/// \file
/// Quad subdivision of polygon meshes: Catmull-Clark (OpenSubdiv's Catmark rules with
/// infinitely sharp creases) and linear subdivision, which share one connectivity: every
/// face of k corners becomes k quads around a new vertex at its centroid
/// (docs/subdivision.md).

#include <functional>

#include "meshedit/core/mesh.h"
#include "meshedit/core/subdivision.h"

namespace meshedit {

/// Where the new and the old points go.
enum class QuadScheme {
    /// Catmull-Clark: face points at the centroids; edge points (A + B + F0 + F1) / 4, or
    /// the midpoint on boundary and crease edges; old vertices by OpenSubdiv's Catmark
    /// vertex rules (smooth and dart, crease, corner), boundary as if mirrored.
    CatmullClark,
    /// Linear: face points at the centroids, edge points at the midpoints, old vertices
    /// stay: the surface does not change, only its faces.
    Linear,
};

struct QuadSubdivisionOptions {
    QuadScheme scheme = QuadScheme::CatmullClark;
    /// How texture coordinates are refined (subdivision.h); linear subdivision refines them
    /// linearly whatever this says, as OpenSubdiv's bilinear scheme does.
    UvInterpolation uv = UvInterpolation::CornersOnly;
    /// Called with the fraction done (0…1), non-decreasing, at coarse intervals, last with
    /// exactly 1; may be empty. Always from the calling thread.
    std::function<void(double)> progress;
    /// At most this many threads for meshes of 100,000 faces or more: 0 means thread_count()
    /// (threads.h). The result is the same for any number.
    unsigned max_threads = 0;
};

/// What `levels` levels of quad subdivision would make of `mesh` (the first level turns a
/// face of k corners into k quads, every later one each quad into 4), and whether they fit
/// in 32-bit handles and the memory budget. Quad subdivision has no topological refusal: any
/// valid mesh, polygons and boundaries included, gives a valid result.
SubdivisionPlan plan_quad_subdivision(const Mesh& mesh, int levels = 1);

/// One level of quad subdivision, written directly into exactly sized arrays (parallel on
/// meshes of 100,000 faces or more). Garbage is collected first. With V, E, F the counts at
/// that point and C the number of face corners (the sum of the face degrees):
///
///   vertices  [0, V) the old vertices, same indices (vertex properties kept on them);
///             V + e the edge point of old edge e; V + E + f the face point of old face f
///   edges     2E + C: [0, 2E) the halves of the old edges (edge g is the half of old edge
///             g / 2 that touches from_vertex(halfedge g)), then one edge per face corner
///   faces     C: the quad of a face's corner, numbered face by face, each face's corners
///             from the one halfedge(f) points to
///
/// Both halves of a crease edge stay creases; the new edges inside the faces are not. Other
/// properties follow the attribute carry (docs/halfedge.md, "What every operation carries"),
/// texture coordinates as face-varying values by `options.uv`.
/// \throws std::length_error if the result would not fit 32-bit handles (nothing changed).
///         If building the result throws (std::bad_alloc), the mesh is left empty but valid.
/// \post validate(mesh) passes; every face is a quad.
void quad_subdivide(Mesh& mesh, const QuadSubdivisionOptions& options = {});

/// The plain reference quad_subdivide() is tested against: the new positions from
/// circulators, then a new mesh built from the list of quads (as Scotty3D's and most
/// course code do). Same vertex indices, faces (by vertex index, in the same order),
/// crease edges and positions as quad_subdivide(); edge indices differ; properties other
/// than positions and creases are dropped. Several times slower.
void quad_subdivide_classic(Mesh& mesh, const QuadSubdivisionOptions& options = {});

}  // namespace meshedit
