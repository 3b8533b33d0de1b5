// Catmull-Clark and linear subdivision: counts and the index layout, hand-computed points
// for every rule (smooth, boundary, crease, corner, dart), the fast path against the classic
// reference level by level, threads, garbage, properties, the plan and progress.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshedit/core/build.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/shapes.h"
#include "subdivision_test_util.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using test::kTol;
using test::near;

Mesh subdivided(Mesh mesh, int levels, QuadScheme scheme = QuadScheme::CatmullClark,
                bool classic = false) {
    QuadSubdivisionOptions options;
    options.scheme = scheme;
    for (int i = 0; i < levels; ++i) {
        if (classic) {
            quad_subdivide_classic(mesh, options);
        } else {
            quad_subdivide(mesh, options);
        }
        EXPECT_VALID(mesh);
    }
    return mesh;
}

bool all_quads(const Mesh& mesh) {
    return std::all_of(mesh.faces().begin(), mesh.faces().end(),
                       [&](Face f) { return mesh.valence(f) == 4; });
}

std::size_t corners(const Mesh& mesh) {
    std::size_t n = 0;
    for (Face f : mesh.faces()) {
        n += mesh.valence(f);
    }
    return n;
}

// Index of the point on edge a-b of `before` (V + e) and of face f's point (V + E + f).
std::uint32_t edge_point(const Mesh& before, std::uint32_t a, std::uint32_t b) {
    const Edge e = before.find_edge(Vertex(a), Vertex(b));
    EXPECT_TRUE(e.is_valid()) << a << "-" << b;
    return static_cast<std::uint32_t>(before.vertices_size()) + e.idx();
}
std::uint32_t face_point(const Mesh& before, Face f) {
    return static_cast<std::uint32_t>(before.vertices_size() + before.edges_size()) + f.idx();
}

long euler(const Mesh& m) {
    return static_cast<long>(m.n_vertices()) - static_cast<long>(m.n_edges()) +
           static_cast<long>(m.n_faces());
}

