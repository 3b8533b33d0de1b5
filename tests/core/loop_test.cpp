// Loop subdivision: element counts, the index layout, the fast path against the classic
// split-and-flip reference, hand-computed positions for every rule, and the progress callback.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "subdivision_test_util.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using test::crease_pairs;
using test::creased_cube;
using test::expect_same_result;
using test::is_crease;
using test::kTol;
using test::mark_crease;
using test::near;
using test::Pairs;

// Subdivides a copy `levels` times with the fast or the classic path, validating each level.
Mesh subdivided(Mesh mesh, int levels, bool classic = false, LoopWeights w = LoopWeights::Warren) {
    LoopOptions options;
    options.weights = w;
    for (int i = 0; i < levels; ++i) {
        if (classic) {
            loop_subdivide_classic(mesh, options);
        } else {
            loop_subdivide(mesh, options);
        }
        EXPECT_VALID(mesh);
    }
    return mesh;
}

std::size_t boundary_edges(const Mesh& mesh) {
    std::size_t n = 0;
    for (Edge e : mesh.edges()) {
        n += mesh.is_boundary(e);
    }
    return n;
}

long euler(const Mesh& m) {
    return static_cast<long>(m.n_vertices()) - static_cast<long>(m.n_edges()) +
           static_cast<long>(m.n_faces());
}

Vec3 pos(const Mesh& mesh, std::uint32_t v) {
    return mesh.position(Vertex(v));
}

// The vertex the subdivision put on the edge a-b of `before` (index V + e).
std::uint32_t edge_vertex(const Mesh& before, std::uint32_t a, std::uint32_t b) {
    const Edge e = before.find_edge(Vertex(a), Vertex(b));
    EXPECT_TRUE(e.is_valid()) << a << "-" << b;
    return static_cast<std::uint32_t>(before.vertices_size()) + e.idx();
}

// Two meshes with different vertex numbering describe the same surface: each vertex of
// `a` has exactly one vertex of `b` within 1e-12, and under that map the faces (with
// orientation) and crease edges agree. (test::same_faces_by_position is not used: it picks
// each face's first corner by an exact lexicographic comparison, which rounding differences
// of 1e-16 can flip on axis-aligned meshes.)
void expect_same_surface(const Mesh& a, const Mesh& b) {
    ASSERT_EQ(a.n_vertices(), b.n_vertices());
    std::vector<std::uint32_t> map(a.vertices_size(), kInvalidIndex);
    for (Vertex v : a.vertices()) {
        for (Vertex w : b.vertices()) {
            if (distance(a.position(v), b.position(w)) <= kTol) {
                ASSERT_EQ(map[v.idx()], kInvalidIndex) << "two vertices near " << v.idx();
                map[v.idx()] = w.idx();
            }
        }
        ASSERT_NE(map[v.idx()], kInvalidIndex) << "no vertex near " << v.idx();
    }
    auto faces = test::canonical_faces(a);
    for (auto& f : faces) {
        for (auto& v : f) {
            v = map[v];
        }
        std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    }
    std::sort(faces.begin(), faces.end());
    EXPECT_EQ(faces, test::canonical_faces(b));
    Pairs creases = crease_pairs(a);
    for (auto& [x, y] : creases) {
        x = map[x];
        y = map[y];
        if (x > y) {
            std::swap(x, y);
        }
    }
    std::sort(creases.begin(), creases.end());
    EXPECT_EQ(creases, crease_pairs(b));
}

// ----------------------------------------------------------------- counts and layout

