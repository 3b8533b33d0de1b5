// Texture coordinates through subdivision against OpenSubdiv: Far's face-varying refinement
// (PrimvarRefiner::InterpolateFaceVarying) for every FVarLinearInterpolation option, on Loop,
// Catmark and bilinear, on meshes with UV seams. Far's channel is built from MeshEdit's corners
// (a vertex's distinct texture coordinates are its values); at every level each MeshEdit
// corner is matched to Far's face-vertex through the vertex and face matching of
// opensubdiv_test.cpp, and its texture coordinate must equal Far's value to 1e-12. A colour
// (a vertex property) must equal Far's vertex interpolation at the same time.

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/io/io.h"
#include "opensubdiv_test_util.h"
#include "subdivision_test_util.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

enum class Scheme { Loop, CatmullClark, Linear };

using test::canonical;
using test::Cycle;
using Value = test::Point;

constexpr UvInterpolation kOptions[] = {
    UvInterpolation::None,         UvInterpolation::CornersOnly, UvInterpolation::CornersPlus1,
    UvInterpolation::CornersPlus2, UvInterpolation::Boundaries,  UvInterpolation::All};

Sdc::Options::FVarLinearInterpolation far_option(UvInterpolation uv) {
    switch (uv) {
        case UvInterpolation::None:
            return Sdc::Options::FVAR_LINEAR_NONE;
        case UvInterpolation::CornersOnly:
            return Sdc::Options::FVAR_LINEAR_CORNERS_ONLY;
        case UvInterpolation::CornersPlus1:
            return Sdc::Options::FVAR_LINEAR_CORNERS_PLUS1;
        case UvInterpolation::CornersPlus2:
            return Sdc::Options::FVAR_LINEAR_CORNERS_PLUS2;
        case UvInterpolation::Boundaries:
            return Sdc::Options::FVAR_LINEAR_BOUNDARIES;
        case UvInterpolation::All:
            break;
    }
    return Sdc::Options::FVAR_LINEAR_ALL;
}

// The largest difference seen per scheme and option, printed at the end (docs quote it).
std::map<std::pair<int, int>, double>& largest() {
    static std::map<std::pair<int, int>, double> m;
    return m;
}

