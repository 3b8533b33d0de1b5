#pragma once
/// \file
/// Names of the well-known attributes: properties that more than one layer reads or writes
/// (the core's operations, the file formats, the renderer, the editor). An algorithm's own
/// scratch properties are named where they are used; connectivity has no name outside the
/// mesh (mesh.h).

namespace meshedit {

/// Edge property (`std::uint8_t`, non-zero = sharp): crease edges. Loop subdivides them like
/// boundaries, split() passes the flag to both halves, COLLADA keeps them in MeshEdit's
/// `<extra>`, the renderer draws them green.
inline constexpr const char* kCreaseProperty = "e:crease";

}  // namespace meshedit