TEST(LoopCounts, ClosedMeshesFollowVPlusEAnd2EPlus3FAnd4F) {
    std::vector<test::NamedMesh> meshes;
    meshes.push_back({"tetrahedron", shapes::tetrahedron()});
    meshes.push_back({"cube", shapes::cube()});
    meshes.push_back({"icosahedron", shapes::icosahedron()});
    meshes.push_back({"torus", shapes::torus(8, 6)});
    for (const auto& [name, before] : meshes) {
        SCOPED_TRACE(name);
        const Mesh after = subdivided(before, 1);
        EXPECT_EQ(after.n_vertices(), before.n_vertices() + before.n_edges());
        EXPECT_EQ(after.n_edges(), 2 * before.n_edges() + 3 * before.n_faces());
        EXPECT_EQ(after.n_faces(), 4 * before.n_faces());
        EXPECT_EQ(euler(after), euler(before));
        EXPECT_TRUE(after.is_triangle_mesh());
        EXPECT_EQ(boundary_edges(after), 0u);
    }
    // Exact numbers for two of them: tetrahedron 4/6/4 -> 10/24/16, torus(8,6) 48/144/96.
    const Mesh tet = subdivided(shapes::tetrahedron(), 1);
    EXPECT_EQ(tet.n_vertices(), 10u);
    EXPECT_EQ(tet.n_edges(), 24u);
    EXPECT_EQ(tet.n_faces(), 16u);
    const Mesh torus = subdivided(shapes::torus(8, 6), 2);
    EXPECT_EQ(torus.n_vertices(), 48u + 144u + 576u);
    EXPECT_EQ(torus.n_faces(), 96u * 16u);
}

TEST(LoopCounts, OpenMeshesDoubleTheirBoundary) {
    std::vector<test::NamedMesh> meshes;
    meshes.push_back({"grid", shapes::grid(3, 2)});
    meshes.push_back({"disk", shapes::disk(5)});
    meshes.push_back({"cylinder", shapes::cylinder(6, 3)});
    meshes.push_back({"two_triangles", test::two_triangles()});
    for (const auto& [name, before] : meshes) {
        SCOPED_TRACE(name);
        const Mesh after = subdivided(before, 1);
        EXPECT_EQ(after.n_vertices(), before.n_vertices() + before.n_edges());
        EXPECT_EQ(after.n_edges(), 2 * before.n_edges() + 3 * before.n_faces());
        EXPECT_EQ(after.n_faces(), 4 * before.n_faces());
        EXPECT_EQ(boundary_edges(after), 2 * boundary_edges(before));
        EXPECT_EQ(euler(after), euler(before));
    }
    // grid(3,2): 12 vertices, 23 edges (10 on the boundary), 12 faces.
    const Mesh grid = subdivided(shapes::grid(3, 2), 1);
    EXPECT_EQ(grid.n_vertices(), 35u);
    EXPECT_EQ(grid.n_edges(), 82u);
    EXPECT_EQ(grid.n_faces(), 48u);
    EXPECT_EQ(boundary_edges(grid), 20u);
}

TEST(LoopLayout, OldVerticesKeepIndicesAndEdgeVertexIsVPlusE) {
    for (bool classic : {false, true}) {
        SCOPED_TRACE(classic ? "classic" : "fast");
        const Mesh before = shapes::grid(2, 2);
        const Mesh after = subdivided(before, 1, classic);
        const auto nv = static_cast<std::uint32_t>(before.vertices_size());
        for (Edge e : before.edges()) {
            const Vertex a = before.vertex(e, 0);
            const Vertex b = before.vertex(e, 1);
            const Vertex m(nv + e.idx());
            // m sits between a and b (boundary edges: exactly the midpoint; grid is planar).
            EXPECT_TRUE(after.find_edge(a, m).is_valid());
            EXPECT_TRUE(after.find_edge(m, b).is_valid());
            EXPECT_FALSE(after.find_edge(a, b).is_valid());
            if (before.is_boundary(e)) {
                EXPECT_TRUE(
                    near(after.position(m), 0.5 * (before.position(a) + before.position(b))));
            }
        }
    }
}

TEST(LoopLayout, FastPathEdgeAndFaceLayout) {
    // Documented in subdivision.cpp and docs: new edge g (< 2E) joins from_vertex(g) and
    // V + g/2; faces 4f..4f+2 are the corners of old face f, 4f+3 its centre.
    const Mesh before = shapes::icosahedron();
    const Mesh after = subdivided(before, 1);
    const auto nv = static_cast<std::uint32_t>(before.vertices_size());
    for (Halfedge h : before.halfedges()) {
        const Edge g(h.idx());
        const Halfedge first = Mesh::halfedge(g, 0);
        EXPECT_EQ(after.from_vertex(first), before.from_vertex(h));
        EXPECT_EQ(after.to_vertex(first).idx(), nv + h.idx() / 2);
    }
    for (Face f : before.faces()) {
        std::vector<Vertex> corners;
        for (Vertex v : before.vertices(f)) {
            corners.push_back(v);
        }
        const Face centre(4 * f.idx() + 3);
        for (Vertex v : after.vertices(centre)) {
            EXPECT_GE(v.idx(), nv);
        }
        for (std::uint32_t i = 0; i < 3; ++i) {
            // Exactly one old corner per corner face, and it is a corner of f.
            int old = 0;
            for (Vertex v : after.vertices(Face(4 * f.idx() + i))) {
                if (v.idx() < nv) {
                    ++old;
                    EXPECT_NE(std::find(corners.begin(), corners.end(), v), corners.end());
                }
            }
            EXPECT_EQ(old, 1);
        }
    }
}

