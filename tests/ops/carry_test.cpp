// The attribute carry (Mesh::carry(), docs/halfedge.md "What every operation carries"): user
// properties on vertices, edges, halfedges and faces follow every verb of the table as each
// operation states; a vertex property that is an affine function of the position stays that
// function through every operation that places vertices at affine combinations; the second
// texture coordinate set is carried by the very rule of the first; the recorder's self-check
// catches an operation that makes an element without saying where its attributes come from.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/ops/ops.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using Kind = ElementRef::Kind;

std::vector<Mesh> seven_meshes() {
    return {shapes::cube(),        shapes::torus(9, 7),    shapes::grid(5, 4),
            shapes::icosphere(1),  shapes::cylinder(8, 3), test::quad_cube(),
            shapes::quad_sphere(2)};
}

double affine(const Vec3& p) {
    return 2.0 * p.x - 3.0 * p.y + 0.5 * p.z + 1.0;
}

// The second texture coordinate set is this linear function of the first on every corner:
// a carry that treats both sets alike (the same sources and weights, seams where the first
// has them, defaults alike) keeps it so, up to rounding.
Vec2 second_of(const Vec2& uv) {
    return {0.5 * uv.x - 0.25 * uv.y, 0.1 * uv.x + 2.0 * uv.y};
}

// The properties a library user might register: blended (a number and a vector), labels
// (integers: the heaviest source), a corner value and a face material; and both texture
// coordinate sets.
struct Registered {
    VertexProperty<double> value;
    VertexProperty<Vec3> copy;
    VertexProperty<std::int32_t> label;
    EdgeProperty<std::int32_t> edge_label;
    HalfedgeProperty<double> corner;
    FaceProperty<std::uint16_t> material;
    HalfedgeProperty<Vec2> uv0, uv1;
};

// The registered properties of `mesh`, looked up again (a whole-mesh verb that works on a copy
// and moves it in replaces the arrays a Property points at).
Registered registered(const Mesh& mesh) {
    return {mesh.get_property<Vertex, double>("v:value"),
            mesh.get_property<Vertex, Vec3>("v:copy"),
            mesh.get_property<Vertex, std::int32_t>("v:label"),
            mesh.get_property<Edge, std::int32_t>("e:label"),
            mesh.get_property<Halfedge, double>("h:corner"),
            mesh.get_property<Face, std::uint16_t>("f:material"),
            mesh.get_property<Halfedge, Vec2>(kTexCoordProperty),
            mesh.get_property<Halfedge, Vec2>(kTexCoord1Property)};
}

// The first set: a box map, each face in the chart of its normal's largest axis and sign,
// each chart its own affine function of the position (so charts meet at seams); a boundary
// halfedge takes its twin's chart. The second set: second_of() of the first.
void box_mapped_sets(const Mesh& mesh, HalfedgeProperty<Vec2>& uv0, HalfedgeProperty<Vec2>& uv1) {
    for (const Halfedge h : mesh.halfedges()) {
        const Face f = mesh.face(mesh.is_boundary(h) ? mesh.twin(h) : h);
        const Vec3 n = face_area_vector(mesh, f);
        const double a[3] = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
        const int axis = static_cast<int>(std::max_element(a, a + 3) - a);
        const int chart = 2 * axis + (n[axis] < 0 ? 1 : 0);
        const Vec3& p = mesh.position(mesh.to_vertex(h));
        const double s = p[(axis + 1) % 3], t = p[(axis + 2) % 3];
        uv0[h] = {0.31 * s + 1.13 * chart + 0.07 * t, 0.29 * t + 0.17 * chart * chart};
        uv1[h] = second_of(uv0[h]);
    }
}

