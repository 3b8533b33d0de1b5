#pragma once
/// \file
/// A bounding-volume hierarchy over a mesh's faces for ray queries: what lets the viewer pick
/// the element under the cursor on the CPU (render/cpu_pick.h) in microseconds instead of an
/// ID render pass over every triangle.
///
/// Faces are cut into the display fan (display_fan.h), as MeshRenderer cuts them, so a hit
/// names the triangle the ID pass would shade: its face, its corners c0 c1 c2 and its sides
/// c0->c1, c1->c2, c2->c0 as halfedges, invalid where the side is a fan diagonal.
///
/// The tree holds indices only (a face, its fan position and three vertices per triangle);
/// positions are read from the mesh at query time, so the mesh passed to intersect() must be
/// the one built or updated, with no vertex moved since unless its faces were passed to
/// update(). After garbage_collection() (which renumbers) call build() again: update() takes
/// faces past the mesh's end for ones an undo took away, not for renumbered ones.
///
/// Local edits: update(mesh, touched) takes the faces an edit changed (their corners, their
/// shape or their deletion; for a moved vertex, every face around it). Their triangles in the
/// tree are marked stale (skipped, their boxes kept), and the touched faces that are still
/// live, with any face appended since, are fan-triangulated into a small overflow list that
/// every query tests by brute force. When the overflow exceeds kUpdateLimit triangles, or the
/// stale ones exceed both that and a quarter of the tree, update() rebuilds the whole tree.

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "meshedit/core/handles.h"
#include "meshedit/core/math.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

class FaceBvh {
public:
    /// A ray origin + t · direction over [t_min, t_max] (direction need not be unit).
    struct Ray {
        Vec3 origin;
        Vec3 direction;
        double t_min = 0.0;
        double t_max = std::numeric_limits<double>::infinity();
    };

    /// The nearest triangle a ray meets.
    struct Hit {
        Face face;
        std::array<Vertex, 3> corners;  ///< c0 (the fan's hub), c1, c2
        /// c0->c1, c1->c2, c2->c0; invalid for a fan diagonal (no mesh edge).
        std::array<Halfedge, 3> sides;
        std::array<double, 3> barycentric{};  ///< of c0, c1, c2 at the hit point
        double t = 0.0;
        /// The ray meets the counter-clockwise (outward) side: the side the renderer keeps
        /// when it culls back faces.
        bool front = true;
    };

    /// Which triangles a ray may hit: both sides, or front sides only (back faces culled).
    enum class Sides { Both, FrontOnly };

    /// update() rebuilds the tree once more triangles than this are in the overflow list (or
    /// stale, and a quarter of the tree).
    static constexpr std::size_t kUpdateLimit = 4096;

    FaceBvh() = default;
    explicit FaceBvh(const Mesh& mesh) { build(mesh); }

    /// Builds the tree over the live faces of `mesh` (binned SAH, ~0.1–0.3 s per million
    /// triangles); the overflow list ends empty.
    void build(const Mesh& mesh);

    /// Brings the tree up to date after a local edit: `touched` are the faces whose corners,
    /// shape or liveness changed (deleted ones included, any order, repeats allowed); faces
    /// appended since the last build or update are taken as touched, and so are faces past
    /// the mesh's end (an undone creation: gone). O(touched + overflow)
    /// unless it rebuilds (see the file comment).
    void update(const Mesh& mesh, std::span<const Face> touched);

    /// The nearest triangle that `ray` meets within its range, or nothing. Ties in t keep one
    /// of the tied triangles.
    std::optional<Hit> intersect(const Mesh& mesh, const Ray& ray, Sides sides = Sides::Both) const;

    /// Where the line origin + t · direction meets the plane of triangle (a, b, c): t and the
    /// barycentrics (of a, b, c), wherever on the plane and the line that is; nothing when the
    /// line is parallel to the plane. The same arithmetic as intersect()'s triangle test.
    static std::optional<std::array<double, 4>> line_plane(const Vec3& a, const Vec3& b,
                                                           const Vec3& c, const Vec3& origin,
                                                           const Vec3& direction);

    /// Triangles in the tree (stale ones included) and in the overflow list.
    std::size_t tree_size() const { return tris_.size(); }
    std::size_t stale_count() const { return stale_; }
    std::size_t overflow_size() const { return overflow_.size(); }
    /// How many times update() fell back to a full rebuild (for tests and statistics).
    std::size_t rebuilds() const { return rebuilds_; }
    bool empty() const { return tris_.size() == stale_ && overflow_.empty(); }

private:
    /// One fan triangle: (c[0], c[1], c[2]) = (c0, from(h), to(h)), h = next^fan(halfedge(f)).
    struct Triangle {
        std::uint32_t face = kInvalidIndex;  ///< kInvalidIndex: stale
        std::uint32_t fan = 0;               ///< i of for_each_fan_triangle, 1 … n−2
        std::array<std::uint32_t, 3> c{};
    };
    /// Children of an inner node are adjacent: `first` and `first` + 1.
    struct Node {
        std::array<float, 3> lo{};
        std::uint32_t first = 0;  ///< leaf: first triangle in tris_; inner: left child
        std::array<float, 3> hi{};
        std::uint32_t count = 0;  ///< triangles of a leaf; 0 for an inner node
    };

    static void append_fan(const Mesh& mesh, Face f, std::vector<Triangle>& out);
    void test(const Mesh& mesh, const Triangle& tri, const Ray& ray, Sides sides, double& best_t,
              const Triangle*& best, std::array<double, 3>& best_b, bool& best_front) const;

    std::vector<Node> nodes_;                ///< nodes_[0] is the root (absent when empty)
    std::vector<Triangle> tris_;             ///< in leaf order
    std::vector<std::uint32_t> face_first_;  ///< face f's triangles: slots_[face_first_[f] …
                                             ///< face_first_[f + 1])
    std::vector<std::uint32_t> slots_;       ///< their positions in tris_
    std::vector<Triangle> overflow_;         ///< tested by brute force
    std::size_t faces_known_ = 0;            ///< faces_size() at the last build or update
    std::size_t stale_ = 0;
    std::size_t rebuilds_ = 0;
};

}  // namespace meshedit