// Face cycles as test::canonical_faces() writes them: each from its smallest index, sorted.
std::vector<std::vector<std::uint32_t>> canonical(std::vector<std::vector<std::uint32_t>> faces) {
    for (auto& f : faces) {
        std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

Vec3 centroid(const Mesh& mesh, Face f) {
    Vec3 sum;
    double k = 0;
    for (Vertex v : mesh.vertices(f)) {
        sum += mesh.position(v);
        k += 1;
    }
    return sum * (1.0 / k);
}

Vec3 pos(const Mesh& mesh, std::uint32_t v) {
    return mesh.position(Vertex(v));
}

// A triangle, a pentagon and a quad in a row (faces of degree 3, 5 and 4), open all round:
//
//        2 ------- 3 ---- 4
//       / \       /       \        faces (0 1 2), (1 5 6 3 2), (6 7 4 3)
//      0 - 1 -- 5 -- 6 ---- 7
Mesh mixed_polygons() {
    return test::mesh_from_faces({{0, 0, 0},
                                  {1, 0, 0},
                                  {0.5, 1, 0},
                                  {2, 1.2, 0.3},
                                  {3, 1, 0},
                                  {2, 0, 0.1},
                                  {3, 0, 0},
                                  {4, 0.5, 0.2}},
                                 {{0, 1, 2}, {1, 5, 6, 3, 2}, {6, 7, 4, 3}});
}

// ----------------------------------------------------------------- counts and layout

TEST(QuadSubdivision, CountsAreVPlusEPlusFAnd2EPlusCAndC) {
    for (auto named : test::sweep_corpus()) {
        SCOPED_TRACE(named.name);
        const Mesh& before = named.mesh;
        const Mesh after = subdivided(before, 1);
        EXPECT_EQ(after.n_vertices(), before.n_vertices() + before.n_edges() + before.n_faces());
        EXPECT_EQ(after.n_edges(), 2 * before.n_edges() + corners(before));
        EXPECT_EQ(after.n_faces(), corners(before));
        EXPECT_TRUE(all_quads(after));
        EXPECT_EQ(euler(after), euler(before));
    }
}

// Each corner c of face f becomes the quad (c, point of the next side, face point, point of
// the side before), with f's orientation; old vertices keep their indices.
TEST(QuadSubdivision, EveryCornerBecomesAQuadAroundTheFacePoint) {
    const Mesh before = mixed_polygons();
    for (bool classic : {false, true}) {
        SCOPED_TRACE(classic ? "classic" : "fast");
        const Mesh after = subdivided(before, 1, QuadScheme::Linear, classic);
        std::vector<std::vector<std::uint32_t>> expected;
        for (Face f : before.faces()) {
            for (Halfedge h : before.halfedges(f)) {
                const std::uint32_t c = before.to_vertex(h).idx();
                const Halfedge n = before.next(h);
                expected.push_back({c, edge_point(before, c, before.to_vertex(n).idx()),
                                    face_point(before, f),
                                    edge_point(before, before.from_vertex(h).idx(), c)});
            }
        }
        EXPECT_EQ(test::canonical_faces(after), canonical(expected));
    }
}

// The fast path's face order: face by face, each from the corner halfedge(f) points to.
TEST(QuadSubdivision, FastPathNumbersQuadsByCorner) {
    const Mesh before = mixed_polygons();
    const Mesh after = subdivided(before, 1);
    std::uint32_t q = 0;
    for (Face f : before.faces()) {
        for (Halfedge h : before.halfedges(f)) {
            bool found = false;
            for (Vertex v : after.vertices(Face(q))) {
                found = found || v.idx() == before.to_vertex(h).idx();
            }
            EXPECT_TRUE(found) << "quad " << q << " is not at corner " << before.to_vertex(h).idx();
            EXPECT_TRUE(after.is_boundary(Vertex(face_point(before, f))) == false);
            ++q;
        }
    }
}

// ----------------------------------------------------------------- the rules by hand

// The cube [-1, 1]^3: a corner (valence 3) goes to 5/9 of itself: (n − 2)/n·p + (Σ q + Σ F)/n²
// = p/3 + (p + p)/9; an edge point is 3/4 of the edge's midpoint; face points are the face
// centres.
TEST(QuadSubdivision, CatmullClarkCubeByHand) {
    const Mesh before = test::quad_cube();
    const Mesh after = subdivided(before, 1);
    ASSERT_EQ(after.n_vertices(), 26u);
    ASSERT_EQ(after.n_faces(), 24u);
    for (std::uint32_t v = 0; v < 8; ++v) {
        EXPECT_TRUE(near(pos(after, v), pos(before, v) * (5.0 / 9.0))) << v;
    }
    for (Edge e : before.edges()) {
        const Vec3 mid =
            (before.position(before.vertex(e, 0)) + before.position(before.vertex(e, 1))) * 0.5;
        EXPECT_TRUE(near(pos(after, 8 + e.idx()), mid * 0.75)) << "edge " << e.idx();
    }
    for (Face f : before.faces()) {
        EXPECT_TRUE(near(pos(after, face_point(before, f)), centroid(before, f)));
    }
}

// One open unit quad (0,0) (1,0) (1,1) (0,1): boundary edges are sharp, so edge points are
// midpoints and every corner (two boundary edges) moves by 3/4·p + 1/8·(a + b): (0,0) goes
// to (1/8, 1/8). Linear leaves the corners where they were.
TEST(QuadSubdivision, BoundaryIsAsIfMirrored) {
    const Mesh before = test::quad_strip(1);
    const Mesh cc = subdivided(before, 1);
    const Mesh linear = subdivided(before, 1, QuadScheme::Linear);
    for (Vertex v : before.vertices()) {
        Vec3 ends;
        for (Vertex w : before.vertices(v)) {
            ends += before.position(w);
        }
        EXPECT_TRUE(near(cc.position(v), 0.75 * before.position(v) + 0.125 * ends)) << v.idx();
        EXPECT_EQ(linear.position(v), before.position(v));
    }
    EXPECT_TRUE(near(pos(cc, 0), {0.125, 0.125, 0}));
    for (Edge e : before.edges()) {
        const Vec3 mid =
            (before.position(before.vertex(e, 0)) + before.position(before.vertex(e, 1))) * 0.5;
        EXPECT_TRUE(near(pos(cc, 4 + e.idx()), mid));
        EXPECT_TRUE(near(pos(linear, 4 + e.idx()), mid));
    }
    EXPECT_TRUE(near(pos(cc, 8), {0.5, 0.5, 0}));
}

// Creases on the triangle cube (test::creased_cube): 0, 1, 2 on two creases take the crease
// rule; 3 and 7 (three) are corners and stay; 5, 6 (darts) and 4 (none) take the smooth
// rule; crease edges give midpoints, smooth edges (A + B + F0 + F1)/4; both halves of a
// crease stay creases, inner edges are not.
TEST(QuadSubdivision, CreaseCornerAndDartRules) {
    const Mesh before = test::creased_cube();
    const Mesh after = subdivided(before, 1);
    const auto crease = before.get_property<Edge, std::uint8_t>(kCreaseProperty);
    const std::uint32_t fp0 = face_point(before, Face(0));
    for (Vertex v : before.vertices()) {
        Vec3 all, sharp, faces;
        std::size_t n = 0, n_sharp = 0;
        for (Halfedge h : before.halfedges(v)) {
            const Vec3 q = before.position(before.to_vertex(h));
            all += q;
            ++n;
            faces += pos(after, fp0 + before.face(h).idx());
            if (crease[Mesh::edge(h)] != 0) {
                sharp += q;
                ++n_sharp;
            }
        }
        const Vec3 p = before.position(v);
        const double dn = static_cast<double>(n);
        const Vec3 expected = n_sharp >= 3   ? p
                              : n_sharp == 2 ? 0.75 * p + 0.125 * sharp
                                             : (dn - 2) / dn * p + (all + faces) * (1 / (dn * dn));
        EXPECT_TRUE(near(after.position(v), expected))
            << "vertex " << v.idx() << ", " << n_sharp << " creases";
    }
    EXPECT_EQ(pos(after, 3), pos(before, 3));
    EXPECT_EQ(pos(after, 7), pos(before, 7));
    for (Edge e : before.edges()) {
        const std::uint32_t a = before.vertex(e, 0).idx(), b = before.vertex(e, 1).idx();
        const std::uint32_t m = edge_point(before, a, b);
        const Vec3 mid = (pos(before, a) + pos(before, b)) * 0.5;
        const Vec3 smooth =
            0.25 * (pos(before, a) + pos(before, b) + pos(after, fp0 + before.face(e, 0).idx()) +
                    pos(after, fp0 + before.face(e, 1).idx()));
        EXPECT_TRUE(near(pos(after, m), crease[e] != 0 ? mid : smooth)) << a << "-" << b;
        EXPECT_EQ(test::is_crease(after, a, m), crease[e] != 0);
        EXPECT_EQ(test::is_crease(after, m, b), crease[e] != 0);
    }
    EXPECT_EQ(test::crease_pairs(after).size(), 2 * test::crease_pairs(before).size());
}

// ----------------------------------------------------------------- fast == classic

std::vector<test::NamedMesh> corpus() {
    std::vector<test::NamedMesh> out = test::sweep_corpus();
    out.push_back({"quad cube", test::quad_cube()});
    out.push_back({"creased cube", test::creased_cube()});
    out.push_back({"mixed polygons", mixed_polygons()});
    out.push_back({"quad strip", test::quad_strip(4)});
    Mesh poked = test::quad_cube();
    poke(poked, Face(2));
    dissolve_edge(poked, poked.find_edge(Vertex(2), Vertex(6)));
    out.push_back({"poked and dissolved cube", poked});
    return out;
}

TEST(QuadFastEqualsClassic, LevelByLevelBothSchemes) {
    for (QuadScheme scheme : {QuadScheme::CatmullClark, QuadScheme::Linear}) {
        for (const auto& named : corpus()) {
            SCOPED_TRACE(named.name + (scheme == QuadScheme::Linear ? " (linear)" : " (CC)"));
            Mesh mesh = named.mesh;
            for (int level = 1; level <= 3; ++level) {
                SCOPED_TRACE("level " + std::to_string(level));
                const Mesh classic = subdivided(mesh, 1, scheme, true);
                mesh = subdivided(mesh, 1, scheme);
                test::expect_same_result(mesh, classic);
                EXPECT_TRUE(all_quads(mesh));
            }
        }
    }
}

// The passes run in chunks on several threads from 100,000 faces: the same bits on one.
TEST(QuadFastEqualsClassic, ThreadsDoNotChangeABit) {
    Mesh one = shapes::torus(400, 260);  // 104,000 triangles
    test::mark_crease(one, 0, one.to_vertex(one.halfedge(Vertex(0))).idx());
    Mesh two = one;
    QuadSubdivisionOptions options;
    options.max_threads = 1;
    quad_subdivide(one, options);
    options.max_threads = 2;
    quad_subdivide(two, options);
    EXPECT_TRUE(test::identical(two, one));
    EXPECT_VALID(two);
}

TEST(QuadSubdivision, GarbageIsCollectedFirstByBothPaths) {
    Mesh mesh = test::quad_cube();
    ASSERT_TRUE(collapse(mesh, mesh.find_edge(Vertex(0), Vertex(1))));
    ASSERT_TRUE(mesh.has_garbage());
    Mesh collected = mesh;
    collected.garbage_collection();
    test::expect_same_result(subdivided(mesh, 1), subdivided(collected, 1));
    test::expect_same_result(subdivided(mesh, 1, QuadScheme::CatmullClark, true),
                             subdivided(collected, 1));
}

TEST(QuadSubdivision, IsolatedVertexStaysPut) {
    PolygonSoup soup =
        test::soup_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}}, {{0, 1, 2}});
    const Mesh before = build_mesh(soup);
    for (bool classic : {false, true}) {
        const Mesh after = subdivided(before, 1, QuadScheme::CatmullClark, classic);
        EXPECT_EQ(pos(after, 3), (Vec3{5, 5, 5}));
        EXPECT_TRUE(after.is_isolated(Vertex(3)));
        EXPECT_EQ(after.n_faces(), 3u);
    }
}

