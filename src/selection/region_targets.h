#pragma once
// Private to meshedit_selection: where subdivide_region() puts the points of a smooth scheme
// (Loop, Catmull-Clark) inside the region, computed on the mesh before it is cut.

#include <cstddef>
#include <utility>
#include <vector>

#include "meshedit/selection/region_ops.h"

namespace meshedit::region_detail {

struct RegionTargets {
    /// The old vertices that move (inner ones, on no crease) and where to.
    std::vector<std::pair<Vertex, Vec3>> vertices;
    /// Per edge of `edges` (subdivide_region()'s order): whether its midpoint moves, and where.
    std::vector<std::pair<bool, Vec3>> edge_points;
};

/// The scheme's new places: for every edge with both faces in the region and no crease mark
/// its edge point, for every inner vertex (every face around it in the region, not on the
/// boundary, on no crease) its vertex point; everything else stays where the linear pattern
/// puts it, so the transition ring and the border join the rest without a gap.
RegionTargets smooth_targets(const Mesh& mesh, const FaceSet& region,
                             const std::vector<Edge>& edges, RegionScheme scheme);

}  // namespace meshedit::region_detail
