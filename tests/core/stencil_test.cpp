// Subdivision stencils: every stencil's point is where one level of subdivision puts the
// element (loop_subdivide(), quad_subdivide()), and every weight is the formula
// docs/teaching.md gives, written out again here independently of loop_rules.h.

#include "meshedit/core/stencil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/subdivision_test_util.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

using test::creased_cube;
using test::mark_crease;
using test::near;

// A closed double cone: apex 0 on top and apex 1 below, each of valence n, around a ring
// 2 … n+1 of valence 4.
Mesh bicone(int n) {
    std::vector<Vec3> p{{0, 0, 1}, {0, 0, -1}};
    std::vector<std::vector<std::uint32_t>> faces;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * std::numbers::pi * k / n;
        p.push_back({std::cos(a), std::sin(a), 0.1 * k});
        const auto ring = [n](int i) { return static_cast<std::uint32_t>(2 + (i % n)); };
        faces.push_back({0, ring(k), ring(k + 1)});
        faces.push_back({1, ring(k + 1), ring(k)});
    }
    return test::mesh_from_faces(p, faces);
}

double weight_of(const Stencil& s, std::uint32_t v) {
    for (const StencilTerm& t : s.terms) {
        if (t.vertex.idx() == v) {
            return t.weight;
        }
    }
    return 0.0;
}

double warren(int n) {
    return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
}

double loop_original(int n) {
    const double c = 3.0 / 8.0 + std::cos(2.0 * std::numbers::pi / n) / 4.0;
    return (5.0 / 8.0 - c * c) / n;
}

TEST(Stencil, InteriorLoopWeightsAreTheFormulasForValence3To12) {
    for (int n = 3; n <= 12; ++n) {
        SCOPED_TRACE("valence " + std::to_string(n));
        const Mesh mesh = bicone(n);
        for (const auto& [scheme, u] : {std::pair{StencilScheme::LoopWarren, warren(n)},
                                        std::pair{StencilScheme::LoopOriginal, loop_original(n)}}) {
            const Stencil s = subdivision_stencil(mesh, ElementRef::vertex(Vertex(0)), scheme);
            ASSERT_TRUE(s.ok()) << s.status;
            EXPECT_EQ(s.rule, "interior vertex");
            EXPECT_EQ(s.valence, static_cast<std::size_t>(n));
            ASSERT_EQ(s.terms.size(), static_cast<std::size_t>(n + 1));
            EXPECT_EQ(s.terms[0].vertex, Vertex(0));
            EXPECT_NEAR(s.terms[0].weight, 1.0 - n * u, 1e-15);
            for (int k = 0; k < n; ++k) {
                EXPECT_NEAR(weight_of(s, 2 + k), u, 1e-15);
            }
        }
    }
    // The two rules agree at valence 3 and 6 only.
    EXPECT_NEAR(warren(3), loop_original(3), 1e-15);
    EXPECT_NEAR(warren(6), loop_original(6), 1e-15);
    EXPECT_GT(std::abs(warren(5) - loop_original(5)), 1e-4);
}

TEST(Stencil, CatmullClarkInteriorWeightsForValence3To12) {
    // On the bicone the apex's faces are triangles (a, q_k, q_k+1): its own share is
    // (n-2)/n plus 1/n² · 1/3 per face; each ring vertex gets 1/n² as a neighbour plus
    // 1/(3n²) from each of its two faces at the apex.
    for (int n = 3; n <= 12; ++n) {
        SCOPED_TRACE("valence " + std::to_string(n));
        const Stencil s = subdivision_stencil(bicone(n), ElementRef::vertex(Vertex(0)),
                                              StencilScheme::CatmullClark);
        const double nn = static_cast<double>(n) * n;
        EXPECT_NEAR(weight_of(s, 0), (n - 2.0) / n + n / (3.0 * nn), 1e-15);
        for (int k = 0; k < n; ++k) {
            EXPECT_NEAR(weight_of(s, 2 + k), 1.0 / nn + 2.0 / (3.0 * nn), 1e-15);
        }
    }
}