TEST(LoopLayout, BoundaryAnchorsAndLinksOnOpenMeshAfterThreeLevels) {
    Mesh mesh = shapes::cylinder(5, 2);
    for (int level = 0; level < 3; ++level) {
        loop_subdivide(mesh);
        ASSERT_VALID(mesh);
    }
    // Every boundary vertex is anchored at an outgoing boundary halfedge, and each boundary
    // loop has 5·8 edges.
    for (Vertex v : mesh.vertices()) {
        const bool on_boundary = std::any_of(mesh.halfedges(v).begin(), mesh.halfedges(v).end(),
                                             [&](Halfedge h) { return mesh.is_boundary(h); });
        EXPECT_EQ(mesh.is_boundary(v), on_boundary) << v.idx();
    }
    const Halfedge start = mesh.halfedge(Vertex(0));
    ASSERT_TRUE(mesh.is_boundary(start));
    std::size_t n = 0;
    for ([[maybe_unused]] Halfedge h : mesh.loop(start)) {
        ++n;
    }
    EXPECT_EQ(n, 40u);
}

// ----------------------------------------------------------------- fast == classic

TEST(LoopFastEqualsClassic, OneLevel) {
    std::vector<test::NamedMesh> meshes;
    meshes.push_back({"tetrahedron", shapes::tetrahedron()});
    meshes.push_back({"icosahedron", shapes::icosahedron()});
    meshes.push_back({"torus", shapes::torus(5, 4)});
    meshes.push_back({"grid", shapes::grid(4, 3)});
    meshes.push_back({"disk", shapes::disk(6)});
    meshes.push_back({"cylinder", shapes::cylinder(5, 2)});
    meshes.push_back({"creased cube", creased_cube()});
    meshes.push_back({"quad sphere", shapes::quad_sphere(2)});
    for (const auto& [name, before] : meshes) {
        SCOPED_TRACE(name);
        for (LoopWeights w : {LoopWeights::Warren, LoopWeights::Loop}) {
            expect_same_result(subdivided(before, 1, false, w), subdivided(before, 1, true, w));
        }
    }
}

TEST(LoopFastEqualsClassic, SeveralLevels) {
    // Vertex V + e depends on the edge indices of the input, which the two paths lay out
    // differently (the classic one appends whatever split() appends), so index equality is
    // checked level by level on a common input; after all levels the two independent runs
    // must still give the same surface, compared face by face through positions.
    std::vector<std::pair<test::NamedMesh, int>> cases;
    cases.push_back({{"creased cube", creased_cube()}, 3});
    cases.push_back({{"grid", shapes::grid(3, 2)}, 3});
    cases.push_back({{"cylinder", shapes::cylinder(4, 1)}, 2});
    cases.push_back({{"quad sphere", shapes::quad_sphere(1)}, 2});
    cases.push_back({{"torus", shapes::torus(4, 3)}, 2});
    for (const auto& [named, levels] : cases) {
        SCOPED_TRACE(named.name);
        Mesh mesh = named.mesh;
        for (int level = 0; level < levels; ++level) {
            SCOPED_TRACE("level " + std::to_string(level + 1));
            const Mesh classic = subdivided(mesh, 1, true);
            mesh = subdivided(mesh, 1, false);
            expect_same_result(mesh, classic);
        }
        const Mesh classic = subdivided(named.mesh, levels, true);
        expect_same_surface(mesh, classic);
    }
}

TEST(LoopFastEqualsClassic, MeshWithoutCreasesGetsNoCreaseProperty) {
    Mesh fast = shapes::icosahedron();
    Mesh classic = shapes::icosahedron();
    loop_subdivide(fast);
    loop_subdivide_classic(classic);
    EXPECT_FALSE(fast.has_property<Edge>(kCreaseProperty));
    EXPECT_FALSE(classic.has_property<Edge>(kCreaseProperty));
}

