// Catmull-Clark one phase at a time (cc_steps.h): each phase valid and what its message says,
// and four phases equal to quad_subdivide() up to numbering, positions to 1e-12, on quads,
// triangles, mixed polygons, a boundary and creases.

#include "meshedit/core/cc_steps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/loop_steps.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/shapes.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit::test {
namespace {

// Four phases and quad_subdivide() on copies of `mesh`: the same mesh up to numbering.
void expect_phases_make_catmull_clark(const Mesh& mesh, const std::string& what) {
    SCOPED_TRACE(what);
    Mesh stepped = mesh;
    const std::size_t faces = mesh.n_faces(), edges = mesh.n_edges();
    for (int phase = 1; phase <= 4; ++phase) {
        ASSERT_EQ(next_cc_phase(stepped), phase);
        ASSERT_TRUE(check_cc_step(stepped));
        const CcStepReport r = cc_step(stepped);
        ASSERT_VALID(stepped);
        EXPECT_EQ(r.phase, phase);
        EXPECT_EQ(r.message.rfind("Catmull-Clark " + std::to_string(phase) + "/4: ", 0), 0u)
            << r.message;
        if (phase == 1) {
            EXPECT_EQ(r.count, faces);
        } else if (phase == 2) {
            EXPECT_EQ(r.count, edges);
        }
    }
    EXPECT_EQ(next_cc_phase(stepped), 1);
    EXPECT_FALSE(stepped.has_property<Vertex>(kCcFacePoint));
    Mesh reference = mesh;
    quad_subdivide(reference);
    // Up to numbering: each vertex of one at the position of one of the other (to 1e-12;
    // a match by symmetry alone could pair a torus with itself turned), then the faces as
    // cycles of matched vertices.
    ASSERT_EQ(stepped.n_vertices(), reference.n_vertices());
    ASSERT_EQ(stepped.n_faces(), reference.n_faces());
    std::vector<std::uint32_t> to(stepped.vertices_size(), UINT32_MAX);
    for (const Vertex v : stepped.vertices()) {
        for (const Vertex w : reference.vertices()) {
            if (norm(stepped.position(v) - reference.position(w)) < 1e-12) {
                to[v.idx()] = w.idx();
            }
        }
        ASSERT_NE(to[v.idx()], UINT32_MAX) << "vertex " << v.idx() << " has no twin";
    }
    const auto cycles = [](const Mesh& m, const std::vector<std::uint32_t>* map) {
        std::multiset<std::vector<std::uint32_t>> out;
        for (const Face f : m.faces()) {
            std::vector<std::uint32_t> c;
            for (const Vertex v : m.vertices(f)) {
                c.push_back(map ? (*map)[v.idx()] : v.idx());
            }
            std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
            out.insert(c);
        }
        return out;
    };
    EXPECT_EQ(cycles(stepped, &to), cycles(reference, nullptr));
}

TEST(CcSteps, FourPhasesMakeCatmullClark) {
    expect_phases_make_catmull_clark(quad_cube(), "quad cube");
    expect_phases_make_catmull_clark(shapes::icosphere(1), "triangles");
    expect_phases_make_catmull_clark(shapes::quad_grid(3, 2), "a boundary");
    expect_phases_make_catmull_clark(shapes::torus(6, 4), "a torus of triangles");
    // A mixed mesh: the cube with one face poked (triangles beside quads) and one hole.
    Mesh mixed = quad_cube();
    ASSERT_TRUE(poke(mixed, Face(0)));
    ASSERT_TRUE(make_boundary(mixed, Face(3)));
    mixed.garbage_collection();
    expect_phases_make_catmull_clark(mixed, "mixed with a hole");
    // Creases: four edges of the cube's top marked sharp.
    Mesh creased = quad_cube();
    auto crease = creased.add_property<Edge, std::uint8_t>(kCreaseProperty, 0);
    for (const Halfedge h : creased.halfedges(Face(1))) {
        crease[Mesh::edge(h)] = 1;
    }
    expect_phases_make_catmull_clark(creased, "creases");
}

TEST(CcSteps, EachPhaseShowsItsPart) {
    Mesh mesh = quad_cube();  // 8 vertices, 12 edges, 6 quads
    cc_step(mesh);            // 1: face points
    EXPECT_EQ(mesh.n_vertices(), 14u);
    EXPECT_EQ(mesh.n_faces(), 24u);
    const Mesh poked = mesh;
    cc_step(mesh);  // 2: edge points
    EXPECT_EQ(mesh.n_vertices(), 26u);
    EXPECT_EQ(mesh.n_faces(), 48u);
    // Old vertices have not moved yet.
    for (std::uint32_t v = 0; v < 8; ++v) {
        EXPECT_EQ(mesh.position(Vertex(v)), poked.position(Vertex(v)));
    }
    cc_step(mesh);  // 3: vertex points: the cube's corners move in
    for (std::uint32_t v = 0; v < 8; ++v) {
        EXPECT_LT(norm(mesh.position(Vertex(v))), norm(poked.position(Vertex(v))));
    }
    const CcStepReport last = cc_step(mesh);  // 4: quads
    EXPECT_EQ(last.count, 24u);               // a spoke per old corner of each face
    EXPECT_EQ(mesh.n_faces(), 24u);
    for (const Face f : mesh.faces()) {
        EXPECT_EQ(mesh.valence(f), 4u);
    }
}

TEST(CcSteps, RefusesAMeshWithoutFacesAndAPhasedLoop) {
    Mesh empty;
    EXPECT_FALSE(check_cc_step(empty));
    EXPECT_NE(check_cc_step(empty).text().find("no faces"), std::string::npos);
    Mesh sphere = shapes::icosphere(1);
    loop_step(sphere);
    EXPECT_NE(check_cc_step(sphere).text().find("a phased Loop is under way"), std::string::npos);
}

}  // namespace
}  // namespace meshedit::test
