#pragma once
// Private to meshedit_algorithms: the position quadric of QEM simplification, shared by
// simplify.cpp and the attribute quadrics of simplify_attributes.h.

#include <algorithm>
#include <cmath>

#include "meshedit/core/math.h"

namespace meshedit::qem {

// A symmetric 4 × 4 quadric v^T Q v, v = (x, y, z, 1), as its 10 distinct entries, and the
// face area it gathers (for the error in distance units).
struct Quadric {
    double a00 = 0, a01 = 0, a02 = 0, a03 = 0, a11 = 0, a12 = 0, a13 = 0, a22 = 0, a23 = 0, a33 = 0;
    double area = 0;

    // w · (plane)(plane)^T for the plane n·x + d = 0.
    void add_plane(const Vec3& n, double d, double w) {
        a00 += w * n.x * n.x, a01 += w * n.x * n.y, a02 += w * n.x * n.z, a03 += w * n.x * d;
        a11 += w * n.y * n.y, a12 += w * n.y * n.z, a13 += w * n.y * d;
        a22 += w * n.z * n.z, a23 += w * n.z * d;
        a33 += w * d * d;
    }
    Quadric operator+(const Quadric& o) const {
        Quadric q;
        q.a00 = a00 + o.a00, q.a01 = a01 + o.a01, q.a02 = a02 + o.a02, q.a03 = a03 + o.a03;
        q.a11 = a11 + o.a11, q.a12 = a12 + o.a12, q.a13 = a13 + o.a13;
        q.a22 = a22 + o.a22, q.a23 = a23 + o.a23, q.a33 = a33 + o.a33;
        q.area = area + o.area;
        return q;
    }
    double operator()(const Vec3& p) const {
        const double x = p.x, y = p.y, z = p.z;
        return a00 * x * x + 2 * a01 * x * y + 2 * a02 * x * z + 2 * a03 * x + a11 * y * y +
               2 * a12 * y * z + 2 * a13 * y + a22 * z * z + 2 * a23 * z + a33;
    }
    // The minimiser of v^T Q v, when the 3 × 3 system is well conditioned.
    bool minimiser(Vec3& out) const {
        const double c00 = a11 * a22 - a12 * a12;
        const double c01 = a02 * a12 - a01 * a22;
        const double c02 = a01 * a12 - a02 * a11;
        const double det = a00 * c00 + a01 * c01 + a02 * c02;
        const double scale = std::max({a00, a11, a22});
        if (!(std::abs(det) > 1e-9 * scale * scale * scale)) {
            return false;
        }
        const double c11 = a00 * a22 - a02 * a02;
        const double c12 = a01 * a02 - a00 * a12;
        const double c22 = a00 * a11 - a01 * a01;
        const double inv = -1.0 / det;
        out = {inv * (c00 * a03 + c01 * a13 + c02 * a23), inv * (c01 * a03 + c11 * a13 + c12 * a23),
               inv * (c02 * a03 + c12 * a13 + c22 * a23)};
        return std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z);
    }
};

}  // namespace meshedit::qem