TEST(LoopFastEqualsClassic, IsolatedVertexStaysPut) {
    //  3 isolated at (5,5,5) next to two triangles 0-1-2, 0-2-4.
    const Mesh before = test::mesh_from_faces(
        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {5, 5, 5}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 4}});
    ASSERT_TRUE(before.is_isolated(Vertex(3)));
    const Mesh fast = subdivided(before, 1);
    expect_same_result(fast, subdivided(before, 1, true));
    EXPECT_TRUE(fast.is_isolated(Vertex(3)));
    EXPECT_EQ(pos(fast, 3), Vec3(5, 5, 5));
}

TEST(LoopPreconditions, PolygonsAreTriangulatedFirstAndReported) {
    for (bool classic : {false, true}) {
        Mesh mesh = shapes::quad_sphere(2);  // 26 vertices, 24 quads
        const LoopReport report = classic ? loop_subdivide_classic(mesh) : loop_subdivide(mesh);
        ASSERT_VALID(mesh);
        EXPECT_EQ(report.triangulated_faces, 24u);
        EXPECT_EQ(mesh.n_faces(), 4u * 48u);
        EXPECT_TRUE(mesh.is_triangle_mesh());
    }
    Mesh tri = shapes::icosahedron();
    EXPECT_EQ(loop_subdivide(tri).triangulated_faces, 0u);
}

TEST(LoopPreconditions, GarbageIsCollectedFirst) {
    Mesh mesh = shapes::cube();
    const Vertex extra = mesh.new_vertex({9, 9, 9});
    mesh.mark_deleted(extra);
    ASSERT_TRUE(mesh.has_garbage());
    ASSERT_VALID(mesh);
    loop_subdivide(mesh);
    ASSERT_VALID(mesh);
    EXPECT_FALSE(mesh.has_garbage());
    EXPECT_EQ(mesh.vertices_size(), 8u + 18u);
}

TEST(LoopPreconditions, GarbageFromACollapseIsCollectedFirstByBothPaths) {
    Mesh before = shapes::icosphere(1);  // 42 vertices, 120 edges, 80 faces
    ASSERT_TRUE(collapse(before, Edge(5)));
    ASSERT_TRUE(before.has_garbage());
    ASSERT_VALID(before);
    const Mesh fast = subdivided(before, 1);
    expect_same_result(fast, subdivided(before, 1, true));
    // 41 vertices, 117 edges, 78 faces after collection.
    EXPECT_EQ(fast.vertices_size(), 41u + 117u);
    EXPECT_EQ(fast.faces_size(), 4u * 78u);
}

// A closed two-triangle pillow would subdivide into a mesh with doubled edges (each edge
// point pair joined inside both faces), which no file can hold. Both paths refuse it before
// anything changes.
TEST(LoopPreconditions, PillowIsRefusedUnchanged) {
    for (const char* name : {"pillow", "pillow and ear", "two pillows at a vertex"}) {
        for (const auto& shape : test::pillow_family()) {
            if (shape.name != name) {
                continue;
            }
            SCOPED_TRACE(shape.name);
            EXPECT_EQ(is_loop_ok(shape.mesh).reason(),
                      "cannot subdivide: two triangles on the same three corners (a closed "
                      "pillow) would be joined by doubled edges");
            for (bool classic : {false, true}) {
                Mesh mesh = shape.mesh;
                EXPECT_THROW(classic ? loop_subdivide_classic(mesh) : loop_subdivide(mesh),
                             std::invalid_argument);
                EXPECT_TRUE(test::identical(mesh, shape.mesh));
            }
        }
    }
    // The rest of the family subdivides into valid meshes.
    for (const auto& shape : test::pillow_family()) {
        if (is_loop_ok(shape.mesh)) {
            Mesh mesh = shape.mesh;
            loop_subdivide(mesh);
            EXPECT_VALID(mesh) << shape.name;
        }
    }
}

TEST(LoopPreconditions, EmptyMeshStaysEmpty) {
    for (bool classic : {false, true}) {
        const Mesh mesh = subdivided(Mesh(), 1, classic);
        EXPECT_TRUE(mesh.is_empty());
        EXPECT_EQ(mesh.n_faces(), 0u);
    }
}

