// Face and vertex normals against hand-computed values.

#include "meshedit/core/normals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "meshedit/core/build.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

::testing::AssertionResult near(const Vec3& actual, const Vec3& expected, double tol = 1e-15) {
    if (norm(actual - expected) <= tol) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure()
           << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") != (" << expected.x
           << ", " << expected.y << ", " << expected.z << ")";
}

// Two triangles of different areas and directions sharing edge 0-1:
//
//            2 (0,1,0)
//            | `.
//            |   `.        face 0 = (0,1,2): area vector (0,0,1)
//  (0,0,0)   0 ---- 1 (1,0,0)
//             `.  .'       face 1 = (1,0,3), 3 = (0,-2,2): area vector (0,2,2)
//               3          (tilted up out of the plane)
//
// Vertex 0's normal is the area-weighted sum (0,2,3)/√13, not the mean of the two unit
// normals, which would be (0,1,1+√2)/|…|.
Mesh hinge() {
    return test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -2, 2}},
                                 {{0, 1, 2}, {1, 0, 3}});
}

TEST(Normals, HingeIsAreaWeighted) {
    const Mesh mesh = hinge();
    ASSERT_VALID(mesh);
    EXPECT_EQ(face_area_vector(mesh, Face(0)), Vec3(0, 0, 1));
    EXPECT_EQ(face_area_vector(mesh, Face(1)), Vec3(0, 2, 2));
    EXPECT_TRUE(near(face_normal(mesh, Face(1)), Vec3(0, 1, 1) / std::sqrt(2.0)));

    const std::vector<Vec3> n = vertex_normals(mesh);
    ASSERT_EQ(n.size(), 4u);
    const Vec3 shared = Vec3(0, 2, 3) / std::sqrt(13.0);
    EXPECT_TRUE(near(n[0], shared));
    EXPECT_TRUE(near(n[1], shared));
    EXPECT_TRUE(near(n[2], Vec3(0, 0, 1)));
    EXPECT_TRUE(near(n[3], Vec3(0, 1, 1) / std::sqrt(2.0)));
    // The unweighted average really is different, so the test discriminates.
    const Vec3 plain = normalize(Vec3(0, 0, 1) + Vec3(0, 1, 1) / std::sqrt(2.0));
    EXPECT_GT(norm(plain - shared), 1e-2);
}

TEST(Normals, PolygonUsesNewellsSum) {
    // Planar 2 × 1 rectangle: twice the area is 4, along +z.
    const Mesh rect =
        test::mesh_from_faces({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}});
    ASSERT_VALID(rect);
    EXPECT_EQ(face_area_vector(rect, Face(0)), Vec3(0, 0, 4));

    // Non-planar quad: Newell's components Σ (y_i − y_i+1)(z_i + z_i+1) etc. give (−1,−1,2).
    const Mesh warped =
        test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}}, {{0, 1, 2, 3}});
    ASSERT_VALID(warped);
    EXPECT_EQ(face_area_vector(warped, Face(0)), Vec3(-1, -1, 2));
    EXPECT_TRUE(near(face_normal(warped, Face(0)), Vec3(-1, -1, 2) / std::sqrt(6.0)));
    // All four corners of a lone face share its normal.
    for (const Vec3& n : vertex_normals(warped)) {
        EXPECT_TRUE(near(n, Vec3(-1, -1, 2) / std::sqrt(6.0)));
    }
}

TEST(Normals, CubeFaceNormalsAreAxes) {
    const Mesh mesh = shapes::cube();
    const std::vector<Vec3> n = face_normals(mesh);
    // Faces come in pairs per side, in the order -x, +x, -y, +y, -z, +z (shapes.h).
    const Vec3 sides[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    ASSERT_EQ(n.size(), 12u);
    for (std::size_t f = 0; f < 12; ++f) {
        EXPECT_EQ(n[f], sides[f / 2]) << f;
        EXPECT_EQ(face_area_vector(mesh, Face(std::uint32_t(f))), 4.0 * sides[f / 2]) << f;
    }
}

TEST(Normals, CubeVertexNormalsFollowTheDiagonals) {
    // Vertex 0 lies in both triangles of its three sides; vertex 1 in both triangles of +x
    // but one each of -y and -z, so its normal leans towards +x: (8,-4,-4)/|…|.
    const std::vector<Vec3> n = vertex_normals(shapes::cube());
    EXPECT_TRUE(near(n[0], Vec3(-1, -1, -1) / std::sqrt(3.0)));
    EXPECT_TRUE(near(n[7], Vec3(1, 1, 1) / std::sqrt(3.0)));
    EXPECT_TRUE(near(n[1], Vec3(2, -1, -1) / std::sqrt(6.0)));
}

TEST(Normals, SphereNormalsApproximatePositions) {
    // Central projection leaves quad_sphere's corner quads skewed, hence the loose bound.
    for (const Mesh& mesh : {shapes::icosphere(3), shapes::quad_sphere(16)}) {
        const std::vector<Vec3> n = vertex_normals(mesh);
        for (Vertex v : mesh.vertices()) {
            EXPECT_NEAR(norm(n[v.idx()]), 1.0, 1e-14);
            EXPECT_LT(norm(n[v.idx()] - mesh.position(v)), 2e-2) << v.idx();
        }
    }
    // Perfectly symmetric one-rings: the icosahedron's normals are its positions.
    const Mesh ico = shapes::icosahedron();
    const std::vector<Vec3> n = vertex_normals(ico);
    for (Vertex v : ico.vertices()) {
        EXPECT_TRUE(near(n[v.idx()], ico.position(v), 1e-14));
    }
}

TEST(Normals, IsolatedAndDeletedElementsGetZero) {
    // Vertex 3 is referenced by no face.
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}}, {{0, 1, 2}});
    ASSERT_VALID(mesh);
    EXPECT_EQ(vertex_normals(mesh)[3], Vec3());

    Mesh two = test::two_triangles();
    two.mark_deleted(Face(1));
    const std::vector<Vec3> fn = face_normals(two);
    ASSERT_EQ(fn.size(), 2u);
    EXPECT_EQ(fn[0], Vec3(0, 0, 1));
    EXPECT_EQ(fn[1], Vec3());
}