// Refines `mesh` `levels` times with MeshEdit and with Far and compares every corner's
// texture coordinate of the set `set` (kTexCoordSets) and every vertex's colour at every level.
void expect_fvar_equal(Mesh mesh, Scheme scheme, UvInterpolation uv, int levels,
                       const char* set = kTexCoordProperty) {
    SCOPED_TRACE(std::string("uv ") + std::string(uv_interpolation_name(uv)) + " " + set);
    mesh.garbage_collection();
    auto tex = mesh.get_property<Halfedge, Vec2>(set);
    ASSERT_TRUE(tex);
    auto colour = mesh.property<Vertex, Vec3>("v:colour", Vec3{});
    for (Vertex v : mesh.vertices()) {
        const Vec3& p = mesh.position(v);
        colour[v] = {std::sin(p.x) + 0.5 * std::cos(p.y), std::sin(p.z), 0.25 * (v.idx() % 7)};
    }

    // Topology, creases and the face-varying channel (distinct values per vertex).
    std::vector<int> sizes, corners, values_of_corners, crease_ends;
    std::vector<Value> values;
    std::map<std::tuple<std::uint32_t, double, double>, int> value_index;
    for (Face f : mesh.faces()) {
        sizes.push_back(static_cast<int>(mesh.valence(f)));
        for (Halfedge h : mesh.halfedges(f)) {
            const Vertex v = mesh.to_vertex(h);
            corners.push_back(static_cast<int>(v.idx()));
            const auto key = std::make_tuple(v.idx(), tex[h].x, tex[h].y);
            auto [it, added] = value_index.emplace(key, static_cast<int>(values.size()));
            if (added) {
                values.push_back({tex[h].x, tex[h].y, 0});
            }
            values_of_corners.push_back(it->second);
        }
    }
    for (const auto& [a, b] : test::crease_pairs(mesh)) {
        crease_ends.push_back(static_cast<int>(a));
        crease_ends.push_back(static_cast<int>(b));
    }
    const std::vector<float> sharpness(crease_ends.size() / 2, Sdc::Crease::SHARPNESS_INFINITE);
    Far::TopologyDescriptor::FVarChannel channel;
    channel.numValues = static_cast<int>(values.size());
    channel.valueIndices = values_of_corners.data();
    Far::TopologyDescriptor desc;
    desc.numVertices = static_cast<int>(mesh.n_vertices());
    desc.numFaces = static_cast<int>(mesh.n_faces());
    desc.numVertsPerFace = sizes.data();
    desc.vertIndicesPerFace = corners.data();
    desc.numCreases = static_cast<int>(sharpness.size());
    desc.creaseVertexIndexPairs = crease_ends.data();
    desc.creaseWeights = sharpness.data();
    desc.numFVarChannels = 1;
    desc.fvarChannels = &channel;
    Sdc::Options options;
    options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    options.SetFVarLinearInterpolation(far_option(uv));
    const Sdc::SchemeType type = scheme == Scheme::Loop           ? Sdc::SCHEME_LOOP
                                 : scheme == Scheme::CatmullClark ? Sdc::SCHEME_CATMARK
                                                                  : Sdc::SCHEME_BILINEAR;
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(
        Factory::Create(desc, Factory::Options(type, options)));
    ASSERT_TRUE(refiner);
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true;
    refiner->RefineUniform(uniform);
    Far::PrimvarRefinerReal<double> primvar(*refiner);
    std::vector<Value> colours;
    for (Vertex v : mesh.vertices()) {
        colours.push_back({colour[v].x, colour[v].y, colour[v].z});
    }
    std::vector<int> vmap(mesh.n_vertices()), fmap(mesh.n_faces());
    for (std::size_t i = 0; i < vmap.size(); ++i) {
        vmap[i] = static_cast<int>(i);
    }
    for (std::size_t i = 0; i < fmap.size(); ++i) {
        fmap[i] = static_cast<int>(i);
    }
    double worst = 0.0;
    for (int level = 1; level <= levels; ++level) {
        SCOPED_TRACE("level " + std::to_string(level));
        const Far::TopologyLevel& parent = refiner->GetLevel(level - 1);
        const Far::TopologyLevel& child = refiner->GetLevel(level);
        std::vector<Value> next_values(child.GetNumFVarValues(0));
        {
            Value* src = values.data();
            Value* dst = next_values.data();
            primvar.InterpolateFaceVarying(level, src, dst, 0);
        }
        values.swap(next_values);
        std::vector<Value> next_colours(child.GetNumVertices());
        {
            Value* src = colours.data();
            Value* dst = next_colours.data();
            primvar.Interpolate(level, src, dst);
        }
        colours.swap(next_colours);

        const Mesh before = mesh;
        if (scheme == Scheme::Loop) {
            LoopOptions loop;
            loop.weights = LoopWeights::Loop;
            loop.uv = uv;
            loop_subdivide(mesh, loop);
        } else {
            QuadSubdivisionOptions quads;
            quads.scheme = scheme == Scheme::Linear ? QuadScheme::Linear : QuadScheme::CatmullClark;
            quads.uv = uv;
            quad_subdivide(mesh, quads);
        }
        ASSERT_EQ(mesh.n_vertices(), static_cast<std::size_t>(child.GetNumVertices()));
        ASSERT_EQ(mesh.n_faces(), static_cast<std::size_t>(child.GetNumFaces()));

        // The layout: old v, then V + e, then (quads) V + E + f.
        ASSERT_TRUE(test::next_vertex_map(before, parent, scheme != Scheme::Loop, vmap, fmap,
                                          mesh.vertices_size()));

        const std::map<Cycle, int> osd_faces = test::faces_by_cycle(child);
        tex = mesh.get_property<Halfedge, Vec2>(set);
        colour = mesh.get_property<Vertex, Vec3>("v:colour");
        ASSERT_TRUE(tex && colour);
        fmap.assign(mesh.faces_size(), -1);
        for (Face f : mesh.faces()) {
            Cycle c;
            std::vector<Halfedge> hs;
            for (Halfedge h : mesh.halfedges(f)) {
                c.push_back(vmap[mesh.to_vertex(h).idx()]);
                hs.push_back(h);
            }
            const auto found = osd_faces.find(canonical(c));
            ASSERT_NE(found, osd_faces.end()) << "face " << f.idx() << " is not a Far face";
            const int osd_face = found->second;
            fmap[f.idx()] = osd_face;
            // Far's face lists its vertices from some corner on; line ours up with it.
            const auto osd_verts = child.GetFaceVertices(osd_face);
            const auto osd_values = child.GetFaceFVarValues(osd_face, 0);
            for (std::size_t i = 0; i < hs.size(); ++i) {
                int k = 0;
                while (osd_verts[k] != c[i]) {
                    ++k;
                }
                const Value& want = values[osd_values[k]];
                const Vec2 got = tex[hs[i]];
                const double d = std::max(std::abs(got.x - want.x), std::abs(got.y - want.y));
                worst = std::max(worst, d);
                ASSERT_LE(d, test::kTol)
                    << "corner of face " << f.idx() << " at vertex " << mesh.to_vertex(hs[i]).idx()
                    << ": (" << got.x << ", " << got.y << ") != Far's (" << want.x << ", " << want.y
                    << ")";
            }
        }
        for (Vertex v : mesh.vertices()) {
            const Value& q = colours[vmap[v.idx()]];
            ASSERT_TRUE(test::near(colour[v], {q.x, q.y, q.z})) << "colour of vertex " << v.idx();
        }
    }
    double& w = largest()[{static_cast<int>(scheme), static_cast<int>(uv)}];
    w = std::max(w, worst);
}

