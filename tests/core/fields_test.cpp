// Scalar fields against closed forms: a sphere's curvatures, a torus's Gaussian curvature
// signs, a plane's zeros, Gauss–Bonnet on closed and open meshes, an equilateral triangle's
// quality, a grid's edge distances.

#include "meshedit/core/fields.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string_view>

#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> field(const Mesh& mesh, const char* name, const FieldOptions& o = {}) {
    const FieldInfo* info = find_field(name);
    EXPECT_NE(info, nullptr) << name;
    return compute_field(mesh, *info, o);
}

TEST(Fields, SphereCurvaturesWithinOnePercent) {
    // icosphere(6): 81,920 triangles on the unit sphere; K = 1, H = 1 at every vertex.
    const Mesh sphere = shapes::icosphere(6);
    ASSERT_GT(sphere.n_faces(), 40000u);
    for (const char* name : {"gauss", "mean"}) {
        SCOPED_TRACE(name);
        const std::vector<double> values = field(sphere, name);
        const FieldStats s = field_stats(values);
        EXPECT_EQ(s.count, sphere.n_vertices());
        EXPECT_NEAR(s.min, 1.0, 0.01);
        EXPECT_NEAR(s.max, 1.0, 0.01);
    }
}

TEST(Fields, GaussBonnetHoldsOnAnyMesh) {
    // Σ angle defects = 2πχ: sphere and cube χ = 2, torus 0, disk and grid 1.
    EXPECT_NEAR(total_angle_defect(shapes::icosphere(3)), 4 * kPi, 1e-9);
    EXPECT_NEAR(total_angle_defect(shapes::cube()), 4 * kPi, 1e-9);
    EXPECT_NEAR(total_angle_defect(test::quad_cube()), 4 * kPi, 1e-9);
    EXPECT_NEAR(total_angle_defect(shapes::torus(12, 8)), 0.0, 1e-9);
    EXPECT_NEAR(total_angle_defect(shapes::disk(7)), 2 * kPi, 1e-9);
    EXPECT_NEAR(total_angle_defect(shapes::grid(5, 3)), 2 * kPi, 1e-9);
}

TEST(Fields, TorusIsPositiveOutsideAndNegativeInside) {
    // Major radius 1, minor 0.4: K > 0 where the vertex is farther from the axis than the
    // tube's centre circle, K < 0 nearer.
    const Mesh torus = shapes::torus(48, 24, 1.0, 0.4);
    const std::vector<double> k = field(torus, "gauss");
    for (Vertex v : torus.vertices()) {
        const Vec3 p = torus.position(v);
        const double from_axis = std::hypot(p.x, p.y);
        if (from_axis > 1.05) {
            EXPECT_GT(k[v.idx()], 0.0) << v.idx();
        } else if (from_axis < 0.95) {
            EXPECT_LT(k[v.idx()], 0.0) << v.idx();
        }
    }
}

TEST(Fields, PlaneIsFlatAndBoundaryHasNoCurvature) {
    const Mesh grid = shapes::grid(4, 4);
    const std::vector<double> k = field(grid, "gauss");
    const std::vector<double> h = field(grid, "mean");
    for (Vertex v : grid.vertices()) {
        if (grid.is_boundary(v)) {
            EXPECT_TRUE(std::isnan(k[v.idx()]));
        } else {
            EXPECT_NEAR(k[v.idx()], 0.0, 1e-12);
            EXPECT_NEAR(h[v.idx()], 0.0, 1e-12);
        }
    }
}

TEST(Fields, EquilateralTriangleIsPerfect) {
    const double s = std::sqrt(3.0) / 2.0;
    const Mesh tri = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0.5, s, 0}}, {{0, 1, 2}});
    EXPECT_NEAR(field(tri, "aspect")[0], 1.0, 1e-12);
    EXPECT_NEAR(field(tri, "min_angle")[0], 60.0, 1e-12);
    EXPECT_NEAR(field(tri, "face_area")[0], s / 2.0, 1e-15);
    // A squashed one is worse on both counts.
    const Mesh flat = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0.5, 0.1, 0}}, {{0, 1, 2}});
    EXPECT_GT(field(flat, "aspect")[0], 2.0);
    EXPECT_LT(field(flat, "min_angle")[0], 12.0);
}