// The vertex normals as first written: one pass over the faces scattering each face's area
// vector (face_area_vector()) to its corners in face order. compute_vertex_normals() gives the
// same bits up to 65,536 faces (one chunk); beyond, a vertex whose faces lie in two chunks
// gets its sums in another order, equal up to rounding.
std::vector<Vec3> scattered_vertex_normals(const Mesh& mesh) {
    std::vector<Vec3> out(mesh.vertices_size());
    for (Face f : mesh.faces()) {
        const Vec3 a = face_area_vector(mesh, f);
        for (Vertex v : mesh.vertices(f)) {
            out[v.idx()] += a;
        }
    }
    for (Vec3& n : out) {
        n = normalize(n);
    }
    return out;
}

::testing::AssertionResult equals_scattered(const Mesh& mesh, const std::vector<Vec3>& n,
                                            double tol = 0.0) {
    const std::vector<Vec3> expected = scattered_vertex_normals(mesh);
    if (n.size() != expected.size()) {
        return ::testing::AssertionFailure() << "size " << n.size();
    }
    for (std::size_t i = 0; i < n.size(); ++i) {
        if (auto r = near(n[i], expected[i], tol); !r) {
            return r << " at vertex " << i;
        }
    }
    return ::testing::AssertionSuccess();
}

TEST(Normals, VertexNormalsEqualTheFaceScatter) {
    Mesh collapsed = shapes::icosphere(2);  // with tombstones
    for (std::uint32_t e : {3u, 40u, 200u}) {
        collapse(collapsed, Edge(e));
    }
    const Mesh meshes[] = {
        shapes::quad_sphere(8), shapes::cylinder(9, 4), shapes::grid(6, 4),
        test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}, {-1, 0.5, 0}},
                              {{0, 1, 2, 3}, {0, 3, 4}}),
        collapsed};
    for (const Mesh& mesh : meshes) {
        ASSERT_VALID(mesh);
        EXPECT_TRUE(equals_scattered(mesh, vertex_normals(mesh)));
    }
}

// 180,000 faces: above the threshold for threads, three chunks. Every thread count gives the
// same bits, also when the face order has nothing to do with the vertex order (almost every
// corner then belongs to another chunk).
TEST(Normals, ThreadedVertexNormalsAreIndependentOfThreads) {
    PolygonSoup shuffled = to_polygon_soup(shapes::torus(300, 300));
    std::vector<std::uint32_t> order(shuffled.n_faces());
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), std::mt19937(5));
    PolygonSoup soup;
    soup.positions = shuffled.positions;
    for (std::uint32_t f : order) {
        const std::uint32_t* c = &shuffled.indices[shuffled.face_offsets[f]];
        soup.add_face({c[0], c[1], c[2]});
    }
    for (const Mesh& mesh : {shapes::torus(300, 300), build_mesh(soup)}) {
        ASSERT_GE(mesh.n_faces(), 100'000u);
        std::vector<Vec3> one, two, all;
        compute_vertex_normals(mesh, one, 1);
        compute_vertex_normals(mesh, two, 2);
        compute_vertex_normals(mesh, all);
        EXPECT_EQ(one, two);
        EXPECT_EQ(one, all);
        EXPECT_TRUE(equals_scattered(mesh, all, 1e-15));
    }
}

TEST(Normals, BuffersAreReused) {
    const Mesh big = shapes::icosphere(2);
    const Mesh small = shapes::tetrahedron();
    std::vector<Vec3> buffer;
    compute_face_normals(big, buffer);  // the largest request: 320 faces
    const Vec3* data = buffer.data();
    compute_vertex_normals(big, buffer);
    EXPECT_EQ(buffer.size(), big.vertices_size());
    EXPECT_EQ(buffer.data(), data);
    compute_vertex_normals(small, buffer);
    EXPECT_EQ(buffer.size(), 4u);
    EXPECT_EQ(buffer.data(), data);
}