TEST(Stencil, SharpRulesNameThemselves) {
    // Open disk: the rim is boundary; the centre is interior.
    const Mesh disk = shapes::disk(6);
    const Stencil rim =
        subdivision_stencil(disk, ElementRef::vertex(Vertex(1)), StencilScheme::LoopWarren);
    EXPECT_EQ(rim.rule, "boundary vertex");
    EXPECT_EQ(weight_of(rim, 1), 0.75);
    EXPECT_EQ(weight_of(rim, 2), 0.125);
    EXPECT_EQ(weight_of(rim, 6), 0.125);
    EXPECT_EQ(weight_of(rim, 0), 0.0);
    const Stencil rim_edge = subdivision_stencil(
        disk, ElementRef::edge(disk.find_edge(Vertex(1), Vertex(2))), StencilScheme::LoopWarren);
    EXPECT_EQ(rim_edge.rule, "boundary edge");
    EXPECT_EQ(weight_of(rim_edge, 1), 0.5);
    EXPECT_EQ(weight_of(rim_edge, 2), 0.5);
    const Stencil spoke = subdivision_stencil(
        disk, ElementRef::edge(disk.find_edge(Vertex(0), Vertex(2))), StencilScheme::LoopWarren);
    EXPECT_EQ(spoke.rule, "interior edge");
    EXPECT_EQ(weight_of(spoke, 0), 0.375);
    EXPECT_EQ(weight_of(spoke, 2), 0.375);
    EXPECT_EQ(weight_of(spoke, 1), 0.125);
    EXPECT_EQ(weight_of(spoke, 3), 0.125);

    // Bicone with creases: one crease edge at the apex is a dart (interior weights), the
    // ring vertex on two creases follows the crease rule, three creases make a corner.
    Mesh mesh = bicone(5);
    mark_crease(mesh, 0, 2);
    const Stencil dart =
        subdivision_stencil(mesh, ElementRef::vertex(Vertex(0)), StencilScheme::LoopWarren);
    EXPECT_EQ(dart.rule, "dart");
    EXPECT_NEAR(weight_of(dart, 3), warren(5), 1e-15);
    mark_crease(mesh, 1, 2);
    const Stencil crease =
        subdivision_stencil(mesh, ElementRef::vertex(Vertex(2)), StencilScheme::CatmullClark);
    EXPECT_EQ(crease.rule, "crease vertex");
    EXPECT_EQ(weight_of(crease, 2), 0.75);
    EXPECT_EQ(weight_of(crease, 0), 0.125);
    EXPECT_EQ(weight_of(crease, 1), 0.125);
    EXPECT_EQ(crease.terms.size(), 3u);
    mark_crease(mesh, 2, 3);
    const Stencil corner =
        subdivision_stencil(mesh, ElementRef::vertex(Vertex(2)), StencilScheme::LoopOriginal);
    EXPECT_EQ(corner.rule, "corner");
    ASSERT_EQ(corner.terms.size(), 1u);
    EXPECT_EQ(corner.terms[0].weight, 1.0);
    const Stencil crease_edge = subdivision_stencil(
        mesh, ElementRef::edge(mesh.find_edge(Vertex(2), Vertex(3))), StencilScheme::LoopWarren);
    EXPECT_EQ(crease_edge.rule, "crease edge");
}

TEST(Stencil, RefusalsNameTheirReason) {
    const Mesh cube = test::quad_cube();
    const Stencil edge =
        subdivision_stencil(cube, ElementRef::edge(Edge(0)), StencilScheme::LoopWarren);
    EXPECT_FALSE(edge.ok());
    EXPECT_NE(edge.status.reason().find("Loop needs triangles"), std::string::npos) << edge.status;
    EXPECT_TRUE(edge.terms.empty());
    const Stencil face =
        subdivision_stencil(cube, ElementRef::face(Face(0)), StencilScheme::LoopWarren);
    EXPECT_NE(face.status.reason().find("no face points"), std::string::npos) << face.status;
    const Stencil dead =
        subdivision_stencil(cube, ElementRef::vertex(Vertex(99)), StencilScheme::CatmullClark);
    EXPECT_FALSE(dead.ok());
    const Stencil cc_face =
        subdivision_stencil(cube, ElementRef::face(Face(0)), StencilScheme::CatmullClark);
    ASSERT_TRUE(cc_face.ok());
    EXPECT_EQ(cc_face.terms.size(), 4u);
}

