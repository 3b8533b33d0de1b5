// The grader's bridge (src/cli/grade_bridge.h) with the reference solution's flip and split:
// a student's edit reaches the Mesh through its setters, so validate() passes, a recorder sees
// the edit and undo gives the mesh back bit for bit; and a broken structure is named in the
// course's terms instead of being written.

#include <gtest/gtest.h>

#include "grade_bridge.h"
#include "meshedit/core/compare.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/validate.h"

namespace meshedit::cli::grade {
namespace {

TEST(GradeBridge, CopyInAndOutChangesNothing) {
    for (Mesh mesh : {shapes::cube(), shapes::disk(12), shapes::grid(3, 2)}) {
        const Mesh before = mesh;
        st::HalfedgeMesh student;
        copy_in(mesh, student);
        EXPECT_EQ(student.nFaces(), mesh.n_faces());  // boundary loops are not counted
        EXPECT_EQ(student.nHalfedges(), mesh.n_halfedges());
        const BridgeError e = copy_out(student, mesh);
        EXPECT_EQ(e.invariant, "") << e.message;
        std::string why;
        EXPECT_TRUE(bitwise_equal(mesh, before, &why)) << why;
    }
}

TEST(GradeBridge, AStudentsFlipAndSplitAreRecordedAndUndone) {
    for (const bool split : {false, true}) {
        Mesh mesh = shapes::disk(6);
        const Mesh before = mesh;
        Mesh after;
        MeshChange change;
        {
            MeshRecorder recorder(mesh);
            st::HalfedgeMesh student;
            copy_in(mesh, student);
            // Edge 0 is a spoke (0-1), edge 1 the rim (1-2): an interior and a boundary case.
            for (int e : {0, 1}) {
                if (split) {
                    EXPECT_TRUE(st::split_edge(student, st::EdgeIter(&student, e)).isSet());
                } else {
                    st::flip_edge(student, st::EdgeIter(&student, e));
                }
            }
            const BridgeError error = copy_out(student, mesh);
            ASSERT_EQ(error.invariant, "") << error.message;
            change = recorder.finish();
        }
        const auto invalid = validate(mesh);
        EXPECT_FALSE(invalid) << invalid->message;
        EXPECT_EQ(mesh.n_vertices(), split ? 9u : 7u);
        after = mesh;
        change.undo(mesh);
        std::string why;
        EXPECT_TRUE(bitwise_equal(mesh, before, &why)) << why;
        change.redo(mesh);
        EXPECT_TRUE(bitwise_equal(mesh, after, &why)) << why;
    }
}

// upsample() through the bound flipEdge() and splitEdge(), which update the student's mesh
// piece by piece (boundary loops moved out of the way of new faces): the same mesh as
// loop_subdivide() makes.
TEST(GradeBridge, BoundOperationsKeepTheStudentsMeshInStep) {
    for (const Mesh& input : {shapes::cube(), shapes::disk(12), shapes::grid(4, 3),
                              shapes::torus(6, 5), shapes::cylinder(6, 2)}) {
        Mesh mesh = input;
        st::HalfedgeMesh student;
        copy_in(mesh, student);
        st::HalfedgeMesh::Operations ops;
        bind_operations(student, mesh, ops);
        st::upsample(student);
        const BridgeError error = copy_out(student, mesh);
        ASSERT_EQ(error.invariant, "") << error.message;
        const auto invalid = validate(mesh);
        ASSERT_FALSE(invalid) << invalid->message;
        Mesh expected = input;
        loop_subdivide(expected);
        const TopologyMatch match = match_topology(mesh, expected);
        ASSERT_TRUE(match.isomorphic) << match.difference;
        for (const Vertex v : mesh.vertices()) {
            EXPECT_LT(distance(mesh.position(v), expected.position(Vertex(match.vertex[v.idx()]))),
                      1e-12);
        }
    }
}

TEST(GradeBridge, NamesWhatCannotBeWritten) {
    Mesh mesh = shapes::cube();
    st::HalfedgeMesh student;
    copy_in(mesh, student);
    student.halfedges[4].twin() = st::HalfedgeIter(&student, 7);
    BridgeError e = copy_out(student, mesh);
    EXPECT_EQ(e.invariant, "twin");
    EXPECT_EQ(e.message,
              "halfedge 4's twin is halfedge 7, whose twin is halfedge 6, not halfedge 4");

    copy_in(mesh, student);
    student.deleteFace(st::FaceIter(&student, 2));
    e = copy_out(student, mesh);
    EXPECT_EQ(e.invariant, "face");
    EXPECT_NE(e.message.find("'s face is deleted"), std::string::npos) << e.message;

    // An old edge keeps its two halfedges: a new pair cannot take it over (its old halfedges,
    // still on it, are named first).
    copy_in(mesh, student);
    st::HalfedgeIter a = student.newHalfedge(), b = student.newHalfedge();
    a->twin() = b;
    b->twin() = a;
    a->edge() = b->edge() = st::EdgeIter(&student, 3);
    a->next() = b->next() = a;
    a->vertex() = b->vertex() = st::VertexIter(&student, 0);
    a->face() = b->face() = st::FaceIter(&student, 0);
    student.edges[3].halfedge() = a;
    e = copy_out(student, mesh);
    EXPECT_EQ(e.invariant, "edge");
    EXPECT_NE(e.message.find("edge 3"), std::string::npos) << e.message;
}

}  // namespace
}  // namespace meshedit::cli::grade
