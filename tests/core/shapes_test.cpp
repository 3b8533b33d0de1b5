// Procedural shapes: exact counts, topology, positions and outward orientation.

#include "meshedit/core/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "meshedit/core/normals.h"
#include "meshedit/core/topology.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

std::size_t count_faces_with_valence(const Mesh& mesh, std::size_t valence) {
    std::size_t n = 0;
    for (Face f : mesh.faces()) {
        n += mesh.valence(f) == valence ? 1 : 0;
    }
    return n;
}

struct ShapeCase {
    std::string name;
    std::function<Mesh()> make;
    std::size_t vertices, edges, faces;
    long euler;
    std::size_t boundary_loops;
    std::size_t face_valence;  // every face has this many sides
    bool on_unit_sphere;
};

std::vector<ShapeCase> shape_cases() {
    using namespace shapes;
    return {
        {"tetrahedron", tetrahedron, 4, 6, 4, 2, 0, 3, true},
        {"cube", cube, 8, 18, 12, 2, 0, 3, false},
        {"icosahedron", icosahedron, 12, 30, 20, 2, 0, 3, true},
        {"icosphere0", [] { return icosphere(0); }, 12, 30, 20, 2, 0, 3, true},
        {"icosphere1", [] { return icosphere(1); }, 42, 120, 80, 2, 0, 3, true},
        {"icosphere2", [] { return icosphere(2); }, 162, 480, 320, 2, 0, 3, true},
        {"icosphere3", [] { return icosphere(3); }, 642, 1920, 1280, 2, 0, 3, true},
        {"torus3x3", [] { return torus(3, 3); }, 9, 27, 18, 0, 0, 3, false},
        {"torus8x6", [] { return torus(8, 6); }, 48, 144, 96, 0, 0, 3, false},
        {"grid1x1", [] { return grid(1, 1); }, 4, 5, 2, 1, 1, 3, false},
        {"grid5x4", [] { return grid(5, 4); }, 30, 69, 40, 1, 1, 3, false},
        {"disk3", [] { return disk(3); }, 4, 6, 3, 1, 1, 3, false},
        {"disk7", [] { return disk(7); }, 8, 14, 7, 1, 1, 3, false},
        {"cylinder3x1", [] { return cylinder(3, 1); }, 6, 12, 6, 0, 2, 3, false},
        {"cylinder6x3", [] { return cylinder(6, 3); }, 24, 60, 36, 0, 2, 3, false},
        {"quad_sphere1", [] { return quad_sphere(1); }, 8, 12, 6, 2, 0, 4, true},
        {"quad_sphere3", [] { return quad_sphere(3); }, 56, 108, 54, 2, 0, 4, true},
        {"quad_sphere8", [] { return quad_sphere(8); }, 386, 768, 384, 2, 0, 4, true},
    };
}

TEST(Shapes, CountsTopologyAndValidity) {
    for (const ShapeCase& c : shape_cases()) {
        SCOPED_TRACE(c.name);
        const Mesh mesh = c.make();
        ASSERT_VALID(mesh);
        EXPECT_EQ(mesh.n_vertices(), c.vertices);
        EXPECT_EQ(mesh.n_edges(), c.edges);
        EXPECT_EQ(mesh.n_faces(), c.faces);
        EXPECT_EQ(euler_characteristic(mesh), c.euler);
        EXPECT_EQ(count_boundary_loops(mesh), c.boundary_loops);
        EXPECT_EQ(count_components(mesh), 1u);
        EXPECT_EQ(count_faces_with_valence(mesh, c.face_valence), c.faces);
        EXPECT_FALSE(mesh.has_garbage());
    }
}

TEST(Shapes, DocumentedSpheresHaveUnitRadius) {
    for (const ShapeCase& c : shape_cases()) {
        if (!c.on_unit_sphere) {
            continue;
        }
        SCOPED_TRACE(c.name);
        const Mesh mesh = c.make();
        for (Vertex v : mesh.vertices()) {
            EXPECT_NEAR(norm(mesh.position(v)), 1.0, 1e-14);
        }
    }
}

TEST(Shapes, NoTwoVerticesCoincide) {
    // Welding at shared edge midpoints (icosphere) and cube edges (quad_sphere) is exact.
    for (const ShapeCase& c : shape_cases()) {
        SCOPED_TRACE(c.name);
        const Mesh mesh = c.make();
        const auto& p = mesh.position_vector();
        for (std::size_t i = 0; i < p.size(); ++i) {
            for (std::size_t j = i + 1; j < p.size(); ++j) {
                ASSERT_GT(distance(p[i], p[j]), 1e-6) << i << " " << j;
            }
        }
    }
}

TEST(Shapes, ClosedShapesAreOutward) {
    for (const ShapeCase& c : shape_cases()) {
        if (c.boundary_loops != 0) {
            continue;
        }
        SCOPED_TRACE(c.name);
        const Mesh mesh = c.make();
        EXPECT_GT(signed_volume(mesh), 0.0);
    }
    // The convex ones: every face normal points away from the centre.
    for (const Mesh& mesh :
         {shapes::tetrahedron(), shapes::cube(), shapes::icosphere(2), shapes::quad_sphere(4)}) {
        for (Face f : mesh.faces()) {
            EXPECT_GT(dot(face_normal(mesh, f), face_centroid(mesh, f)), 0.0);
        }
    }
}

