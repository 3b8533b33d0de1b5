// Procedural shapes. Each builds a PolygonSoup with outward (counter-clockwise from outside)
// corner order and hands it to build_mesh(), so shapes exercise the same path as file input.

#include "meshedit/core/shapes.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <tuple>
#include <unordered_map>

#include "meshedit/core/assert.h"
#include "meshedit/core/build.h"

namespace meshedit::shapes {
namespace {

using Index = std::uint32_t;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Splits every triangle of `soup` into four, sharing one midpoint per undirected edge, and
// projects the new points to the unit sphere.
PolygonSoup split_on_sphere(const PolygonSoup& soup) {
    PolygonSoup out;
    out.positions = soup.positions;
    // Key: smaller index in the high half, larger in the low half.
    std::unordered_map<std::uint64_t, Index> midpoints;
    midpoints.reserve(soup.n_faces() * 3 / 2);
    auto midpoint = [&](Index a, Index b) {
        const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
        auto [it, inserted] = midpoints.try_emplace(key, Index(out.positions.size()));
        if (inserted) {
            out.positions.push_back(normalize(out.positions[a] + out.positions[b]));
        }
        return it->second;
    };
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const Index* c = &soup.indices[soup.face_offsets[f]];
        const Index a = c[0], b = c[1], d = c[2];
        const Index ab = midpoint(a, b), bd = midpoint(b, d), da = midpoint(d, a);
        out.add_face({a, ab, da});
        out.add_face({ab, b, bd});
        out.add_face({da, bd, d});
        out.add_face({ab, bd, da});
    }
    return out;
}

PolygonSoup icosahedron_soup() {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    PolygonSoup soup;
    soup.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3& p : soup.positions) {
        p = normalize(p);
    }
    static constexpr std::array<std::array<Index, 3>, 20> kFaces{{
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1},
    }};
    for (const auto& f : kFaces) {
        soup.add_face_range(f);
    }
    return soup;
}

}  // namespace

Mesh tetrahedron() {
    PolygonSoup soup;
    const double s = 1.0 / std::sqrt(3.0);
    soup.positions = {{s, s, s}, {s, -s, -s}, {-s, s, -s}, {-s, -s, s}};
    soup.add_face({0, 1, 2});
    soup.add_face({0, 3, 1});
    soup.add_face({0, 2, 3});
    soup.add_face({1, 3, 2});
    return build_mesh(soup);
}