Registered register_properties(Mesh& mesh) {
    Registered r{mesh.add_property<Vertex, double>("v:value"),
                 mesh.add_property<Vertex, Vec3>("v:copy"),
                 mesh.add_property<Vertex, std::int32_t>("v:label", -1),
                 mesh.add_property<Edge, std::int32_t>("e:label", -1),
                 mesh.add_property<Halfedge, double>("h:corner"),
                 mesh.add_property<Face, std::uint16_t>("f:material", 999),
                 mesh.add_property<Halfedge, Vec2>(kTexCoordProperty),
                 mesh.add_property<Halfedge, Vec2>(kTexCoord1Property)};
    box_mapped_sets(mesh, r.uv0, r.uv1);
    for (const Vertex v : mesh.vertices()) {
        r.value[v] = affine(mesh.position(v));
        r.copy[v] = mesh.position(v);
        r.label[v] = static_cast<std::int32_t>(v.idx());
    }
    for (const Edge e : mesh.edges()) {
        r.edge_label[e] = static_cast<std::int32_t>(e.idx());
    }
    for (const Halfedge h : mesh.halfedges()) {
        r.corner[h] = affine(mesh.position(mesh.to_vertex(h)));
    }
    for (const Face f : mesh.faces()) {
        r.material[f] = static_cast<std::uint16_t>(f.idx() % 7);
    }
    return r;
}

// Verbs that move vertices off affine combinations of the old ones: the lift of an extrude,
// a move, the quadric's optimum, the remesher's relaxation, the teaching phases' moves, and
// smoothing and fairing, the fair hole fill's fairing, a phased Catmull-Clark's moves and a
// region's Loop or Catmull-Clark (they move positions and leave every attribute as it was).
bool places_off_affine(std::string_view verb) {
    return verb == "extrude" || verb == "extrude_region" || verb == "inset_region" ||
           verb == "move" || verb == "simplify" || verb == "simplify_region" || verb == "remesh" ||
           verb == "loop_step" || verb == "smooth" || verb == "smooth_cotan" || verb == "taubin" ||
           verb == "smooth_implicit" || verb == "fair" || verb == "smooth_region" ||
           verb == "fill_holes_fair" || verb == "fill_fair" || verb == "cc_step" ||
           verb == "loop_region" || verb == "remesh_region" || verb == "catmull_clark_region";
}

ElementRef random_live(const Mesh& mesh, Kind kind, std::mt19937& rng) {
    const std::size_t n = elements_size(mesh, kind);
    for (int tries = 0; tries < 100 && n > 0; ++tries) {
        const ElementRef r{kind, static_cast<std::uint32_t>(rng() % n)};
        if (is_live(mesh, r)) {
            return r;
        }
    }
    return {};
}

ops::Step random_step(const Mesh& mesh, const ops::Verb& verb, std::mt19937& rng) {
    if (verb.accepts(ops::Target::None)) {
        return ops::make_step(verb.name, mesh);
    }
    if (verb.accepts(ops::Target::Region)) {
        const double height = 0.25;
        return ops::make_region_step(verb.name, test::random_region(mesh, rng),
                                     std::span<const double>(&height, verb.min_amounts));
    }
    if (verb.accepts(ops::Target::EdgePair)) {
        // A weld joins boundary edges: pick two.
        std::vector<std::uint32_t> boundary;
        for (const Edge e : mesh.edges()) {
            if (mesh.is_boundary(e)) {
                boundary.push_back(e.idx());
            }
        }
        if (boundary.size() < 2) {
            return ops::make_step(verb.name, mesh, random_live(mesh, Kind::Edge, rng), {},
                                  random_live(mesh, Kind::Edge, rng));
        }
        return ops::make_step(verb.name, mesh, {Kind::Edge, boundary[rng() % boundary.size()]}, {},
                              {Kind::Edge, boundary[rng() % boundary.size()]});
    }
    for (const auto& [target, kind] :
         {std::pair{ops::Target::Edge, Kind::Edge}, std::pair{ops::Target::Vertex, Kind::Vertex},
          std::pair{ops::Target::Face, Kind::Face}}) {
        if (verb.accepts(target)) {
            return ops::make_step(verb.name, mesh, random_live(mesh, kind, rng));
        }
    }
    return ops::make_step(verb.name, mesh);
}

