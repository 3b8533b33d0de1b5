#pragma once
/// \file
/// Inputs shared by the benchmark programs that need polygon meshes (bench_local_ops,
/// bench_catmark).

#include <cmath>
#include <cstdint>

#include "meshedit/core/build.h"
#include "meshedit/core/mesh.h"

namespace meshedit::bench {

/// The m × n quad grid on a torus (R = 1, r = 0.4), closed, no boundary: m·n vertices, vertex
/// (i, j) = i·n + j. With `cut_tenth`, quad (i, j) is cut into two triangles when
/// (i + 3j) % 10 == 0, so one quad in ten is two triangles (1.1·m·n faces).
inline PolygonSoup quad_torus_soup(int m, int n, bool cut_tenth) {
    PolygonSoup soup;
    soup.positions.reserve(std::size_t(m) * n);
    for (int i = 0; i < m; ++i) {
        const double u = 2.0 * M_PI * i / m;
        for (int j = 0; j < n; ++j) {
            const double v = 2.0 * M_PI * j / n;
            const double rho = 1.0 + 0.4 * std::cos(v);
            soup.positions.push_back({rho * std::cos(u), rho * std::sin(u), 0.4 * std::sin(v)});
        }
    }
    const auto id = [&](int i, int j) { return std::uint32_t((i % m) * n + (j % n)); };
    for (int i = 0; i < m; ++i) {
        for (int j = 0; j < n; ++j) {  // (u, then v) order is outward, as shapes::torus
            const std::uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1),
                                d = id(i, j + 1);
            if (cut_tenth && (i + 3 * j) % 10 == 0) {
                soup.add_face({a, b, c});
                soup.add_face({a, c, d});
            } else {
                soup.add_face({a, b, c, d});
            }
        }
    }
    return soup;
}

inline Mesh quad_torus(int m, int n, bool cut_tenth) {
    return build_mesh(quad_torus_soup(m, n, cut_tenth));
}

}  // namespace meshedit::bench
