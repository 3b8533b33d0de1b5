// Edge collapse to the midpoint (docs/spec.md §3). The smaller-index endpoint v0 survives; v1, the
// edge and its triangles go. Expected meshes: the input's list with the edge's faces removed,
// v1 renamed to v0, v0 moved, and v1 erased (indices above it shift down by one).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/op_test_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

using test::Indexed;

// The expected result of collapsing v0-v1 (v0 < v1) whose faces are `faces`.
Mesh expected_collapse(const Mesh& input, std::uint32_t v0, std::uint32_t v1,
                       const std::vector<test::Corners>& faces) {
    Indexed expected = test::indexed(input);
    for (const auto& f : faces) {
        expected.remove(f);
    }
    expected.positions[v0] = test::midpoint(input, v0, v1);
    expected.rename(v1, v0);
    // A polygon beside the edge now holds v0 twice in a row: it loses that corner.
    for (test::Corners& f : expected.faces) {
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (f[i] == v0 && f[(i + 1) % f.size()] == v0) {
                f.erase(f.begin() + static_cast<std::ptrdiff_t>(i));
                break;
            }
        }
    }
    expected.erase_vertex(v1);
    return expected.build();
}

// Collapses v0-v1, which must succeed, and checks the returned vertex.
void expect_collapse(Mesh& mesh, std::uint32_t v0, std::uint32_t v1) {
    const Edge e = mesh.find_edge(Vertex(v0), Vertex(v1));
    ASSERT_TRUE(e.is_valid());
    const Vec3 mid = test::midpoint(mesh, v0, v1);
    const long chi = test::euler(mesh);
    EXPECT_TRUE(is_collapse_ok(mesh, e));
    const OpResult<Vertex> r = collapse(mesh, e);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(*r, Vertex(std::min(v0, v1))) << "the smaller index survives";
    EXPECT_FALSE(mesh.is_deleted(*r));
    EXPECT_TRUE(mesh.is_deleted(Vertex(std::max(v0, v1))));
    EXPECT_TRUE(mesh.is_deleted(e));
    EXPECT_EQ(mesh.position(*r), mid);
    EXPECT_EQ(test::euler(mesh), chi);
}

