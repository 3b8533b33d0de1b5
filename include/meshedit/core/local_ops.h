#pragma once
/// \file
/// Local operations on the halfedge mesh. Contract (as Scotty3D's halfedge-local.cpp states
/// it): each op either succeeds, or returns a refusal with a reason and leaves the mesh
/// exactly as it was. Each has a pure predicate (`is_*_ok`) the UI can call to grey out a
/// command; the op calls the same predicate first. Diagrams: docs/halfedge.md and above each
/// op in src/local_ops/flip_split.cpp, collapse.cpp and triangulate.cpp.

#include <cstdint>
#include <string_view>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/core/op_status.h"

namespace meshedit {

/// Which operation's code names the elements of a rewiring diagram (h0, t0, a, b, v0 … as
/// the diagrams above flip, split and collapse and in docs/halfedge.md call them); ByIndex:
/// labelled by index. The verb table states it per verb (ops::Verb::names) and the diagram
/// (render/op_diagram.h) reads it, so neither compares verb names. Collapse also widens the
/// region drawn to every face at either end of the edge (what a collapse relinks).
enum class CodeNames : std::uint8_t { ByIndex, Flip, Split, Collapse };

/// The outcome of an op: the handle it documents on success, or the refusal reason.
template <class H>
class OpResult {
public:
    constexpr OpResult(H value) : value_(value) {}  // NOLINT: implicit on purpose
    constexpr OpResult(OpStatus refusal) : reason_(refusal.reason()) {}  // NOLINT

