#pragma once
/// \file
/// The quality measures of the benchmarks that change a surface (bench_simplify,
/// bench_remesh), the same code for every implementation: a sampled symmetric Hausdorff
/// distance, the smallest angle, the spread of edge lengths.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "meshedit/core/build.h"
#include "meshedit/core/closest_point.h"
#include "meshedit/core/display_fan.h"
#include "meshedit/core/mesh.h"

namespace meshedit::bench {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;
inline constexpr int kSamples = 100'000;

struct Surface {
    std::vector<Vec3> points;
    Triangles triangles;
};

/// The halfedge mesh of a surface (build_mesh(), as every MeshEdit run starts from).
inline Mesh mesh_of(const Surface& s) {
    PolygonSoup soup;
    soup.positions = s.points;
    for (const auto& t : s.triangles) {
        soup.add_face({t[0], t[1], t[2]});
    }
    return build_mesh(soup);
}

/// The triangles of a mesh (polygons cut as the renderer cuts them), its live vertices
/// numbered densely.
inline Surface surface_of(const Mesh& mesh) {
    Surface out;
    std::vector<std::uint32_t> index(mesh.vertices_size(), 0);
    for (Vertex v : mesh.vertices()) {
        index[v.idx()] = static_cast<std::uint32_t>(out.points.size());
        out.points.push_back(mesh.position(v));
    }
    for (Face f : mesh.faces()) {
        for_each_fan_triangle(mesh, f, [&](std::size_t, Vertex c0, Halfedge h) {
            out.triangles.push_back({index[c0.idx()], index[mesh.from_vertex(h).idx()],
                                     index[mesh.to_vertex(h).idx()]});
        });
    }
    return out;
}

// The largest distance from kSamples points on `from` (by area, fixed seed) to `to`.
inline double one_sided(const Surface& from, const TriangleTree& to) {
    std::vector<double> cumulative;
    cumulative.reserve(from.triangles.size());
    double total = 0.0;
    for (const auto& t : from.triangles) {
        const Vec3& a = from.points[t[0]];
        total += 0.5 * norm(cross(from.points[t[1]] - a, from.points[t[2]] - a));
        cumulative.push_back(total);
    }
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < kSamples; ++i) {
        const auto at = std::lower_bound(cumulative.begin(), cumulative.end(), unit(rng) * total);
        const auto& t = from.triangles[std::min<std::size_t>(at - cumulative.begin(),
                                                             from.triangles.size() - 1)];
        double r1 = std::sqrt(unit(rng)), r2 = unit(rng);
        const Vec3 p = from.points[t[0]] * (1 - r1) + from.points[t[1]] * (r1 * (1 - r2)) +
                       from.points[t[2]] * (r1 * r2);
        worst = std::max(worst, std::sqrt(to.closest(p).distance_squared));
    }
    return worst;
}

inline double hausdorff_percent(const Surface& input, const Surface& result) {
    const TriangleTree in_tree(input.points, input.triangles);
    const TriangleTree out_tree(result.points, result.triangles);
    BoundingBox box;
    for (const Vec3& p : input.points) {
        box.add(p);
    }
    const double d = std::max(one_sided(input, out_tree), one_sided(result, in_tree));
    return 100.0 * d / box.diagonal();
}

/// The smallest angle of any triangle, in degrees.
inline double min_angle_deg(const Surface& s) {
    double smallest = 180.0;
    for (const auto& t : s.triangles) {
        for (int i = 0; i < 3; ++i) {
            const Vec3& p = s.points[t[i]];
            const Vec3 u = s.points[t[(i + 1) % 3]] - p, v = s.points[t[(i + 2) % 3]] - p;
            const double c = dot(u, v) / (norm(u) * norm(v));
            smallest = std::min(smallest, std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI);
        }
    }
    return smallest;
}

/// Of the vertices inside the surface (not on its border), the share with valence 6, in %,
/// and how many have valence 4 or less: what isotropic remeshing's flips aim at.
struct Valences {
    double six_pct = 0.0;
    std::size_t four_or_less = 0;
};
inline Valences interior_valences(const Surface& s) {
    std::vector<std::uint32_t> valence(s.points.size(), 0);
    std::set<std::pair<std::uint32_t, std::uint32_t>> once, twice;
    for (const auto& t : s.triangles) {
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t a = t[i], b = t[(i + 1) % 3];
            const std::pair<std::uint32_t, std::uint32_t> e{std::min(a, b), std::max(a, b)};
            if (!once.insert(e).second) {
                twice.insert(e);
            } else {
                ++valence[a];
                ++valence[b];
            }
        }
    }
    std::vector<bool> border(s.points.size(), false);
    for (const auto& e : once) {
        if (twice.count(e) == 0) {
            border[e.first] = border[e.second] = true;
        }
    }
    std::size_t inside = 0, six = 0;
    Valences out;
    for (std::size_t v = 0; v < valence.size(); ++v) {
        if (valence[v] == 0 || border[v]) {
            continue;
        }
        ++inside;
        six += valence[v] == 6 ? 1 : 0;
        out.four_or_less += valence[v] <= 4 ? 1 : 0;
    }
    out.six_pct = inside > 0 ? 100.0 * static_cast<double>(six) / static_cast<double>(inside) : 0.0;
    return out;
}

/// The standard deviation of the edge lengths over their mean (each edge once).
inline double edge_length_spread(const Surface& s) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& t : s.triangles) {
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t a = t[i], b = t[(i + 1) % 3];
            edges.insert({std::min(a, b), std::max(a, b)});
        }
    }
    double sum = 0.0, squares = 0.0;
    for (const auto& [a, b] : edges) {
        const double l = distance(s.points[a], s.points[b]);
        sum += l;
        squares += l * l;
    }
    const double n = static_cast<double>(edges.size());
    const double mean = sum / n;
    return std::sqrt(std::max(0.0, squares / n - mean * mean)) / mean;
}

}  // namespace meshedit::bench
