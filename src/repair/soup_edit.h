#pragma once
/// \file
/// Editing a MeshSoup with its attributes in step (private to meshedit_repair): removing
/// faces, renumbering vertices, turning faces over, and the wording the steps share.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "meshedit/io/io.h"
#include "meshedit/repair/repair.h"

namespace meshedit::repair_detail {

/// A vertex that renumber_vertices() removes.
inline constexpr std::uint32_t kGone = UINT32_MAX;

/// `fraction` of the box's diagonal, clamped to the largest double (no overflow).
double fraction_of_diagonal(const BoundingBox& box, double fraction);

/// Whether a closed part has an inside and which way it faces, summed triangle by triangle
/// (corners relative to one origin, for the digits): six times the signed volume, twice the
/// area, and the extent. A flat part, a double-sided sheet (6|V| ≤ 1e-6 · 2A · diagonal:
/// thinner than a millionth of its size), encloses nothing and faces neither way; its sign
/// is the rounding's (the fills closed one in 2CylinderEngine.glb, which `check --problems`
/// called inside out while repair, from another origin, left it). Orienting, the fills' turn
/// and the Problems panel all decide by this.
struct Enclosure {
    double six_volume = 0.0;
    double twice_area = 0.0;
    BoundingBox box;

    void add(const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 n = cross(b - a, c - a);
        six_volume += dot(a, cross(b, c));
        twice_area += norm(n);
        box.add(a);
        box.add(b);
        box.add(c);
    }
    bool faces_inward() const { return six_volume < -1e-6 * twice_area * box.diagonal(); }
};

/// The merge distance `tolerance` names for the vertices faces use.
double merge_distance(const PolygonSoup& soup, const MergeTolerance& tolerance);

/// Calls fn(a, b, face, corner) for each side of each face, from its corner `corner` (an
/// index into soup.indices) at vertex a to the next corner's vertex b; sides whose ends are
/// one vertex are skipped.
template <class Fn>
void for_each_side(const PolygonSoup& soup, Fn&& fn) {
    for (std::uint32_t f = 0; f < soup.n_faces(); ++f) {
        const std::uint32_t begin = soup.face_offsets[f];
        const std::uint32_t n = soup.face_offsets[f + 1] - begin;
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t a = soup.indices[begin + i];
            const std::uint32_t b = soup.indices[begin + (i + 1) % n];
            if (a != b) {
                fn(a, b, f, begin + i);
            }
        }
    }
}

/// Which vertices some face uses.
std::vector<bool> used_vertices(const PolygonSoup& soup);

/// Keeps the faces with keep[f], in order, with their corner attributes, materials and face
/// property values; the others go with theirs.
void keep_faces(MeshSoup& soup, const std::vector<bool>& keep);

/// A corner of a rebuilt face (rebuild_faces()): vertex `vertex`, with the attributes of old
/// corner `c` moved `t` of the way to those of old corner `d` (t = 0: c's as they are).
struct NewCorner {
    std::uint32_t vertex, c, d;
    double t;
};

/// Replaces every face: new face k has the corners [offsets[k], offsets[k + 1]) of `corners`
/// (texture coordinates blended, normals blended and normalised) and old face source[k]'s
/// material, colour and property values. Vertices and creases stay as they are.
void rebuild_faces(MeshSoup& soup, const std::vector<NewCorner>& corners,
                   const std::vector<std::uint32_t>& offsets,
                   const std::vector<std::uint32_t>& source);

/// Keeps the corners with keep[c] (with their attributes); each face keeps its kept corners
/// in order, and may be left with fewer than 3 (the caller removes it).
void keep_corners(MeshSoup& soup, const std::vector<bool>& keep);

/// Renumbers vertex v as new_index[v] (kGone: removed) among `n_new` vertices. A new vertex
/// takes the position, normal and property values of the lowest old vertex that maps to it.
/// Faces and creases are renumbered; \return how many creases were dropped (their ends became
/// one vertex, or one was removed).
std::size_t renumber_vertices(MeshSoup& soup, const std::vector<std::uint32_t>& new_index,
                              std::size_t n_new);

/// Removes the vertices that were used (used_before[v]) and are used by no face now.
/// \return how many; creases dropped with them are added to `dropped_creases`.
std::size_t remove_unused_vertices(MeshSoup& soup, const std::vector<bool>& used_before,
                                   std::size_t& dropped_creases);

/// Reverses the corners of face f and their attributes, keeping the first corner first.
void reverse_face(MeshSoup& soup, std::size_t f);

/// Why a polygon is degenerate (remove_degenerate_faces()), or None.
enum class Degenerate { None, Few, Pinched, Flat };

/// Drops repeated consecutive corners of a polygon (cyclically: a, a, b, c, a is a, b, c).
void drop_repeated_corners(std::vector<std::uint32_t>& corners);

/// Whether the polygon through vertices `corners` (no repeated consecutive corners) has fewer
/// than 3 corners, a corner twice, or zero area: below 1e-12 of its longest side squared,
/// where rounding cannot tell it from 0.
Degenerate degenerate(const std::vector<Vec3>& positions,
                      const std::vector<std::uint32_t>& corners);

/// Appends `index` to result.first while fewer than kRepairShown are listed.
void note_first(RepairResult& result, std::uint32_t index);

/// "1 face" / "3 faces".
std::string count_of(std::size_t n, const char* one, const char* many);

/// ": 3, 7, 9" or ": 3, 7, 9, 11, 12, …" (when `count` is more than listed).
std::string listed(const RepairResult& result);

/// "; and 2 vertices only they used; dropped 1 crease …", what went with the removed faces.
std::string also_removed(std::size_t vertices, std::size_t creases);

/// A number in the project's shortest round-trip form.
std::string number(double x);

/// Turns over each part that a fill closed (no boundary left, found from the faces `filled`)
/// and that encloses a negative volume (holes.cpp): a part had no inside while it was open.
/// \return how many parts; `faces` counts their faces.
std::size_t turn_closed_parts_outward(Mesh& mesh, const std::vector<Face>& filled,
                                      std::size_t& faces);
/// "turned over 12 faces so that 1 part the fills closed faces outward".
std::string turned_outward(std::size_t faces, std::size_t parts);

}  // namespace meshedit::repair_detail
