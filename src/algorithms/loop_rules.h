#pragma once
// Private to meshedit_core: the Loop subdivision rules shared by the fast path
// (subdivision.cpp) and the classic reference (loop_steps.cpp). Both paths gather
// their inputs differently (raw arrays vs. circulators) and feed them through these
// functions, so there is exactly one definition of every weight and rule.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/math.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/subdivision.h"

namespace meshedit::loop_rules {

// ----------------------------------------------------------------- weights

/// `u` for an interior vertex of valence n: `p' = (1 - n·u)·p + u·Σ neighbours`.
/// Warren: 3/16 for n = 3, else 3/(8n). Loop: (5/8 − (3/8 + 1/4·cos(2π/n))²)/n. The two agree
/// at n = 3 (3/16) and n = 6 (1/16) and differ otherwise. n = 0 (isolated vertex) gives 0.
inline double interior_weight(std::size_t n, LoopWeights weights) {
    if (n == 0) {
        return 0.0;
    }
    const double dn = static_cast<double>(n);
    if (weights == LoopWeights::Loop) {
        const double c = 0.375 + 0.25 * std::cos(2.0 * std::numbers::pi / dn);
        return (0.625 - c * c) / dn;
    }
    return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * dn);
}

/// interior_weight() cached for small valences (the cosine is not free in a hot loop).
class WeightTable {
public:
    explicit WeightTable(LoopWeights weights) : weights_(weights) {
        for (std::size_t n = 0; n < table_.size(); ++n) {
            table_[n] = interior_weight(n, weights);
        }
    }
    double operator()(std::size_t n) const {
        return n < table_.size() ? table_[n] : interior_weight(n, weights_);
    }

private:
    LoopWeights weights_;
    std::array<double, 32> table_{};
};

// ----------------------------------------------------------------- classification

/// An edge is sharp when it is on the boundary or flagged in kCreaseProperty.
inline bool is_sharp(bool boundary, std::uint8_t crease_flag) {
    return boundary || crease_flag != 0;
}

/// How an old vertex moves, by the number of sharp edges at it.
enum class VertexRule : std::uint8_t {
    Smooth,  ///< 0 sharp edges, or 1 (a dart): the interior weights
    Crease,  ///< exactly 2 (boundary or crease curve): 3/4·p + 1/8·(a + b)
    Corner,  ///< 3 or more: stays put
};

inline VertexRule classify(std::size_t n_sharp) {
    if (n_sharp <= 1) {
        return VertexRule::Smooth;
    }
    return n_sharp == 2 ? VertexRule::Crease : VertexRule::Corner;
}

// ----------------------------------------------------------------- position rules

/// Smooth old vertex: `(1 − n·u)·p + u·Σ neighbours`, u from `weight(n)`.
inline Vec3 smooth_vertex_point(const Vec3& p, const Vec3& neighbour_sum, std::size_t n, double u) {
    return (1.0 - static_cast<double>(n) * u) * p + u * neighbour_sum;
}

/// Old vertex on exactly two sharp edges whose far ends sum to `sharp_sum` (= a + b).
inline Vec3 crease_vertex_point(const Vec3& p, const Vec3& sharp_sum) {
    return 0.75 * p + 0.125 * sharp_sum;
}

/// Interior edge A-B between triangles whose third corners are C and D.
inline Vec3 smooth_edge_point(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return 0.375 * (a + b) + 0.125 * (c + d);
}

/// Boundary or crease edge A-B: the midpoint.
inline Vec3 sharp_edge_point(const Vec3& a, const Vec3& b) {
    return midpoint(a, b);
}

// ----------------------------------------------------------------- preconditions

/// Brings the mesh into the shape both paths expect: garbage collected (dense indices, so
/// the new vertex on edge e is V + e) and all faces triangles.
/// \return the report with the number of triangulated faces.
/// \throws std::invalid_argument if is_loop_ok() refuses, before anything changes.
inline LoopReport prepare(Mesh& mesh) {
    if (const OpStatus ok = is_loop_ok(mesh); !ok) {
        throw std::invalid_argument(std::string(ok.reason()));
    }
    LoopReport report;
    if (mesh.has_garbage()) {
        mesh.garbage_collection();
    }
    if (!mesh.is_triangle_mesh()) {
        report.triangulated_faces = triangulate(mesh);
        // triangulate() adds edges and faces but deletes nothing; collect anyway so the
        // index layout never depends on that.
        if (mesh.has_garbage()) {
            mesh.garbage_collection();
        }
    }
    return report;
}

/// The crease flags, or a null property when the mesh has none (of type uint8).
inline EdgeProperty<std::uint8_t> crease_property(const Mesh& mesh) {
    return mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
}

// ----------------------------------------------------------------- progress

/// Forwards progress to LoopOptions::progress, if set, with non-decreasing values; callers
/// call it once per chunk of work (never per element).
class Progress {
public:
    explicit Progress(const std::function<void(double)>& callback) : callback_(callback) {}
    bool enabled() const { return static_cast<bool>(callback_); }
    void operator()(double fraction) {
        if (callback_ && fraction >= last_) {
            last_ = fraction;
            callback_(fraction);
        }
    }

private:
    const std::function<void(double)>& callback_;
    double last_ = 0.0;
};

}  // namespace meshedit::loop_rules