double weight_sum(const Stencil& s) {
    double sum = 0.0;
    for (const StencilTerm& t : s.terms) {
        sum += t.weight;
    }
    return sum;
}

std::vector<test::NamedMesh> meshes() {
    std::vector<test::NamedMesh> out;
    out.push_back({"icosahedron", shapes::icosahedron()});
    out.push_back({"torus", shapes::torus(6, 5)});
    out.push_back({"creased cube", creased_cube()});
    out.push_back({"open grid", shapes::grid(3, 2)});
    out.push_back({"bicone 7", bicone(7)});
    return out;
}

TEST(Stencil, LoopStencilsAreWhereLPutsEveryVertexAndEdgePoint) {
    for (const auto& [name, input] : meshes()) {
        for (const auto& [scheme, weights] :
             {std::pair{StencilScheme::LoopWarren, LoopWeights::Warren},
              std::pair{StencilScheme::LoopOriginal, LoopWeights::Loop}}) {
            SCOPED_TRACE(name + ", " + scheme_name(scheme));
            Mesh refined = input;
            LoopOptions options;
            options.weights = weights;
            loop_subdivide(refined, options);
            const std::size_t nv = input.vertices_size();
            for (Vertex v : input.vertices()) {
                const Stencil s = subdivision_stencil(input, ElementRef::vertex(v), scheme);
                EXPECT_NEAR(weight_sum(s), 1.0, 1e-14);
                EXPECT_TRUE(near(s.position, refined.position(v), 1e-12)) << "vertex " << v.idx();
            }
            for (Edge e : input.edges()) {
                const Stencil s = subdivision_stencil(input, ElementRef::edge(e), scheme);
                EXPECT_TRUE(near(s.position,
                                 refined.position(Vertex(static_cast<std::uint32_t>(nv + e.idx()))),
                                 1e-12))
                    << "edge " << e.idx();
            }
        }
    }
}

TEST(Stencil, CatmullClarkStencilsAreWhereShiftCPutsEveryPoint) {
    std::vector<test::NamedMesh> all = meshes();
    all.push_back({"quad cube", test::quad_cube()});
    all.push_back({"quad strip", test::quad_strip(3)});
    for (const auto& [name, input] : all) {
        SCOPED_TRACE(name);
        Mesh refined = input;
        quad_subdivide(refined);
        const std::size_t nv = input.vertices_size();
        const std::size_t ne = input.edges_size();
        for (Vertex v : input.vertices()) {
            const Stencil s =
                subdivision_stencil(input, ElementRef::vertex(v), StencilScheme::CatmullClark);
            EXPECT_NEAR(weight_sum(s), 1.0, 1e-14);
            EXPECT_TRUE(near(s.position, refined.position(v), 1e-12)) << "vertex " << v.idx();
        }
        for (Edge e : input.edges()) {
            const Stencil s =
                subdivision_stencil(input, ElementRef::edge(e), StencilScheme::CatmullClark);
            EXPECT_TRUE(near(s.position,
                             refined.position(Vertex(static_cast<std::uint32_t>(nv + e.idx()))),
                             1e-12))
                << "edge " << e.idx();
        }
        for (Face f : input.faces()) {
            const Stencil s =
                subdivision_stencil(input, ElementRef::face(f), StencilScheme::CatmullClark);
            EXPECT_TRUE(near(
                s.position, refined.position(Vertex(static_cast<std::uint32_t>(nv + ne + f.idx()))),
                1e-12))
                << "face " << f.idx();
        }
    }
}

}  // namespace
}  // namespace meshedit
