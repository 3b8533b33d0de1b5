#pragma once
/// \file
/// Face and vertex normals, and the signed volume they enclose.

#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/core/op_status.h"

namespace meshedit {

/// Twice the area vector of `f` (Newell's formula; for a triangle, the cross product of two
/// edges). Its direction is the face normal, its length twice the area.
Vec3 face_area_vector(const Mesh& mesh, Face f);
/// Unit normal of `f` (zero for a degenerate face).
Vec3 face_normal(const Mesh& mesh, Face f);
/// The mean of `f`'s corners (where a face's dot is drawn and what a box selects it by).
Vec3 face_centroid(const Mesh& mesh, Face f);

/// Unit face normals for every face index (deleted faces get zero), written into `out`
/// (resized; its capacity is reused between calls).
void compute_face_normals(const Mesh& mesh, std::vector<Vec3>& out);

/// Area-weighted vertex normals: for each vertex, the normalised sum of the area vectors of
/// its faces. One pass over the faces, no circulation per vertex. Isolated vertices and
/// vertices whose faces cancel get zero. `out` is indexed by vertex index (resized; capacity
/// reused). On meshes of 100,000 faces or more, chunks of faces run on thread_count()
/// threads (threads.h). The order of every sum depends on the mesh
/// alone, so the result is bit-for-bit the same for any number of threads (and, up to 65,536
/// faces, the plain sum in face order).
void compute_vertex_normals(const Mesh& mesh, std::vector<Vec3>& out);
/// The same with at most `max_threads` threads (0: no limit beyond the hardware's).
void compute_vertex_normals(const Mesh& mesh, std::vector<Vec3>& out, unsigned max_threads);

/// After a local edit: brings `out`, the vertex normals compute_vertex_normals() gave when the
/// mesh had `old_vertices` and `old_faces` as vertices_size() and faces_size(), up to date,
/// bit for bit as a full compute_vertex_normals() would give them now. The edit changed
/// `faces` (their corners, or created or deleted them) and `vertices` (moved them, created
/// them, or changed their faces): MeshChange::region() gives both; indices out of range or
/// deleted are allowed. Every corner of those faces and of the faces around those vertices
/// is summed again in the full pass's order, and so are the few vertices whose place in
/// that order moved with the sizes (the parallel chunks' vertex ranges are proportional to
/// the sizes). O(what changed). Appends every vertex it recomputed to `recomputed` (sorted,
/// unique), around which the caller redraws.
void update_vertex_normals(const Mesh& mesh, std::span<const Face> faces,
                           std::span<const Vertex> vertices, std::size_t old_vertices,
                           std::size_t old_faces, std::vector<Vec3>& out,
                           std::vector<Vertex>& recomputed);

/// Signed volume enclosed by the faces (each polygon fanned from its first corner): positive
/// when a closed mesh's faces point outwards, negative when it is inside out. Meaningful for
/// closed meshes only; taken about the first live vertex, so far-off meshes keep precision.
double signed_volume(const Mesh& mesh);

/// True when the mesh is closed (no boundary halfedge) and every connected component encloses
/// a positive signed volume, i.e. every part's faces point outwards. Then, seen from outside
/// every part, only front faces can be visible (unless a surface intersects itself), which
/// lets a renderer cull back faces. One inside-out part makes it false.
bool is_closed_and_outward(const Mesh& mesh);

/// Which edges split smooth shading ("sharp" edges): crease edges (kCreaseProperty) when
/// `creases`, and with `auto_smooth_deg` every edge whose two faces' normals differ by more
/// than that angle (Blender's Auto Smooth). A boundary edge bounds anyway: it has one face.
struct NormalSplit {
    bool creases = true;
    std::optional<double> auto_smooth_deg;
};

/// The dihedral angle of interior edge `e` in degrees: the angle between its two faces'
/// normals, 0 where the surface is flat, near 180 where it folds back. NaN on the boundary
/// or beside a degenerate face (no normal). What the `dihedral` field shows.
double dihedral_angle_deg(const Mesh& mesh, Edge e);

/// The feature angle of remesh() and simplify() that marks nothing (off).
inline constexpr double kNoFeatureAngle = std::numeric_limits<double>::infinity();

/// Why crease_by_angle() cannot run with `degrees`, or ok: NaN, below 0 or above 180. Pure.
OpStatus check_crease_by_angle(double degrees);

/// Marks as creases (kCreaseProperty, the flag K toggles) every interior edge whose dihedral
/// angle exceeds `degrees` (Blender's Select Sharp Edges and Mark Sharp): the creases that are
/// there stay, boundary edges and edges beside a degenerate face are left alone, and the crease
/// property is added only when an edge is marked. Writes through the property's handle after
/// mesh.touch(e), so a recorded edit undoes it. O(E). \pre check_crease_by_angle() returned
/// ok. \return how many edges it marked (creases already are not counted).
std::size_t crease_by_angle(Mesh& mesh, double degrees);

/// Area-weighted normals per face corner, indexed by halfedge: `out[h]` is the normal of the
/// corner at to_vertex(h) in face(h). Around a vertex the sharp edges cut its faces into
/// wedges; each corner gets the normalised sum of the area vectors of its wedge. A vertex on
/// no sharp edge gets its vertex normal (`vertex_normals`, from compute_vertex_normals()), so
/// a mesh without sharp edges shades exactly as with vertex normals. Boundary halfedges get
/// zero. O(H). \return false, leaving `out` alone, when no edge is sharp.
bool compute_corner_normals(const Mesh& mesh, const NormalSplit& split,
                            const std::vector<Vec3>& vertex_normals, std::vector<Vec3>& out);

/// Convenience forms returning a new vector.
std::vector<Vec3> face_normals(const Mesh& mesh);
std::vector<Vec3> vertex_normals(const Mesh& mesh);

}  // namespace meshedit
