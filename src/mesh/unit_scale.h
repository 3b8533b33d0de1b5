#pragma once
// Private to meshedit_core: runs an algorithm whose arithmetic squares coordinates (quadrics,
// lengths, areas) on a mesh scaled by a power of two so that its largest coordinate lies in
// [0.5, 1): coordinates near 1e300 would overflow and near 1e-300 underflow, and a power of
// two scales both ways without rounding.

#include <algorithm>
#include <cmath>

#include "meshedit/core/mesh.h"

namespace meshedit {

/// The exponent e of the largest coordinate (in [2^(e−1), 2^e)), 0 for an empty or all-zero
/// mesh: multiplying by 2^−e brings every coordinate into (−1, 1).
inline int unit_exponent(const Mesh& mesh) {
    double largest = 0.0;
    for (Vertex v : mesh.vertices()) {
        const Vec3& p = mesh.position(v);
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    int exponent = 0;
    if (largest > 0.0 && std::isfinite(largest)) {
        std::frexp(largest, &exponent);
    }
    return exponent;
}

/// p · 2^exponent.
inline Vec3 scaled_point(const Vec3& p, int exponent) {
    return {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent)};
}

class UnitScale {
public:
    explicit UnitScale(Mesh& mesh) : mesh_(mesh), exponent_(unit_exponent(mesh)) {
        apply(-exponent_);
    }
    ~UnitScale() { apply(exponent_); }
    UnitScale(const UnitScale&) = delete;
    UnitScale& operator=(const UnitScale&) = delete;

    /// A length of the original mesh in the scaled one, and back.
    double scaled(double length) const { return std::ldexp(length, -exponent_); }
    double unscaled(double length) const { return std::ldexp(length, exponent_); }

private:
    void apply(int exponent) {
        if (exponent == 0) {
            return;
        }
        for (Vertex v : mesh_.vertices()) {
            mesh_.position(v) = scaled_point(mesh_.position(v), exponent);
        }
    }

    Mesh& mesh_;
    int exponent_;
};

}  // namespace meshedit
