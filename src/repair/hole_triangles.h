#pragma once
// Private to meshedit_repair: which triangles cover a hole, computed on the hole's corners
// alone (indices 0…n−1 around it, side i from corner i to i + 1), and the flips that turn a
// fan into them, so that fill_holes_fair() makes the patch with the local operations.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "meshedit/core/math.h"

namespace meshedit::repair_detail {

/// Holes of up to this many sides take the minimum-weight search (O(n³), under a millisecond
/// at 100 sides).
inline constexpr std::size_t kMinEarSides = 100;
/// Larger ones up to this many sides are first clipped strictly in their mean plane (O(n²):
/// the outline must be simple there and every ear empty, so the cover does not fold), and
/// the fill flips the ears to Delaunay: on the bench's 300-edge holes the refined and faired
/// patch came out within 3% as close to the surface cut away as from the minimum-weight
/// cover, in 0.5–0.66 of the time (the O(n³) search was 17 of the armadillo's 47 ms).
inline constexpr std::size_t kMaxStrictEarSides = 5'000;
/// When that fails (an outline that folds over in its plane), the minimum-weight search up to
/// this many sides, then ear clipping without those checks (O(n log n)).
inline constexpr std::size_t kMaxDynamicSides = 300;

/// A hole as the triangulations see it.
struct HoleLoop {
    std::vector<Vec3> points;           ///< corner i's position
    std::vector<Vec3> outside_normals;  ///< unit normal of the face across side i
    /// Whether corners i and k may not be joined (the mesh has that edge already, or they
    /// are one vertex).
    std::function<bool(std::size_t, std::size_t)> forbidden;
};

/// Corners of a triangle, ordered as the sides run (side i appears as i → i + 1).
using HoleTriangle = std::array<std::uint32_t, 3>;

struct HoleTriangles {
    std::vector<HoleTriangle> triangles;  ///< n − 2 of them, or none
    std::string why;                      ///< why there are none
    bool clipped = false;                 ///< by clipped_ears() (not Delaunay: flip them)
};

/// Liepa (2003): the triangulation whose largest dihedral angle (between its triangles and
/// with the faces around the hole) is smallest, then of least area; O(n³) time, O(n²) memory.
HoleTriangles minimum_weight_triangles(const HoleLoop& hole);
/// Ear clipping: the corner with the smallest inside angle (in the hole's mean plane) first.
/// `strict`: only when the outline is simple in that plane, and only convex ears holding no
/// other corner (then the triangles do not overlap there); none, with the reason, otherwise.
HoleTriangles clipped_ears(const HoleLoop& hole, bool strict);
/// Which of the two, by the hole's size (the constants above).
HoleTriangles hole_triangles(const HoleLoop& hole);

/// One flip on the way from the fan: the fan's diagonal apex–z becomes x–y.
struct FanFlip {
    std::uint32_t x, y, z;
};
/// The flips that turn the fan around `apex` (its diagonals apex–k) into `triangles`, in the
/// order to apply them. O(n) flips, O(n) time.
std::vector<FanFlip> flips_from_fan(const std::vector<HoleTriangle>& triangles, std::size_t n,
                                    std::uint32_t apex);

}  // namespace meshedit::repair_detail
