#pragma once
/// \file
/// Global counts: boundary loops, connected components, Euler characteristic, genus.
/// Closedness.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "meshedit/core/mesh.h"

namespace meshedit {

/// Counts of a mesh as `meshedit info` reports them.
struct MeshStats {
    std::size_t vertices = 0;
    std::size_t edges = 0;
    std::size_t faces = 0;
    std::size_t boundary_loops = 0;
    std::size_t components = 0;     ///< connected components, isolated vertices included
    long euler_characteristic = 0;  ///< V - E + F
    long genus = 0;                 ///< from χ = Σ (2 − 2g − b) over components
};

std::size_t count_boundary_loops(const Mesh& mesh);
/// True if no live halfedge is a boundary halfedge (every edge has two faces). An empty mesh
/// is closed; a mesh with isolated vertices and no faces too.
bool is_closed(const Mesh& mesh);
std::size_t count_components(const Mesh& mesh);
/// Per vertex index, the smallest vertex index of its connected component: equal labels mean
/// one component. Deleted vertices label themselves.
std::vector<std::uint32_t> component_roots(const Mesh& mesh);
long euler_characteristic(const Mesh& mesh);
MeshStats compute_stats(const Mesh& mesh);

}  // namespace meshedit