TEST(Fields, EdgeFieldsAndDistances) {
    const Mesh cube = shapes::cube();  // [-1, 1]³, each side cut by a diagonal
    const std::vector<double> dihedral = field(cube, "dihedral");
    const std::vector<double> length = field(cube, "edge_length");
    for (Edge e : cube.edges()) {
        const bool diagonal = std::abs(length[e.idx()] - 2.0 * std::sqrt(2.0)) < 1e-12;
        EXPECT_NEAR(dihedral[e.idx()], diagonal ? 0.0 : 90.0, 1e-9);
        if (!diagonal) {
            EXPECT_NEAR(length[e.idx()], 2.0, 1e-15);
        }
    }
    // Grid vertex (i, j) is j·4 + i; diagonals run (i, j) to (i+1, j+1); the unit square
    // spans 3 × 3 cells of side 1/3.
    const Mesh grid = shapes::grid(3, 3);
    FieldOptions from_corner;
    from_corner.source = Vertex(0);
    const std::vector<double> d = field(grid, "distance", from_corner);
    EXPECT_EQ(d[0], 0.0);
    EXPECT_NEAR(d[15], std::sqrt(2.0), 1e-12);                     // three diagonals
    EXPECT_NEAR(d[3], 1.0, 1e-12);                                 // along the bottom row
    EXPECT_NEAR(d[7], 1.0 / 3.0 * (2.0 + std::sqrt(2.0)), 1e-12);  // (3, 1)
}

TEST(Fields, ValenceStatsAndPercentiles) {
    const Mesh ico = shapes::icosahedron();
    const FieldStats s = field_stats(field(ico, "valence"));
    EXPECT_EQ(s.count, 12u);
    EXPECT_EQ(s.min, 5.0);
    EXPECT_EQ(s.max, 5.0);
    const std::vector<double> values{4.0, 1.0, std::nan(""), 3.0, 2.0, 5.0};
    EXPECT_EQ(field_percentile(values, 0.0), 1.0);
    EXPECT_EQ(field_percentile(values, 1.0), 5.0);
    EXPECT_EQ(field_percentile(values, 0.5), 3.0);
    EXPECT_EQ(field_stats(values).mean, 3.0);
    EXPECT_NEAR(surface_area(test::quad_cube()), 24.0, 1e-12);
}

// The viewer's hover: an element of the field's kind reads its own value; any other reads the
// values of the field's elements it touches.
TEST(Fields, ValuesAtAnElementOfAnyKind) {
    const Mesh cube = test::quad_cube();
    std::vector<double> per_vertex(cube.vertices_size()), per_face(cube.faces_size());
    for (std::size_t i = 0; i < per_vertex.size(); ++i) {
        per_vertex[i] = 10.0 + static_cast<double>(i);
    }
    for (std::size_t i = 0; i < per_face.size(); ++i) {
        per_face[i] = 100.0 + static_cast<double>(i);
    }
    using Kind = ElementRef::Kind;
    const auto at = [&](FieldSite site, const std::vector<double>& v, ElementRef e) {
        return field_values_at(cube, site, v, e);
    };
    const auto own = at(FieldSite::Vertex, per_vertex, ElementRef::vertex(Vertex(3)));
    ASSERT_EQ(own.size(), 1u);
    EXPECT_EQ(own[0].second, 13.0);
    // A quad's four corners, each with its value.
    const auto corners = at(FieldSite::Vertex, per_vertex, ElementRef::face(Face(2)));
    ASSERT_EQ(corners.size(), 4u);
    for (const auto& [r, value] : corners) {
        EXPECT_EQ(r.kind, Kind::Vertex);
        EXPECT_EQ(value, per_vertex[r.index]);
    }
    // An edge between two faces reads both faces; a vertex of the cube its three faces.
    EXPECT_EQ(at(FieldSite::Face, per_face, ElementRef::edge(Edge(0))).size(), 2u);
    EXPECT_EQ(at(FieldSite::Face, per_face, ElementRef::vertex(Vertex(0))).size(), 3u);
    // A halfedge reads its face.
    const Halfedge h(5);
    const auto face = at(FieldSite::Face, per_face, ElementRef::halfedge(h));
    ASSERT_EQ(face.size(), 1u);
    EXPECT_EQ(face[0].first, ElementRef::face(cube.face(h)));
    EXPECT_TRUE(at(FieldSite::Face, per_face, ElementRef{}).empty());
}

