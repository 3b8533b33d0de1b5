#pragma once
// Private to meshedit_core: the rules of Catmull-Clark (OpenSubdiv's Catmark scheme,
// infinitely sharp creases, boundary edges sharp) and of linear subdivision, shared by the
// fast path (quad_subdivision.cpp) and the classic reference (quad_subdivision_classic.cpp)
// so that there is one definition of every weight. Which edges are sharp and how many sharp
// edges make a crease or a corner is the same as Loop's (loop_rules.h): OpenSubdiv's Sdc
// classifies vertices the same way for every scheme.

#include <cstddef>

#include "algorithms/loop_rules.h"
#include "meshedit/core/math.h"
#include "meshedit/core/quad_subdivision.h"

namespace meshedit::catmark_rules {

/// The face point: the centroid of the k corners whose sum is `corner_sum`.
inline Vec3 face_point(const Vec3& corner_sum, std::size_t k) {
    return corner_sum * (1.0 / static_cast<double>(k));
}

/// An edge point. Catmull-Clark on a smooth edge A-B between faces with points F0 and F1:
/// (A + B + F0 + F1) / 4; on a boundary or crease edge, and always in linear subdivision,
/// the midpoint.
inline Vec3 edge_point(QuadScheme scheme, bool sharp, const Vec3& a, const Vec3& b, const Vec3& f0,
                       const Vec3& f1) {
    if (sharp || scheme == QuadScheme::Linear) {
        return loop_rules::sharp_edge_point(a, b);
    }
    return 0.25 * (a + b + f0 + f1);
}

/// What an old vertex p gathers from its one-ring: the far ends of its n edges, the points
/// of its faces, and the far ends of its sharp edges.
struct Ring {
    Vec3 neighbour_sum;
    Vec3 face_point_sum;
    Vec3 sharp_sum;
    std::size_t valence = 0;
    std::size_t n_sharp = 0;
};

/// The new position of old vertex p.
/// - Smooth (no sharp edge) or dart (one): p·(n − 2)/n + (Σ neighbours + Σ face points)/n²,
///   OpenSubdiv's Catmark smooth mask.
/// - Crease (two sharp edges, so every boundary vertex without creases): 3/4·p + 1/8·(a + b).
/// - Corner (three or more), or an isolated vertex: stays.
/// Linear subdivision keeps every old vertex where it is.
inline Vec3 vertex_point(QuadScheme scheme, const Vec3& p, const Ring& ring) {
    if (scheme == QuadScheme::Linear || ring.valence == 0) {
        return p;
    }
    switch (loop_rules::classify(ring.n_sharp)) {
        case loop_rules::VertexRule::Smooth: {
            const double n = static_cast<double>(ring.valence);
            return ((n - 2.0) / n) * p +
                   (ring.neighbour_sum + ring.face_point_sum) * (1.0 / (n * n));
        }
        case loop_rules::VertexRule::Crease:
            return loop_rules::crease_vertex_point(p, ring.sharp_sum);
        case loop_rules::VertexRule::Corner:
            break;
    }
    return p;
}

}  // namespace meshedit::catmark_rules
