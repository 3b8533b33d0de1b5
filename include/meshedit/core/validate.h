#pragma once
/// \file
/// Machine-checked invariants of the halfedge mesh (listed in docs/halfedge.md).

#include <optional>
#include <string>

#include "meshedit/core/mesh.h"

namespace meshedit {

/// Which element a validation failure is about.
enum class ElementKind { Vertex, Halfedge, Edge, Face };

/// The first broken invariant found.
struct ValidationError {
    std::string invariant;  ///< short name, e.g. "next-prev", "boundary-anchor"
    ElementKind kind;       ///< kind of the offending element
    std::uint32_t index;    ///< its index
    std::string message;    ///< readable sentence naming the element and what is wrong
};

/// Checks every invariant: references in range and not deleted, `prev(next(h)) == h`,
/// `twin` orbit, `to_vertex(prev(h)) == from_vertex(h)`, each loop has one face (or none) and
/// at least 3 halfedges for a face, face and vertex anchors, the boundary-anchor rule, each
/// vertex's outgoing halfedges form a single orbit, tombstone consistency and counts,
/// finite positions, no face visiting a vertex twice and no two edges joining the same two
/// vertices (so that every valid mesh survives a write and a read as itself). O(n).
/// \return std::nullopt if the mesh is valid, else the first failure.
std::optional<ValidationError> validate(const Mesh& mesh);

}  // namespace meshedit