TEST(Normals, FarFromOriginKeepsPrecision) {
    // Newell's sum about the first corner does not lose the normal to cancellation.
    const Vec3 o(1e8, -3e8, 2e8);
    const Mesh mesh = test::mesh_from_faces(
        {o, o + Vec3(1, 0, 0), o + Vec3(1, 1, 0), o + Vec3(0, 1, 0)}, {{0, 1, 2, 3}});
    EXPECT_EQ(face_normal(mesh, Face(0)), Vec3(0, 0, 1));
}

TEST(Normals, SignedVolumeIsPositiveOutwardAndNegativeInsideOut) {
    // The asymmetric cube spans [-1, 1]^3.
    EXPECT_DOUBLE_EQ(signed_volume(shapes::cube()), 8.0);
    PolygonSoup inside_out = to_polygon_soup(shapes::cube());
    for (std::uint32_t f = 0; f < inside_out.n_faces(); ++f) {
        std::reverse(inside_out.indices.begin() + inside_out.face_offsets[f],
                     inside_out.indices.begin() + inside_out.face_offsets[f + 1]);
    }
    EXPECT_DOUBLE_EQ(signed_volume(build_mesh(inside_out)), -8.0);
    EXPECT_EQ(signed_volume(Mesh()), 0.0);
}

TEST(Normals, ClosedAndOutwardNeedsEveryPartOutward) {
    EXPECT_TRUE(is_closed_and_outward(shapes::cube()));
    EXPECT_TRUE(is_closed_and_outward(shapes::torus(12, 8)));
    EXPECT_FALSE(is_closed_and_outward(shapes::grid(3, 2)));  // open
    EXPECT_TRUE(is_closed_and_outward(Mesh()));

    // Two cubes side by side; then the same with the small one inside out. Its volume is
    // smaller than the big one's, so the whole mesh's signed volume stays positive: only the
    // per-part test sees it.
    PolygonSoup soup = to_polygon_soup(shapes::cube());
    const PolygonSoup small = to_polygon_soup(shapes::cube());
    const auto base = static_cast<std::uint32_t>(soup.positions.size());
    for (const Vec3& p : small.positions) {
        soup.positions.push_back(0.25 * p + Vec3(5, 0, 0));
    }
    PolygonSoup flipped = soup;
    for (std::uint32_t f = 0; f < small.n_faces(); ++f) {
        std::vector<std::uint32_t> face(small.indices.begin() + small.face_offsets[f],
                                        small.indices.begin() + small.face_offsets[f + 1]);
        for (std::uint32_t& i : face) {
            i += base;
        }
        soup.add_face_range(face);
        std::reverse(face.begin(), face.end());
        flipped.add_face_range(face);
    }
    EXPECT_TRUE(is_closed_and_outward(build_mesh(soup)));
    const Mesh with_inside_out = build_mesh(flipped);
    EXPECT_GT(signed_volume(with_inside_out), 0.0);
    EXPECT_FALSE(is_closed_and_outward(with_inside_out));
}

TEST(Normals, SignedVolumeFarFromOriginKeepsPrecision) {
    // Taken about a vertex of the mesh, not the origin: a unit cube 1e9 away still has
    // volume 1 to many digits (about the origin, the terms of size 1e18 would cancel).
    Mesh mesh = shapes::cube();
    for (Vertex v : mesh.vertices()) {
        mesh.position(v) = 0.5 * mesh.position(v) + Vec3(1e9, -2e9, 3e9);
    }
    EXPECT_NEAR(signed_volume(mesh), 1.0, 1e-6);
}

// Coordinates above ~1e154 overflow the cross products (a file converted with them once got
// `vn 0 0 -nan`, which MeshEdit then refused to read). Scaled by a power of two, every normal
// is the same bits as the unscaled mesh's, face and vertex normals alike.
TEST(Normals, HugeCoordinatesGiveTheSameNormalsAsScaledOnes) {
    const Mesh small = shapes::icosphere(2);
    Mesh huge = small;
    const double s = std::ldexp(1.0, 700);  // about 5e210
    for (const Vertex v : huge.vertices()) {
        huge.position(v) *= s;
    }
    const std::vector<Vec3> expected = vertex_normals(small);
    const std::vector<Vec3> actual = vertex_normals(huge);
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i) {
        ASSERT_TRUE(is_finite(actual[i])) << "vertex " << i;
        EXPECT_EQ(actual[i], expected[i]) << "vertex " << i;
    }
    for (const Face f : huge.faces()) {
        EXPECT_EQ(face_normal(huge, f), face_normal(small, f)) << "face " << f.idx();
    }
}

}  // namespace
}  // namespace meshedit