// ----------------------------------------------------------------- attributes

// Vertex properties stay on the old vertices (new ones get the default); face properties are
// reset; a mesh without creases gets no crease property.
TEST(QuadSubdivision, PropertiesFollowTheLayout) {
    Mesh mesh = test::quad_cube();
    auto tag = mesh.add_property<Vertex, int>("v:tag", -1);
    auto ftag = mesh.add_property<Face, int>("f:tag", -1);
    for (Vertex v : mesh.vertices()) {
        tag[v] = static_cast<int>(v.idx()) * 10;
    }
    ftag[Face(0)] = 7;
    quad_subdivide(mesh);
    tag = mesh.get_property<Vertex, int>("v:tag");
    ftag = mesh.get_property<Face, int>("f:tag");
    ASSERT_TRUE(tag && ftag);
    // Old vertices keep their labels and new points take a source's (the heaviest: an
    // integer is a label); face 0's four quads, the first four faces, copy its tag.
    for (Vertex v : mesh.vertices()) {
        if (v.idx() < 8) {
            EXPECT_EQ(tag[v], static_cast<int>(v.idx()) * 10) << v.idx();
        } else {
            EXPECT_TRUE(tag[v] >= 0 && tag[v] < 80 && tag[v] % 10 == 0) << v.idx();
        }
    }
    for (Face f : mesh.faces()) {
        EXPECT_EQ(ftag[f], f.idx() < 4 ? 7 : -1) << f.idx();
    }
    EXPECT_FALSE(mesh.has_property<Edge>(kCreaseProperty));
}

