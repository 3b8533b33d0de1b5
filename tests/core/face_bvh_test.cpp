// The face BVH against a brute-force ray cast over every fan triangle: on random rays over
// triangle and polygon meshes, front sides only, after local edits passed to update(), and
// across the rebuilds update() falls back to.

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <vector>

#include "meshedit/core/display_fan.h"
#include "meshedit/core/face_bvh.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/core/shapes.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

using Sides = FaceBvh::Sides;

/// Every fan triangle of every live face, nearest first-found on ties; sides named as
/// MeshRenderer::upload() names them.
std::optional<FaceBvh::Hit> brute_force(const Mesh& mesh, const FaceBvh::Ray& ray, Sides sides) {
    std::optional<FaceBvh::Hit> best;
    for (Face f : mesh.faces()) {
        const Halfedge h0 = mesh.halfedge(f);
        const std::size_t n = mesh.valence(f);
        for_each_fan_triangle(mesh, f, [&](std::size_t i, Vertex c0, Halfedge h) {
            const Vertex c1 = mesh.from_vertex(h), c2 = mesh.to_vertex(h);
            const Vec3 &a = mesh.position(c0), &b = mesh.position(c1), &c = mesh.position(c2);
            const auto line = FaceBvh::line_plane(a, b, c, ray.origin, ray.direction);
            if (!line) {
                return;
            }
            const auto [t, b0, b1, b2] = *line;
            const bool front = dot(cross(b - a, c - a), ray.direction) < 0.0;
            if (b1 < 0.0 || b1 > 1.0 || b2 < 0.0 || b1 + b2 > 1.0 || t < ray.t_min ||
                t >= (best ? best->t : ray.t_max) || (sides == Sides::FrontOnly && !front)) {
                return;
            }
            best =
                FaceBvh::Hit{f,
                             {c0, c1, c2},
                             {i == 1 ? h0 : Halfedge(), h, i + 2 == n ? mesh.next(h) : Halfedge()},
                             {b0, b1, b2},
                             t,
                             front};
        });
    }
    return best;
}

/// Rays from a box around the mesh towards points inside its bounds (most of them hit).
std::vector<FaceBvh::Ray> random_rays(const BoundingBox& box, int count, unsigned seed) {
    const Vec3 size = box.max - box.min + Vec3{0.1, 0.1, 0.1};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto point = [&](double spread) {
        const Vec3 c = box.center();
        return Vec3{c.x + spread * (u(rng) - 0.5) * size.x, c.y + spread * (u(rng) - 0.5) * size.y,
                    c.z + spread * (u(rng) - 0.5) * size.z};
    };
    std::vector<FaceBvh::Ray> rays;
    for (int i = 0; i < count; ++i) {
        const Vec3 from = point(3.0);
        FaceBvh::Ray ray{from, point(1.0) - from};
        if (i % 5 == 0) {
            ray.t_max = 0.8;  // a segment: stops short of some hits
        }
        if (i % 7 == 0) {
            ray.direction = {0.0, 0.0, -1.0};  // axis-parallel: zero direction components
            ray.origin.z = box.max.z + 1.0;
        }
        rays.push_back(ray);
    }
    return rays;
}

/// `rays_around`: where to aim the rays, if not at the mesh's bounds.
void expect_same(const Mesh& mesh, const FaceBvh& bvh, int count, unsigned seed,
                 std::optional<BoundingBox> rays_around = {}) {
    int hits = 0;
    for (const Sides sides : {Sides::Both, Sides::FrontOnly}) {
        for (const FaceBvh::Ray& ray :
             random_rays(rays_around.value_or(mesh.bounds()), count, seed)) {
            const auto expected = brute_force(mesh, ray, sides);
            const auto got = bvh.intersect(mesh, ray, sides);
            ASSERT_EQ(expected.has_value(), got.has_value());
            if (!got) {
                continue;
            }
            ++hits;
            ASSERT_EQ(got->t, expected->t);
            if (got->face != expected->face) {
                continue;  // a ray through a shared edge or corner: either is right
            }
            EXPECT_EQ(got->corners, expected->corners);
            EXPECT_EQ(got->sides, expected->sides);
            EXPECT_EQ(got->barycentric, expected->barycentric);
            EXPECT_EQ(got->front, expected->front);
            EXPECT_FALSE(mesh.is_deleted(got->face));
        }
    }
    EXPECT_GT(hits, count / 4);  // the rays really test something
}

