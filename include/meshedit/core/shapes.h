#pragma once
/// \file
/// Procedural meshes for tests, samples and benchmarks. All are consistently oriented
/// (outward normals for closed shapes, +z for flat ones) and built through build_mesh().

#include "meshedit/core/mesh.h"

namespace meshedit::shapes {

/// Regular tetrahedron: 4 vertices, 4 triangles, inscribed in the unit sphere.
Mesh tetrahedron();
/// Cube [-1,1]^3 with one diagonal per face: 8 vertices, 18 edges, 12 triangles. Vertex
/// `i` is `((i&1) ? 1 : -1, (i&2) ? 1 : -1, (i&4) ? 1 : -1)`. Each side is split along the
/// diagonal from its lowest-index corner, the classic asymmetric layout (vertices 0 and 7
/// have valence 6, the others 4), which makes Loop subdivision visibly asymmetric. Faces,
/// in this order:
///
///     -x: (0,4,6) (0,6,2)    +x: (1,3,7) (1,7,5)
///     -y: (0,1,5) (0,5,4)    +y: (2,6,7) (2,7,3)
///     -z: (0,2,3) (0,3,1)    +z: (4,5,7) (4,7,6)
Mesh cube();
/// Regular icosahedron: 12 vertices, 30 edges, 20 triangles, on the unit sphere.
Mesh icosahedron();
/// Icosahedron subdivided `k` times by midpoint splits, projected to the unit sphere:
/// 10·4^k + 2 vertices, 20·4^k triangles.
Mesh icosphere(int k);
/// Torus with `m` segments around the main ring and `n` around the tube (m, n ≥ 3), radii
/// R and r, in the z = 0 plane: m·n vertices, 2·m·n triangles, genus 1. Vertex (i, j) (ring
/// step i, tube step j) has index i·n + j.
Mesh torus(int m, int n, double R = 1.0, double r = 0.4);
/// Open triangulated grid on [0,1]² in the z = 0 plane with nx × ny quads, each cut by the
/// diagonal from its (i,j) corner to (i+1,j+1): (nx+1)(ny+1) vertices, 2·nx·ny triangles.
/// Vertex (i, j) has index j·(nx+1) + i.
Mesh grid(int nx, int ny);
/// Disk as a fan in the z = 0 plane: vertex 0 at the centre, `n` rim vertices on the unit
/// circle (vertex k + 1 at angle 2πk/n), n triangles (0, k+1, k+2).
Mesh disk(int n);
/// Open cylinder (no caps), radius 1, height 2 along z, `m` segments around, `n` rows of
/// quads each split into two triangles: m·(n+1) vertices, 2·m·n triangles, two boundaries.
/// Vertex (i, j) (segment i, row j from z = -1 up) has index j·m + i.
Mesh cylinder(int m, int n);
/// Quad-faced cube-sphere: each cube face divided into k × k quads, projected to the unit
/// sphere (central projection), welded along cube edges: 6k² + 2 vertices, 12k² edges, 6k²
/// quads.
Mesh quad_sphere(int k);
/// Open grid of nx × ny unit quads in the z = 0 plane, vertex (i, j) at (i, j, 0) with index
/// j·(nx+1) + i, quad (i, j) = face j·nx + i: every interior vertex has valence 4, so edge
/// loops and rings run straight across it.
Mesh quad_grid(int nx, int ny);
/// Torus of m × n quads (R = 1, r = 0.4, in the z = 0 plane): vertex (i, j) (ring step i,
/// tube step j) has index i·n + j, quad (i, j) = face i·n + j; every vertex has valence 4.
Mesh quad_torus(int m, int n);

}  // namespace meshedit::shapes
