#pragma once
/// \file
/// Procedural test meshes beyond shapes.h: small hand-drawn configurations, and the corpus
/// used by invariant sweeps.

#include <cstdint>
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

/// Two triangles sharing edge 1-2 (a quad cut by its diagonal), in the z = 0 plane:
///
///     3 ----- 2
///     |     / |
///     |   /   |
///     | /     |
///     0 ----- 1      faces (0,1,2) and (0,2,3)
Mesh two_triangles();

/// Vertex 0 at the origin surrounded by `n` triangles (a closed one-ring fan whose rim is
/// the boundary): n + 1 vertices.
Mesh one_ring(int n);

/// Two triangles touching at a single vertex ("bow tie"), a non-manifold vertex:
///     faces (0,1,2) and (0,3,4).
PolygonSoup bowtie_soup();

/// A named mesh of the sweep corpus.
struct NamedMesh {
    std::string name;
    Mesh mesh;
};

/// Meshes for invariant sweeps: tetrahedron, cube, icosahedron, torus(8,6), grid(5,4),
/// disk(7), cylinder(6,3), icosphere(1).
std::vector<NamedMesh> sweep_corpus();

}  // namespace meshedit::test
