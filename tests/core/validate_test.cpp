// validate(): each broken invariant is reported by name, with the offending element.
#include <gtest/gtest.h>

#include <cmath>

#include "meshedit/core/validate.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

// Raw access to a connectivity array, to break it on purpose.
template <class H, class T>
memory::Array<T>& raw(Mesh& mesh, const char* name) {
    return mesh.get_property<H, T>(name).vector();
}

void expect_failure(const Mesh& mesh, const std::string& invariant, ElementKind kind,
                    std::uint32_t index) {
    const auto error = validate(mesh);
    ASSERT_TRUE(error.has_value()) << "expected '" << invariant << "' to fail";
    EXPECT_EQ(error->invariant, invariant) << error->message;
    EXPECT_EQ(error->kind, kind) << error->message;
    EXPECT_EQ(error->index, index) << error->message;
    EXPECT_FALSE(error->message.empty());
}

TEST(Validate, AcceptsValidMeshes) {
    EXPECT_FALSE(validate(Mesh()).has_value());
    EXPECT_FALSE(validate(test::two_triangles()).has_value());
    EXPECT_FALSE(validate(test::one_ring(6)).has_value());
}

TEST(Validate, NonFinitePosition) {
    Mesh mesh = test::two_triangles();
    mesh.position(Vertex(2)).z = std::nan("");
    expect_failure(mesh, "finite-position", ElementKind::Vertex, 2);
    EXPECT_EQ(validate(mesh)->message, "vertex 2: has a non-finite position");
}

TEST(Validate, PrevDisagreesWithNext) {
    Mesh mesh = test::two_triangles();
    const Halfedge h = mesh.halfedge(Face(0));
    raw<Halfedge, Halfedge>(mesh, "h:prev")[mesh.next(h).idx()] = mesh.next(h);
    const auto error = validate(mesh);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->invariant, "next-prev");
    EXPECT_EQ(error->index, h.idx());
}

TEST(Validate, NextStartsElsewhere) {
    Mesh mesh = test::two_triangles();
    const Halfedge h = mesh.halfedge(Face(0));
    // Point h at a vertex that is not where its next starts.
    const Vertex wrong = mesh.to_vertex(mesh.next(h));
    raw<Halfedge, Vertex>(mesh, "h:vertex")[h.idx()] = wrong;
    ASSERT_TRUE(validate(mesh));
    EXPECT_EQ(validate(mesh)->kind, ElementKind::Halfedge);
}

TEST(Validate, ReferenceToDeletedFace) {
    Mesh mesh = test::two_triangles();
    mesh.mark_deleted(Face(1));
    const auto error = validate(mesh);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->invariant, "face-reference");
    EXPECT_EQ(error->kind, ElementKind::Halfedge);
    EXPECT_EQ(mesh.face(Halfedge(error->index)), Face(1));
    EXPECT_NE(error->message.find("face 1"), std::string::npos) << error->message;
}

TEST(Validate, FaceAnchorInAnotherFace) {
    Mesh mesh = test::two_triangles();
    mesh.set_halfedge(Face(0), mesh.halfedge(Face(1)));
    expect_failure(mesh, "face-anchor", ElementKind::Face, 0);
}

TEST(Validate, VertexAnchorStartsElsewhere) {
    Mesh mesh = test::one_ring(5);
    mesh.set_halfedge(Vertex(0), mesh.halfedge(Vertex(1)));
    expect_failure(mesh, "vertex-anchor", ElementKind::Vertex, 0);
}

TEST(Validate, BoundaryVertexMustAnchorOnBoundary) {
    Mesh mesh = test::two_triangles();
    // Vertex 0's outgoing interior halfedge 0 -> 2.
    const Halfedge interior = mesh.find_halfedge(Vertex(0), Vertex(2));
    ASSERT_FALSE(mesh.is_boundary(interior));
    mesh.set_halfedge(Vertex(0), interior);
    expect_failure(mesh, "boundary-anchor", ElementKind::Vertex, 0);
}