// grid(3,3), vertex (i,j) = 4j + i. Interior edge 5-6 between (1,6,5) and (5,6,10); 5
// survives at (0.5, 1/3).
//   8 --- 9 -- 10 -- 11        8 --- 9 -- 10 -- 11
//   |   / |   / |   / |        |   / |  _/  _/  |
//   | /   | /   | /   |        | /   |_/ __/     |
//   4 --- 5 --- 6 --- 7   =>   4 ----- 5 ------- 7
//   |   / |   / |   / |        |   / /  \__      |
//   | /   | /   | /   |        | /  /       \__  |
//   0 --- 1 --- 2 --- 3        0 --- 1 --- 2 --- 3
TEST(Collapse, GridInteriorEdge) {
    Mesh mesh = shapes::grid(3, 3);
    const Mesh expected = expected_collapse(mesh, 5, 6, {{1, 6, 5}, {5, 6, 10}});
    expect_collapse(mesh, 5, 6);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// The same collapse with creases on 6-10 and 1-6: each merges into the edge that takes its
// place (5-10, 1-5), so a feature line beside a collapse survives it.
TEST(Collapse, MergedEdgesKeepTheirCrease) {
    Mesh mesh = shapes::grid(3, 3);
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    crease[mesh.find_edge(Vertex(6), Vertex(10))] = 1;
    crease[mesh.find_edge(Vertex(1), Vertex(6))] = 1;
    expect_collapse(mesh, 5, 6);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> creased;
    for (const Edge e : mesh.edges()) {
        if (crease[e] != 0) {
            const Halfedge h = mesh.halfedge(e, 0);
            const std::uint32_t a = mesh.from_vertex(h).idx();
            const std::uint32_t b = mesh.to_vertex(h).idx();
            creased.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    std::sort(creased.begin(), creased.end());
    EXPECT_EQ(creased, (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{1, 5}, {5, 10}}));
}

// grid(2,2), vertex (i,j) = 3j + i. Boundary edge 0-1 of (0,1,4); 0 survives at (0.25, 0)
// and stays anchored on the boundary.
//   3 --- 4 --- 5        3 --- 4 --- 5
//   |   / |   / |        |   /   \ / |
//   | /   | /   |   =>   | /     / \ |
//   0 --- 1 --- 2          0 ------- 2
TEST(Collapse, GridBoundaryEdge) {
    Mesh mesh = shapes::grid(2, 2);
    const Mesh expected = expected_collapse(mesh, 0, 1, {{0, 1, 4}});
    expect_collapse(mesh, 0, 1);
    EXPECT_TRUE(mesh.is_boundary(Vertex(0)));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// grid(2,2): interior edge 1-4 from the boundary vertex 1 to the centre 4; 1 survives on the
// boundary.
TEST(Collapse, GridEdgeFromBoundaryToInterior) {
    Mesh mesh = shapes::grid(2, 2);
    const Mesh expected = expected_collapse(mesh, 1, 4, {{0, 1, 4}, {1, 5, 4}});
    expect_collapse(mesh, 1, 4);
    EXPECT_TRUE(mesh.is_boundary(Vertex(1)));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// grid(1,1): vertex 1 is an ear (both its edges on the boundary). Collapsing 0-1 removes
// the ear's triangle:
//   2 --- 3        2 --- 3
//   |   / |        |   /
//   | /   |   =>   | /
//   0 --- 1        0          (0 moves to (0.5, 0))
TEST(Collapse, Ear) {
    Mesh mesh = shapes::grid(1, 1);
    const Mesh expected = expected_collapse(mesh, 0, 1, {{0, 1, 3}});
    expect_collapse(mesh, 0, 1);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// Cube side -x: the diagonal 0-6 shrinks to the side's centre, where 0 now sits.
//   6 ----- 4        . ----- 4
//   | \     |        |  \  / |
//   |   \   |   =>   |    0  |      (edges 0-2, 0-4, 0-7 remain)
//   |     \ |        |  /    |
//   2 ----- 0        2 ----- .
TEST(Collapse, CubeSideDiagonal) {
    Mesh mesh = shapes::cube();
    const Mesh expected = expected_collapse(mesh, 0, 6, {{0, 4, 6}, {0, 6, 2}});
    expect_collapse(mesh, 0, 6);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// Icosahedron edge 0-1 between (0,5,1) and (0,1,7):
//        5               5
//      /   \             |
//     1 --- 0     =>     0
//      \   /             |
//        7               7
TEST(Collapse, Icosahedron) {
    Mesh mesh = shapes::icosahedron();
    const Mesh expected = expected_collapse(mesh, 0, 1, {{0, 5, 1}, {0, 1, 7}});
    expect_collapse(mesh, 0, 1);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// torus(4,4), vertex (i,j) = 4i + j: the diagonal 0-5 of cell (0,0).
TEST(Collapse, Torus) {
    Mesh mesh = shapes::torus(4, 4);
    const Mesh expected = expected_collapse(mesh, 0, 5, {{0, 4, 5}, {0, 5, 1}});
    expect_collapse(mesh, 0, 5);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// Collapsing until nothing more is allowed keeps the mesh valid and its topology.
TEST(Collapse, IcosahedronDownToTheMinimum) {
    Mesh mesh = shapes::icosahedron();
    for (bool progress = true; progress;) {
        progress = false;
        for (Edge e : mesh.edges()) {
            if (collapse(mesh, e)) {
                ASSERT_VALID(mesh);
                progress = true;
            }
        }
    }
    EXPECT_EQ(test::euler(mesh), 2);
    EXPECT_EQ(mesh.n_vertices(), 4u) << "a tetrahedron is as small as a sphere gets";
}

// ----------------------------------------------------------------- refusals

void expect_refused(Mesh& mesh, Edge e, std::string_view reason) {
    const Mesh before = mesh;
    EXPECT_EQ(is_collapse_ok(mesh, e).reason(), reason);
    const OpResult<Vertex> r = collapse(mesh, e);
    EXPECT_FALSE(r);
    EXPECT_EQ(r.reason(), reason);
    EXPECT_TRUE(test::identical(mesh, before));
}

// ----------------------------------------------------------------- polygons

// A cube of six quads: the two quads beside edge 0-1 lose a corner each and become
// triangles. Only vertex 1 and the edge are deleted (V-1, E-1, F+0): a polygon loses a
// corner where a triangle would disappear.
//      3 ------ 2            3 ------ 2
//      |        |            |    .`  |
//      |  quad  |     =>     |  .`    |     (0,1,2,3) -> (0,2,3), and the quad on the
//      |        |            |.`      |     other side of 0-1 likewise
//      0 ------ 1            0(mid)
TEST(Collapse, QuadCubeEdge) {
    Mesh mesh = test::quad_cube();
    const Mesh input = mesh;
    const std::size_t edges = mesh.n_edges();
    expect_collapse(mesh, 0, 1);
    EXPECT_EQ(mesh.n_edges(), edges - 1);
    EXPECT_EQ(mesh.n_faces(), 6u);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected_collapse(input, 0, 1, {})));
}

// A boundary side of a quad strip: the quad loses corner 1 and becomes a triangle; the next
// quad takes 0 in 1's place.
//   3 ----- 4 ----- 5        3 ----- 4 ----- 5
//   |       |       |        |     / |       |
//   |       |       |   =>   |   /   |       |      (0,1,4,3) -> (0,4,3)
//   |       |       |        | /     |       |      (1,2,5,4) -> (0,2,5,4)
//   0 ----- 1 ----- 2        0 ------------- 2
TEST(Collapse, BoundarySideOfAQuadStrip) {
    Mesh mesh = test::quad_strip(2);
    const Mesh input = mesh;
    expect_collapse(mesh, 0, 1);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected_collapse(input, 0, 1, {})));
    EXPECT_TRUE(mesh.is_boundary(mesh.halfedge(Vertex(0)))) << "boundary anchor";
}

// A lone quad: a side collapses and a triangle is left (a lone triangle cannot shrink).
TEST(Collapse, LoneQuadBecomesATriangle) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}});
    const Mesh input = mesh;
    expect_collapse(mesh, 1, 2);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected_collapse(input, 1, 2, {})));
    expect_refused(mesh, mesh.find_edge(Vertex(0), Vertex(1)),
                   "cannot collapse: the mesh would degenerate");
}

