#pragma once
// Private to meshedit_algorithms: the Laplacian's weights shared by smoothing and fairing
// (smoothing.cpp, fairing.cpp), and the checks both make of positions.

#include <cstdint>
#include <string>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/core/smoothing.h"

namespace meshedit::laplacian {

/// The weight of every edge (by edge index; 0 for deleted edges): 1 for Uniform; for
/// Cotangent (cot α + cot β) / 2 of the angles opposite the edge (one term on the boundary),
/// clamped to 0 from below so that every step stays a convex combination and every system
/// stays positive definite, and bounded above where a triangle is degenerate.
std::vector<double> edge_weights(const Mesh& mesh, SmoothWeights weights);

/// The weight of one live edge, as edge_weights() gives it: for a pass that reads a few edges
/// of a big mesh (fair() on a small region).
double edge_weight(const Mesh& mesh, Edge e, SmoothWeights weights);

/// "cannot <verb>: vertex 12 has a position that is not a finite number", or empty.
std::string refuse_non_finite(const Mesh& mesh, const char* verb);

/// The vertices on a crease edge (kCreaseProperty), by vertex index; all 0 without creases.
std::vector<std::uint8_t> crease_vertices(const Mesh& mesh);

}  // namespace meshedit::laplacian