void expect_all_options(const Mesh& mesh, Scheme scheme, int levels = 3) {
    for (const UvInterpolation uv : kOptions) {
        expect_fvar_equal(mesh, scheme, uv, levels);
    }
}

// ------------------------------------------------------------------ UV maps with seams

// Angles about the point `c` in the xy-plane, in [0, 2π), computed once per vertex so that
// the corners of a vertex agree to the bit; a face that straddles the cut at angle 0 takes
// its small angles plus 2π, so the cut is a seam along edges. A vertex at c has no angle of
// its own: each face gives it the mean of its other corners' (a value per face: a junction).
std::vector<double> face_angles(const Mesh& mesh, Face f, Vec3 c) {
    std::vector<double> a;
    std::vector<bool> at_c;
    for (Halfedge h : mesh.halfedges(f)) {
        const Vec3& p = mesh.position(mesh.to_vertex(h));
        const double t = std::atan2(p.y - c.y, p.x - c.x);
        at_c.push_back(std::hypot(p.x - c.x, p.y - c.y) < 1e-12);
        a.push_back(t < 0 ? t + 2.0 * std::numbers::pi : t);
    }
    double lo = 7, hi = -1, sum = 0;
    int k = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!at_c[i]) {
            lo = std::min(lo, a[i]);
            hi = std::max(hi, a[i]);
        }
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!at_c[i] && hi - lo > std::numbers::pi && a[i] < std::numbers::pi) {
            a[i] += 2.0 * std::numbers::pi;
        }
        if (!at_c[i]) {
            sum += a[i];
            ++k;
        }
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (at_c[i]) {
            a[i] = k > 0 ? sum / k : 0.0;
        }
    }
    return a;
}

// Cylindrical map about the z axis: u = angle / 2π, v = z. A seam where u wraps, and the
// vertices on the axis are junctions of all their faces' values.
void cylindrical_uvs(Mesh& mesh, const char* set = kTexCoordProperty) {
    auto tex = mesh.property<Halfedge, Vec2>(set, Vec2{});
    for (Face f : mesh.faces()) {
        const std::vector<double> a = face_angles(mesh, f, {});
        std::size_t i = 0;
        for (Halfedge h : mesh.halfedges(f)) {
            const Vec3& p = mesh.position(mesh.to_vertex(h));
            tex[h] = {a[i++] / (2.0 * std::numbers::pi), 0.7 * p.z + 0.1};
        }
    }
}

// Planar (x, y) plus a twist about `c` that grows with the distance from it: a seam along
// the ray from c in +x that ends inside the mesh at c, where every corner agrees (a dart).
void slit_uvs(Mesh& mesh, Vec3 c) {
    auto tex = mesh.property<Halfedge, Vec2>(kTexCoordProperty, Vec2{});
    for (Face f : mesh.faces()) {
        const std::vector<double> a = face_angles(mesh, f, c);
        std::size_t i = 0;
        for (Halfedge h : mesh.halfedges(f)) {
            const Vec3& p = mesh.position(mesh.to_vertex(h));
            const double r = std::hypot(p.x - c.x, p.y - c.y);
            tex[h] = {0.3 * p.x + 0.05 * p.y, 0.3 * p.y + 0.02 * (r == 0.0 ? 0.0 : a[i] * r)};
            ++i;
        }
    }
}

