// QEM simplification: refusals leave the mesh alone; planes, boundaries and cube edges are
// kept exactly (their quadric error is 0); a sphere stays a sphere with no face turned over;
// the error bound stops early; the result is valid and the same every time.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/simplify.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

SimplifyOptions to(std::size_t faces) {
    SimplifyOptions options;
    options.target_faces = faces;
    return options;
}

Mesh simplified(Mesh mesh, const SimplifyOptions& options, SimplifyReport* report = nullptr) {
    EXPECT_EQ(check_simplify(mesh, options), "");
    const SimplifyReport r = simplify(mesh, options);
    EXPECT_VALID(mesh);
    if (report != nullptr) {
        *report = r;
    }
    return mesh;
}

TEST(SimplifyRefuses, BadTargetsPolygonsAndBounds) {
    const Mesh ball = shapes::icosphere(2);  // 320 triangles
    EXPECT_EQ(check_simplify(ball, to(0)),
              "cannot simplify: the target must be from 1 to 319 faces (the mesh has 320), not 0");
    EXPECT_NE(check_simplify(ball, to(320)), "");
    EXPECT_NE(check_simplify(ball, to(1000)), "");
    SimplifyOptions nan = to(100);
    nan.max_error = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(check_simplify(ball, nan),
              "cannot simplify: the error bound must be a number of 0 or more");
    SimplifyOptions angle = to(100);
    angle.max_normal_change_deg = 0;
    EXPECT_NE(check_simplify(ball, angle), "");
    EXPECT_EQ(check_simplify(test::quad_cube(), to(3)),
              "cannot simplify: QEM needs triangles and 6 of the 6 faces are polygons "
              "(triangulate them first: the `triangulate` step, Ctrl+T in the viewer)");
    EXPECT_EQ(check_simplify(Mesh(), to(1)), "cannot simplify: the mesh has no faces");
    EXPECT_EQ(check_simplify(ball, to(100)), "");
}

// A flat grid has zero error everywhere: it goes down to the target, stays in its plane, and
// its boundary (feature planes) keeps the square's corners and sides.
TEST(Simplify, FlatGridStaysFlatAndSquare) {
    const Mesh grid = shapes::grid(12, 12);  // 288 triangles on [0,1]²
    const Mesh out = simplified(grid, to(20));
    EXPECT_LE(out.n_faces(), 20u);
    for (Vertex v : out.vertices()) {
        const Vec3& p = out.position(v);
        EXPECT_NEAR(p.z, 0.0, 1e-12);
        if (out.is_boundary(v)) {
            const double to_side = std::min({p.x, 1 - p.x, p.y, 1 - p.y});
            EXPECT_NEAR(to_side, 0.0, 1e-9) << "boundary vertex " << v.idx() << " left the square";
        }
    }
    const BoundingBox box = out.bounds();
    EXPECT_NEAR(box.min.x, 0.0, 1e-12);
    EXPECT_NEAR(box.max.x, 1.0, 1e-12);
    EXPECT_NEAR(box.min.y, 0.0, 1e-12);
    EXPECT_NEAR(box.max.y, 1.0, 1e-12);
}

// Every vertex of the flat-sided cube stays on its surface (on a side plane, an edge or a
// corner: zero error), so the box is exact; it gets far below its 768 triangles.
TEST(Simplify, CubeKeepsItsSidesEdgesAndCorners) {
    const Mesh cube = test::flat_sided_cube();
    ASSERT_EQ(cube.n_faces(), 768u);
    const double s = 1.0 / std::sqrt(3.0);
    SimplifyOptions options = to(12);
    options.max_error = 1e-9;
    SimplifyReport report;
    const Mesh out = simplified(cube, options, &report);
    EXPECT_LE(out.n_faces(), 48u) << report.refused_topology << " topology refusals, "
                                  << report.refused_normal << " normal refusals";
    for (Vertex v : out.vertices()) {
        const Vec3& p = out.position(v);
        const double largest = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        EXPECT_NEAR(largest, s, 1e-9) << "vertex " << v.idx() << " left the cube's surface";
    }
    EXPECT_NEAR(out.bounds().min.x, -s, 1e-12);
    EXPECT_NEAR(out.bounds().max.z, s, 1e-12);
    EXPECT_LE(report.largest_error, 1e-9);
}