TEST(Validate, TombstoneCountMismatchIsCaught) {
    Mesh mesh = test::two_triangles();
    raw<Face, std::uint8_t>(mesh, "f:deleted")[1] = 1;  // bypasses mark_deleted()
    expect_failure(mesh, "deleted-count", ElementKind::Face, 0);
}

TEST(Validate, EdgeWithoutFaces) {
    Mesh mesh = test::two_triangles();
    const Vertex a = mesh.new_vertex({5, 5, 0});
    const Vertex b = mesh.new_vertex({6, 5, 0});
    const Halfedge h = mesh.new_edge(a, b);
    mesh.set_next(h, Mesh::twin(h));
    mesh.set_next(Mesh::twin(h), h);
    mesh.set_halfedge(a, h);
    mesh.set_halfedge(b, Mesh::twin(h));
    expect_failure(mesh, "edge-has-face", ElementKind::Edge, Mesh::edge(h).idx());
}

// Two edges joining vertices 0 and 1 (a slit linked by hand): every link is consistent, but
// no face list can describe it.
TEST(Validate, DoubledEdge) {
    const Mesh mesh = test::slit_pillow();
    expect_failure(mesh, "multi-edge", ElementKind::Edge, 0);
    EXPECT_EQ(validate(mesh)->message, "edge 0: joins vertices 0 and 1, as edge 3 does");
}

// One hexagon (0,1,2,0,3,4) visiting vertex 0 twice (two triangles' outlines joined at 0),
// with two boundary triangles around it, linked by hand so that every other invariant holds.
//
//     2       4          face: 0->1->2->0->3->4->0
//     | \   / |          boundary loops: 1->0->2->1 and 3->0->4->3
//     |  0    |
//     | /   \ |
//     1       3
TEST(Validate, FaceVisitingAVertexTwice) {
    Mesh mesh;
    const Vertex v[5] = {mesh.new_vertex({0, 0, 0}), mesh.new_vertex({-1, -1, 0}),
                         mesh.new_vertex({-1, 1, 0}), mesh.new_vertex({1, -1, 0}),
                         mesh.new_vertex({1, 1, 0})};
    const int corners[6] = {0, 1, 2, 0, 3, 4};
    Halfedge h[6];
    for (int i = 0; i < 6; ++i) {
        h[i] = mesh.new_edge(v[corners[i]], v[corners[(i + 1) % 6]]);
    }
    const Face f = mesh.new_face();
    for (int i = 0; i < 6; ++i) {
        mesh.set_next(h[i], h[(i + 1) % 6]);
        mesh.set_face(h[i], f);
        mesh.set_face(Mesh::twin(h[i]), Face());
    }
    mesh.set_halfedge(f, h[0]);
    // Boundary: 1->0 (twin h0), 0->2 (twin h2), 2->1 (twin h1); 3->0, 0->4, 4->3.
    mesh.set_next(Mesh::twin(h[0]), Mesh::twin(h[2]));
    mesh.set_next(Mesh::twin(h[2]), Mesh::twin(h[1]));
    mesh.set_next(Mesh::twin(h[1]), Mesh::twin(h[0]));
    mesh.set_next(Mesh::twin(h[3]), Mesh::twin(h[5]));
    mesh.set_next(Mesh::twin(h[5]), Mesh::twin(h[4]));
    mesh.set_next(Mesh::twin(h[4]), Mesh::twin(h[3]));
    mesh.set_halfedge(v[0], Mesh::twin(h[2]));
    mesh.set_halfedge(v[1], Mesh::twin(h[0]));
    mesh.set_halfedge(v[2], Mesh::twin(h[1]));
    mesh.set_halfedge(v[3], Mesh::twin(h[3]));
    mesh.set_halfedge(v[4], Mesh::twin(h[4]));
    expect_failure(mesh, "face-corner", ElementKind::Face, 0);
    EXPECT_EQ(validate(mesh)->message, "face 0: visits vertex 0 twice");
}

}  // namespace
}  // namespace meshedit
