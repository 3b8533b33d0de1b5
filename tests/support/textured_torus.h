#pragma once
/// \file
/// A torus with texture coordinates and vertex colours, for the attribute-aware QEM's test
/// (tests/core/simplify_attributes_test.cpp) and its bench row (bench/bench_simplify.cpp).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/shapes.h"

namespace meshedit::test {

// Texture coordinates (angle around the axis, angle around the tube) / 2π, each less `turn` (a
// share of a turn, to move the seams), as the set `name`, on a torus of major radius 1 about
// the z axis (any faces): one chart cut open along two loops (seams where the angles wrap),
// the UV an affine function of the angles.
inline void add_angle_uvs(Mesh& mesh, const char* name = kTexCoordProperty, double turn = 0.0) {
    auto uv = mesh.add_property<Halfedge, Vec2>(name);
    const auto wrap = [](double x) { return x - std::floor(x); };
    std::vector<Vec2> corner;
    std::vector<Halfedge> hs;
    for (Face f : mesh.faces()) {
        corner.clear();
        hs.clear();
        for (Halfedge h : mesh.halfedges(f)) {
            const Vec3& p = mesh.position(mesh.to_vertex(h));
            const double rho = std::hypot(p.x, p.y);
            const double u = std::atan2(p.y, p.x) / (2 * std::numbers::pi) - turn;
            const double v = std::atan2(p.z, rho - 1.0) / (2 * std::numbers::pi) - turn;
            corner.push_back(turn == 0.0 ? Vec2{u < -1e-9 ? u + 1.0 : u, v < -1e-9 ? v + 1.0 : v}
                                         : Vec2{wrap(u), wrap(v)});
            hs.push_back(h);
        }
        // A face across the wrap takes the far side's values on its near corners.
        for (const bool along_u : {true, false}) {
            double low = 2, high = -1;
            for (const Vec2& c : corner) {
                const double x = along_u ? c.x : c.y;
                low = std::min(low, x), high = std::max(high, x);
            }
            for (Vec2& c : corner) {
                double& x = along_u ? c.x : c.y;
                if (high - low > 0.5 && x < 0.5) {
                    x += 1.0;
                }
            }
        }
        for (std::size_t k = 0; k < hs.size(); ++k) {
            uv[hs[k]] = corner[k];
        }
    }
}

// shapes::torus(m, n) with add_angle_uvs().
inline Mesh uv_torus(int m, int n) {
    Mesh mesh = shapes::torus(m, n);
    add_angle_uvs(mesh);
    return mesh;
}

inline void add_colors(Mesh& mesh) {
    auto color = mesh.add_property<Vertex, Vec4>(kColorProperty);
    for (Vertex v : mesh.vertices()) {
        const Vec3& p = mesh.position(v);
        color[v] = {0.5 + 0.3 * std::sin(3 * p.x), 0.5 + 0.3 * std::cos(2 * p.y), 0.5 + 0.4 * p.z,
                    1.0};
    }
}

}  // namespace meshedit::test
