// Isotropic remeshing: refusals; edge lengths gather around the target; every vertex ends on
// the input surface; valences move toward 6; boundaries, creases and corners stay exactly.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/closest_point.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/shapes.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

RemeshOptions length(double l, int iterations = 3) {
    RemeshOptions options;
    options.target_length = l;
    options.iterations = iterations;
    return options;
}

Mesh remeshed(Mesh mesh, const RemeshOptions& options, RemeshReport* report = nullptr) {
    EXPECT_EQ(check_remesh(mesh, options), "");
    const RemeshReport r = remesh(mesh, options);
    EXPECT_VALID(mesh);
    EXPECT_FALSE(mesh.has_garbage());
    if (report != nullptr) {
        *report = r;
    }
    return mesh;
}

double edge_length(const Mesh& mesh, Edge e) {
    return distance(mesh.position(mesh.vertex(e, 0)), mesh.position(mesh.vertex(e, 1)));
}

std::size_t valence_six_share_percent(const Mesh& mesh) {
    std::size_t six = 0, interior = 0;
    for (Vertex v : mesh.vertices()) {
        if (!mesh.is_boundary(v)) {
            ++interior;
            six += mesh.valence(v) == 6;
        }
    }
    return interior > 0 ? 100 * six / interior : 0;
}

TEST(RemeshRefuses, BadInput) {
    const Mesh ball = shapes::icosphere(1);
    EXPECT_EQ(check_remesh(test::quad_cube(), length(0.1)),
              "cannot remesh: remeshing needs triangles and 6 of the 6 faces are polygons "
              "(triangulate them first: the `triangulate` step, Ctrl+T in the viewer)");
    EXPECT_EQ(check_remesh(ball, length(0.1, 0)),
              "cannot remesh: iterations must be from 1 to 100, not 0");
    EXPECT_NE(check_remesh(ball, length(0.1, 101)), "");
    EXPECT_NE(check_remesh(ball, length(-1)), "");
    EXPECT_NE(check_remesh(ball, length(std::numeric_limits<double>::quiet_NaN())), "");
    EXPECT_NE(check_remesh(ball, length(std::numeric_limits<double>::infinity())), "");
    const std::string tiny = check_remesh(ball, length(1e-6)).text();
    EXPECT_NE(tiny.find("triangles (at most 100,000,000)"), std::string::npos) << tiny;
    EXPECT_EQ(check_remesh(Mesh(), length(0.1)), "cannot remesh: the mesh has no faces");
    Mesh point = shapes::tetrahedron();  // every corner on one point: no mean length
    for (Vertex v : point.vertices()) {
        point.position(v) = Vec3{};
    }
    EXPECT_EQ(check_remesh(point, length(0)),
              "cannot remesh: every edge has length 0 (a degenerate mesh), so there is no mean "
              "length to aim for");
    EXPECT_EQ(check_remesh(ball, length(0)), "");  // 0: the mean length
}

// A coarse sphere refined to L = 0.1: lengths gather in [4/5 L, 4/3 L], every vertex lies on
// the input polyhedron, and more than half the vertices have valence 6 (flips that would bend
// the surface more are not made, so not all can).
TEST(Remesh, SphereEdgesNearTheTargetAndOnTheInput) {
    const Mesh ball = shapes::icosphere(2);  // 320 triangles, edges about 0.3
    const TriangleTree input(ball);
    const double l = 0.1;
    RemeshReport report;
    const Mesh out = remeshed(ball, length(l), &report);
    EXPECT_GT(out.n_faces(), 2000u);
    EXPECT_GT(report.splits, 0u);
    std::size_t inside = 0;
    for (Edge e : out.edges()) {
        const double len = edge_length(out, e);
        EXPECT_LT(len, 4.0 / 3.0 * l * 1.5) << "edge " << e.idx();
        inside += len >= 0.6 * l && len <= 4.0 / 3.0 * l;
    }
    EXPECT_GT(100 * inside / out.n_edges(), 90u) << inside << " of " << out.n_edges();
    for (Vertex v : out.vertices()) {
        EXPECT_LT(std::sqrt(input.closest(out.position(v)).distance_squared), 1e-9) << v.idx();
    }
    EXPECT_GT(valence_six_share_percent(out), 50u);
}

