#pragma once
/// \file
/// Small hand-built soups for the repair tests, and reading faces back as lists.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "meshedit/io/io.h"
#include "support/fixtures.h"

namespace meshedit::test {

inline MeshSoup soup_of(const std::vector<Vec3>& positions, const Faces& faces) {
    MeshSoup soup;
    soup.soup = soup_from_faces(positions, faces);
    return soup;
}

/// The cube [-1,1]³ as six quads (fixtures.h, quad_cube()), each quad reversed when `inward`.
inline MeshSoup cube_soup(bool inward) {
    std::vector<Vec3> p;
    for (const double z : {-1.0, 1.0}) {
        p.insert(p.end(), {{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}});
    }
    Faces faces{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    if (inward) {
        for (auto& face : faces) {
            std::reverse(face.begin() + 1, face.end());
        }
    }
    return soup_of(p, faces);
}

/// A triangulated grid of nx × ny unit squares in the z = 0 plane, vertex (i, j) numbered
/// j·(nx+1) + i, without the squares `holes` lists (as i + j·nx).
inline MeshSoup grid_soup(int nx, int ny, const std::vector<int>& holes) {
    std::vector<Vec3> p;
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            p.push_back({static_cast<double>(i), static_cast<double>(j), 0.0});
        }
    }
    Faces faces;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            if (std::find(holes.begin(), holes.end(), i + j * nx) != holes.end()) {
                continue;
            }
            const auto v = [&](int di, int dj) {
                return static_cast<std::uint32_t>((j + dj) * (nx + 1) + i + di);
            };
            faces.push_back({v(0, 0), v(1, 0), v(1, 1)});
            faces.push_back({v(0, 0), v(1, 1), v(0, 1)});
        }
    }
    return soup_of(p, faces);
}

}  // namespace meshedit::test