// The attribute carry (refine_carry.h): a label (an integer: the heaviest source) stays on
// the old vertices and an edge point takes one end's; both halves of an edge copy it and the
// edges inside the old faces are new.
TEST(LoopPreconditions, UserPropertiesFollowTheStatedDerivation) {
    Mesh mesh = shapes::tetrahedron();
    auto tag = mesh.add_property<Vertex, int>("v:tag", -1);
    auto edge_tag = mesh.add_property<Edge, int>("e:tag", -1);
    for (Vertex v : mesh.vertices()) {
        tag[v] = static_cast<int>(v.idx());
    }
    std::vector<std::pair<int, int>> ends;
    for (Edge e : mesh.edges()) {
        edge_tag[e] = 7 + static_cast<int>(e.idx());
        ends.emplace_back(mesh.vertex(e, 0).idx(), mesh.vertex(e, 1).idx());
    }
    loop_subdivide(mesh);
    ASSERT_VALID(mesh);
    tag = mesh.get_property<Vertex, int>("v:tag");
    edge_tag = mesh.get_property<Edge, int>("e:tag");
    ASSERT_TRUE(tag && edge_tag);
    for (Vertex v : mesh.vertices()) {
        if (v.idx() < 4) {
            EXPECT_EQ(tag[v], static_cast<int>(v.idx()));
        } else {
            const auto [a, b] = ends[v.idx() - 4];  // the point of edge v - V
            EXPECT_TRUE(tag[v] == a || tag[v] == b) << v.idx();
        }
    }
    ASSERT_EQ(edge_tag.vector().size(), 24u);
    for (Edge e : mesh.edges()) {
        EXPECT_EQ(edge_tag[e], e.idx() < 12 ? 7 + static_cast<int>(e.idx() / 2) : -1);
    }
}

// ----------------------------------------------------------------- hand-computed positions

TEST(LoopPositions, TetrahedronWarrenAndLoopAgreeAtValenceThree) {
    // Vertices A(1,1,1), B(1,-1,-1), C(-1,1,-1), D(-1,-1,1); they sum to 0, every vertex
    // has valence 3.
    //   Old vertex (Warren, n = 3: u = 3/16):  p' = (1 - 9/16)·p + 3/16·(S - p) with S = 0
    //                                          = 7/16·p - 3/16·p = p/4
    //   Loop's weight at n = 3: (5/8 - (3/8 + 1/4·cos(2π/3))²)/3 = (5/8 - 1/16)/3 = 3/16,
    //   the same, so both options give p/4 here (they also agree at n = 6; see the
    //   octahedron below for a case where they differ).
    //   Edge A-B: 3/8·(A+B) + 1/8·(C+D) with C+D = -(A+B): (A+B)/4, e.g. A-B -> (1/2, 0, 0).
    const std::vector<Vec3> p{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    const Mesh before = test::mesh_from_faces(p, {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}});
    for (LoopWeights w : {LoopWeights::Warren, LoopWeights::Loop}) {
        for (bool classic : {false, true}) {
            const Mesh after = subdivided(before, 1, classic, w);
            for (std::uint32_t v = 0; v < 4; ++v) {
                EXPECT_TRUE(near(pos(after, v), 0.25 * p[v])) << v;
            }
            EXPECT_TRUE(near(pos(after, edge_vertex(before, 0, 1)), {0.5, 0, 0}));
            EXPECT_TRUE(near(pos(after, edge_vertex(before, 0, 2)), {0, 0.5, 0}));
            EXPECT_TRUE(near(pos(after, edge_vertex(before, 2, 3)), {-0.5, 0, 0}));
        }
    }
    // The same holds for shapes::tetrahedron() (also centred at the origin).
    const Mesh shape = shapes::tetrahedron();
    const Mesh after = subdivided(shape, 1);
    for (Vertex v : shape.vertices()) {
        EXPECT_TRUE(near(after.position(v), 0.25 * shape.position(v)));
    }
}