/// A quad, a pentagon and a triangle: fans with diagonals, and a boundary.
Mesh polygons() {
    return test::mesh_from_faces({{0, 0, 0},
                                  {1, 0, 0},
                                  {2, 0, 0.2},
                                  {2, 1, 0.1},
                                  {1, 1, 0},
                                  {0, 1, 0},
                                  {1.5, 1.8, 0.3},
                                  {0.5, 1.6, -0.2}},
                                 {{0, 1, 4, 5}, {1, 2, 3, 6, 4}, {5, 4, 6, 7}});
}

TEST(FaceBvh, AgreesWithBruteForce) {
    for (const Mesh& mesh : {shapes::torus(24, 12), shapes::icosphere(3), shapes::grid(9, 7),
                             shapes::quad_sphere(5), polygons(), test::quad_cube()}) {
        const FaceBvh bvh(mesh);
        expect_same(mesh, bvh, 400, 11);
    }
}

TEST(FaceBvh, NamesFanSidesAsTheRenderer) {
    // The pentagon (1,2,3,6,4) is fanned from 1: (1,2,3) (1,3,6) (1,6,4). Its middle
    // triangle has no real side; the first has 1->2 and 2->3, the last 6->4 and 4->1.
    const Mesh mesh = polygons();
    const FaceBvh bvh(mesh);
    EXPECT_EQ(bvh.tree_size(), 2u + 3u + 2u);
    for (const Sides sides : {Sides::Both, Sides::FrontOnly}) {
        const FaceBvh::Ray down{{1.45, 0.6, 5.0}, {0.0, 0.0, -1.0}};
        const auto hit = bvh.intersect(mesh, down, sides);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->face, Face(1));
        EXPECT_EQ(hit->corners, (std::array{Vertex(1), Vertex(3), Vertex(6)}));
        EXPECT_FALSE(hit->sides[0].is_valid());
        EXPECT_TRUE(hit->sides[1].is_valid());
        EXPECT_FALSE(hit->sides[2].is_valid());
        EXPECT_TRUE(hit->front);
        EXPECT_NEAR(hit->barycentric[0] + hit->barycentric[1] + hit->barycentric[2], 1.0, 1e-12);
    }
    // From below, only the back side is there.
    const FaceBvh::Ray up{{1.45, 0.6, -5.0}, {0.0, 0.0, 1.0}};
    EXPECT_TRUE(bvh.intersect(mesh, up, Sides::Both));
    EXPECT_FALSE(bvh.intersect(mesh, up, Sides::FrontOnly));
}

TEST(FaceBvh, EmptyMeshHitsNothing) {
    const Mesh mesh;
    const FaceBvh bvh(mesh);
    EXPECT_TRUE(bvh.empty());
    EXPECT_FALSE(bvh.intersect(mesh, {{0, 0, 5}, {0, 0, -1}}));
}

TEST(FaceBvh, SkipsDeletedFaces) {
    Mesh mesh = shapes::icosphere(2);
    std::mt19937 rng(3);
    for (int i = 0; i < 60; ++i) {
        (void)collapse(mesh, Edge(static_cast<std::uint32_t>(rng() % mesh.edges_size())));
    }
    ASSERT_TRUE(mesh.has_garbage());
    const FaceBvh bvh(mesh);
    expect_same(mesh, bvh, 300, 5);
}

