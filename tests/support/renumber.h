#pragma once
/// \file
/// A mesh renumbered at random, for the tests and the benchmark of `meshedit compare`
/// (core/compare.h): the same mesh with its vertices and faces in another order and each
/// face's first corner elsewhere.

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "meshedit/core/build.h"
#include "meshedit/core/mesh.h"

namespace meshedit::test {

/// `mesh` rebuilt with its vertices and faces shuffled and each face's corners rotated by a
/// random step, from `seed`; `shift` moves every position.
inline Mesh renumbered(const Mesh& mesh, unsigned seed, Vec3 shift = {0, 0, 0}) {
    const PolygonSoup soup = to_polygon_soup(mesh);
    std::mt19937 rng(seed);
    std::vector<std::uint32_t> order(soup.positions.size());  // new index -> old
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::uint32_t> index(order.size());  // old -> new
    PolygonSoup out;
    out.positions.reserve(order.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) {
        index[order[i]] = i;
        out.positions.push_back(soup.positions[order[i]] + shift);
    }
    std::vector<std::size_t> faces(soup.n_faces());
    std::iota(faces.begin(), faces.end(), std::size_t{0});
    std::shuffle(faces.begin(), faces.end(), rng);
    std::vector<std::uint32_t> corners;
    for (const std::size_t f : faces) {
        corners.clear();
        for (std::uint32_t c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
            corners.push_back(index[soup.indices[c]]);
        }
        std::rotate(corners.begin(), corners.begin() + rng() % corners.size(), corners.end());
        out.add_face_range(corners);
    }
    return build_mesh(out);
}

}  // namespace meshedit::test