TEST(LoopPositions, OctahedronWarrenAndLoopDiffer) {
    // Vertices ±x, ±y, ±z; every vertex has valence 4 and its neighbours sum to 0.
    //   Warren u = 3/(8·4) = 3/32:  p' = (1 - 12/32)·p = 5/8·p   -> +x goes to (0.625, 0, 0)
    //   Loop   u = (5/8 - (3/8 + 1/4·cos(π/2))²)/4 = (40/64 - 9/64)/4 = 31/256:
    //          p' = (1 - 124/256)·p = 33/64·p                    -> (0.515625, 0, 0)
    //   Edge +x/+y (opposite +z, -z): 3/8·(1,1,0) + 1/8·(0,0,0) = (3/8, 3/8, 0) for both.
    const Mesh before = test::mesh_from_faces(
        {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
        {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
    for (bool classic : {false, true}) {
        const Mesh warren = subdivided(before, 1, classic, LoopWeights::Warren);
        const Mesh loop = subdivided(before, 1, classic, LoopWeights::Loop);
        EXPECT_TRUE(near(pos(warren, 0), {0.625, 0, 0}));
        EXPECT_TRUE(near(pos(loop, 0), {0.515625, 0, 0}));
        EXPECT_TRUE(near(pos(warren, 5), {0, 0, -0.625}));
        EXPECT_TRUE(near(pos(loop, 5), {0, 0, -0.515625}));
        EXPECT_NE(pos(warren, 0), pos(loop, 0));
        const std::uint32_t m = edge_vertex(before, 0, 2);
        EXPECT_TRUE(near(pos(warren, m), {0.375, 0.375, 0}));
        EXPECT_TRUE(near(pos(loop, m), {0.375, 0.375, 0}));
    }
}

TEST(LoopPositions, OpenFanBoundaryRules) {
    // Centre 0 with an irregular rim; the rim is the boundary:
    //
    //              2 (0,2,0)
    //            /   \    .
    //   (-2,0,0) 3 -- 0 -- 1 (2,0,0)        faces (0,1,2) (0,2,3) (0,3,4) (0,4,1)
    //            \   /
    //              4 (0,-2,1)
    //
    //   Centre (interior, n = 4, neighbours sum to (0,0,1)):
    //     Warren u = 3/32: 5/8·0 + 3/32·(0,0,1)      = (0, 0, 3/32)
    //     Loop   u = 31/256: (1-124/256)·0 + 31/256·(0,0,1) = (0, 0, 31/256)
    //   Rim 1 (boundary neighbours 2 and 4): 3/4·(2,0,0) + 1/8·((0,2,0) + (0,-2,1)) = (3/2, 0, 1/8)
    //   Rim 4 (neighbours 3 and 1): 3/4·(0,-2,1) + 1/8·((-2,0,0) + (2,0,0)) = (0, -3/2, 3/4)
    //   Boundary edge 1-2: midpoint (1, 1, 0);  edge 4-1: (1, -1, 1/2)
    //   Spoke 0-1 (interior, opposite 2 and 4): 3/8·(2,0,0) + 1/8·(0,0,1) = (3/4, 0, 1/8)
    //   Spoke 0-4 (opposite 3 and 1): 3/8·(0,-2,1) + 1/8·(0,0,0) = (0, -3/4, 3/8)
    const Mesh before =
        test::mesh_from_faces({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {-2, 0, 0}, {0, -2, 1}},
                              {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}});
    for (bool classic : {false, true}) {
        SCOPED_TRACE(classic ? "classic" : "fast");
        const Mesh after = subdivided(before, 1, classic);
        EXPECT_TRUE(near(pos(after, 0), {0, 0, 3.0 / 32}));
        EXPECT_TRUE(near(pos(after, 1), {1.5, 0, 0.125}));
        EXPECT_TRUE(near(pos(after, 4), {0, -1.5, 0.75}));
        EXPECT_TRUE(near(pos(after, edge_vertex(before, 1, 2)), {1, 1, 0}));
        EXPECT_TRUE(near(pos(after, edge_vertex(before, 4, 1)), {1, -1, 0.5}));
        EXPECT_TRUE(near(pos(after, edge_vertex(before, 0, 1)), {0.75, 0, 0.125}));
        EXPECT_TRUE(near(pos(after, edge_vertex(before, 0, 4)), {0, -0.75, 0.375}));
        const Mesh loop = subdivided(before, 1, classic, LoopWeights::Loop);
        EXPECT_TRUE(near(pos(loop, 0), {0, 0, 31.0 / 256}));
        EXPECT_TRUE(near(pos(loop, 1), {1.5, 0, 0.125}));  // boundary: weights do not matter
    }
}

TEST(LoopPositions, RegularOneRingFan) {
    // test::one_ring(6): rim k at angle 60°·k on the unit circle, so p[k-1] + p[k+1] = p[k].
    //   Rim: 3/4·p + 1/8·p = 7/8·p.  Spoke 0-k: 3/8·p[k] + 1/8·p[k] = p[k]/2.  Centre: 0.
    const Mesh before = test::one_ring(6);
    const Mesh after = subdivided(before, 1);
    EXPECT_TRUE(near(pos(after, 0), {0, 0, 0}));
    for (std::uint32_t k = 1; k <= 6; ++k) {
        EXPECT_TRUE(near(pos(after, k), 0.875 * pos(before, k))) << k;
        EXPECT_TRUE(near(pos(after, edge_vertex(before, 0, k)), 0.5 * pos(before, k))) << k;
        const std::uint32_t next = k % 6 + 1;
        EXPECT_TRUE(near(pos(after, edge_vertex(before, k, next)),
                         0.5 * (pos(before, k) + pos(before, next))));
    }
}

TEST(LoopPositions, CreasedCubeCornersCreasesAndDarts) {
    // See creased_cube() for the marked edges. Cube vertex i = (±1, ±1, ±1) by bits of i.
    //   7 (1,1,1), 3 (1,1,-1): 3 creases, corners, stay put.
    //   0 (-1,-1,-1): creases to 1 and 2: 3/4·(-1,-1,-1) + 1/8·((1,-1,-1) + (-1,1,-1))
    //                 = (-3/4, -3/4, -3/4) + (0, 0, -1/4) = (-3/4, -3/4, -1)
    //   1 (1,-1,-1): creases to 0 and 3: (3/4, -3/4, -1);  2: (-3/4, 3/4, -1)
    //   5 (1,-1,1): one crease (dart) -> smooth, valence 4 (neighbours 1, 4, 7, 0 sum to
    //               (0,-2,0)): 5/8·(1,-1,1) + 3/32·(0,-2,0) = (5/8, -13/16, 5/8)
    //   6 (-1,1,1): dart, neighbours 2, 4, 7, 0 sum to (-2,0,0): (-13/16, 5/8, 5/8)
    //   4 (-1,-1,1): smooth, neighbours 0, 5, 6, 7 sum to (0,0,2): (-5/8, -5/8, 13/16)
    //   Crease edge 0-1: midpoint (0, -1, -1); crease edge 3-7: (1, 1, 0).
    //   Smooth edge 4-7 (top diagonal, opposite 5 and 6): 3/8·(0,0,2) + 1/8·(0,0,2) = (0,0,1)
    //   Smooth edge 4-5 (opposite 7 and 0): 3/8·(0,-2,2) + 1/8·(0,0,0) = (0, -3/4, 3/4)
    const Mesh before = creased_cube();
    for (bool classic : {false, true}) {
        SCOPED_TRACE(classic ? "classic" : "fast");
        const Mesh after = subdivided(before, 1, classic);
        EXPECT_EQ(pos(after, 7), Vec3(1, 1, 1));
        EXPECT_EQ(pos(after, 3), Vec3(1, 1, -1));
        EXPECT_TRUE(near(pos(after, 0), {-0.75, -0.75, -1}));
        EXPECT_TRUE(near(pos(after, 1), {0.75, -0.75, -1}));
        EXPECT_TRUE(near(pos(after, 2), {-0.75, 0.75, -1}));
        EXPECT_TRUE(near(pos(after, 5), {0.625, -0.8125, 0.625}));
        EXPECT_TRUE(near(pos(after, 6), {-0.8125, 0.625, 0.625}));
        EXPECT_TRUE(near(pos(after, 4), {-0.625, -0.625, 0.8125}));
        const std::uint32_t m01 = edge_vertex(before, 0, 1);
        const std::uint32_t m37 = edge_vertex(before, 3, 7);
        EXPECT_TRUE(near(pos(after, m01), {0, -1, -1}));
        EXPECT_TRUE(near(pos(after, m37), {1, 1, 0}));
        EXPECT_TRUE(near(pos(after, edge_vertex(before, 4, 7)), {0, 0, 1}));
        EXPECT_TRUE(near(pos(after, edge_vertex(before, 4, 5)), {0, -0.75, 0.75}));

        // Both children of a crease stay creases; the edges crossing old faces do not.
        EXPECT_TRUE(is_crease(after, 0, m01));
        EXPECT_TRUE(is_crease(after, m01, 1));
        EXPECT_TRUE(is_crease(after, 3, m37));
        EXPECT_TRUE(is_crease(after, m37, 7));
        EXPECT_EQ(crease_pairs(after).size(), 14u);
        const std::uint32_t m03 = edge_vertex(before, 0, 3);  // bottom diagonal, no crease
        EXPECT_TRUE(after.find_edge(Vertex(m01), Vertex(m03)).is_valid());
        EXPECT_FALSE(is_crease(after, m01, m03));
    }
}

TEST(LoopPositions, CreasesSurviveSeveralLevels) {
    // Three levels: the corners never move, the crease count doubles per level, and crease
    // curves between corners or around a loop stay exactly on their line or plane (the crease
    // rule 3/4·p + 1/8·(a + b) only mixes points of the curve): the bottom loop in z = -1
    // (4·8 creases) and the 7-3 line x = y = 1 (8 creases). The 7-5 and 7-6 lines end at
    // darts, which move by the smooth rule and pull the crease ends along.
    const Mesh after = subdivided(creased_cube(), 3);
    EXPECT_EQ(pos(after, 7), Vec3(1, 1, 1));
    EXPECT_EQ(pos(after, 3), Vec3(1, 1, -1));
    const Pairs creases = crease_pairs(after);
    EXPECT_EQ(creases.size(), 7u * 8u);
    int bottom = 0;
    int line73 = 0;
    for (auto [a, b] : creases) {
        const Vec3 pa = pos(after, a);
        const Vec3 pb = pos(after, b);
        bottom += pa.z == -1.0 && pb.z == -1.0;
        line73 += pa.x == 1.0 && pa.y == 1.0 && pb.x == 1.0 && pb.y == 1.0;
    }
    EXPECT_EQ(bottom, 32);
    EXPECT_EQ(line73, 8);
}

// ----------------------------------------------------------------- progress

TEST(LoopProgress, NonDecreasingAndEndsAtOne) {
    // torus(200, 120): 72,000 edges, several progress chunks in the fast path.
    for (bool classic : {false, true}) {
        SCOPED_TRACE(classic ? "classic" : "fast");
        Mesh mesh = classic ? shapes::torus(40, 30) : shapes::torus(200, 120);
        std::vector<double> seen;
        LoopOptions options;
        options.progress = [&](double t) { seen.push_back(t); };
        if (classic) {
            loop_subdivide_classic(mesh, options);
        } else {
            loop_subdivide(mesh, options);
        }
        ASSERT_VALID(mesh);
        ASSERT_GE(seen.size(), 3u);
        EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
        EXPECT_GE(seen.front(), 0.0);
        EXPECT_EQ(seen.back(), 1.0);
    }
}

// 102,400 faces: just above the threshold for threads. One thread and all of them give the same
// arrays, bit for bit, and progress still comes in order from the calling thread.
TEST(LoopThreads, SameResultOnAnyNumberOfThreads) {
    Mesh input = shapes::torus(256, 200);
    auto crease = input.add_property<Edge, std::uint8_t>(kCreaseProperty, 0);
    for (std::uint32_t e = 0; e < input.edges_size(); e += 7) {
        crease[Edge(e)] = 1;
    }
    Mesh serial = input;
    LoopOptions one;
    one.max_threads = 1;
    loop_subdivide(serial, one);  // validates itself in debug builds

    Mesh threaded = input;
    std::vector<double> seen;
    const std::thread::id caller = std::this_thread::get_id();
    bool other_thread = false;
    LoopOptions all;
    all.progress = [&](double t) {
        seen.push_back(t);
        other_thread = other_thread || std::this_thread::get_id() != caller;
    };
    loop_subdivide(threaded, all);
    EXPECT_TRUE(test::identical(threaded, serial));
    EXPECT_FALSE(other_thread);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.back(), 1.0);
}

}  // namespace
}  // namespace meshedit