TEST(FaceBvh, NonFiniteCornersAreNeverHit) {
    Mesh mesh = shapes::torus(24, 12);
    const BoundingBox box = mesh.bounds();
    mesh.position(Vertex(5)).x = NAN;
    mesh.position(Vertex(77)).z = INFINITY;
    mesh.position(Vertex(78)).y = -INFINITY;
    const FaceBvh bvh(mesh);
    expect_same(mesh, bvh, 400, 13, box);
}

/// The faces an edit of edge e may change: every face around either end, before the edit.
std::vector<Face> faces_near(const Mesh& mesh, Edge e) {
    std::vector<Face> out;
    for (unsigned i = 0; i < 2; ++i) {
        for (Face f : mesh.faces(mesh.vertex(e, i))) {
            out.push_back(f);
        }
    }
    return out;
}

TEST(FaceBvh, UpdateAfterLocalEditsAgreesWithBruteForce) {
    for (Mesh mesh : {shapes::torus(30, 14), shapes::quad_sphere(6), polygons()}) {
        FaceBvh bvh(mesh);
        std::mt19937 rng(17);
        int applied = 0;
        for (int step = 0; step < 120; ++step) {
            const Edge e(static_cast<std::uint32_t>(rng() % mesh.edges_size()));
            if (mesh.is_deleted(e)) {
                continue;
            }
            const std::vector<Face> touched = faces_near(mesh, e);
            bool ok = false;
            switch (step % 3) {
                case 0:
                    ok = flip(mesh, e).ok();
                    break;
                case 1:
                    ok = split(mesh, e).ok();
                    break;
                default:
                    ok = collapse(mesh, e).ok();
                    break;
            }
            if (!ok) {
                continue;
            }
            ++applied;
            bvh.update(mesh, touched);
            if (step % 10 == 0) {
                expect_same(mesh, bvh, 150, static_cast<unsigned>(step));
            }
        }
        EXPECT_GT(applied, 3);
        EXPECT_GT(bvh.overflow_size(), 0u);
        EXPECT_EQ(bvh.rebuilds(), 0u);  // small edits stay in the overflow list
        expect_same(mesh, bvh, 400, 99);
    }
}

TEST(FaceBvh, UpdateRebuildsPastTheLimit) {
    Mesh mesh = shapes::torus(80, 40);  // 6,400 triangles
    FaceBvh bvh(mesh);
    // A vertex moved: every face is touched (as a whole-mesh edit would be).
    for (Vertex v : mesh.vertices()) {
        mesh.position(v).z += 0.01 * mesh.position(v).x;
    }
    std::vector<Face> all;
    for (Face f : mesh.faces()) {
        all.push_back(f);
    }
    bvh.update(mesh, all);
    EXPECT_EQ(bvh.rebuilds(), 1u);
    EXPECT_EQ(bvh.overflow_size(), 0u);
    EXPECT_EQ(bvh.stale_count(), 0u);
    expect_same(mesh, bvh, 300, 8);
}

// Undoing a recorded edit removes the faces it appended: update() drops them (no rebuild).
TEST(FaceBvh, UpdateFollowsAnUndoneEdit) {
    Mesh mesh = shapes::torus(30, 20);
    FaceBvh bvh(mesh);
    MeshRecorder recorder(mesh);
    for (std::uint32_t e = 0; e < 40; e += 4) {
        ASSERT_TRUE(split(mesh, Edge(e)));
    }
    const MeshChange change = recorder.finish();
    const MeshChange::Region region = change.region();
    bvh.update(mesh, faces_to_redraw(mesh, region));
    expect_same(mesh, bvh, 300, 10);
    change.undo(mesh);
    bvh.update(mesh, faces_to_redraw(mesh, region));
    EXPECT_EQ(bvh.rebuilds(), 0u);
    expect_same(mesh, bvh, 300, 11);
}

}  // namespace
}  // namespace meshedit
