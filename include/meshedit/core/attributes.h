#pragma once
/// \file
/// Names of the well-known attributes: properties that more than one layer reads or writes
/// (the core's operations, the file formats, the renderer, the editor). An algorithm's own
/// scratch properties are named where they are used; connectivity has no name outside the
/// mesh (mesh.h).

#include <string_view>
#include <utility>

#include "meshedit/core/properties.h"

namespace meshedit {

/// Edge property (`std::uint8_t`, non-zero = sharp): crease edges. Loop subdivides them like
/// boundaries, split() passes the flag to both halves, COLLADA keeps them in MeshEdit's
/// `<extra>`, the renderer draws them green.
inline constexpr const char* kCreaseProperty = "e:crease";

/// Halfedge property (Vec2): the texture coordinate of the corner of face(h) at to_vertex(h)
/// (face-varying: a seam is where two corners of a vertex differ). OBJ `vt`, glTF TEXCOORD_0.
inline constexpr const char* kTexCoordProperty = "h:texcoord";
/// Halfedge property (Vec2): the second texture coordinate set (a lightmap's, say), face-varying
/// like the first and carried, refined, simplified and compared by the same rules, with seams
/// of its own. glTF TEXCOORD_1, COLLADA's `<input semantic="TEXCOORD" set="1">`; OBJ, OFF,
/// PLY and STL have none. The renderer and the viewer show the first set only.
inline constexpr const char* kTexCoord1Property = "h:texcoord1";
/// The texture coordinate sets, in order: what treats texture coordinates treats each of them.
inline constexpr const char* kTexCoordSets[] = {kTexCoordProperty, kTexCoord1Property};
/// Halfedge property (Vec3): the normal a file gave the corner of face(h) at to_vertex(h)
/// (split normals; per-vertex normals are the seamless case). OBJ `vn`, glTF NORMAL.
inline constexpr const char* kCornerNormalProperty = "h:normal";
/// Vertex property (Vec4, RGBA, each 0–1): the vertex colour. Blends like positions through
/// every operation (a split's midpoint gets the mean colour). PLY red green blue alpha, OFF
/// COFF, OBJ `v x y z r g b`, glTF COLOR_0.
inline constexpr const char* kColorProperty = "v:color";
/// Face property (Vec4, RGBA, each 0–1): a face colour (OFF's colour after the index list).
inline constexpr const char* kFaceColorProperty = "f:color";
/// Face property (std::uint32_t): the face's index in Mesh::materials() (OBJ `usemtl`).
inline constexpr const char* kMaterialProperty = "f:material";

/// The properties a phased Loop leaves on the mesh between phases (loop_steps.h), which the
/// renderer's overlay draws: where each vertex goes, and which vertices and edges the phases
/// made or flipped.
inline constexpr const char* kLoopTarget = "v:loop_target";        ///< Vec3: where it goes
inline constexpr const char* kLoopHasTarget = "v:loop_has";        ///< uint8: 1 if it has one
inline constexpr const char* kLoopEdgePoint = "e:loop_point";      ///< Vec3 (phase 1 only)
inline constexpr const char* kLoopNewVertex = "v:loop_new";        ///< uint8: made by a split
inline constexpr const char* kLoopNewEdge = "e:loop_new";          ///< uint8: crosses an old face
inline constexpr const char* kLoopFlippedEdge = "e:loop_flipped";  ///< uint8: flipped in 3

/// What a phased Catmull-Clark (cc_steps.h) leaves on the mesh between phases: which vertices
/// are face points (phase 1) and edge points (phase 2), and that the old ones moved (3).
inline constexpr const char* kCcFacePoint = "v:cc_face_point";  ///< uint8
inline constexpr const char* kCcEdgePoint = "v:cc_edge_point";  ///< uint8
inline constexpr const char* kCcMoved = "v:cc_moved";           ///< uint8 (all 1)

/// The well-known attributes whose Carry rule is not their type's default (Mesh::carry()):
/// a crease survives any merge or split that touches it; the Loop overlay is written by its
/// phases, never derived.
inline constexpr std::pair<std::string_view, Carry> kCarryRules[] = {
    {kCreaseProperty, Carry::Any},   {kLoopTarget, Carry::None},    {kLoopHasTarget, Carry::None},
    {kLoopEdgePoint, Carry::None},   {kLoopNewVertex, Carry::None}, {kLoopNewEdge, Carry::None},
    {kLoopFlippedEdge, Carry::None}, {kCcFacePoint, Carry::None},   {kCcEdgePoint, Carry::None},
    {kCcMoved, Carry::None},
};

}  // namespace meshedit
