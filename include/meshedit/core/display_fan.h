#pragma once
/// \file
/// The display triangulation of a polygon face, shared by the surface (MeshRenderer), the
/// face tint of the overlay (both must cut a non-planar polygon the same way, or the tint
/// dips behind the surface) and the closest-point tree (which measures that same surface).

#include "meshedit/core/mesh.h"

namespace meshedit {

/// Calls fn(i, c0, h) for the fan triangles (c0, from_vertex(h), to_vertex(h)), i = 1 … n−2,
/// of face f: a fan from c0, the corner where halfedge(f) starts. Exact for convex faces.
template <class Fn>
void for_each_fan_triangle(const Mesh& mesh, Face f, Fn&& fn) {
    const Halfedge h0 = mesh.halfedge(f);
    const Vertex c0 = mesh.from_vertex(h0);
    const std::size_t n = mesh.valence(f);
    Halfedge h = mesh.next(h0);
    for (std::size_t i = 1; i + 1 < n; ++i, h = mesh.next(h)) {
        fn(i, c0, h);
    }
}

}  // namespace meshedit