// The default length is the mean: a remeshed torus keeps about its size and face count and
// improves its valences; the run is deterministic.
TEST(Remesh, MeanLengthByDefaultAndDeterministic) {
    const Mesh torus = shapes::torus(24, 12);
    const Mesh a = remeshed(torus, RemeshOptions{});
    const Mesh b = remeshed(torus, RemeshOptions{});
    EXPECT_TRUE(test::identical(a, b));
    EXPECT_GT(a.n_faces(), torus.n_faces() / 2);
    EXPECT_LT(a.n_faces(), torus.n_faces() * 2);
}

// A flat open grid: stays flat; its boundary stays on the square's sides and its four corners
// stay where they were.
TEST(Remesh, BoundaryAndCornersStay) {
    const Mesh grid = shapes::grid(6, 6);
    const Mesh out = remeshed(grid, length(0.06));
    EXPECT_GT(out.n_faces(), grid.n_faces());
    int corners = 0;
    for (Vertex v : out.vertices()) {
        const Vec3& p = out.position(v);
        EXPECT_EQ(p.z, 0.0);
        if (out.is_boundary(v)) {
            EXPECT_EQ(std::min({p.x, 1 - p.x, p.y, 1 - p.y}), 0.0) << v.idx();
        }
        corners += (p.x == 0 || p.x == 1) && (p.y == 0 || p.y == 1);
    }
    EXPECT_EQ(corners, 4);
}

// Creases: a cube of flat triangles with its 12 edges creased keeps its 8 corners exactly and
// every vertex on its surface; crease vertices stay on the cube's edges.
TEST(Remesh, CreasesKeepTheCubeSharp) {
    Mesh cube = shapes::quad_sphere(1);
    QuadSubdivisionOptions linear;
    linear.scheme = QuadScheme::Linear;
    quad_subdivide(cube, linear);
    quad_subdivide(cube, linear);
    triangulate(cube);
    cube.garbage_collection();
    auto crease = cube.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    for (Edge e : cube.edges()) {
        const double turn =
            dot(face_normal(cube, cube.face(e, 0)), face_normal(cube, cube.face(e, 1)));
        crease[e] = turn < 0.5;
    }
    const double s = 1.0 / std::sqrt(3.0);
    const Mesh out = remeshed(cube, length(0.12));
    const auto flags = out.get_property<Edge, std::uint8_t>(kCreaseProperty);
    ASSERT_TRUE(flags);
    int corners = 0;
    for (Vertex v : out.vertices()) {
        const Vec3& p = out.position(v);
        int on_faces = 0;
        for (double c : {p.x, p.y, p.z}) {
            on_faces += std::abs(std::abs(c) - s) < 1e-12;
        }
        EXPECT_GE(on_faces, 1) << "vertex " << v.idx() << " left the cube";
        corners += on_faces == 3;
        int crease_edges = 0;
        for (Edge e : out.edges(v)) {
            crease_edges += flags[e] != 0;
        }
        if (crease_edges >= 2) {
            EXPECT_GE(on_faces, 2) << "crease vertex " << v.idx() << " left the cube's edges";
        }
    }
    EXPECT_EQ(corners, 8);
}

TEST(Remesh, ProgressRisesToOne) {
    std::vector<double> seen;
    RemeshOptions options = length(0.2, 2);
    options.progress = [&](double f) { seen.push_back(f); };
    remeshed(shapes::icosphere(2), options);
    ASSERT_EQ(seen.size(), 9u);  // 0, then four phases per iteration
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_EQ(seen.back(), 1.0);
}

}  // namespace
}  // namespace meshedit