// A sphere at 10%: still round (every vertex within 5% of the radius), every face still
// facing outward, valid.
TEST(Simplify, SphereStaysRoundAndOutward) {
    const Mesh ball = shapes::icosphere(4);  // 5,120 triangles
    SimplifyReport report;
    const Mesh out = simplified(ball, to(512), &report);
    EXPECT_LE(out.n_faces(), 512u);
    EXPECT_GE(out.n_faces(), 500u);
    EXPECT_EQ(report.collapses * 2, ball.n_faces() - out.n_faces());
    for (Vertex v : out.vertices()) {
        EXPECT_NEAR(norm(out.position(v)), 1.0, 0.05) << v.idx();
    }
    for (Face f : out.faces()) {
        Vec3 centre;
        for (Vertex v : out.vertices(f)) {
            centre += out.position(v);
        }
        EXPECT_GT(dot(face_normal(out, f), centre), 0.0) << "face " << f.idx() << " turned over";
    }
    EXPECT_FALSE(report.stopped_early);
    EXPECT_GT(report.largest_error, 0.0);
}

// A crease on the torus's outer equator (z = 0, 48 edges) stays one closed crease loop in
// the plane z = 0 at 10%: collapses along it merge crease edges into crease edges, and its
// penalty planes (soft: 100 times a face's weight) keep its vertices within 1e-5 of it.
TEST(Simplify, CreaseLoopStaysAClosedCreaseLoop) {
    Mesh torus = shapes::torus(48, 24);
    auto crease = torus.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    for (int i = 0; i < 48; ++i) {
        crease[torus.find_edge(Vertex(i * 24), Vertex(((i + 1) % 48) * 24))] = 1;
    }
    const Mesh out = simplified(torus, to(230));
    const auto kept = out.get_property<Edge, std::uint8_t>(kCreaseProperty);
    ASSERT_TRUE(kept);
    std::vector<int> crease_degree(out.vertices_size(), 0);
    std::size_t creases = 0;
    for (const Edge e : out.edges()) {
        if (kept[e] != 0) {
            ++creases;
            for (const Vertex v :
                 {out.from_vertex(out.halfedge(e, 0)), out.to_vertex(out.halfedge(e, 0))}) {
                ++crease_degree[v.idx()];
                EXPECT_NEAR(out.position(v).z, 0.0, 1e-5)
                    << "vertex " << v.idx() << " left the crease";
            }
        }
    }
    EXPECT_GE(creases, 8u);
    EXPECT_LT(creases, 48u) << "the crease was simplified too";
    for (const Vertex v : out.vertices()) {
        EXPECT_TRUE(crease_degree[v.idx()] == 0 || crease_degree[v.idx()] == 2)
            << "vertex " << v.idx() << " ends a crease: the loop broke";
    }
}

// The error bound stops before the target; a looser bound goes further.
TEST(Simplify, ErrorBoundStopsEarly) {
    const Mesh ball = shapes::icosphere(3);
    SimplifyOptions tight = to(40);
    tight.max_error = 1e-4;
    SimplifyReport r1;
    const Mesh a = simplified(ball, tight, &r1);
    EXPECT_TRUE(r1.stopped_early);
    EXPECT_GT(a.n_faces(), 40u);
    EXPECT_LE(r1.largest_error, 1e-4);
    SimplifyOptions loose = tight;
    loose.max_error = 1e-2;
    const Mesh b = simplified(ball, loose);
    EXPECT_LT(b.n_faces(), a.n_faces());
}

// An open, curved patch: valid, the same every time, and its boundary held by the feature
// planes to within 0.1% of its size (a plane through a curved boundary's edge lets a vertex
// slide slightly along the face normal, so not exactly).
TEST(Simplify, OpenMeshIsValidAndDeterministic) {
    Mesh grid = shapes::grid(20, 20);
    for (Vertex v : grid.vertices()) {
        Vec3& p = grid.position(v);
        p.z = 0.2 * std::sin(3 * p.x) * std::cos(2 * p.y);
    }
    const Mesh a = simplified(grid, to(200));
    const Mesh b = simplified(grid, to(200));
    EXPECT_TRUE(test::identical(a, b));
    EXPECT_NEAR(a.bounds().min.x, 0.0, 1e-3);
    EXPECT_NEAR(a.bounds().max.x, 1.0, 1e-3);
    EXPECT_NEAR(a.bounds().min.y, 0.0, 1e-3);
    EXPECT_NEAR(a.bounds().max.y, 1.0, 1e-3);
    EXPECT_LE(a.n_faces(), 200u);
}

TEST(Simplify, ProgressRisesToOne) {
    std::vector<double> seen;
    SimplifyOptions options = to(1000);
    options.progress = [&](double f) { seen.push_back(f); };
    simplified(shapes::icosphere(5), options);  // 20,480 triangles
    ASSERT_GE(seen.size(), 3u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_EQ(seen.front(), 0.0);
    EXPECT_EQ(seen.back(), 1.0);
}

}  // namespace
}  // namespace meshedit
