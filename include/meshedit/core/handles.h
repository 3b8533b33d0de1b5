#pragma once
/// \file
/// Typed element handles: a `uint32_t` index per element kind, so a vertex can never be passed
/// where a face is expected. Handles are trivially copyable, 4 bytes, hashable and ordered; they
/// stay valid across copies and moves of the mesh and are invalidated only by
/// Mesh::garbage_collection() (see docs/halfedge.md, "Handle lifetime").

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>

namespace meshedit {

/// The index an invalid (default-constructed) handle holds.
inline constexpr std::uint32_t kInvalidIndex = std::numeric_limits<std::uint32_t>::max();

/// Common base of the four handle types; `Tag` keeps them distinct types.
template <class Tag>
class Handle {
public:
    constexpr Handle() = default;
    explicit constexpr Handle(std::uint32_t idx) : idx_(idx) {}

    /// The element's position in its property arrays.
    constexpr std::uint32_t idx() const { return idx_; }
    /// False for a default-constructed handle ("none").
    constexpr bool is_valid() const { return idx_ != kInvalidIndex; }

    constexpr auto operator<=>(const Handle&) const = default;

private:
    std::uint32_t idx_ = kInvalidIndex;
};

/// A vertex of the mesh.
class Vertex : public Handle<Vertex> {
public:
    using Handle::Handle;
};

/// A directed half of an edge. Halfedges 2k and 2k+1 are twins and together form edge k.
class Halfedge : public Handle<Halfedge> {
public:
    using Handle::Handle;
};

/// An undirected edge; its halfedges are 2k and 2k+1.
class Edge : public Handle<Edge> {
public:
    using Handle::Handle;
};

/// A face (a polygon with at least three sides).
class Face : public Handle<Face> {
public:
    using Handle::Handle;
};

}  // namespace meshedit

template <class Tag>
struct std::hash<meshedit::Handle<Tag>> {
    std::size_t operator()(const meshedit::Handle<Tag>& h) const noexcept { return h.idx(); }
};
template <>
struct std::hash<meshedit::Vertex> : std::hash<meshedit::Handle<meshedit::Vertex>> {};
template <>
struct std::hash<meshedit::Halfedge> : std::hash<meshedit::Handle<meshedit::Halfedge>> {};
template <>
struct std::hash<meshedit::Edge> : std::hash<meshedit::Handle<meshedit::Edge>> {};
template <>
struct std::hash<meshedit::Face> : std::hash<meshedit::Handle<meshedit::Face>> {};
