#pragma once
/// \file
/// A reference to one element of a mesh, whatever its kind: what the editor selects and
/// hovers, what picking returns, what the renderer highlights. It lives beside the mesh (as
/// Scotty3D keeps its ElementRef beside its halfedge mesh) because its rules are the mesh's:
/// it stays valid across operations and is invalidated only by garbage collection, through
/// whose maps remap() carries it.

#include <cstdint>
#include <string>

#include "meshedit/core/handles.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

/// At most one element: a vertex, edge, halfedge or face, by index; or none.
struct ElementRef {
    enum class Kind { None, Vertex, Edge, Halfedge, Face };
    Kind kind = Kind::None;
    std::uint32_t index = kInvalidIndex;

    static ElementRef vertex(Vertex v) { return {Kind::Vertex, v.idx()}; }
    static ElementRef edge(Edge e) { return {Kind::Edge, e.idx()}; }
    static ElementRef halfedge(Halfedge h) { return {Kind::Halfedge, h.idx()}; }
    static ElementRef face(Face f) { return {Kind::Face, f.idx()}; }
    bool is_none() const { return kind == Kind::None; }
    friend bool operator==(const ElementRef&, const ElementRef&) = default;
};

/// "vertex", "edge", "halfedge", "face"; "nothing" for none.
const char* kind_name(ElementRef::Kind kind);

/// The size of the index range of `kind` in `mesh` (deleted elements included); 0 for none.
std::size_t elements_size(const Mesh& mesh, ElementRef::Kind kind);

/// True if `element` names a live element of `mesh` (in range and not deleted).
bool is_live(const Mesh& mesh, const ElementRef& element);

/// "edge 5" — the kind and the index, nothing looked up in a mesh.
std::string to_string(const ElementRef& element);

/// A one-line description for status lines and panels: "edge 5 (2–7)", "halfedge 9 (2→7)",
/// "vertex 3", "face 12", "nothing selected"; "(deleted)" or "(not in the mesh)" for a stale
/// reference.
std::string describe(const Mesh& mesh, const ElementRef& element);

/// The same element after garbage collection: its new index, or none if it was deleted.
ElementRef remap(const ElementRef& element, const GarbageCollectionMap& map);

}  // namespace meshedit
