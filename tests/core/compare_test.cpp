// Comparing two meshes (compare.h): a mesh and a randomly renumbered copy of it match with a
// mapping that carries every position onto its own; an edge flip, other counts or another
// face degree do not, naming where; the deviations are exact on a flat grid with one vertex
// lifted.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/build.h"
#include "meshedit/core/compare.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"
#include "support/renumber.h"

namespace meshedit {
namespace {

using test::renumbered;

// Several meshes side by side as one (components), each shifted along x.
Mesh side_by_side(const std::vector<Mesh>& parts) {
    PolygonSoup out;
    double x = 0.0;
    for (const Mesh& part : parts) {
        const PolygonSoup soup = to_polygon_soup(part);
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        for (const Vec3& p : soup.positions) {
            out.positions.push_back(p + Vec3{x, 0, 0});
        }
        for (std::size_t f = 0; f < soup.n_faces(); ++f) {
            std::vector<std::uint32_t> corners;
            for (std::uint32_t c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
                corners.push_back(base + soup.indices[c]);
            }
            out.add_face_range(corners);
        }
        x += 3.0;
    }
    return build_mesh(out);
}

// The mapping is an isomorphism: it commutes with next and twin and agrees with to_vertex and
// face, and is one to one.
void expect_isomorphism(const Mesh& a, const Mesh& b, const TopologyMatch& m) {
    ASSERT_TRUE(m.isomorphic) << m.difference;
    std::vector<bool> hit_v(b.vertices_size()), hit_f(b.faces_size()), hit_h(b.halfedges_size());
    for (const Halfedge h : a.halfedges()) {
        const Halfedge g(m.halfedge[h.idx()]);
        ASSERT_TRUE(b.is_valid(g));
        EXPECT_EQ(m.halfedge[a.next(h).idx()], b.next(g).idx());
        EXPECT_EQ(m.halfedge[Mesh::twin(h).idx()], Mesh::twin(g).idx());
        EXPECT_EQ(m.vertex[a.to_vertex(h).idx()], b.to_vertex(g).idx());
        EXPECT_EQ(a.is_boundary(h), b.is_boundary(g));
        if (!a.is_boundary(h)) {
            EXPECT_EQ(m.face[a.face(h).idx()], b.face(g).idx());
        }
        EXPECT_FALSE(hit_h[g.idx()]);
        hit_h[g.idx()] = true;
    }
    for (const Vertex v : a.vertices()) {
        EXPECT_FALSE(hit_v[m.vertex[v.idx()]]);
        hit_v[m.vertex[v.idx()]] = true;
    }
    for (const Face f : a.faces()) {
        EXPECT_FALSE(hit_f[m.face[f.idx()]]);
        hit_f[m.face[f.idx()]] = true;
    }
}

// A renumbered copy matches, its mapping carries each vertex to its own position, and the
// deviation is exactly 0.
void expect_renumbered_copy_matches(const Mesh& mesh, unsigned seed) {
    const Mesh copy = renumbered(mesh, seed);
    const TopologyMatch m = match_topology(mesh, copy);
    expect_isomorphism(mesh, copy, m);
    for (const Vertex v : mesh.vertices()) {
        EXPECT_EQ(mesh.position(v), copy.position(Vertex(m.vertex[v.idx()])));
    }
    const Deviation d = measure_deviation(mesh, copy, m);
    EXPECT_TRUE(d.by_mapping);
    EXPECT_EQ(d.max, 0.0);
    EXPECT_EQ(d.rms, 0.0);
    EXPECT_EQ(d.hausdorff, 0.0);
}

TEST(Compare, RenumberedCopiesMatchWithTheirPositions) {
    expect_renumbered_copy_matches(shapes::torus(12, 8), 1);  // closed, many symmetries
    expect_renumbered_copy_matches(shapes::grid(5, 4), 2);    // a boundary
    expect_renumbered_copy_matches(shapes::disk(7), 3);
    expect_renumbered_copy_matches(shapes::cylinder(6, 3), 4);  // two boundaries
    expect_renumbered_copy_matches(shapes::quad_torus(6, 5), 5);
    expect_renumbered_copy_matches(shapes::quad_grid(3, 4), 6);
    // Components, among them two equal ones, and polygons of several degrees.
    PolygonSoup mixed;
    mixed.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0},
                       {1, 1, 0}, {0, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    mixed.add_face({0, 1, 4, 5});
    mixed.add_face({1, 2, 3, 4});
    mixed.add_face({5, 4, 3, 6, 7});
    expect_renumbered_copy_matches(
        side_by_side({shapes::cube(), build_mesh(mixed), shapes::tetrahedron(),
                      shapes::tetrahedron(), shapes::quad_sphere(1)}),
        7);
}

TEST(Compare, MovedCopiesMatchThroughSignatures) {
    // No position in common: the start comes from the rarest signature.
    for (const Mesh& mesh : {shapes::torus(10, 6), shapes::grid(4, 4), shapes::cylinder(5, 2),
                             side_by_side({shapes::cube(), shapes::cube(), shapes::disk(5)})}) {
        const Mesh copy = renumbered(mesh, 11, {0.5, -2, 3});
        const TopologyMatch m = match_topology(mesh, copy);
        expect_isomorphism(mesh, copy, m);
    }
}

TEST(Compare, IsolatedVerticesPairByPosition) {
    PolygonSoup soup = to_polygon_soup(shapes::tetrahedron());
    soup.positions.push_back({5, 5, 5});
    soup.positions.push_back({-5, 0, 0});
    const Mesh a = build_mesh(soup);
    const Mesh b = renumbered(a, 8);
    ASSERT_EQ(b.n_vertices(), 6u);
    const TopologyMatch m = match_topology(a, b);
    ASSERT_TRUE(m.isomorphic) << m.difference;
    for (const Vertex v : a.vertices()) {
        EXPECT_EQ(a.position(v), b.position(Vertex(m.vertex[v.idx()])));
    }
}

TEST(Compare, AnEdgeFlipIsNamed) {
    const Mesh a = shapes::torus(12, 8);
    Mesh b = renumbered(a, 9);
    ASSERT_TRUE(flip(b, b.find_edge(Vertex(0), b.to_vertex(b.halfedge(Vertex(0))))).ok());
    const TopologyMatch m = match_topology(a, b);
    EXPECT_FALSE(m.isomorphic);
    EXPECT_TRUE(m.vertex.empty());
    EXPECT_FALSE(m.first_a.is_none());
    EXPECT_FALSE(m.first_b.is_none());
    EXPECT_NE(m.difference.find(" of A"), std::string::npos) << m.difference;
    EXPECT_NE(m.difference.find(" of B"), std::string::npos) << m.difference;
    // The flip changed four vertices' valences: where the match failed is one of them, or a
    // face or halfedge beside them.
    const TopologyMatch moved = match_topology(a, renumbered(b, 10, {1, 1, 1}));
    EXPECT_FALSE(moved.isomorphic);
    EXPECT_FALSE(moved.difference.empty());
}

TEST(Compare, OtherCountsOrDegreesDiffer) {
    TopologyMatch m = match_topology(shapes::grid(3, 3), shapes::grid(3, 4));
    EXPECT_FALSE(m.isomorphic);
    EXPECT_EQ(m.difference, "the vertex counts differ: 16 in A, 20 in B");
    EXPECT_TRUE(m.first_a.is_none());

    // Same counts (V 6, E 7, F 2): two quads side by side, and a triangle beside a pentagon.
    PolygonSoup quads;
    quads.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {0, 1, 0}};
    quads.add_face({0, 1, 4, 5});
    quads.add_face({1, 2, 3, 4});
    PolygonSoup pent = quads;
    pent.indices.clear();
    pent.face_offsets = {0};
    pent.add_face({0, 1, 5});
    pent.add_face({1, 2, 3, 4, 5});
    m = match_topology(build_mesh(quads), build_mesh(pent));
    EXPECT_FALSE(m.isomorphic);
    EXPECT_FALSE(m.difference.empty());
}

// A flat 4×4 grid and the same with vertex 12 (inside) lifted by 0.3: every distance is known.
TEST(Compare, DeviationOfOneLiftedVertex) {
    const Mesh a = shapes::grid(4, 4);
    Mesh b = renumbered(a, 12);
    const Vertex lifted_a(12);  // (2, 2)
    const TopologyMatch m = match_topology(a, b);
    ASSERT_TRUE(m.isomorphic);
    b.position(Vertex(m.vertex[lifted_a.idx()])).z = 0.3;
    // The positions no longer agree: the match still follows them where they do.
    const TopologyMatch again = match_topology(a, b);
    ASSERT_TRUE(again.isomorphic);
    EXPECT_EQ(again.vertex, m.vertex);
    const Deviation d = measure_deviation(a, b, again);
    EXPECT_TRUE(d.by_mapping);
    EXPECT_DOUBLE_EQ(d.max, 0.3);
    EXPECT_DOUBLE_EQ(d.rms, 0.3 / 5.0);  // one of 25 vertices
    EXPECT_DOUBLE_EQ(d.vertex[lifted_a.idx()], 0.3);
    EXPECT_EQ(d.vertex[0], 0.0);
    EXPECT_NEAR(d.b_to_a, 0.3, 1e-15);  // the tip, over the plane
    EXPECT_LT(d.a_to_b, 0.3);           // the plane under a tent is nearer its sides
    EXPECT_GT(d.a_to_b, 0.0);
    EXPECT_NEAR(d.hausdorff, 0.3, 1e-15);
    EXPECT_DOUBLE_EQ(d.diagonal, std::sqrt(2.0));
    EXPECT_NEAR(percent_of(d.hausdorff, d.diagonal), 30.0 / std::sqrt(2.0), 1e-12);

    // Other connectivity (an edge flipped in the flat grid): by closest points, the lifted
    // vertex is 0.3 from the plane and the others on it.
    Mesh flat = shapes::grid(4, 4);
    ASSERT_TRUE(flip(flat, flat.find_edge(Vertex(0), Vertex(6))).ok());
    Mesh tent = shapes::grid(4, 4);
    tent.position(lifted_a).z = 0.3;
    const TopologyMatch other = match_topology(tent, flat);
    EXPECT_FALSE(other.isomorphic);
    const Deviation c = measure_deviation(tent, flat, other);
    EXPECT_FALSE(c.by_mapping);
    EXPECT_NEAR(c.max, 0.3, 1e-15);
    EXPECT_NEAR(c.rms, 0.3 / 5.0, 1e-15);
    EXPECT_NEAR(c.vertex[lifted_a.idx()], 0.3, 1e-15);
    EXPECT_EQ(c.vertex[0], 0.0);
    EXPECT_NEAR(c.hausdorff, 0.3, 1e-15);
}

// Attributes computed from the geometry alone (a corner's texture coordinate from its vertex
// and its face's centre, so the seams are real; colours from positions; a material per face
// side), so a renumbered copy gets them by the same rule.
void decorate(Mesh& mesh) {
    auto uv = mesh.property<Halfedge, Vec2>(kTexCoordProperty);
    auto colour = mesh.property<Vertex, Vec4>(kColorProperty);
    auto material = mesh.property<Face, std::uint32_t>(kMaterialProperty);
    mesh.materials() = {Material{.name = "up"}, Material{.name = "down"}};
    for (const Face f : mesh.faces()) {
        const Vec3 c = face_centroid(mesh, f);
        material[f] = c.y > 0 ? 0 : 1;
        for (const Halfedge h : mesh.halfedges(f)) {
            const Vec3 p = mesh.position(mesh.to_vertex(h));
            uv[h] = Vec2{p.x + 0.5 * std::round(c.z), p.y};
        }
    }
    for (const Vertex v : mesh.vertices()) {
        const Vec3 p = mesh.position(v);
        colour[v] = Vec4{p.x, p.y, p.z, 1.0};
    }
}

// A decorated torus and a renumbered decorated copy.
struct DecoratedPair {
    Mesh a = shapes::torus(12, 8);
    Mesh b = renumbered(a, 7);
    DecoratedPair() {
        decorate(a);
        decorate(b);
    }
};

TEST(Compare, AttributesOfARenumberedCopyAreTheSameAndAChangeIsFound) {
    DecoratedPair pair;
    Mesh &a = pair.a, &b = pair.b;
    const TopologyMatch match = match_topology(a, b);
    ASSERT_TRUE(match.isomorphic);
    std::vector<AttributeDifference> d = compare_attributes(a, b, match);
    ASSERT_EQ(d.size(), 3u);  // texture coordinates, vertex colours, materials
    for (const AttributeDifference& x : d) {
        EXPECT_TRUE(x.in_a && x.in_b) << x.name;
        EXPECT_EQ(x.differing, 0u) << x.name;
        EXPECT_GT(x.compared, 0u) << x.name;
    }
    // One corner of B moved by 0.25 in u, one vertex's colour, one face's material.
    auto uv = b.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const Halfedge moved = b.halfedge(Face(5));
    uv[moved].x += 0.25;
    b.get_property<Vertex, Vec4>(kColorProperty)[Vertex(3)].y = 0.5;
    auto material = b.get_property<Face, std::uint32_t>(kMaterialProperty);
    material[Face(9)] = 1 - material[Face(9)];
    d = compare_attributes(a, b, match);
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d[0].name, "texture coordinates");
    EXPECT_EQ(d[0].differing, 1u);
    EXPECT_NEAR(d[0].max, 0.25, 1e-12);
    EXPECT_EQ(match.halfedge[d[0].first_a.index], moved.idx());
    EXPECT_EQ(d[1].name, "vertex colours");
    EXPECT_EQ(d[1].differing, 1u);
    EXPECT_EQ(match.vertex[d[1].first_a.index], 3u);
    EXPECT_EQ(d[2].name, "materials");
    EXPECT_EQ(d[2].differing, 1u);
    EXPECT_EQ(match.face[d[2].first_a.index], 9u);
    // An attribute one side lacks.
    auto colours = b.get_property<Vertex, Vec4>(kColorProperty);
    b.remove_property(colours);
    d = compare_attributes(a, b, match);
    EXPECT_TRUE(d[1].in_a);
    EXPECT_FALSE(d[1].in_b);
}