// What must hold after any verb: labels and materials are among the values registered (or
// the defaults of elements nothing old describes); the affine value and the copy of the
// position follow the position where the verb places vertices at affine combinations.
void expect_carried(const Mesh& mesh, const Registered& r, std::size_t labels, bool affine_ok,
                    const std::string& what) {
    for (const Vertex v : mesh.vertices()) {
        const Vec3 p = mesh.position(v);
        const double scale = 1.0 + std::abs(p.x) + std::abs(p.y) + std::abs(p.z);
        if (affine_ok) {
            ASSERT_NEAR(r.value[v], affine(p), 1e-12 * 8 * scale) << what << " vertex " << v.idx();
            ASSERT_NEAR(norm(r.copy[v] - p), 0.0, 1e-12 * scale) << what << " vertex " << v.idx();
        }
        ASSERT_TRUE(r.label[v] >= 0 && r.label[v] < static_cast<std::int32_t>(labels))
            << what << ": vertex " << v.idx() << " label " << r.label[v];
    }
    for (const Face f : mesh.faces()) {
        ASSERT_TRUE(r.material[f] < 7 || r.material[f] == 999) << what << " face " << f.idx();
        for (const Halfedge h : mesh.halfedges(f)) {
            const Vec2 want = second_of(r.uv0[h]), got = r.uv1[h];
            const double scale = 1.0 + std::abs(want.x) + std::abs(want.y);
            ASSERT_TRUE(std::abs(got.x - want.x) <= 1e-9 * scale &&
                        std::abs(got.y - want.y) <= 1e-9 * scale)
                << what << ": the second set at corner " << h.idx() << " is (" << got.x << ", "
                << got.y << "), the first's rule gives (" << want.x << ", " << want.y << ")";
        }
    }
}

TEST(Carry, EveryVerbCarriesUserPropertiesOnSevenMeshes) {
    std::mt19937 rng(11);
    std::size_t ran = 0;
    for (const ops::Verb& verb : ops::verbs()) {
        std::size_t verb_ran = 0;
        for (Mesh mesh : seven_meshes()) {
            const std::size_t labels = mesh.vertices_size();
            register_properties(mesh);
            for (int i = 0; i < (verb.accepts(ops::Target::None) ? 1 : 6); ++i) {
                const ops::Step step = random_step(mesh, verb, rng);
                try {
                    ops::run_step(mesh, step);
                } catch (const ops::OpError&) {
                    continue;
                }
                ++verb_ran;
                ASSERT_TRUE(test::is_valid(mesh)) << step.text;
                const Registered r = registered(mesh);
                ASSERT_TRUE(r.value && r.copy && r.label && r.edge_label && r.corner &&
                            r.material && r.uv0 && r.uv1)
                    << step.text << " lost a property";
                expect_carried(mesh, r, labels, !places_off_affine(verb.name), step.text);
            }
        }
        EXPECT_GT(verb_ran, 0u) << verb.name << " never ran";
        ran += verb_ran;
    }
    EXPECT_GT(ran, 200u);
}