// A quad and a triangle share both edges of vertex 1 (valence 2). Collapsing 0-1: the
// triangle goes and its edge 1-2 is deleted, the quad loses corner 1 and takes the
// triangle's 0-2 in its place. (The sweep found the anchor walk starting from 1-2.)
//   3 ----- 2
//   |   Q / |
//   |   1   |     Q = (0,1,2,3), T = (2,1,0)  ->  (0,2,3)
//   | / T   |
//   0 ------'
TEST(Collapse, QuadAndTriangleAroundAValenceTwoVertex) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {0.5, 0.5, 0}, {1, 1, 0}, {0, 1, 0}},
                                      {{0, 1, 2, 3}, {2, 1, 0}});
    ASSERT_VALID(mesh);
    const Mesh input = mesh;
    expect_collapse(mesh, 0, 1);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected_collapse(input, 0, 1, {{2, 1, 0}})));
}

// A triangle beside a quad, inside a closed mesh: the triangle goes (its two other edges
// merge), the quad loses a corner. The quad cube with its top face cut by the diagonal 4-6.
TEST(Collapse, TriangleBesideQuad) {
    Indexed cut = test::indexed(test::quad_cube());
    cut.remove({4, 5, 6, 7});
    cut.add({4, 5, 6});
    cut.add({4, 6, 7});
    Mesh mesh = cut.build();
    const Mesh input = mesh;
    expect_collapse(mesh, 4, 5);  // (4,5,6) goes; (0,1,5,4) -> (0,1,4)
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected_collapse(input, 4, 5, {{4, 5, 6}})));
}

// Every edge of a tetrahedron: the mesh would collapse to a two-triangle pillow.
TEST(Collapse, RefusesTetrahedron) {
    Mesh mesh = shapes::tetrahedron();
    for (Edge e : mesh.edges()) {
        expect_refused(mesh, e, "cannot collapse: the mesh would degenerate");
    }
}

// A lone triangle: every edge would leave a dangling edge.
TEST(Collapse, RefusesLoneTriangle) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    for (Edge e : mesh.edges()) {
        expect_refused(mesh, e, "cannot collapse: the mesh would degenerate");
    }
}