    explicit constexpr operator bool() const { return reason_.empty(); }
    constexpr bool ok() const { return reason_.empty(); }
    /// The handle; \pre ok().
    constexpr H value() const { return value_; }
    constexpr H operator*() const { return value_; }
    constexpr std::string_view reason() const { return reason_; }

private:
    H value_{};
    std::string_view reason_;
};

/// \return ok if `e` is a live interior edge whose flipped edge would not already exist (nor
/// join a vertex to itself) and whose faces would not visit a vertex twice.
OpStatus is_flip_ok(const Mesh& mesh, Edge e);
/// Turns `e` inside its two faces to join the corners that follow its ends: for triangles
/// (a,b,c),(c,b,d) → (a,d,c),(a,b,d) where b-c is `e`; polygons keep their number of sides
/// (Scotty3D's rule; docs/halfedge.md). No allocation; O(1) relinking after an
/// O(valence(a)) search for an existing a-d edge (plus O(sides) for polygons).
/// \return the same edge handle, now joining a and d.
OpResult<Edge> flip(Mesh& mesh, Edge e);

/// \return ok if `e` is live, has a face, and is not between two triangles on the same three
/// corners.
OpStatus is_split_ok(const Mesh& mesh, Edge e);
/// Splits `e` at its midpoint. An interior edge's two triangles become four; a boundary
/// edge's one triangle becomes two and the boundary gains the vertex. A face beside `e` that
/// is not a triangle is not divided: it only gains the vertex as a corner (as bisect()).
/// O(1); no allocation beyond appending the new elements. A crease edge (kCreaseProperty)
/// leaves two creases.
/// \return the new vertex m. `halfedge(m)` is `halfedge(e, i)`, where i = 0 for an interior
/// edge and i is the boundary side for a boundary edge: it runs along the original edge from
/// m towards the old `to_vertex(halfedge(e, i))`, and `e` itself (shortened) is that half.
/// So on a boundary edge `halfedge(m)` is m's outgoing boundary halfedge, as the
/// boundary-anchor rule requires.
OpResult<Vertex> split(Mesh& mesh, Edge e);

/// \return ok if `e` is live.
OpStatus is_bisect_ok(const Mesh& mesh, Edge e);
/// Inserts a vertex m at the midpoint of `e` without dividing any face: both faces (or a
/// face and a boundary loop) gain m as a corner. A crease edge leaves two creases.
/// \return m; `halfedge(m)` follows the same rule as split()'s.
OpResult<Vertex> bisect(Mesh& mesh, Edge e);

/// \return ok if collapsing `e` keeps the mesh a valid manifold: `e` is not an interior edge
/// joining two boundary vertices (that would pinch the surface); the link condition holds
/// (the endpoints' common neighbours are exactly the corners opposite `e` in the triangles
/// beside it, and no other polygon holds both endpoints); and nothing degenerates (a
/// tetrahedron, a lone triangle, a two-triangle pillow).
OpStatus is_collapse_ok(const Mesh& mesh, Edge e);
/// Collapses `e` to its midpoint. The endpoint with the smaller index survives (so CLI edge
/// names stay predictable); the other endpoint, `e`, the triangles beside `e` and one of the
/// two edges each of them merges are deleted (garbage collection is left to the caller); a
/// polygon beside `e` only loses a corner.
/// O(valence). \return the surviving vertex, anchored at an outgoing boundary halfedge if
/// it is on the boundary.
OpResult<Vertex> collapse(Mesh& mesh, Edge e);

/// \return ok if shrinking `f` to a point keeps the mesh a valid manifold: no other face
/// would visit the new vertex twice or shrink below three corners (a triangle across a side
/// disappears), no two edges would join the same vertices, and the new vertex would be on
/// one hole at most with a face left around it.
OpStatus is_collapse_face_ok(const Mesh& mesh, Face f);
/// Shrinks `f` to one vertex at the average of its corners (Scotty3D's collapse_face): the
/// corner with the smallest index survives there, the others, f's sides and f go; a polygon
/// across a side loses a corner, a triangle across one disappears (its two other edges
/// merge), a boundary gap across one closes over it. \return the surviving vertex.
OpResult<Vertex> collapse_face(Mesh& mesh, Face f);

/// \return ok if `f` is live and can be cut into triangles without adding an edge that
/// already exists (a triangle is ok: triangulating it changes nothing).
OpStatus is_triangulate_ok(const Mesh& mesh, Face f);
/// Splits polygon `f` into triangles by diagonals inside it, never adding an edge that
/// already exists: a fan from `from_vertex(halfedge(f))` if possible, else a fan from the
/// first corner after it that allows one, else any valid triangulation (O(n³) search).
/// \return `f` (now one of the triangles).
OpResult<Face> triangulate(Mesh& mesh, Face f);
/// Triangulates every non-triangle face; faces that is_triangulate_ok() refuses are left
/// as they are. \return how many faces were triangulated.
std::size_t triangulate(Mesh& mesh);

// ------------------------------------------- removing and filling
// (src/local_ops/dissolve.cpp)

/// \return ok if `f` is live and no corner of it would be on two holes once it is gone (a
/// corner already on the boundary must have a side of `f` on that boundary).
OpStatus is_make_boundary_ok(const Mesh& mesh, Face f);
/// Deletes `f`, leaving a hole (Scotty3D's make_boundary, "delete face"). Sides of `f` that
/// were on the boundary already go with it, so the hole merges with the holes beside it, and
/// corners left without edges go too; the mesh may fall into several parts.
/// \return a boundary halfedge of the new hole, or an invalid handle when nothing of `f`'s
/// part is left (a lone face).
OpResult<Halfedge> make_boundary(Mesh& mesh, Face f);

/// \return ok if `h` is a live boundary halfedge whose loop has at least three sides.
OpStatus is_fill_hole_ok(const Mesh& mesh, Halfedge h);
/// Fills the boundary loop through `h` with one new face. \return the face.
OpResult<Face> fill_hole(Mesh& mesh, Halfedge h);

/// \return ok if `e` is live and the faces beside it share no corner but its ends (inside),
/// or its face can become a hole (make_boundary's rule, on the boundary).
OpStatus is_dissolve_edge_ok(const Mesh& mesh, Edge e);
/// Removes `e` and merges the two faces beside it into one, the face of `halfedge(e, 0)`.
/// On the boundary the one face joins the hole, as make_boundary() does.
/// \return the merged face, or an invalid handle for a boundary edge.
OpResult<Face> dissolve_edge(Mesh& mesh, Edge e);

/// \return ok if `v` is live, has edges, and the merged face would have at least three
/// corners, none twice; on the boundary, the edge that closes it must not exist yet.
OpStatus is_dissolve_vertex_ok(const Mesh& mesh, Vertex v);
/// Removes `v` and its edges and merges the faces around it into one. On the boundary an
/// edge joins v's two boundary neighbours (one of v's boundary edges, turned), so the merged
/// face does not swallow the hole. \return the merged face.
OpResult<Face> dissolve_vertex(Mesh& mesh, Vertex v);

// ------------------------------------------------------------- welding
// (src/local_ops/weld.cpp)

/// \return ok if `e1` and `e2` are two live boundary edges of different faces whose weld
/// would not make a face visit a vertex twice, nor an edge join a vertex to itself, nor two
/// edges join the same vertices.
OpStatus is_weld_ok(const Mesh& mesh, Edge e1, Edge e2);
/// Glues boundary edges `e1` and `e2` into one interior edge (Scotty3D's weld_edges): e1's
/// face and e2's face meet across it, oriented alike. The ends of `e1` survive, each at the
/// midpoint of itself and the end of `e2` it meets; e2 and its ends go. Two edges that meet
/// at a vertex are zipped there. \return `e1`.
OpResult<Edge> weld(Mesh& mesh, Edge e1, Edge e2);

// ------------------------------------------------------------ faces (src/local_ops/poke.cpp)

/// \return ok if `f` is live.
OpStatus is_poke_ok(const Mesh& mesh, Face f);
/// Pokes `f` (Scotty3D's inset_vertex): a new vertex c at the average of f's corners, joined
/// to every corner, so that an n-gon becomes a fan of n triangles; `f` stays the triangle on
/// `halfedge(f)` and the n − 1 others are new. Works on any face, boundary sides included.
/// \return c; `halfedge(c)` runs from c to `from_vertex(halfedge(f))`.
OpResult<Vertex> poke(Mesh& mesh, Face f);

// ------------------------------------------------ inset and extrude
// (src/local_ops/extrude.cpp)

/// \return ok if `f` is live, the amounts are finite, `shrink` is below 1 and, for a height
/// other than 0, `f` has an area (so a normal).
OpStatus is_extrude_ok(const Mesh& mesh, Face f, double height, double shrink);
/// Surrounds `f` with a ring of quads, one per side, whose inner corners are a copy of f's
/// moved `shrink` of the way to f's centre (0: the same size, 0.5: half; negative grows) and
/// `height` (model units) along f's unit normal. `f` keeps its handle and becomes the inner
/// face; the outer corners do not move. \return `f`.
OpResult<Face> extrude_face(Mesh& mesh, Face f, double height, double shrink);
/// \return ok if `f` is live and `shrink` is finite and below 1.
OpStatus is_inset_ok(const Mesh& mesh, Face f, double shrink);
/// extrude_face() with height 0: a ring of quads inside `f`. \return `f`, the inner face.
OpResult<Face> inset_face(Mesh& mesh, Face f, double shrink);

/// An interactive extrude or inset builds its topology once (Scotty3D's extrude_positions):
/// extrude_face() at the first amounts, then extrude_positions() for every other amount. Taken
/// just before extrude_face(): f's sides h[i] (p[i] -> p[i+1]), its corners p[i], their
/// average, and where the operation's new elements start.
struct ExtrudeBase {
    Face f;
    std::vector<Halfedge> sides;
    std::vector<Vec3> corners;
    Vec3 centre{0, 0, 0};
    std::uint32_t first_vertex = 0, first_edge = 0, first_face = 0;
};
ExtrudeBase extrude_base(const Mesh& mesh, Face f);
/// Whether extrude_positions() can place the corners at these amounts (is_extrude_ok()'s
/// reasons). Pure.
OpStatus is_extrude_positions_ok(const ExtrudeBase& base, double height, double shrink);
/// Puts the inner corners extrude_face() made where extrude_face(base.f, height, shrink)
/// puts them and blends what they carry with the weights of that shrink: the mesh is then
/// bit for bit what extrude_face() at these amounts makes. Writes only elements the
/// operation appended (what a recorded change's refresh_after() takes in).
/// \pre extrude_face(base.f, …) ran just after `base` was taken, and nothing since but this.
OpStatus extrude_positions(Mesh& mesh, const ExtrudeBase& base, double height, double shrink);

// ------------------------------------------------------------ bevel (src/local_ops/bevel.cpp)

/// \return ok if `v` is live with at least three edges and 0 <= t < 1.
OpStatus is_bevel_vertex_ok(const Mesh& mesh, Vertex v, double t);
/// Replaces `v` by a new face with one corner on each of its edges, a fraction `t` of the way
/// along it (t = 0: a face of no area at v's place). Each face around v gains a corner; on
/// the boundary the new face has a side on the hole. \return the new face.
OpResult<Face> bevel_vertex(Mesh& mesh, Vertex v, double t);
/// \return ok if `e` is live, its ends have at least five edges together (so the new face has
/// three corners or more) and 0 <= t < 1.
OpStatus is_bevel_edge_ok(const Mesh& mesh, Edge e, double t);
/// Replaces `e` by a new face with one corner on each other edge of its two ends, a fraction
/// `t` of the way along it; `e` goes. On the boundary the new face has a side on the hole
/// (Scotty3D refuses boundary edges; Blender bevels them, and so does MeshEdit).
/// \return the new face.
OpResult<Face> bevel_edge(Mesh& mesh, Edge e, double t);

/// What a bevel of a vertex or an edge will make, taken just before it runs (as Scotty3D's
/// bevel_positions() takes its start positions): the fan of halfedges split apart, the
/// corner each one leaves after the bevel (the reused vertex or the one it appends), where
/// each corner starts to slide, and the values the bevel's carry overwrites in place (of
/// the reused corners and of the corners of the faces around). The interactive bevel builds
/// the topology once and then only calls bevel_positions().
struct BevelBase {
    Face face;                       ///< the face the bevel makes
    std::vector<Halfedge> o;         ///< the fan; corner w[i] slides along o[i]
    std::vector<Vertex> w;           ///< the corners
    std::vector<bool> reused;        ///< w[i] was a vertex before (the bevelled one, an end)
    std::vector<Vertex> from;        ///< the vertex w[i] slides from
    std::vector<Vec3> start;         ///< from[i]'s position before the bevel
    std::vector<Halfedge> at_start;  ///< loop i's corner at from[i] (before the bevel)
    std::vector<Halfedge> at_next;   ///< loop i's corner just before to_vertex(o[i+1])
    std::uint32_t first_edge = 0;    ///< the new edge of loop i is first_edge + i
    std::vector<std::vector<std::byte>> kept_w;         ///< reused w[i]'s attribute values
    std::vector<std::vector<std::byte>> kept_arriving;  ///< twin(o[i+1])'s attribute values
};
/// \pre is_bevel_vertex_ok() / is_bevel_edge_ok() (any amount). Pure.
BevelBase bevel_vertex_base(const Mesh& mesh, Vertex v);
BevelBase bevel_edge_base(const Mesh& mesh, Edge e);
/// \return ok if bevel_positions() can place the corners at `t` (0 <= t < 1). Pure.
OpStatus is_bevel_positions_ok(const BevelBase& base, double t);
/// Puts the corners a bevel made where the same bevel at amount `t` puts them and derives
/// what they carry again with t's weights: the mesh is then bit for bit what the bevel at
/// `t` makes. Writes only elements the bevel wrote (what a recorded change's refresh_after()
/// takes in). \pre the bevel ran just after `base` was taken, and nothing since but this.
OpStatus bevel_positions(Mesh& mesh, const BevelBase& base, double t);

// ----------------------------------------------------- orientation
// (src/local_ops/orientation.cpp)

/// Reverses every face and boundary loop (Scotty3D's flip_orientation): each halfedge
/// runs the other way, so outward becomes inward. Never refuses; creates and deletes
/// nothing; handles stay valid. Applying it twice gives the mesh back bit for bit.
void flip_orientation(Mesh& mesh);

}  // namespace meshedit
