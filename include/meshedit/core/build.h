#pragma once
/// \file
/// Turning an indexed polygon soup into a halfedge mesh: the one place where input topology
/// is diagnosed and repaired. File readers produce a PolygonSoup; only this builds a Mesh.

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshedit/core/math.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

/// Positions plus polygons as index lists (CSR layout): face `f` has the corners
/// `indices[face_offsets[f] .. face_offsets[f+1])`, counter-clockwise seen from outside.
struct PolygonSoup {
    std::vector<Vec3> positions;
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> face_offsets{0};

    std::size_t n_faces() const { return face_offsets.size() - 1; }
    /// Appends one polygon.
    void add_face(std::initializer_list<std::uint32_t> corners) {
        indices.insert(indices.end(), corners.begin(), corners.end());
        face_offsets.push_back(static_cast<std::uint32_t>(indices.size()));
    }
    template <class Range>
    void add_face_range(const Range& corners) {
        indices.insert(indices.end(), std::begin(corners), std::end(corners));
        face_offsets.push_back(static_cast<std::uint32_t>(indices.size()));
    }
};

/// What build_mesh() changed to make the input a valid manifold mesh.
struct BuildReport {
    /// Input faces dropped: fewer than 3 corners or a repeated corner index.
    std::vector<std::uint32_t> dropped_faces;
    /// Undirected input edges (as vertex index pairs, smaller first) used by more than two
    /// faces or twice in the same direction; they were cut apart into boundary edges.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> nonmanifold_edges;
    /// Input vertices whose faces formed several separate fans; each extra fan got a copy of
    /// the vertex (appended after the input vertices).
    std::vector<std::uint32_t> split_vertices;
    /// Number of vertex copies added for split_vertices.
    std::size_t added_vertices = 0;
    /// Input vertices referenced by no face (kept as isolated vertices).
    std::size_t isolated_vertices = 0;

    bool repaired() const {
        return !dropped_faces.empty() || !nonmanifold_edges.empty() || !split_vertices.empty();
    }
    /// One line per kind of repair, e.g. "split 2 non-manifold vertices (3, 17)".
    std::string summary() const;
};

/// Thrown for input that cannot become a mesh at all (an index out of range, a non-finite
/// position); the message names the face or vertex.
class TopologyError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Estimated peak bytes of holding a soup of that size and building its mesh (the soup, the
/// builder's scratch and the mesh's arrays), for readers that check the memory budget
/// (budget.h) before they make a soup that big.
double build_bytes(double vertices, double corners, double faces);

/// What build_mesh() refuses, checked alone: offsets that do not cover the indices, an index
/// out of range, a non-finite position. \throws TopologyError naming the face or vertex.
void check_polygon_soup(const PolygonSoup& soup);

/// Builds a halfedge mesh from `soup`. Vertex `i` of the result is `soup.positions[i]`; the
/// faces keep their order, minus dropped ones. Non-manifold input is repaired (never refused):
/// non-manifold and inconsistently oriented edges are cut into boundary edges, then every
/// vertex whose faces form several fans is split into one vertex per fan. O(n log n).
/// \throws TopologyError on an index out of range or a non-finite position.
/// \post validate(result) passes.
Mesh build_mesh(const PolygonSoup& soup, BuildReport* report = nullptr);

/// The inverse: positions of all vertices and the corner lists of all live faces, in index
/// order (garbage-collect first to get dense indices).
PolygonSoup to_polygon_soup(const Mesh& mesh);

}  // namespace meshedit