// The second set: compared on its own, per corner, after the first; one side's alone is said.
TEST(Compare, TheSecondTextureCoordinateSetIsComparedOnItsOwn) {
    DecoratedPair pair;
    Mesh &a = pair.a, &b = pair.b;
    const TopologyMatch match = match_topology(a, b);
    ASSERT_TRUE(match.isomorphic);
    const auto add_second = [](Mesh& mesh) {
        auto uv1 = mesh.add_property<Halfedge, Vec2>(kTexCoord1Property);
        for (const Halfedge h : mesh.halfedges()) {
            const Vec3 p = mesh.position(mesh.to_vertex(h));
            uv1[h] = Vec2{p.z, 2 * p.x};
        }
        return uv1;
    };
    add_second(a);
    std::vector<AttributeDifference> d = compare_attributes(a, b, match);
    ASSERT_EQ(d.size(), 4u);
    EXPECT_EQ(d[1].name, "second texture coordinate set");
    EXPECT_TRUE(d[1].in_a);
    EXPECT_FALSE(d[1].in_b);
    auto uv1 = add_second(b);
    d = compare_attributes(a, b, match);
    ASSERT_EQ(d.size(), 4u);
    EXPECT_EQ(d[1].differing, 0u);
    EXPECT_EQ(d[1].compared, d[0].compared);
    EXPECT_STREQ(d[1].elements, "corners");
    const Halfedge moved = b.halfedge(Face(4));
    uv1[moved].y -= 0.5;
    d = compare_attributes(a, b, match);
    EXPECT_EQ(d[0].differing, 0u);
    EXPECT_EQ(d[1].differing, 1u);
    EXPECT_NEAR(d[1].max, 0.5, 1e-12);
    EXPECT_EQ(match.halfedge[d[1].first_a.index], moved.idx());
}

}  // namespace
}  // namespace meshedit