Mesh cube() {
    PolygonSoup soup;
    for (int i = 0; i < 8; ++i) {
        soup.positions.push_back(
            {(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0});
    }
    // Each side is split along the diagonal from its lowest-index corner; the list is
    // repeated verbatim in shapes.h, which tests compare against.
    static constexpr std::array<std::array<Index, 3>, 12> kFaces{{
        {0, 4, 6},
        {0, 6, 2},  // -x
        {1, 3, 7},
        {1, 7, 5},  // +x
        {0, 1, 5},
        {0, 5, 4},  // -y
        {2, 6, 7},
        {2, 7, 3},  // +y
        {0, 2, 3},
        {0, 3, 1},  // -z
        {4, 5, 7},
        {4, 7, 6},  // +z
    }};
    for (const auto& f : kFaces) {
        soup.add_face_range(f);
    }
    return build_mesh(soup);
}

Mesh icosahedron() {
    return build_mesh(icosahedron_soup());
}

Mesh icosphere(int k) {
    PolygonSoup soup = icosahedron_soup();
    for (int i = 0; i < k; ++i) {
        soup = split_on_sphere(soup);
    }
    return build_mesh(soup);
}

Mesh torus(int m, int n, double R, double r) {
    MESHEDIT_ASSERT(m >= 3 && n >= 3);
    PolygonSoup soup;
    soup.positions.reserve(std::size_t(m) * n);
    for (int i = 0; i < m; ++i) {
        const double u = kTwoPi * i / m;
        for (int j = 0; j < n; ++j) {
            const double v = kTwoPi * j / n;
            const double rho = R + r * std::cos(v);
            soup.positions.push_back({rho * std::cos(u), rho * std::sin(u), r * std::sin(v)});
        }
    }
    auto id = [&](int i, int j) { return Index((i % m) * n + (j % n)); };
    // d/du × d/dv points away from the tube axis, so (u, then v) order is outward.
    for (int i = 0; i < m; ++i) {
        for (int j = 0; j < n; ++j) {
            const Index a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            soup.add_face({a, b, c});
            soup.add_face({a, c, d});
        }
    }
    return build_mesh(soup);
}

Mesh grid(int nx, int ny) {
    MESHEDIT_ASSERT(nx >= 1 && ny >= 1);
    PolygonSoup soup;
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            soup.positions.push_back({double(i) / nx, double(j) / ny, 0.0});
        }
    }
    auto id = [&](int i, int j) { return Index(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            soup.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            soup.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    return build_mesh(soup);
}

Mesh disk(int n) {
    MESHEDIT_ASSERT(n >= 3);
    PolygonSoup soup;
    soup.positions.push_back({0.0, 0.0, 0.0});
    for (int k = 0; k < n; ++k) {
        const double a = kTwoPi * k / n;
        soup.positions.push_back({std::cos(a), std::sin(a), 0.0});
    }
    for (int k = 0; k < n; ++k) {
        soup.add_face({0, Index(k + 1), Index((k + 1) % n + 1)});
    }
    return build_mesh(soup);
}

Mesh cylinder(int m, int n) {
    MESHEDIT_ASSERT(m >= 3 && n >= 1);
    PolygonSoup soup;
    for (int j = 0; j <= n; ++j) {
        const double z = -1.0 + 2.0 * j / n;
        for (int i = 0; i < m; ++i) {
            const double a = kTwoPi * i / m;
            soup.positions.push_back({std::cos(a), std::sin(a), z});
        }
    }
    auto id = [&](int i, int j) { return Index(j * m + (i % m)); };
    // Around (θ), then up (z): tangent(θ) × z is the outward radial direction.
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < m; ++i) {
            soup.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            soup.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    return build_mesh(soup);
}

Mesh quad_sphere(int k) {
    MESHEDIT_ASSERT(k >= 1);
    // Cube faces as (normal, u, v) axis triples with u × v = normal, so (u, then v) is CCW
    // seen from outside. Axes are signed: +1..+3 for +x..+z, negative for the opposite side.
    static constexpr std::array<std::array<int, 3>, 6> kSides{
        {{+1, +2, +3}, {-1, +3, +2}, {+2, +3, +1}, {-2, +1, +3}, {+3, +1, +2}, {-3, +2, +1}}};
    // Lattice points on the cube surface have integer coordinates in [-k, k] (step 2), so
    // welding along cube edges is an exact key lookup, not a tolerance test.
    std::map<std::tuple<int, int, int>, Index> lattice;
    PolygonSoup soup;
    auto axis = [](int signed_axis) {
        std::array<int, 3> a{0, 0, 0};
        a[std::abs(signed_axis) - 1] = signed_axis > 0 ? 1 : -1;
        return a;
    };
    auto vertex = [&](const std::array<int, 3>& p) {
        auto [it, inserted] = lattice.try_emplace({p[0], p[1], p[2]}, Index(soup.positions.size()));
        if (inserted) {
            soup.positions.push_back(normalize(Vec3(p[0], p[1], p[2])));
        }
        return it->second;
    };
    std::vector<Index> ids(std::size_t(k + 1) * (k + 1));
    for (const auto& side : kSides) {
        const auto n = axis(side[0]), u = axis(side[1]), v = axis(side[2]);
        for (int j = 0; j <= k; ++j) {
            for (int i = 0; i <= k; ++i) {
                std::array<int, 3> p{};
                for (int c = 0; c < 3; ++c) {
                    p[c] = n[c] * k + u[c] * (2 * i - k) + v[c] * (2 * j - k);
                }
                ids[j * (k + 1) + i] = vertex(p);
            }
        }
        for (int j = 0; j < k; ++j) {
            for (int i = 0; i < k; ++i) {
                const std::size_t a = j * (k + 1) + i;
                soup.add_face({ids[a], ids[a + 1], ids[a + k + 2], ids[a + k + 1]});
            }
        }
    }
    return build_mesh(soup);
}

Mesh quad_grid(int nx, int ny) {
    MESHEDIT_ASSERT(nx >= 1 && ny >= 1);
    PolygonSoup soup;
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            soup.positions.push_back({double(i), double(j), 0.0});
        }
    }
    auto id = [&](int i, int j) { return Index(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            soup.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    return build_mesh(soup);
}

Mesh quad_torus(int m, int n) {
    MESHEDIT_ASSERT(m >= 3 && n >= 3);
    PolygonSoup soup;
    for (int i = 0; i < m; ++i) {
        for (int j = 0; j < n; ++j) {
            const double u = kTwoPi * i / m, w = kTwoPi * j / n;
            soup.positions.push_back({(1.0 + 0.4 * std::cos(w)) * std::cos(u),
                                      (1.0 + 0.4 * std::cos(w)) * std::sin(u), 0.4 * std::sin(w)});
        }
    }
    auto id = [&](int i, int j) { return Index(((i + m) % m) * n + (j + n) % n); };
    for (int i = 0; i < m; ++i) {
        for (int j = 0; j < n; ++j) {
            soup.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    return build_mesh(soup);
}

}  // namespace meshedit::shapes
