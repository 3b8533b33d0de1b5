// Crease-aware normals: sharp edges (creases, or Auto Smooth's angle) cut the faces around
// a vertex into wedges and each corner takes its wedge's normal; a vertex on no sharp edge
// keeps its vertex normal bit for bit.

#include <gtest/gtest.h>

#include <cmath>

#include "meshedit/core/attributes.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

void crease(Mesh& mesh, Edge e) {
    auto flags = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    if (!flags) {
        flags = mesh.add_property<Edge, std::uint8_t>(kCreaseProperty, 0);
    }
    flags[e] = 1;
}

TEST(CornerNormals, NoSharpEdgeNoCornerNormals) {
    const Mesh mesh = shapes::torus(8, 6);
    std::vector<Vec3> out{Vec3{1, 2, 3}};
    EXPECT_FALSE(compute_corner_normals(mesh, {}, vertex_normals(mesh), out));
    EXPECT_EQ(out.size(), 1u) << "left alone";
    // Auto Smooth at 90°: the torus's faces turn by far less.
    EXPECT_FALSE(compute_corner_normals(mesh, {true, 90.0}, vertex_normals(mesh), out));
}

TEST(CornerNormals, AutoSmoothSplitsTheCubeIntoItsSides) {
    // The triangulated cube: its 12 box edges turn by 90°, its 6 diagonals by 0°. At 30°
    // every corner takes the normal of its side of the box exactly.
    const Mesh mesh = shapes::cube();
    std::vector<Vec3> out;
    ASSERT_TRUE(compute_corner_normals(mesh, {false, 30.0}, vertex_normals(mesh), out));
    for (Face f : mesh.faces()) {
        const Vec3 side = face_normal(mesh, f);
        for (Halfedge h : mesh.halfedges(f)) {
            EXPECT_NEAR(distance(out[h.idx()], side), 0.0, 1e-15) << "corner " << h.idx();
        }
    }
    // Creases alone (none marked): nothing splits.
    EXPECT_FALSE(compute_corner_normals(mesh, {true, std::nullopt}, vertex_normals(mesh), out));
}

TEST(CornerNormals, ACreaseRingSplitsACylinderInTwo) {
    // Open cylinder, 12 segments, 2 rows; crease the middle ring (row 1).
    Mesh mesh = shapes::cylinder(12, 2);
    for (int i = 0; i < 12; ++i) {
        crease(mesh, mesh.find_edge(Vertex(static_cast<std::uint32_t>(12 + i)),
                                    Vertex(static_cast<std::uint32_t>(12 + (i + 1) % 12))));
    }
    const std::vector<Vec3> vn = vertex_normals(mesh);
    std::vector<Vec3> out;
    ASSERT_TRUE(compute_corner_normals(mesh, {}, vn, out));
    for (Face f : mesh.faces()) {
        // Which side of the ring the face lies on: above if any corner is on row 2.
        bool above = false;
        for (Vertex v : mesh.vertices(f)) {
            above = above || v.idx() >= 24;
        }
        for (Halfedge h : mesh.halfedges(f)) {
            const Vertex v = mesh.to_vertex(h);
            if (v.idx() < 12 || v.idx() >= 24) {
                EXPECT_EQ(out[h.idx()], vn[v.idx()]) << "rim vertices keep their normals";
                continue;
            }
            // A ring vertex: the sum over the faces on this side only.
            Vec3 sum;
            for (Face g : mesh.faces(v)) {
                bool g_above = false;
                for (Vertex w : mesh.vertices(g)) {
                    g_above = g_above || w.idx() >= 24;
                }
                if (g_above == above) {
                    sum += face_area_vector(mesh, g);
                }
            }
            EXPECT_NEAR(distance(out[h.idx()], normalize(sum)), 0.0, 1e-12)
                << "ring vertex " << v.idx();
        }
    }
    // Turned off, the crease no longer splits.
    EXPECT_FALSE(compute_corner_normals(mesh, {false, std::nullopt}, vn, out));
}

TEST(CornerNormals, ADartKeepsOneWedge) {
    // One crease edge ending inside the mesh: its inner end has one cut, hence one wedge of
    // all its faces — the vertex normal (to rounding).
    Mesh mesh = shapes::icosphere(1);
    const Vertex v(0);
    const Halfedge h = mesh.halfedge(v);
    crease(mesh, Mesh::edge(h));
    const std::vector<Vec3> vn = vertex_normals(mesh);
    std::vector<Vec3> out;
    ASSERT_TRUE(compute_corner_normals(mesh, {}, vn, out));
    for (Halfedge g : mesh.halfedges(v)) {
        EXPECT_NEAR(distance(out[mesh.prev(g).idx()], vn[v.idx()]), 0.0, 1e-12);
    }
}

}  // namespace
}  // namespace meshedit