// ----------------------------------------------------------------- plan and progress

TEST(QuadSubdivisionPlan, CountsMatchTheResult) {
    const Mesh before = mixed_polygons();
    Mesh mesh = before;
    for (int level = 1; level <= 3; ++level) {
        quad_subdivide(mesh);
        const SubdivisionPlan plan = plan_quad_subdivision(before, level);
        ASSERT_TRUE(plan.ok()) << plan.status;
        EXPECT_EQ(plan.vertices, static_cast<double>(mesh.n_vertices()));
        EXPECT_EQ(plan.edges, static_cast<double>(mesh.n_edges()));
        EXPECT_EQ(plan.faces, static_cast<double>(mesh.n_faces()));
    }
}

TEST(QuadSubdivisionPlan, RefusesWhatWouldNotFit) {
    const SubdivisionPlan plan = plan_quad_subdivision(test::quad_cube(), 16);
    ASSERT_FALSE(plan.ok());
    EXPECT_EQ(plan.status.reason().rfind("cannot subdivide: level ", 0), 0u) << plan.status;
}

TEST(QuadSubdivision, ProgressRisesToOne) {
    for (bool classic : {false, true}) {
        Mesh mesh = shapes::torus(40, 30);
        std::vector<double> seen;
        QuadSubdivisionOptions options;
        options.progress = [&](double f) { seen.push_back(f); };
        classic ? quad_subdivide_classic(mesh, options) : quad_subdivide(mesh, options);
        ASSERT_FALSE(seen.empty());
        EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
        EXPECT_EQ(seen.front(), 0.0);
        EXPECT_EQ(seen.back(), 1.0);
    }
}

}  // namespace
}  // namespace meshedit