// A box map: each face projected along its normal's largest axis into that axis's own chart
// (and the sign's), so charts meet at seams and a chart of one face has corner values.
void box_uvs(Mesh& mesh, const char* set = kTexCoordProperty) {
    auto tex = mesh.property<Halfedge, Vec2>(set, Vec2{});
    for (Face f : mesh.faces()) {
        std::vector<Vec3> p;
        for (Vertex v : mesh.vertices(f)) {
            p.push_back(mesh.position(v));
        }
        const Vec3 n = cross(p[1] - p[0], p[2] - p[0]);
        const double a[3] = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
        const int axis = static_cast<int>(std::max_element(a, a + 3) - a);
        const int chart = 2 * axis + (n[axis] < 0 ? 1 : 0);
        for (Halfedge h : mesh.halfedges(f)) {
            const Vec3& at = mesh.position(mesh.to_vertex(h));
            const double s = at[(axis + 1) % 3], t = at[(axis + 2) % 3];
            tex[h] = {0.31 * s + 1.13 * chart + 0.07 * t, 0.29 * t + 0.17 * chart * chart};
        }
    }
}

// ------------------------------------------------------------------ meshes

// The quad cube with a box map: six charts of one face each, every edge a seam.
Mesh boxed(Mesh mesh) {
    box_uvs(mesh);
    return mesh;
}

Mesh cylindrical(Mesh mesh) {
    cylindrical_uvs(mesh);
    return mesh;
}

// A 4 × 3 grid (boundary, valence 2 to 4 on the border) with a slit ending inside, and a crease
// crossing the slit's line.
Mesh slit_grid(bool quads) {
    Mesh mesh = quads ? shapes::quad_grid(4, 3) : shapes::grid(4, 3);
    // Center on an interior vertex.
    Vec3 lo = mesh.position(Vertex(0)), hi = lo;
    for (Vertex v : mesh.vertices()) {
        lo = Vec3{std::min(lo.x, mesh.position(v).x), std::min(lo.y, mesh.position(v).y), 0};
        hi = Vec3{std::max(hi.x, mesh.position(v).x), std::max(hi.y, mesh.position(v).y), 0};
    }
    Vertex centre(0);
    const Vec3 want{lo.x + 0.25 * (hi.x - lo.x), lo.y + (hi.y - lo.y) / 3.0, 0};
    for (Vertex v : mesh.vertices()) {
        if (distance(mesh.position(v), want) < distance(mesh.position(centre), want)) {
            centre = v;
        }
    }
    slit_uvs(mesh, mesh.position(centre));
    // A crease from the centre downward, across no seam, and a bump to make z non-trivial.
    for (Halfedge h : mesh.halfedges(centre)) {
        const Vertex w = mesh.to_vertex(h);
        if (std::abs(mesh.position(w).x - mesh.position(centre).x) < 1e-9 &&
            mesh.position(w).y < mesh.position(centre).y) {
            test::mark_crease(mesh, centre.idx(), w.idx());
        }
    }
    for (Vertex v : mesh.vertices()) {
        Vec3 p = mesh.position(v);
        p.z = 0.1 * p.x * p.y;
        mesh.position(v) = p;
    }
    return mesh;
}

TEST(OpenSubdivFaceVarying, CatmarkBoxMappedCube) {
    expect_all_options(boxed(test::quad_cube()), Scheme::CatmullClark);
}
TEST(OpenSubdivFaceVarying, CatmarkCreasedCubeWithTrianglesAndAHexagon) {
    Mesh mesh = test::quad_cube();
    poke(mesh, Face(1));
    dissolve_edge(mesh, mesh.find_edge(Vertex(2), Vertex(6)));
    test::mark_crease(mesh, 0, 1);
    test::mark_crease(mesh, 1, 2);
    expect_all_options(cylindrical(mesh), Scheme::CatmullClark);
    expect_all_options(boxed(mesh), Scheme::CatmullClark);
}
TEST(OpenSubdivFaceVarying, CatmarkSlitGridWithBoundaryAndCrease) {
    expect_all_options(slit_grid(true), Scheme::CatmullClark);
    expect_all_options(slit_grid(false), Scheme::CatmullClark);
}
TEST(OpenSubdivFaceVarying, CatmarkCylinderAndQuadSphere) {
    expect_all_options(cylindrical(shapes::cylinder(7, 3)), Scheme::CatmullClark);
    expect_all_options(cylindrical(shapes::quad_sphere(1)), Scheme::CatmullClark, 2);
}

