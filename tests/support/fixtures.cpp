#include "support/fixtures.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/quad_subdivision.h"
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

Mesh quad_cube() {
    return mesh_from_faces(
        {{-1, -1, -1},
         {1, -1, -1},
         {1, 1, -1},
         {-1, 1, -1},
         {-1, -1, 1},
         {1, -1, 1},
         {1, 1, 1},
         {-1, 1, 1}},
        {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
}

Mesh two_copies(const Mesh& mesh, const Vec3& offset) {
    PolygonSoup soup = to_polygon_soup(mesh);
    const auto n = static_cast<std::uint32_t>(soup.positions.size());
    const std::size_t faces = soup.n_faces();
    for (std::uint32_t i = 0; i < n; ++i) {
        soup.positions.push_back(soup.positions[i] + offset);
    }
    for (std::size_t f = 0; f < faces; ++f) {
        std::vector<std::uint32_t> copy;
        for (std::uint32_t c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
            copy.push_back(soup.indices[c] + n);
        }
        soup.add_face_range(copy);
    }
    return build_mesh(soup);
}

Mesh flat_sided_cube() {
    Mesh mesh = shapes::quad_sphere(1);
    QuadSubdivisionOptions linear;
    linear.scheme = QuadScheme::Linear;
    for (int i = 0; i < 3; ++i) {
        quad_subdivide(mesh, linear);
    }
    triangulate(mesh);
    mesh.garbage_collection();
    return mesh;
}

std::size_t crease_count(const Mesh& mesh) {
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    std::size_t n = 0;
    for (Edge e : mesh.edges()) {
        n += crease && crease[e] != 0;
    }
    return n;
}

Mesh quad_strip(int n) {
    std::vector<Vec3> positions;
    for (int row = 0; row < 2; ++row) {
        for (int i = 0; i <= n; ++i) {
            positions.push_back({static_cast<double>(i), static_cast<double>(row), 0.0});
        }
    }
    std::vector<std::vector<std::uint32_t>> faces;
    const auto top = static_cast<std::uint32_t>(n + 1);
    for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
        faces.push_back({i, i + 1, top + i + 1, top + i});
    }
    return mesh_from_faces(positions, faces);
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

PolygonSoup pillow_and_ear_soup() {
    return soup_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                           {{0, 1, 2}, {0, 2, 1}, {0, 1, 3}});
}

// Halfedges: edge 0 = 0->1 (face A), 1 = 1->2 (A), 2 = 2->0 (A), 3 = 1->0 (face B); B's 0->2
// and 2->1 are the twins of edges 2 and 1. The twins of edges 0 and 3 form the slit.
//
//          2
//        /   \        A = (0,1,2) above the slit, B = (0,2,1) below it
//       0 === 1       the slit: boundary loop 1->0 (twin of edge 0), 0->1 (twin of edge 3)
Mesh slit_pillow() {
    Mesh mesh;
    const Vertex v0 = mesh.new_vertex({0, 0, 0});
    const Vertex v1 = mesh.new_vertex({1, 0, 0});
    const Vertex v2 = mesh.new_vertex({0.5, 1, 0});
    const Halfedge a01 = mesh.new_edge(v0, v1);
    const Halfedge a12 = mesh.new_edge(v1, v2);
    const Halfedge a20 = mesh.new_edge(v2, v0);
    const Halfedge b10 = mesh.new_edge(v1, v0);
    const Face fa = mesh.new_face();
    const Face fb = mesh.new_face();
    const Halfedge b02 = Mesh::twin(a20), b21 = Mesh::twin(a12);
    for (const auto& [h, n, f] : {std::tuple{a01, a12, fa},
                                  {a12, a20, fa},
                                  {a20, a01, fa},
                                  {b02, b21, fb},
                                  {b21, b10, fb},
                                  {b10, b02, fb}}) {
        mesh.set_next(h, n);
        mesh.set_face(h, f);
    }
    mesh.set_next(Mesh::twin(a01), Mesh::twin(b10));
    mesh.set_next(Mesh::twin(b10), Mesh::twin(a01));
    mesh.set_face(Mesh::twin(a01), Face());
    mesh.set_face(Mesh::twin(b10), Face());
    mesh.set_halfedge(fa, a01);
    mesh.set_halfedge(fb, b02);
    mesh.set_halfedge(v0, Mesh::twin(b10));  // 0 -> 1 on the slit
    mesh.set_halfedge(v1, Mesh::twin(a01));  // 1 -> 0 on the slit
    mesh.set_halfedge(v2, a20);
    return mesh;
}

std::vector<NamedMesh> pillow_family() {
    std::vector<NamedMesh> out;
    const std::vector<Vec3> tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    out.push_back({"pillow", mesh_from_faces(tri, {{0, 1, 2}, {0, 2, 1}})});
    out.push_back({"pillow and ear", build_mesh(pillow_and_ear_soup())});
    out.push_back({"two pillows at a vertex",
                   mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}},
                                   {{0, 1, 2}, {0, 2, 1}, {0, 3, 4}, {0, 4, 3}})});
    out.push_back({"quad and triangle on two edges",
                   mesh_from_faces({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0.5, 1.5, 0}},
                                   {{0, 1, 2, 3}, {0, 3, 2}})});
    out.push_back(
        {"bipyramid",
         mesh_from_faces({{1, 0, 0}, {-0.5, 0.87, 0}, {-0.5, -0.87, 0}, {0, 0, 1}, {0, 0, -1}},
                         {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}})});
    out.push_back({"triangle", mesh_from_faces(tri, {{0, 1, 2}})});
    out.push_back({"boundary valence 2",
                   mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0.5, 0}},
                                   {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}})});
    return out;
}

std::vector<NamedMesh> big_corpus() {
    std::vector<NamedMesh> out;
    out.push_back({"torus 40k", shapes::torus(200, 100)});
    out.push_back({"icosphere 5k", shapes::icosphere(4)});
    out.push_back({"grid 20k", shapes::grid(100, 100)});
    return out;
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

Faces faces_of(const PolygonSoup& soup) {
    Faces faces;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        faces.emplace_back(soup.indices.begin() + soup.face_offsets[f],
                           soup.indices.begin() + soup.face_offsets[f + 1]);
    }
    return faces;
}

std::vector<Face> random_region(const Mesh& mesh, std::mt19937& rng) {
    std::vector<Face> out;
    for (int tries = 0; tries < 100 && mesh.faces_size() > 0 && out.empty(); ++tries) {
        const Face f(static_cast<std::uint32_t>(rng() % mesh.faces_size()));
        if (!mesh.is_deleted(f)) {
            out.push_back(f);
        }
    }
    if (!out.empty()) {
        for (const Halfedge h : mesh.halfedges(out.front())) {
            const Face g = mesh.face(Mesh::twin(h));
            if (g.is_valid() && rng() % 2 == 0) {
                out.push_back(g);
            }
        }
        // Half the time every face around one of its corners too, so that the region has an
        // inner vertex (what smoothing and simplifying a region move).
        if (rng() % 2 == 0) {
            const Vertex v = mesh.to_vertex(mesh.halfedge(out.front()));
            for (const Halfedge h : mesh.halfedges(v)) {
                const Face g = mesh.face(h);
                if (g.is_valid() && std::find(out.begin(), out.end(), g) == out.end()) {
                    out.push_back(g);
                }
            }
        }
    }
    return out;
}

}  // namespace meshedit::test