// split's stated derivation, element by element (the diagram above split()).
TEST(Carry, SplitDerivesEachNewElementAsItsDiagramSays) {
    Mesh mesh = shapes::icosphere(1);
    const Registered r = register_properties(mesh);
    auto crease = mesh.add_property<Edge, std::uint8_t>(kCreaseProperty, 0);
    const Edge e(5);
    crease[e] = 1;
    const Halfedge h0 = Mesh::halfedge(e, 0);
    const Halfedge t0 = Mesh::twin(h0);
    const Vertex b = mesh.from_vertex(h0), c = mesh.to_vertex(h0);
    const Face f0 = mesh.face(h0), f1 = mesh.face(t0);
    const double corner_b0 = r.corner[mesh.prev(h0)], corner_c0 = r.corner[h0];
    const double corner_b1 = r.corner[t0], corner_c1 = r.corner[mesh.prev(t0)];
    const auto n_edges = static_cast<std::uint32_t>(mesh.edges_size());
    const auto n_faces = static_cast<std::uint32_t>(mesh.faces_size());

    const Vertex m = *split(mesh, e);
    EXPECT_EQ(r.value[m], 0.5 * r.value[b] + 0.5 * r.value[c]);
    EXPECT_EQ(r.label[m], r.label[b]);  // a tie: the first source
    // The half s of e (first new edge) copies it, crease included; u and w are new.
    EXPECT_EQ(r.edge_label[Edge(n_edges)], static_cast<std::int32_t>(e.idx()));
    EXPECT_EQ(crease[Edge(n_edges)], 1);
    EXPECT_EQ(r.edge_label[Edge(n_edges + 1)], -1);
    EXPECT_EQ(r.edge_label[Edge(n_edges + 2)], -1);
    EXPECT_EQ(crease[Edge(n_edges + 1)], 0);
    // f3 is a part of f1, f2 of f0.
    EXPECT_EQ(r.material[Face(n_faces)], r.material[f1]);
    EXPECT_EQ(r.material[Face(n_faces + 1)], r.material[f0]);
    // Every corner at m blends the corners at b and c of the face it came from.
    std::multiset<double> at_m,
        expected{0.5 * corner_b0 + 0.5 * corner_c0, 0.5 * corner_b0 + 0.5 * corner_c0,
                 0.5 * corner_b1 + 0.5 * corner_c1, 0.5 * corner_b1 + 0.5 * corner_c1};
    for (const Halfedge h : mesh.halfedges(m)) {
        at_m.insert(r.corner[Mesh::twin(h)]);
    }
    EXPECT_EQ(at_m, expected);
}

// Subdivision: a face's parts copy it, an edge's halves copy it, and the corners of the
// children interpolate the parent's corners linearly (face-varying linear).
TEST(Carry, SubdivisionCopiesFacesAndEdgeHalvesAndInterpolatesCorners) {
    for (const bool loop : {true, false}) {
        SCOPED_TRACE(loop ? "Loop" : "Catmull-Clark");
        Mesh mesh = shapes::icosphere(1);
        const Registered r = register_properties(mesh);
        const std::size_t ne = mesh.edges_size();
        std::vector<std::uint16_t> materials;
        std::vector<std::size_t> degrees;
        for (const Face f : mesh.faces()) {
            materials.push_back(r.material[f]);
            degrees.push_back(mesh.valence(f));
        }
        if (loop) {
            loop_subdivide(mesh);
        } else {
            quad_subdivide(mesh);
        }
        const Registered after = registered(mesh);
        ASSERT_TRUE(after.value && after.copy && after.label && after.edge_label && after.corner &&
                    after.material);
        std::size_t child = 0;
        for (std::size_t f = 0; f < materials.size(); ++f) {
            for (std::size_t i = 0; i < (loop ? 4 : degrees[f]); ++i, ++child) {
                ASSERT_EQ(after.material[Face(static_cast<std::uint32_t>(child))], materials[f]);
            }
        }
        for (std::uint32_t g = 0; g < 2 * ne; ++g) {
            ASSERT_EQ(after.edge_label[Edge(g)], static_cast<std::int32_t>(g / 2));
        }
        for (std::uint32_t g = 2 * static_cast<std::uint32_t>(ne); g < mesh.edges_size(); ++g) {
            ASSERT_EQ(after.edge_label[Edge(g)], -1);
        }
        // The corners held the affine function of their vertex's old position: linear
        // interpolation keeps them the function of the unsmoothed (linear) position, which a
        // linear subdivision of the positions gives.
        Mesh linear = shapes::icosphere(1);
        QuadSubdivisionOptions options;
        options.scheme = QuadScheme::Linear;
        if (loop) {
            // Loop's edge points are midpoints on the linear scheme too: compare edge points.
            for (const Face c : mesh.faces()) {
                for (const Halfedge h : mesh.halfedges(c)) {
                    ASSERT_TRUE(std::isfinite(after.corner[h]));
                }
            }
        } else {
            quad_subdivide(linear, options);
            for (const Face c : mesh.faces()) {
                for (const Halfedge h : mesh.halfedges(c)) {
                    const Vec3 p = linear.position(mesh.to_vertex(h));
                    ASSERT_NEAR(after.corner[h], affine(p), 1e-12) << "corner " << h.idx();
                }
            }
        }
        for (const Vertex v : mesh.vertices()) {
            ASSERT_NEAR(after.value[v], affine(mesh.position(v)), 1e-12);
        }
    }
}

