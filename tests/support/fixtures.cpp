#include "support/fixtures.h"

#include <cmath>
#include <numbers>

#include "meshedit/core/shapes.h"

namespace meshedit::test {

PolygonSoup soup_from_faces(const std::vector<Vec3>& positions,
                            const std::vector<std::vector<std::uint32_t>>& faces) {
    PolygonSoup soup;
    soup.positions = positions;
    for (const auto& f : faces) {
        soup.add_face_range(f);
    }
    return soup;
}

Mesh mesh_from_faces(const std::vector<Vec3>& positions,
                     const std::vector<std::vector<std::uint32_t>>& faces) {
    return build_mesh(soup_from_faces(positions, faces));
}

Mesh two_triangles() {
    return mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
}

Mesh one_ring(int n) {
    std::vector<Vec3> positions{{0, 0, 0}};
    std::vector<std::vector<std::uint32_t>> faces;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n;
        positions.push_back({std::cos(a), std::sin(a), 0.0});
        faces.push_back(
            {0, static_cast<std::uint32_t>(1 + i), static_cast<std::uint32_t>(1 + (i + 1) % n)});
    }
    return mesh_from_faces(positions, faces);
}

PolygonSoup bowtie_soup() {
    return soup_from_faces({{0, 0, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}},
                           {{0, 1, 2}, {0, 3, 4}});
}

std::vector<NamedMesh> sweep_corpus() {
    std::vector<NamedMesh> out;
    out.push_back({"tetrahedron", shapes::tetrahedron()});
    out.push_back({"cube", shapes::cube()});
    out.push_back({"icosahedron", shapes::icosahedron()});
    out.push_back({"torus", shapes::torus(8, 6)});
    out.push_back({"grid", shapes::grid(5, 4)});
    out.push_back({"disk", shapes::disk(7)});
    out.push_back({"cylinder", shapes::cylinder(6, 3)});
    out.push_back({"icosphere", shapes::icosphere(1)});
    return out;
}

}  // namespace meshedit::test
