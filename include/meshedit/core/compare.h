#pragma once
/// \file
/// Whether two meshes are the same mesh, and how far apart they are (`meshedit compare`,
/// docs/cli.md): an isomorphism of the halfedge structures, found by propagation from one
/// matched halfedge per connected component, and the positional difference under it (or,
/// when the connectivity differs, by closest points).

#include <cstdint>
#include <string>
#include <vector>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

/// An isomorphism from mesh A's halfedge structure onto mesh B's, or why there is none.
/// Renumbered vertices, edges and faces, a face's first corner rotated, components in another
/// order all match; a mirrored copy (every face's orientation flipped) does not, as its
/// halfedges run the other way.
struct TopologyMatch {
    bool isomorphic = false;
    /// By A's element index, B's element index (kInvalidIndex for A's deleted elements; all
    /// empty when not isomorphic). An edge e of A goes to Mesh::edge(halfedge[2e]); an
    /// isolated vertex goes to an isolated vertex of B, at the same position when there is one.
    std::vector<std::uint32_t> vertex, halfedge, face;
    /// When not isomorphic: the reason in the element vocabulary ("the face counts differ: 12
    /// and 11", "halfedge 7 (2→5) of A and halfedge 9 (4→1) of B: …").
    std::string difference;
    /// Where the propagation failed, in A and in B (none when the counts already differ).
    ElementRef first_a, first_b;
};

/// Decides whether `a` and `b` are the same halfedge structure up to renumbering, and gives
/// the mapping. Per component of A it starts at a halfedge whose endpoints' positions a
/// halfedge of B shares (a renumbered copy matches at the first try), else at A's halfedge
/// whose refined signature (valences, face degrees, boundary, and their neighbours') is rarest
/// in B, trying each candidate of B; each try propagates along next and twin and stops at the
/// first inconsistency. O(size) for a renumbered copy; symmetric meshes whose signature
/// histograms agree but which differ can cost a try per candidate.
TopologyMatch match_topology(const Mesh& a, const Mesh& b);

/// How far A's vertices and surface are from B's.
struct Deviation {
    /// True: vertex distances are to the matched vertex of B; false: to B's surface.
    bool by_mapping = false;
    /// By A's vertex index, its distance (NaN for a deleted vertex).
    std::vector<double> vertex;
    double max = 0.0, rms = 0.0;  ///< over `vertex`
    /// Sampled one-sided distances (the largest distance of a vertex or a display triangle's
    /// centroid of one mesh to the other's surface) and the symmetric Hausdorff distance,
    /// their maximum. Exact 0 when the mapping moves no vertex.
    double a_to_b = 0.0, b_to_a = 0.0, hausdorff = 0.0;
    /// A's bounding-box diagonal, what percentages are of (0 for a single point).
    double diagonal = 0.0;
};

/// The deviation of `a` from `b`, under `match` when it is isomorphic. A surface is its
/// display triangles (polygons fanned as the renderer cuts them) and its isolated vertices;
/// a mesh without vertices is infinitely far from one with some.
Deviation measure_deviation(const Mesh& a, const Mesh& b, const TopologyMatch& match);

/// How one attribute (attributes.h) differs between A and B under an isomorphism.
struct AttributeDifference {
    std::string name;  ///< "texture coordinates", "corner normals", "vertex colours", …
    bool in_a = false, in_b = false;  ///< which mesh has it
    std::size_t compared = 0;         ///< corners, vertices or faces compared (both have it)
    const char* elements = "faces";   ///< what `compared` counts: "corners", "vertices", "faces"
    std::size_t differing = 0;        ///< of those, whose values are not equal
    double max = 0.0;                 ///< the largest component difference (0 for materials)
    ElementRef first_a;               ///< A's first differing element
};

/// Texture coordinates (per corner, each set), corner normals, vertex and face colours and face
/// materials (compared by name, colour, opacity and texture) of A against B's matched
/// elements; each attribute either mesh has, in that order. Empty unless `match` is
/// isomorphic.
std::vector<AttributeDifference> compare_attributes(const Mesh& a, const Mesh& b,
                                                    const TopologyMatch& match);

/// 100 * distance / diagonal; 0 when both are 0.
double percent_of(double distance, double diagonal);

}  // namespace meshedit
