#pragma once
/// \file
/// Selecting regions of a mesh as an editor does (Blender's loops, rings, linked, grow and
/// shrink, select by trait, shortest path; MeshLab's select by condition). GL-free: the box
/// and lasso, which need a camera, build on these sets in meshedit_overlay. Every function is
/// pure and costs what it visits: a loop or a ring the edges it walks, a flood the region.

#include <cstdint>
#include <optional>
#include <vector>

#include "meshedit/core/mesh.h"

namespace meshedit {

/// A set of elements of one kind, as one bit per element index (a million faces: 125 KB).
template <class H>
class ElementSet {
public:
    ElementSet() = default;
    /// An empty set for a mesh with `size` elements of the kind (Mesh::faces_size(), …).
    explicit ElementSet(std::size_t size) : size_(size), words_((size + 63) / 64, 0) {}

    std::size_t size() const { return size_; }  ///< the index range, not the count
    bool contains(H h) const {
        return h.idx() < size_ && ((words_[h.idx() / 64] >> (h.idx() % 64)) & 1) != 0;
    }
    void insert(H h) { words_[h.idx() / 64] |= std::uint64_t{1} << (h.idx() % 64); }
    void erase(H h) { words_[h.idx() / 64] &= ~(std::uint64_t{1} << (h.idx() % 64)); }
    /// How many elements are in the set.
    std::size_t count() const;
    bool empty() const { return count() == 0; }
    /// The elements in increasing index order.
    std::vector<H> elements() const;
    bool operator==(const ElementSet&) const = default;

private:
    std::size_t size_ = 0;
    std::vector<std::uint64_t> words_;
};

using VertexSet = ElementSet<Vertex>;
using EdgeSet = ElementSet<Edge>;
using FaceSet = ElementSet<Face>;

// ------------------------------------------------------------ loops and rings

/// The edge loop through `e` (Blender's Alt+click): from each end, on across every interior
/// vertex of valence 4 to the edge opposite the one it came by. It stops at a pole (valence
/// other than 4) and at the border; a loop that comes back to `e` is closed. On the border,
/// a boundary edge's loop follows the boundary across vertices of valence 3 (the border of
/// a quad grid) and stops at corners. In walking order, `e` first, then one way, then the
/// other. \pre `e` is live.
std::vector<Edge> edge_loop(const Mesh& mesh, Edge e);

/// The edge ring through `e` (Blender's Ctrl+Alt+click): across each quad beside it to the
/// opposite edge, and on from there, until a face that is not a quad, the border, or `e`
/// again. In walking order, `e` first. \pre `e` is live.
std::vector<Edge> edge_ring(const Mesh& mesh, Edge e);

// ------------------------------------------------------------ regions

struct LinkedOptions {
    bool stop_at_creases = false;  ///< kCreaseProperty edges bound the region
    bool stop_at_seams = false;    ///< edges where the texture coordinates differ across
};
/// The faces reachable from `seeds` across edges (Blender's select linked, L).
FaceSet linked_faces(const Mesh& mesh, const FaceSet& seeds, const LinkedOptions& options = {});

/// The faces that share a vertex with one of `faces` (Blender's select more, Ctrl+numpad +).
FaceSet grow(const Mesh& mesh, const FaceSet& faces);
/// `faces` without those that share a vertex with a face outside it or with the border
/// (Blender's select less).
FaceSet shrink(const Mesh& mesh, const FaceSet& faces);
/// The vertices joined by an edge to one of `vertices`, and those.
VertexSet grow(const Mesh& mesh, const VertexSet& vertices);
/// `vertices` without those joined by an edge to a vertex outside it, or on the border.
VertexSet shrink(const Mesh& mesh, const VertexSet& vertices);
/// The live elements not in the set.
template <class H>
ElementSet<H> invert(const Mesh& mesh, const ElementSet<H>& set);

// ------------------------------------------------------------ by trait

enum class Trait {
    Boundary,    ///< vertices, edges and faces on the border
    Crease,      ///< crease edges (and their vertices, and the faces beside them)
    Valence,     ///< vertices with `k` edges
    Degree,      ///< faces with `k` corners
    FacingAway,  ///< faces whose normal turns more than `angle_deg` from `direction`
};
struct TraitQuery {
    Trait trait = Trait::Boundary;
    std::size_t k = 4;        ///< Valence, Degree
    Vec3 direction{0, 0, 1};  ///< FacingAway (need not be unit)
    double angle_deg = 90.0;  ///< FacingAway
};
VertexSet vertices_with(const Mesh& mesh, const TraitQuery& query);
EdgeSet edges_with(const Mesh& mesh, const TraitQuery& query);
FaceSet faces_with(const Mesh& mesh, const TraitQuery& query);

// ------------------------------------------------------------ between modes

/// Blender's conversions: a vertex selection selects the edges and faces all of whose
/// vertices are in it; an edge or face selection selects the vertices it touches.
EdgeSet edges_of_vertices(const Mesh& mesh, const VertexSet& vertices);
FaceSet faces_of_vertices(const Mesh& mesh, const VertexSet& vertices);
VertexSet vertices_of_faces(const Mesh& mesh, const FaceSet& faces);
VertexSet vertices_of_edges(const Mesh& mesh, const EdgeSet& edges);

// ------------------------------------------------------------ shortest paths

/// The vertices of a shortest path along the edges from `a` to `b` (Euclidean edge lengths,
/// Dijkstra; ties go to the lower index), `a` first; none when no path joins them.
std::optional<std::vector<Vertex>> shortest_vertex_path(const Mesh& mesh, Vertex a, Vertex b);
/// The faces of a shortest path across edges from `f` to `g` (distances between face
/// centroids), `f` first; none when no path joins them.
std::optional<std::vector<Face>> shortest_face_path(const Mesh& mesh, Face f, Face g);

}  // namespace meshedit
