#pragma once
/// \file
/// Holes cut out of a closed scan for bench_fill: a disc of faces around a seed face, grown in
/// the order of its distance from the seed (Dijkstra over the faces, a step the distance
/// between two centroids: geodesic-ish), until its border reaches the wanted number of edges.
/// The disc is then closed up so that the hole is one simple loop: a face with two or more
/// sides on the disc joins it (no slivers or one-face notches), and so do the faces around a
/// vertex the disc touches twice (a pinched border).
/// Vertex i of mesh_of(s) is point i of `s`, face f its triangle f. The removed faces are kept:
/// they are the surface a fill should give back.

#include <array>
#include <cstdint>
#include <functional>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bench_quality.h"
#include "meshedit/core/mesh.h"

namespace meshedit::bench {

struct CutHole {
    Surface holed;    ///< the scan without the disc, unused vertices dropped
    Surface removed;  ///< the disc's faces (the original surface where the hole is)
    std::size_t border_edges = 0;
};

/// The faces across each side of every face of a closed triangle mesh (mesh_of(s) numbers
/// faces as `s` does).
inline std::vector<std::array<std::uint32_t, 3>> face_neighbours(const Mesh& mesh) {
    std::vector<std::array<std::uint32_t, 3>> out(mesh.faces_size());
    for (const Face f : mesh.faces()) {
        int i = 0;
        for (const Halfedge h : mesh.halfedges(f)) {
            const Face g = mesh.face(Mesh::twin(h));
            if (!g.is_valid() || i > 2) {
                throw std::runtime_error("bench_holes: the scan must be a closed triangle mesh");
            }
            out[f.idx()][i++] = g.idx();
        }
    }
    return out;
}

/// The number of runs of disc faces around `v` (2 or more: the disc touches itself there).
inline int disc_runs(const Mesh& mesh, const std::vector<std::uint8_t>& in, Vertex v) {
    int runs = 0;  // counted where they start
    Face last;
    for (const Face f : mesh.faces(v)) {
        runs += (in[f.idx()] != 0 && (!last.is_valid() || in[last.idx()] == 0)) ? 1 : 0;
        last = f;
    }
    const Face first = *mesh.faces(v).begin();
    if (runs > 1 && in[first.idx()] != 0 && in[last.idx()] != 0) {
        --runs;  // the last run goes on into the first
    }
    return runs;
}

/// Cuts a hole of at least `wanted` border edges around face `seed` of the closed triangle
/// surface `s`. \throws std::runtime_error when the disc cannot grow that far (it would cover
/// the scan) or does not leave exactly one hole.
inline CutHole cut_hole(const Surface& s, std::uint32_t seed, std::size_t wanted) {
    const Mesh mesh = mesh_of(s);
    const auto across = face_neighbours(mesh);
    const std::size_t nf = s.triangles.size();
    std::vector<Vec3> centre(nf);
    for (std::size_t f = 0; f < nf; ++f) {
        const auto& t = s.triangles[f];
        centre[f] = (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) * (1.0 / 3.0);
    }
    std::vector<std::uint8_t> in(nf, 0);
    std::vector<double> dist(nf, 1e300);
    std::size_t border = 0, count = 0;
    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    std::vector<std::uint32_t> touched;  // faces added since the last closing up
    const auto add = [&](std::uint32_t f) {
        in[f] = 1;
        ++count;
        touched.push_back(f);
        for (const std::uint32_t g : across[f]) {
            border = in[g] != 0 ? border - 1 : border + 1;
            const double dg = dist[f] + distance(centre[f], centre[g]);
            if (in[g] == 0 && dg < dist[g]) {
                dist[g] = dg;
                queue.push({dg, g});
            }
        }
    };
    // Closing up: a face with two or more sides on the disc joins it, and so do the faces
    // around a vertex where the disc touches itself, until there are none. Only the faces
    // beside those added and the corners of those added can change, so a worklist does it.
    const auto close_up = [&] {
        while (!touched.empty()) {
            const std::uint32_t f = touched.back();
            touched.pop_back();
            for (const std::uint32_t g : across[f]) {
                int sides = 0;
                for (const std::uint32_t k : across[g]) {
                    sides += in[k];
                }
                if (in[g] == 0 && sides >= 2) {
                    add(g);
                }
            }
            for (const std::uint32_t c : s.triangles[f]) {
                const Vertex v(c);
                if (disc_runs(mesh, in, v) > 1) {
                    for (const Face g : mesh.faces(v)) {
                        if (in[g.idx()] == 0) {
                            add(g.idx());
                        }
                    }
                }
            }
        }
    };
    // Closing up shortens the border, so grow and close until it is long enough.
    dist[seed] = 0.0;
    queue.push({0.0, seed});
    while (border < wanted) {
        while (border < wanted && !queue.empty()) {
            const auto [d, f] = queue.top();
            queue.pop();
            if (in[f] == 0 && d <= dist[f]) {
                add(f);
            }
        }
        if (border < wanted || 2 * count > nf) {
            throw std::runtime_error("a hole of " + std::to_string(wanted) +
                                     " edges does not fit on this scan");
        }
        close_up();
    }
    CutHole out;
    out.border_edges = border;
    std::vector<std::uint32_t> index(s.points.size(), UINT32_MAX);
    for (std::size_t f = 0; f < nf; ++f) {
        const auto& t = s.triangles[f];
        if (in[f] != 0) {
            out.removed.triangles.push_back(t);
            continue;
        }
        std::array<std::uint32_t, 3> u{};
        for (int i = 0; i < 3; ++i) {
            if (index[t[i]] == UINT32_MAX) {
                index[t[i]] = static_cast<std::uint32_t>(out.holed.points.size());
                out.holed.points.push_back(s.points[t[i]]);
            }
            u[i] = index[t[i]];
        }
        out.holed.triangles.push_back(u);
    }
    out.removed.points = s.points;
    // Exactly one loop of `border` edges.
    const Mesh holed = mesh_of(out.holed);
    std::size_t loops = 0, edges = 0;
    std::vector<std::uint8_t> seen(holed.halfedges_size(), 0);
    for (const Halfedge h : holed.halfedges()) {
        if (holed.is_boundary(h) && seen[h.idx()] == 0) {
            ++loops;
            for (const Halfedge x : holed.loop(h)) {
                seen[x.idx()] = 1;
                ++edges;
            }
        }
    }
    if (loops != 1 || edges != border || holed.n_vertices() != out.holed.points.size()) {
        throw std::runtime_error("the cut left " + std::to_string(loops) + " holes of " +
                                 std::to_string(edges) + " edges, not one of " +
                                 std::to_string(border));
    }
    return out;
}

}  // namespace meshedit::bench