TEST(Shapes, ApproximateVolumes) {
    // Inscribed polyhedra approach the smooth volume from below.
    EXPECT_DOUBLE_EQ(signed_volume(shapes::cube()), 8.0);
    const double sphere = 4.0 / 3.0 * std::acos(-1.0);
    const double v3 = signed_volume(shapes::icosphere(3));
    EXPECT_LT(v3, sphere);
    EXPECT_GT(v3, 0.99 * sphere);
    const double torus = 2.0 * std::pow(std::acos(-1.0), 2) * 1.0 * 0.4 * 0.4;
    const double vt = signed_volume(shapes::torus(64, 32));
    EXPECT_LT(vt, torus);
    EXPECT_GT(vt, 0.99 * torus);
}

TEST(Shapes, OpenShapesFaceTheDocumentedWay) {
    for (const Mesh& mesh : {shapes::grid(3, 2), shapes::disk(5)}) {
        for (Face f : mesh.faces()) {
            EXPECT_LT(norm(face_normal(mesh, f) - Vec3(0, 0, 1)), 1e-15);
        }
    }
    const Mesh cyl = shapes::cylinder(8, 2);
    for (Face f : cyl.faces()) {
        const Vec3 c = face_centroid(cyl, f);
        EXPECT_GT(dot(face_normal(cyl, f), Vec3(c.x, c.y, 0.0)), 0.0);
    }
}

TEST(Shapes, CubeMatchesDocumentedLayout) {
    const Mesh mesh = shapes::cube();
    ASSERT_VALID(mesh);
    for (std::uint32_t i = 0; i < 8; ++i) {
        const Vec3 expected((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
        EXPECT_EQ(mesh.position(Vertex(i)), expected) << i;
    }
    // The list from shapes.h, in order.
    const std::vector<std::vector<std::uint32_t>> documented{
        {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
        {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
    std::uint32_t fi = 0;
    for (Face f : mesh.faces()) {
        std::vector<std::uint32_t> corners;
        for (Vertex v : mesh.vertices(f)) {
            corners.push_back(v.idx());
        }
        // Compare as cycles: rotate to start at the smallest index.
        std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()),
                    corners.end());
        EXPECT_EQ(corners, documented[fi]) << "face " << fi;
        ++fi;
    }
    EXPECT_EQ(fi, 12u);
    // Asymmetric: the diagonals meet at vertices 0 and 7 only.
    for (Vertex v : mesh.vertices()) {
        const bool hub = v.idx() == 0 || v.idx() == 7;
        EXPECT_EQ(mesh.valence(v), hub ? 6u : 4u) << v.idx();
    }
}

TEST(Shapes, IndexLayouts) {
    const Mesh g = shapes::grid(4, 3);
    for (int j = 0; j <= 3; ++j) {
        for (int i = 0; i <= 4; ++i) {
            EXPECT_EQ(g.position(Vertex(std::uint32_t(j * 5 + i))), Vec3(i / 4.0, j / 3.0, 0.0));
        }
    }
    // Diagonal from (i,j) to (i+1,j+1): vertex (0,0) is joined to (1,1), (1,0) not to (0,1).
    EXPECT_TRUE(g.find_edge(Vertex(0), Vertex(6)).is_valid());
    EXPECT_FALSE(g.find_edge(Vertex(1), Vertex(5)).is_valid());

    const int m = 6, n = 4;
    const Mesh t = shapes::torus(m, n, 2.0, 0.5);
    for (int i = 0; i < m; ++i) {
        for (int j = 0; j < n; ++j) {
            const Vec3 p = t.position(Vertex(std::uint32_t(i * n + j)));
            const double u = 2.0 * std::acos(-1.0) * i / m, v = 2.0 * std::acos(-1.0) * j / n;
            EXPECT_NEAR(std::atan2(p.y, p.x), std::remainder(u, 2.0 * std::acos(-1.0)), 1e-12);
            EXPECT_NEAR(std::hypot(p.x, p.y), 2.0 + 0.5 * std::cos(v), 1e-12);
            EXPECT_NEAR(p.z, 0.5 * std::sin(v), 1e-12);
        }
    }

    const Mesh c = shapes::cylinder(5, 2);
    for (int j = 0; j <= 2; ++j) {
        for (int i = 0; i < 5; ++i) {
            const Vec3 p = c.position(Vertex(std::uint32_t(j * 5 + i)));
            EXPECT_NEAR(std::hypot(p.x, p.y), 1.0, 1e-14);
            EXPECT_DOUBLE_EQ(p.z, -1.0 + j);
        }
    }

    const Mesh d = shapes::disk(6);
    EXPECT_EQ(d.position(Vertex(0)), Vec3(0, 0, 0));
    EXPECT_EQ(d.valence(Vertex(0)), 6u);
    EXPECT_EQ(d.position(Vertex(1)), Vec3(1, 0, 0));
}

TEST(Shapes, IcosphereRefinesTheIcosahedron) {
    // The first 12 vertices of every level are the icosahedron's, unchanged.
    const Mesh ico = shapes::icosahedron();
    const Mesh fine = shapes::icosphere(2);
    for (std::uint32_t i = 0; i < 12; ++i) {
        EXPECT_EQ(fine.position(Vertex(i)), ico.position(Vertex(i)));
        EXPECT_EQ(ico.valence(Vertex(i)), 5u);
    }
    // Every new vertex has valence 6.
    for (Vertex v : fine.vertices()) {
        if (v.idx() >= 12) {
            EXPECT_EQ(fine.valence(v), 6u);
        }
    }
}

TEST(Shapes, QuadSphereValences) {
    // The 8 cube corners have valence 3, every other vertex 4.
    const Mesh mesh = shapes::quad_sphere(5);
    std::size_t corners = 0;
    for (Vertex v : mesh.vertices()) {
        const std::size_t val = mesh.valence(v);
        EXPECT_TRUE(val == 3 || val == 4);
        corners += val == 3 ? 1 : 0;
    }
    EXPECT_EQ(corners, 8u);
}

}  // namespace
}  // namespace meshedit