// Triangular bipyramid: equator 0-1-2, poles 3 (top) and 4 (bottom). The equator edge 0-1
// lies in (0,1,3) and (1,0,4), but 0 and 1 also share the neighbour 2.
//          3
//        / | \    top: (0,1,3), (1,2,3), (2,0,3)
//      0 --|-- 2
//        \ | /    bottom, around 4 below: (1,0,4), (2,1,4), (0,2,4)
//          1
TEST(Collapse, RefusesLinkCondition) {
    const double s = std::sqrt(3.0) / 2.0;
    Mesh mesh =
        test::mesh_from_faces({{1, 0, 0}, {-0.5, s, 0}, {-0.5, -s, 0}, {0, 0, 1}, {0, 0, -1}},
                              {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}});
    ASSERT_VALID(mesh);
    expect_refused(mesh, mesh.find_edge(Vertex(0), Vertex(1)),
                   "cannot collapse: the link condition fails");
    // A pole edge is fine: the result is a tetrahedron.
    EXPECT_TRUE(is_collapse_ok(mesh, mesh.find_edge(Vertex(0), Vertex(3))));
}

// grid(2,1): every vertex is on the boundary; the interior edges 1-4 and 0-4 (and 1-5)
// would pinch the strip into two fans sharing a vertex.
//   3 --- 4 --- 5
//   |   / |   / |
//   | /   | /   |
//   0 --- 1 --- 2
TEST(Collapse, RefusesInteriorEdgeBetweenBoundaryVertices) {
    Mesh mesh = shapes::grid(2, 1);
    const char* reason =
        "cannot collapse: an interior edge joining two boundary vertices would pinch the surface";
    expect_refused(mesh, mesh.find_edge(Vertex(1), Vertex(4)), reason);
    expect_refused(mesh, mesh.find_edge(Vertex(0), Vertex(4)), reason);
}

// A quad (0,1,2,3) next to the triangle (0,3,4) across edge 0-3: a polygon is no reason to
// refuse, but 0 and 3 are both on the rim and the edge between them is inside.
TEST(Collapse, QuadBesideTriangleOnTheRimPinches) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0.5, 0}},
                                      {{0, 1, 2, 3}, {0, 3, 4}});
    expect_refused(mesh, mesh.find_edge(Vertex(0), Vertex(3)),
                   "cannot collapse: an interior edge joining two boundary vertices would pinch "
                   "the surface");
}

// Two triangles (0,1,2) and (0,2,1) glued along all three edges: a == d.
TEST(Collapse, RefusesPillow) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}});
    for (Edge e : mesh.edges()) {
        expect_refused(mesh, e, "cannot collapse: the mesh would degenerate");
    }
}

// The smallest input that made collapse() leave a self-loop (issue: OBJ faces `1 2 3`,
// `1 3 2`, `1 2 4`). The builder now makes it a closed pillow (0,1,2), (0,2,1) and a separate
// triangle on copies of 0 and 1 (vertices 4 and 5), with no doubled edge; every collapse
// is refused and leaves the mesh as it was.
TEST(Collapse, RefusesEveryEdgeOfThePillowAndEar) {
    Mesh mesh = build_mesh(test::pillow_and_ear_soup());
    ASSERT_VALID(mesh);
    ASSERT_EQ(mesh.n_edges(), 6u);
    for (Edge e : mesh.edges()) {
        expect_refused(mesh, e, "cannot collapse: the mesh would degenerate");
    }
}

// A slit linked by hand (two edges 0-1): collapsing either would turn the other into a
// self-loop. Refused by name; the faces' shared edges are refused as a pillow.
TEST(Collapse, RefusesAnEdgeDoubledByAnother) {
    Mesh mesh = test::slit_pillow();
    expect_refused(mesh, Edge(0), "cannot collapse: another edge joins the same two vertices");
    expect_refused(mesh, Edge(3), "cannot collapse: another edge joins the same two vertices");
    expect_refused(mesh, Edge(1), "cannot collapse: the mesh would degenerate");
    expect_refused(mesh, Edge(2), "cannot collapse: the mesh would degenerate");
}

TEST(Collapse, RefusesDeletedEdge) {
    Mesh mesh = shapes::grid(2, 2);
    const Edge e = mesh.find_edge(Vertex(1), Vertex(4));
    ASSERT_TRUE(collapse(mesh, e));
    expect_refused(mesh, e, "cannot collapse: the edge is deleted");
}

}  // namespace
}  // namespace meshedit