// A mesh at 1e200, 1e-200 and 2^1020: its squares overflow or underflow (every angle came
// out as atan2(inf, inf) = 45°, the defect wrong). Angles, quality and Gauss–Bonnet are the
// unit mesh's; lengths, areas, volume and curvatures scale as they should, or are inf when
// the value itself is past 1.8e308 — never NaN. (Tiny meshes: vertex normals still underflow,
// so mean curvature is not checked there.)
TEST(Fields, HugeAndTinyCoordinatesGiveTheUnitMeshsValues) {
    const Mesh unit = shapes::icosphere(1);
    for (const double scale : {1e200, 1e-200, std::ldexp(1.0, 1020)}) {
        SCOPED_TRACE(scale);
        Mesh big = unit;
        for (Vertex v : big.vertices()) {
            big.position(v) = scale * big.position(v);
        }
        EXPECT_NEAR(total_angle_defect(big), total_angle_defect(unit), 1e-12);
        for (const char* name : {"min_angle", "aspect", "dihedral"}) {
            const FieldStats a = field_stats(field(unit, name));
            const FieldStats b = field_stats(field(big, name));
            EXPECT_EQ(b.count, a.count) << name;
            EXPECT_NEAR(b.min, a.min, 1e-9 * a.max) << name;
            EXPECT_NEAR(b.max, a.max, 1e-9 * a.max) << name;
        }
        // Lengths scale by `scale`, Gaussian curvature by 1/scale², mean curvature by 1/scale.
        const struct {
            const char* name;
            double factor;
        } scaled[] = {{"edge_length", scale}, {"distance", scale}, {"mean", 1.0 / scale}};
        for (const auto& [name, factor] : scaled) {
            if (scale < 1.0 && std::string_view(name) == "mean") {
                continue;  // vertex normals underflow at 1e-200 (not scaled yet)
            }
            const FieldStats a = field_stats(field(unit, name));
            const FieldStats b = field_stats(field(big, name));
            EXPECT_EQ(b.count, a.count) << name;
            EXPECT_NEAR(b.mean / factor, a.mean, 1e-9 * a.mean) << name;
            EXPECT_NEAR(b.max / factor, a.max, 1e-9 * a.max) << name;
        }
        const double area = surface_area(big);
        const double volume = signed_volume(big);
        if (scale > 1.0) {
            EXPECT_EQ(area, std::numeric_limits<double>::infinity());
            EXPECT_EQ(volume, std::numeric_limits<double>::infinity());
        } else {
            EXPECT_EQ(area, 0.0);  // 1e-400 underflows
            EXPECT_EQ(volume, 0.0);
        }
    }
    // Large enough to overflow the squares, small enough for the area to be finite.
    Mesh big = unit;
    for (Vertex v : big.vertices()) {
        big.position(v) = 1e150 * big.position(v);
    }
    EXPECT_NEAR(surface_area(big) / 1e300, surface_area(unit), 1e-9 * surface_area(unit));
    EXPECT_NEAR(field_stats(field(big, "gauss")).mean * 1e300,
                field_stats(field(unit, "gauss")).mean, 1e-9);
}

TEST(StoredFields, AMeshsScalarPropertiesAreFieldsNamedWithoutTheirPrefix) {
    Mesh mesh = shapes::cube();
    auto deviation = mesh.add_property<Vertex, double>("v:ply:deviation", 0.0);
    auto label = mesh.add_property<Face, std::int32_t>("f:label", 0);
    mesh.add_property<Vertex, double>("v:ply:valence", 0.0);    // a computed field's name
    mesh.add_property<Vertex, float>("v:mean", 0.0f);           // likewise, without ply:
    mesh.add_property<Vertex, std::uint8_t>("v:loop_has", 0);   // MeshEdit's own: not a field
    mesh.add_property<Vertex, Vec3>("v:ply:velocity", Vec3{});  // not a scalar
    for (const Vertex v : mesh.vertices()) {
        deviation[v] = 0.5 * v.idx();
    }
    for (const Face f : mesh.faces()) {
        label[f] = -static_cast<std::int32_t>(f.idx());
    }
    const std::vector<const FieldInfo*> stored = stored_fields(mesh);
    std::vector<std::string> names;
    for (const FieldInfo* info : stored) {
        names.emplace_back(info->name);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"deviation", "ply:valence", "user:mean", "label"}));
    EXPECT_EQ(mesh_fields(mesh).size(), field_infos().size() + 4);
    EXPECT_EQ(find_field(mesh, "valence"), find_field("valence"));  // the computed one wins

    const FieldInfo* d = find_field(mesh, "deviation");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d, stored.front());  // one FieldInfo per property, however often asked
    EXPECT_EQ(d->site, FieldSite::Vertex);
    EXPECT_EQ(d->property, "v:ply:deviation");
    const std::vector<double> dv = compute_field(mesh, *d);
    ASSERT_EQ(dv.size(), mesh.vertices_size());
    for (const Vertex v : mesh.vertices()) {
        EXPECT_EQ(dv[v.idx()], 0.5 * v.idx());
    }
    const FieldInfo* l = find_field(mesh, "label");
    ASSERT_NE(l, nullptr);
    EXPECT_EQ(l->site, FieldSite::Face);
    const std::vector<double> lv = compute_field(mesh, *l);
    for (const Face f : mesh.faces()) {
        EXPECT_EQ(lv[f.idx()], -static_cast<double>(f.idx()));
    }
    EXPECT_EQ(field_names(mesh, ",").substr(0, 11), "gauss,mean,");
    EXPECT_TRUE(field_names(mesh).ends_with("distance deviation ply:valence user:mean label"));

    // A mesh without the property (another file) reads no values, never stale ones.
    const Mesh plain = shapes::cube();
    EXPECT_EQ(find_field(plain, "deviation"), nullptr);
    for (const double x : compute_field(plain, *d)) {
        EXPECT_TRUE(std::isnan(x));
    }
}

}  // namespace
}  // namespace meshedit
