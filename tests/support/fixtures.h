#pragma once
/// \file
/// Procedural test meshes beyond shapes.h: small hand-drawn configurations, and the corpus
/// used by invariant sweeps.

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "meshedit/core/build.h"
#include "meshedit/core/mesh.h"

namespace meshedit::test {

/// Builds a mesh from positions and polygons; the test fails (via exception) on bad input.
Mesh mesh_from_faces(const std::vector<Vec3>& positions,
                     const std::vector<std::vector<std::uint32_t>>& faces);

/// The soup for mesh_from_faces().
PolygonSoup soup_from_faces(const std::vector<Vec3>& positions,
                            const std::vector<std::vector<std::uint32_t>>& faces);

/// Two triangles sharing edge 0-2 (a quad cut by its diagonal), in the z = 0 plane:
///
///     3 ----- 2
///     |     / |
///     |   /   |
///     | /     |
///     0 ----- 1      faces (0,1,2) and (0,2,3)
Mesh two_triangles();

/// The cube [-1,1]³ as six quads; vertex (x, y, z) corners numbered 0-3 at z = -1 and 4-7
/// at z = 1, counter-clockwise seen from +z: faces (0,3,2,1), (4,5,6,7), (0,1,5,4),
/// (1,2,6,5), (2,3,7,6), (3,0,4,7).
Mesh quad_cube();

/// The quad cube, linear-subdivided three times (8 × 8 quads a side, all flat) and cut into
/// triangles: 768 triangles on the six planes of [-1/√3, 1/√3]³.
Mesh flat_sided_cube();

/// How many edges carry the crease flag (kCreaseProperty).
std::size_t crease_count(const Mesh& mesh);

/// `n` unit quads in a row in the z = 0 plane: vertices 0..n at y = 0, n+1..2n+1 at y = 1,
/// faces (i, i+1, n+2+i, n+1+i).
Mesh quad_strip(int n);

/// Two copies of `mesh`, the second moved by `offset` and numbered after the first (two
/// separate pieces: select linked, paths that cannot join).
Mesh two_copies(const Mesh& mesh, const Vec3& offset);

/// Vertex 0 at the origin surrounded by `n` triangles (a closed one-ring fan whose rim is
/// the boundary): n + 1 vertices.
Mesh one_ring(int n);

/// Two triangles touching at a single vertex ("bow tie"), a non-manifold vertex:
///     faces (0,1,2) and (0,3,4).
PolygonSoup bowtie_soup();

/// The smallest input that made collapse() corrupt a mesh (as OBJ: 4 vertices, faces
/// `1 2 3`, `1 3 2`, `1 2 4`): edge 0-1 has three faces. Built, it is a closed two-triangle
/// pillow (0,1,2), (0,2,1) plus a separate triangle on copies of 0 and 1.
PolygonSoup pillow_and_ear_soup();

/// Three vertices and two faces (0,1,2), (0,2,1) whose sides 0-1 are two different edges: a
/// slit, i.e. a boundary loop of two edges, linked by hand (build_mesh() never makes one).
/// validate() rejects it ("multi-edge"); the local operations must still not corrupt it.
Mesh slit_pillow();

/// A named mesh of the sweep corpus.
struct NamedMesh {
    std::string name;
    Mesh mesh;
};

/// Meshes for invariant sweeps: tetrahedron, cube, icosahedron, torus(8,6), grid(5,4),
/// disk(7), cylinder(6,3), icosphere(1).
std::vector<NamedMesh> sweep_corpus();

/// Valid meshes at the edge of what the operations accept: a closed two-triangle pillow, the
/// repaired pillow_and_ear_soup(), two pillows sharing a vertex (repaired bow tie), a quad and
/// a triangle sharing two edges (an interior vertex of valence 2), a triangular bipyramid,
/// a single triangle and a fan around a boundary vertex of valence 2.
std::vector<NamedMesh> pillow_family();

/// Bigger meshes for the sweep (thousands to tens of thousands of faces): a 40,000-face
/// torus, an icosphere of 5,120 faces and a 20,000-face open grid.
std::vector<NamedMesh> big_corpus();

/// Faces as lists of corner indices (a soup's, for exact comparisons).
using Faces = std::vector<std::vector<std::uint32_t>>;
/// The soup's faces as corner lists, in order.
Faces faces_of(const PolygonSoup& soup);

/// A random region for the region verbs: a live face and, with odds one in two each, the
/// faces across its sides, and with odds one in two every face around its first corner (an
/// inner vertex); none when the mesh has no face.
std::vector<Face> random_region(const Mesh& mesh, std::mt19937& rng);

}  // namespace meshedit::test