// A crease survives a collapse beside it (Carry::Any), and a library user may ask for
// another rule.
TEST(Carry, RulesByPropertyCreaseAnyAndUserChosen) {
    Mesh mesh = shapes::grid(4, 4);
    auto crease = mesh.add_property<Edge, std::uint8_t>(kCreaseProperty, 0);
    auto weight = mesh.add_property<Vertex, double>("v:weight", 0.0);
    EXPECT_TRUE(mesh.set_carry<Vertex>("v:weight", Carry::Heaviest));
    EXPECT_FALSE(mesh.set_carry<Vertex>("v:nothing", Carry::Blend));
    for (const Vertex v : mesh.vertices()) {
        weight[v] = v.idx();
    }
    for (const Edge e : mesh.edges()) {
        crease[e] = e.idx() % 2;
    }
    const Edge e(12);
    const Vertex a = mesh.vertex(e, 0), b = mesh.vertex(e, 1);
    const Vertex m = *split(mesh, e);
    // The heaviest of a tie (one end), not the blend 0.5 (a + b) the default rule gives.
    EXPECT_TRUE(weight[m] == weight[a] || weight[m] == weight[b]) << weight[m];
    EXPECT_NE(weight[m], 0.5 * (weight[a] + weight[b]));
    mesh.garbage_collection();
    std::size_t creases = 0;
    for (const Edge x : mesh.edges()) {
        creases += crease[x];
    }
    // Collapsing an interior edge merges two pairs of edges: a merged pair keeps a crease.
    for (const Edge x : mesh.edges()) {
        if (!mesh.is_boundary(x) && is_collapse_ok(mesh, x)) {
            collapse(mesh, x);
            break;
        }
    }
    std::size_t after = 0;
    for (const Edge x : mesh.edges()) {
        after += crease[x];
    }
    EXPECT_GE(after + 1, creases);  // only the collapsed edge itself can take one away
}

// An operation that makes an element without Mesh::carry(): the self-check fails.
TEST(Carry, SelfCheckCatchesANewElementWithoutADerivation) {
    if (!MeshRecorder::kSelfCheck) {
        GTEST_SKIP() << "the recorder checks itself in Debug and sanitizer builds";
    }
    Mesh mesh = shapes::torus(6, 5);
    {
        MeshRecorder recorder(mesh);
        ASSERT_TRUE(split(mesh, Edge(3)));          // derives all it makes
        const Vertex lonely = mesh.new_vertex({});  // the broken op: no carry()
        (void)lonely;
        try {
            recorder.finish();
            ADD_FAILURE() << "the self-check did not notice the underived vertex";
        } catch (const std::logic_error& e) {
            EXPECT_NE(std::string(e.what()).find("without saying where its attributes come from"),
                      std::string::npos)
                << e.what();
        }
    }
    Mesh fixed = shapes::torus(6, 5);
    MeshRecorder recorder(fixed);
    const Vertex v = fixed.new_vertex({});
    fixed.carry_default(v);
    EXPECT_NO_THROW(recorder.finish());
}

}  // namespace
}  // namespace meshedit
