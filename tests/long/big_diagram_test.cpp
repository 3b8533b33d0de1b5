// The rewiring diagram at a size a copy of the mesh made impossible (label `long`: a 4M-face
// mesh takes about 580 MB and a second to build).

#include <gtest/gtest.h>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/core/shapes.h"
#include "meshedit/overlay/op_diagram.h"

namespace meshedit {
namespace {

// A flip on a 4M-face torus: the diagram is read from the recorded change, lists what the
// flip relinked (six halfedges, two faces, as on any pair of triangles) and leaves the mesh
// as the flip left it.
TEST(BigDiagram, AFlipOnFourMillionFacesDraws) {
    Mesh mesh = shapes::torus(1000, 2000);
    ASSERT_EQ(mesh.n_faces(), 4'000'000u);
    const Edge e(1'234'567);
    const std::string described = describe(mesh, ElementRef::edge(e));
    MeshRecorder recorder(mesh);
    ASSERT_TRUE(flip(mesh, e));
    const MeshChange change = recorder.finish();
    const Halfedge h = Mesh::halfedge(e, 0);
    const Vertex a = mesh.from_vertex(h), b = mesh.to_vertex(h);
    const OpDiagram d = op_diagram(mesh, change, "flip", CodeNames::Flip,
                                   [&](const Mesh&) { return ElementRef::edge(e); });
    EXPECT_EQ(d.title, "flip of " + described);
    EXPECT_EQ(d.changes.size(), 8u);
    EXPECT_FALSE(d.picture.lines.empty());
    EXPECT_EQ(mesh.from_vertex(h), a);
    EXPECT_EQ(mesh.to_vertex(h), b);
    EXPECT_EQ(mesh.n_faces(), 4'000'000u);
}

}  // namespace
}  // namespace meshedit