TEST(OpenSubdivFaceVarying, LoopBoxMappedCreasedCube) {
    expect_all_options(boxed(test::creased_cube()), Scheme::Loop);
}
TEST(OpenSubdivFaceVarying, LoopIcosahedronAndDisk) {
    // Valence 5 everywhere; a disk's centre of valence 9 on the axis (a junction of 9 values).
    expect_all_options(cylindrical(shapes::icosahedron()), Scheme::Loop);
    expect_all_options(cylindrical(shapes::disk(9)), Scheme::Loop);
}
TEST(OpenSubdivFaceVarying, LoopSlitGridWithBoundaryAndCrease) {
    expect_all_options(slit_grid(false), Scheme::Loop);
}
TEST(OpenSubdivFaceVarying, LoopTetrahedronAndTorus) {
    // Valence 3, and a torus whose cylindrical seam is a closed loop.
    expect_all_options(cylindrical(shapes::tetrahedron()), Scheme::Loop);
    expect_all_options(cylindrical(shapes::torus(8, 5)), Scheme::Loop, 2);
}

TEST(OpenSubdivFaceVarying, BilinearIsLinearForEveryOption) {
    expect_all_options(boxed(test::quad_cube()), Scheme::Linear);
    expect_all_options(slit_grid(false), Scheme::Linear);
}

// Two sets on one mesh, each with its own seams (a box map and a cylindrical map, in either
// order): each set is refined as Far refines its own channel, whatever the other holds.
TEST(OpenSubdivFaceVarying, SecondSetRefinesLikeTheFirst) {
    Mesh quads = test::quad_cube();
    test::mark_crease(quads, 0, 1);
    Mesh triangles = test::creased_cube();
    for (const bool box_first : {true, false}) {
        for (Mesh* mesh : {&quads, &triangles}) {
            box_uvs(*mesh, kTexCoordSets[box_first ? 0 : 1]);
            cylindrical_uvs(*mesh, kTexCoordSets[box_first ? 1 : 0]);
        }
        for (const UvInterpolation uv : kOptions) {
            for (const char* set : kTexCoordSets) {
                expect_fvar_equal(quads, Scheme::CatmullClark, uv, 2, set);
                expect_fvar_equal(triangles, Scheme::Loop, uv, 2, set);
            }
        }
    }
}

// A course mesh from dae/ with a cylindrical map.
TEST(OpenSubdivFaceVarying, CourseBowlCylindrical) {
    const std::filesystem::path file = std::filesystem::path(MESHEDIT_SOURCE_DIR) / "dae/bowl.dae";
    Mesh mesh = read_mesh(file).mesh;
    for (const UvInterpolation uv : kOptions) {
        expect_fvar_equal(cylindrical(mesh), Scheme::CatmullClark, uv, 2);
        Mesh triangles = cylindrical(mesh);
        triangulate(triangles);
        expect_fvar_equal(triangles, Scheme::Loop, uv, 2);
    }
}

// A real textured file: assimp's spider, its own UVs (seams where its charts meet).
TEST(OpenSubdivFaceVarying, AssimpSpiderOwnUvs) {
    const std::filesystem::path file = "/usr/share/assimp/models/OBJ/spider.obj";
    if (!std::filesystem::exists(file)) {
        GTEST_SKIP() << file << " is absent (Debian package assimp-testmodels)";
    }
    Mesh mesh = read_mesh(file).mesh;
    ASSERT_TRUE(mesh.has_property<Halfedge>(kTexCoordProperty));
    for (const UvInterpolation uv : kOptions) {
        expect_fvar_equal(mesh, Scheme::CatmullClark, uv, 2);
        Mesh triangles = mesh;
        triangulate(triangles);
        expect_fvar_equal(triangles, Scheme::Loop, uv, 2);
    }
}

// Every scheme with every option on a disk (a junction of nine values at its centre, a seam,
// a boundary); prints the largest difference from Far of each, over every test this process
// ran (docs/subdivision.md quotes the whole binary's).
TEST(OpenSubdivFaceVarying, ZzEverySchemeAndOption) {
    for (const Scheme scheme : {Scheme::Loop, Scheme::CatmullClark, Scheme::Linear}) {
        expect_all_options(cylindrical(shapes::disk(9)), scheme, 2);
    }
    const char* names[] = {"Loop", "Catmull-Clark", "bilinear"};
    EXPECT_EQ(largest().size(), 3u * std::size(kOptions));
    for (const auto& [key, d] : largest()) {
        EXPECT_LE(d, test::kTol);
        std::printf(
            "%-14s %-11s max |MeshEdit - Far| = %.3g\n", names[key.first],
            std::string(uv_interpolation_name(static_cast<UvInterpolation>(key.second))).c_str(),
            d);
    }
}

}  // namespace
}  // namespace meshedit
