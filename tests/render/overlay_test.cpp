// Overlay geometry (no GL): exact counts, positions and colours of the primitives that the
// renderer will draw, checked against values worked out by hand.

#include "meshedit/overlay/overlay.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "meshedit/bezier/bezier_curve.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/loop_steps.h"
#include "meshedit/core/shapes.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

constexpr double kTol = 1e-12;
const Color kRed{1.0f, 0.0f, 0.0f, 1.0f};

#define EXPECT_VEC_NEAR(actual, expected)                 \
    do {                                                  \
        const Vec3 a_ = (actual);                         \
        const Vec3 e_ = (expected);                       \
        EXPECT_NEAR(a_.x, e_.x, kTol) << "x of " #actual; \
        EXPECT_NEAR(a_.y, e_.y, kTol) << "y of " #actual; \
        EXPECT_NEAR(a_.z, e_.z, kTol) << "z of " #actual; \
    } while (false)

std::size_t count_lines_of(const OverlayBatch& b, const Color& c) {
    std::size_t n = 0;
    for (const auto& l : b.lines) {
        n += l.color == c ? 1 : 0;
    }
    return n;
}

/// The triangle (0,0,0), (3,0,0), (0,3,0): centroid (1,1,0), so inset positions are easy to
/// work out by hand.
Mesh right_triangle() {
    return test::mesh_from_faces({{0, 0, 0}, {3, 0, 0}, {0, 3, 0}}, {{0, 1, 2}});
}

/// Strictly inside right_triangle() (not on its boundary).
bool strictly_inside_right_triangle(const Vec3& p) {
    return p.x > 0.0 && p.y > 0.0 && p.x + p.y < 3.0 && p.z == 0.0;
}

// ----------------------------------------------------------------- OverlayBatch

TEST(OverlayBatch, AppendConcatenatesInOrder) {
    OverlayBatch a;
    a.points.push_back({{1, 0, 0}, kRed, 1.0f});
    a.lines.push_back({{0, 0, 0}, {1, 0, 0}, kRed, 1.0f});
    OverlayBatch b;
    b.points.push_back({{2, 0, 0}, kRed, 2.0f});
    b.triangles.push_back({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, kRed});
    a.append(b);
    ASSERT_EQ(a.points.size(), 2u);
    EXPECT_EQ(a.points[0].p, Vec3(1, 0, 0));
    EXPECT_EQ(a.points[1].p, Vec3(2, 0, 0));
    EXPECT_EQ(a.lines.size(), 1u);
    EXPECT_EQ(a.triangles.size(), 1u);
    a.clear();
    EXPECT_TRUE(a.empty());
}

// ----------------------------------------------------------------- feature edges

TEST(FeatureEdges, GridBoundaryEdges) {
    const Mesh mesh = shapes::grid(2, 2);
    const OverlayStyle style;
    OverlayBatch out;
    add_feature_edges(mesh, style, out);
    ASSERT_EQ(out.lines.size(), 8u);
    for (const auto& l : out.lines) {
        EXPECT_EQ(l.color, style.boundary);
        EXPECT_EQ(l.width_px, style.feature_width_px);
        // Boundary edges of [0,1]² run along one of its sides.
        const bool on_side = (l.a.x == l.b.x && (l.a.x == 0.0 || l.a.x == 1.0)) ||
                             (l.a.y == l.b.y && (l.a.y == 0.0 || l.a.y == 1.0));
        EXPECT_TRUE(on_side);
    }
    EXPECT_TRUE(out.points.empty());
    EXPECT_TRUE(out.triangles.empty());
}

TEST(FeatureEdges, ClosedMeshWithoutCreasesHasNone) {
    OverlayBatch out;
    add_feature_edges(shapes::cube(), OverlayStyle{}, out);
    EXPECT_TRUE(out.empty());
}

TEST(FeatureEdges, CreasedCubeEdges) {
    Mesh mesh = shapes::cube();
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    // The 12 cube edges join corners differing in one coordinate (one index bit); the six
    // face diagonals stay smooth.
    std::size_t n_creases = 0;
    for (Edge e : mesh.edges()) {
        const auto i = mesh.vertex(e, 0).idx();
        const auto j = mesh.vertex(e, 1).idx();
        if (std::popcount(i ^ j) == 1) {
            crease[e] = 1;
            ++n_creases;
        }
    }
    ASSERT_EQ(n_creases, 12u);
    const OverlayStyle style;
    OverlayBatch out;
    add_feature_edges(mesh, style, out);
    ASSERT_EQ(out.lines.size(), 12u);
    for (const auto& l : out.lines) {
        EXPECT_EQ(l.color, style.crease);
        EXPECT_EQ(l.width_px, style.feature_width_px);
        // Axis-aligned: exactly one coordinate differs.
        int differing = 0;
        for (int k = 0; k < 3; ++k) {
            differing += l.a[k] != l.b[k] ? 1 : 0;
        }
        EXPECT_EQ(differing, 1);
    }
}

TEST(FeatureEdges, BoundaryCreaseUsesBoundaryColour) {
    Mesh mesh = shapes::grid(2, 2);
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    for (Edge e : mesh.edges()) {
        crease[e] = 1;  // every edge, boundary or not
    }
    const OverlayStyle style;
    OverlayBatch out;
    add_feature_edges(mesh, style, out);
    EXPECT_EQ(out.lines.size(), mesh.n_edges());
    EXPECT_EQ(count_lines_of(out, style.boundary), 8u);
    EXPECT_EQ(count_lines_of(out, style.crease), mesh.n_edges() - 8u);
}

TEST(FeatureEdges, ZeroCreaseValueIsSmooth) {
    Mesh mesh = shapes::cube();
    mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    OverlayBatch out;
    add_feature_edges(mesh, OverlayStyle{}, out);
    EXPECT_TRUE(out.empty());
}

TEST(FeatureEdges, DeletedEdgesAreSkipped) {
    Mesh mesh = shapes::grid(2, 2);
    const Edge boundary_edge = mesh.find_edge(Vertex(0), Vertex(1));
    ASSERT_TRUE(boundary_edge.is_valid());
    mesh.mark_deleted(boundary_edge);
    OverlayBatch out;
    add_feature_edges(mesh, OverlayStyle{}, out);
    EXPECT_EQ(out.lines.size(), 7u);
}

// ----------------------------------------------------------------- element highlights

TEST(ElementHighlight, VertexIsOnePointAtItsPosition) {
    const Mesh mesh = test::two_triangles();
    const OverlayStyle style;
    OverlayBatch out;
    add_element_highlight(mesh, ElementRef::vertex(Vertex(2)), kRed, style, out);
    ASSERT_EQ(out.points.size(), 1u);
    EXPECT_TRUE(out.lines.empty());
    EXPECT_TRUE(out.triangles.empty());
    EXPECT_EQ(out.points[0].p, mesh.position(Vertex(2)));
    EXPECT_EQ(out.points[0].color, kRed);
    EXPECT_EQ(out.points[0].size_px, style.vertex_size_px);
}

TEST(ElementHighlight, EdgeIsOneLineBetweenItsEnds) {
    const Mesh mesh = right_triangle();
    const OverlayStyle style;
    const Edge e = mesh.find_edge(Vertex(1), Vertex(2));
    ASSERT_TRUE(e.is_valid());
    OverlayBatch out;
    add_element_highlight(mesh, ElementRef::edge(e), kRed, style, out);
    ASSERT_EQ(out.lines.size(), 1u);
    EXPECT_TRUE(out.points.empty());
    EXPECT_TRUE(out.triangles.empty());
    const std::set<std::pair<double, double>> ends{{out.lines[0].a.x, out.lines[0].a.y},
                                                   {out.lines[0].b.x, out.lines[0].b.y}};
    EXPECT_EQ(ends, (std::set<std::pair<double, double>>{{3, 0}, {0, 3}}));
    EXPECT_EQ(out.lines[0].width_px, style.edge_width_px);
    EXPECT_EQ(out.lines[0].color, kRed);
}

TEST(ElementHighlight, InteriorHalfedgeArrowByHand) {
    const Mesh mesh = right_triangle();
    const OverlayStyle style;  // inset 0.2
    ASSERT_FLOAT_EQ(style.halfedge_inset, 0.2f);
    const double s = style.halfedge_inset;
    const Halfedge h = mesh.find_halfedge(Vertex(0), Vertex(1));
    ASSERT_TRUE(h.is_valid());
    ASSERT_FALSE(mesh.is_boundary(h));
    OverlayBatch out;
    add_element_highlight(mesh, ElementRef::halfedge(h), kRed, style, out);
    ASSERT_EQ(out.lines.size(), 1u);
    ASSERT_EQ(out.arrowheads.size(), 1u);
    EXPECT_TRUE(out.points.empty());

    // Shortened to 15% … 85% of (0,0)→(3,0): x = 0.45 and 2.55; then each end moves `s` of
    // the way to the centroid (1,1): x + s(1 − x), y = s.
    const auto& shaft = out.lines[0];
    EXPECT_VEC_NEAR(shaft.a, Vec3(0.45 + s * (1.0 - 0.45), s, 0));
    EXPECT_VEC_NEAR(shaft.b, Vec3(2.55 + s * (1.0 - 2.55), s, 0));
    EXPECT_NEAR(shaft.a.x, 0.56, 1e-7);  // float inset: 0.2f is not exactly 0.2
    EXPECT_NEAR(shaft.b.x, 2.24, 1e-7);
    EXPECT_EQ(shaft.color, kRed);
    EXPECT_EQ(shaft.width_px, style.edge_width_px);
    EXPECT_TRUE(strictly_inside_right_triangle(shaft.a));
    EXPECT_TRUE(strictly_inside_right_triangle(shaft.b));

    // Arrowhead: tip at the shaft's head end, its axis along the shaft (so it points along
    // the halfedge), sized in pixels by the style whatever the mesh's scale.
    const auto& head = out.arrowheads[0];
    EXPECT_EQ(head.tip, shaft.b);
    EXPECT_EQ(head.tail, shaft.a);
    EXPECT_VEC_NEAR(head.across, Vec3(0, 1, 0));  // into the face, in its plane
    EXPECT_EQ(head.color, kRed);
    EXPECT_EQ(head.length_px, style.arrowhead_length_px);
    EXPECT_EQ(head.half_width_px, style.arrowhead_half_width_px);
    EXPECT_TRUE(out.triangles.empty());
}

TEST(ElementHighlight, BoundaryHalfedgeArrowIsMirroredOutside) {
    const Mesh mesh = right_triangle();
    const OverlayStyle style;
    const double s = style.halfedge_inset;
    const Halfedge h = mesh.find_halfedge(Vertex(1), Vertex(0));
    ASSERT_TRUE(h.is_valid());
    ASSERT_TRUE(mesh.is_boundary(h));
    OverlayBatch out;
    add_element_highlight(mesh, ElementRef::halfedge(h), kRed, style, out);
    ASSERT_EQ(out.lines.size(), 1u);
    ASSERT_EQ(out.arrowheads.size(), 1u);

    // (3,0)→(0,0): shortened to x = 2.55 … 0.45, inset towards the twin's centroid (1,1)
    // mirrored across the edge, i.e. (1,−1).
    const auto& shaft = out.lines[0];
    EXPECT_VEC_NEAR(shaft.a, Vec3(2.55 + s * (1.0 - 2.55), -s, 0));
    EXPECT_VEC_NEAR(shaft.b, Vec3(0.45 + s * (1.0 - 0.45), -s, 0));
    // The head at the x = 0 end, pointing along the shaft.
    const auto& head = out.arrowheads[0];
    EXPECT_EQ(head.tip, shaft.b);
    EXPECT_EQ(head.tail, shaft.a);
}

TEST(ElementHighlight, TwinArrowsLieOnOppositeSidesOfTheEdge) {
    const Mesh mesh = test::two_triangles();
    const Halfedge h = mesh.find_halfedge(Vertex(0), Vertex(2));  // the shared diagonal
    ASSERT_TRUE(h.is_valid());
    ASSERT_FALSE(mesh.is_boundary(Mesh::edge(h)));
    const OverlayStyle style;
    OverlayBatch a;
    OverlayBatch b;
    add_element_highlight(mesh, ElementRef::halfedge(h), kRed, style, a);
    add_element_highlight(mesh, ElementRef::halfedge(Mesh::twin(h)), kRed, style, b);
    ASSERT_EQ(a.lines.size(), 1u);
    ASSERT_EQ(b.lines.size(), 1u);
    // Side of the diagonal y = x: each arrow lies in its own face, left of its halfedge.
    const Vec3 d = mesh.position(Vertex(2)) - mesh.position(Vertex(0));
    const auto side = [&](const Vec3& p) { return cross(d, p - mesh.position(Vertex(0))).z; };
    const auto& la = a.lines[0];
    const auto& lb = b.lines[0];
    EXPECT_GT(side(la.a), 0.0);
    EXPECT_GT(side(la.b), 0.0);
    EXPECT_LT(side(lb.a), 0.0);
    EXPECT_LT(side(lb.b), 0.0);
}

TEST(ElementHighlight, ArrowLiesInATiltedFacePlane) {
    const Mesh mesh =
        test::mesh_from_faces({{1, 0, 0}, {0, 2, 0}, {0, 0, 3}}, {{0, 1, 2}});  // x+y/2+z/3=1
    const Vec3 n{1.0, 0.5, 1.0 / 3.0};
    for (Halfedge h : mesh.halfedges()) {
        OverlayBatch out;
        add_element_highlight(mesh, ElementRef::halfedge(h), kRed, OverlayStyle{}, out);
        ASSERT_EQ(out.lines.size(), 1u);
        ASSERT_EQ(out.arrowheads.size(), 1u);
        const auto& head = out.arrowheads[0];
        for (const Vec3& p : {out.lines[0].a, out.lines[0].b, head.tip, head.tail}) {
            EXPECT_NEAR(dot(n, p), 1.0, 1e-12);
        }
        EXPECT_NEAR(dot(n, head.across), 0.0, 1e-12);
        EXPECT_NEAR(dot(head.tail - head.tip, head.across), 0.0, 1e-12);
        EXPECT_NEAR(norm(head.across), 1.0, 1e-12);
    }
}

TEST(ElementHighlight, QuadFaceTintIsTwoOffsetTriangles) {
    const Mesh mesh =
        test::mesh_from_faces({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}});
    const OverlayStyle style;
    OverlayBatch out;
    add_element_highlight(mesh, ElementRef::face(Face(0)), kRed, style, out);
    ASSERT_EQ(out.triangles.size(), 2u);
    EXPECT_TRUE(out.lines.empty());
    EXPECT_TRUE(out.points.empty());
    const double lift = 1e-3 * std::sqrt(5.0);  // bounding-box diagonal of [0,2]×[0,1]
    std::set<std::pair<double, double>> corners;
    for (const auto& t : out.triangles) {
        EXPECT_EQ(t.color[0], kRed[0]);
        EXPECT_EQ(t.color[1], kRed[1]);
        EXPECT_EQ(t.color[2], kRed[2]);
        EXPECT_EQ(t.color[3], style.face_tint_alpha);
        for (const Vec3& p : {t.a, t.b, t.c}) {
            EXPECT_NEAR(p.z, lift, kTol);
            corners.insert({p.x, p.y});
        }
        // Same winding as the face (+z normal).
        EXPECT_GT(cross(t.b - t.a, t.c - t.a).z, 0.0);
    }
    EXPECT_EQ(corners, (std::set<std::pair<double, double>>{{0, 0}, {2, 0}, {2, 1}, {0, 1}}));
    // The two triangles cover the quad: total area 2.
    double area = 0.0;
    for (const auto& t : out.triangles) {
        area += 0.5 * norm(cross(t.b - t.a, t.c - t.a));
    }
    EXPECT_NEAR(area, 2.0, kTol);
}

TEST(ElementHighlight, CubeFaceTintIsOffsetOutward) {
    const Mesh mesh = shapes::cube();
    OverlayBatch out;
    add_element_highlight(mesh, ElementRef::face(Face(0)), kRed, OverlayStyle{}, out);  // -x
    ASSERT_EQ(out.triangles.size(), 1u);
    const double x = -1.0 - 1e-3 * std::sqrt(12.0);
    EXPECT_NEAR(out.triangles[0].a.x, x, kTol);
    EXPECT_NEAR(out.triangles[0].b.x, x, kTol);
    EXPECT_NEAR(out.triangles[0].c.x, x, kTol);
}

// Many elements at once (a region's selection) draw what each alone draws, in order: the
// faces' tints lifted by the same diagonal, measured once.
TEST(ElementHighlight, ManyAtOnceEqualEachAlone) {
    const Mesh mesh = shapes::cube();
    const std::vector<ElementRef> refs{ElementRef::face(Face(0)), ElementRef::vertex(Vertex(3)),
                                       ElementRef::face(Face(5)), ElementRef::edge(Edge(2)),
                                       ElementRef::face(Face(7))};
    const OverlayStyle style;
    OverlayBatch alone, together;
    for (const ElementRef& e : refs) {
        add_element_highlight(mesh, e, kRed, style, alone);
    }
    add_element_highlights(mesh, refs, kRed, style, together);
    ASSERT_EQ(together.triangles.size(), alone.triangles.size());
    ASSERT_EQ(together.triangles.size(), 3u);
    for (std::size_t i = 0; i < alone.triangles.size(); ++i) {
        EXPECT_EQ(together.triangles[i].a, alone.triangles[i].a);
        EXPECT_EQ(together.triangles[i].b, alone.triangles[i].b);
        EXPECT_EQ(together.triangles[i].c, alone.triangles[i].c);
    }
    ASSERT_EQ(together.points.size(), 1u);
    EXPECT_EQ(together.points[0].p, alone.points[0].p);
    ASSERT_EQ(together.lines.size(), 1u);
    EXPECT_EQ(together.lines[0].a, alone.lines[0].a);
}

TEST(ElementHighlight, InvalidHandlesAddNothing) {
    Mesh mesh = test::two_triangles();
    const OverlayStyle style;
    const std::vector<ElementRef> refs{
        ElementRef{},
        ElementRef::vertex(Vertex()),
        ElementRef::edge(Edge()),
        ElementRef::halfedge(Halfedge()),
        ElementRef::face(Face()),
        ElementRef::vertex(Vertex(static_cast<std::uint32_t>(mesh.vertices_size()))),
        ElementRef::edge(Edge(static_cast<std::uint32_t>(mesh.edges_size()))),
        ElementRef::halfedge(Halfedge(static_cast<std::uint32_t>(mesh.halfedges_size()))),
        ElementRef::face(Face(static_cast<std::uint32_t>(mesh.faces_size()))),
        ElementRef{ElementRef::Kind::Face, 12345},
    };
    for (const ElementRef& r : refs) {
        OverlayBatch out;
        add_element_highlight(mesh, r, kRed, style, out);
        EXPECT_TRUE(out.empty()) << "kind " << static_cast<int>(r.kind) << " index " << r.index;
    }
}

TEST(ElementHighlight, DeletedElementsAddNothing) {
    Mesh mesh = test::two_triangles();
    // Tombstones only (the overlay never follows connectivity of a deleted element).
    const Edge e = mesh.find_edge(Vertex(0), Vertex(2));
    mesh.mark_deleted(e);
    mesh.mark_deleted(Face(1));
    mesh.mark_deleted(Vertex(3));
    const OverlayStyle style;
    for (const ElementRef& r : {ElementRef::edge(e), ElementRef::halfedge(Mesh::halfedge(e, 0)),
                                ElementRef::halfedge(Mesh::halfedge(e, 1)),
                                ElementRef::face(Face(1)), ElementRef::vertex(Vertex(3))}) {
        OverlayBatch out;
        add_element_highlight(mesh, r, kRed, style, out);
        EXPECT_TRUE(out.empty()) << "kind " << static_cast<int>(r.kind) << " index " << r.index;
    }
}

TEST(ElementHighlight, AppendsWithoutClearing) {
    const Mesh mesh = test::two_triangles();
    OverlayBatch out;
    add_element_highlight(mesh, ElementRef::vertex(Vertex(0)), kRed, OverlayStyle{}, out);
    add_element_highlight(mesh, ElementRef::vertex(Vertex(1)), kRed, OverlayStyle{}, out);
    EXPECT_EQ(out.points.size(), 2u);
}

// ----------------------------------------------------------------- Bezier curves

BezierCurve cubic() {
    return BezierCurve{{{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}}};
}

TEST(BezierOverlay, AllLevelsOfACubic) {
    const BezierCurve curve = cubic();
    const OverlayStyle style;
    OverlayBatch out;
    add_bezier_curve(curve, 0.5, -1, false, style, out);
    EXPECT_EQ(out.lines.size(), 3u + 2u + 1u);
    ASSERT_EQ(out.points.size(), 4u + 3u + 2u + 1u);
    EXPECT_TRUE(out.triangles.empty());

    // Each level in its own colour, lines and discs alike.
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(count_lines_of(out, style.levels[k]), 3u - k) << "level " << k;
    }
    const auto levels = curve.levels(0.5);
    std::size_t i = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        for (const Vec3& p : levels[k]) {
            EXPECT_EQ(out.points[i].p, p);
            EXPECT_EQ(out.points[i].color, style.levels[k]);
            ++i;
        }
    }
    // The last point is B(0.5), bigger than the level discs.
    const auto& eval = out.points.back();
    EXPECT_VEC_NEAR(eval.p, bernstein(curve.control_points, 0.5));
    EXPECT_VEC_NEAR(eval.p, Vec3(2.0, 1.5, 0.0));
    EXPECT_EQ(eval.color, style.evaluated_point);
    EXPECT_GT(eval.size_px, out.points.front().size_px);

    // The control polygon's lines join consecutive control points.
    EXPECT_EQ(out.lines[0].a, curve.control_points[0]);
    EXPECT_EQ(out.lines[0].b, curve.control_points[1]);
    EXPECT_EQ(out.lines[2].b, curve.control_points[3]);
}

TEST(BezierOverlay, MaxLevelLimitsTheLevels) {
    const BezierCurve curve = cubic();
    const OverlayStyle style;
    struct Case {
        int max_level;
        std::size_t lines, points;
        bool evaluated;
    };
    for (const Case& c : {Case{0, 3, 4, false}, Case{1, 5, 7, false}, Case{2, 6, 9, false},
                          Case{3, 6, 10, true}, Case{7, 6, 10, true}, Case{-1, 6, 10, true}}) {
        OverlayBatch out;
        add_bezier_curve(curve, 0.25, c.max_level, false, style, out);
        EXPECT_EQ(out.lines.size(), c.lines) << "max_level " << c.max_level;
        EXPECT_EQ(out.points.size(), c.points) << "max_level " << c.max_level;
        std::size_t n_eval = 0;
        for (const auto& p : out.points) {
            n_eval += p.color == style.evaluated_point ? 1 : 0;
        }
        EXPECT_EQ(n_eval, c.evaluated ? 1u : 0u) << "max_level " << c.max_level;
    }
}

TEST(BezierOverlay, ShowCurveAddsThePolyline) {
    const BezierCurve curve = cubic();
    const OverlayStyle style;
    OverlayBatch without;
    OverlayBatch with;
    add_bezier_curve(curve, 0.5, 0, false, style, without);
    add_bezier_curve(curve, 0.5, 0, true, style, with);
    const auto samples = curve.polyline(200);
    ASSERT_EQ(with.lines.size(), without.lines.size() + samples.size() - 1);
    EXPECT_EQ(with.points.size(), without.points.size());
    std::size_t i = 0;
    for (const auto& l : with.lines) {
        if (l.color != style.curve) {
            continue;
        }
        EXPECT_EQ(l.a, samples[i]);
        EXPECT_EQ(l.b, samples[i + 1]);
        ++i;
    }
    EXPECT_EQ(i, samples.size() - 1);
    EXPECT_EQ(with.lines.back().b, curve.control_points.back());  // the curve ends at P3
}

TEST(BezierOverlay, EverythingLiesInTheZ0Plane) {
    const BezierCurve curve{{{0, 0, 1}, {1, 1, -2}, {2, 0, 5}}};
    OverlayBatch out;
    add_bezier_curve(curve, 0.3, -1, true, OverlayStyle{}, out);
    ASSERT_FALSE(out.empty());
    for (const auto& p : out.points) {
        EXPECT_EQ(p.p.z, 0.0);
    }
    for (const auto& l : out.lines) {
        EXPECT_EQ(l.a.z, 0.0);
        EXPECT_EQ(l.b.z, 0.0);
    }
}

TEST(BezierOverlay, LevelColoursWrapAround) {
    OverlayStyle style;
    style.levels = {{1, 0, 0, 1}, {0, 1, 0, 1}};
    OverlayBatch out;
    add_bezier_curve(cubic(), 0.5, 2, false, style, out);
    EXPECT_EQ(count_lines_of(out, style.levels[0]), 3u + 1u);  // levels 0 and 2
    EXPECT_EQ(count_lines_of(out, style.levels[1]), 2u);
}

TEST(BezierOverlay, DegenerateCurves) {
    const OverlayStyle style;
    OverlayBatch out;
    add_bezier_curve(BezierCurve{}, 0.5, -1, true, style, out);
    EXPECT_TRUE(out.empty());

    // One control point: level 0 is already the last level, B(t) = P0; no curve to draw.
    add_bezier_curve(BezierCurve{{{1, 2, 0}}}, 0.5, -1, true, style, out);
    ASSERT_EQ(out.points.size(), 1u);
    EXPECT_EQ(out.points[0].p, Vec3(1, 2, 0));
    EXPECT_EQ(out.points[0].color, style.evaluated_point);
    EXPECT_TRUE(out.lines.empty());
}

// ----------------------------------------------------------------- control nets

BezierPatch grid_patch(double z) {
    BezierPatch patch;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            patch.control_points.push_back({double(c), double(r), z});
        }
    }
    return patch;
}

TEST(ControlNets, OneFourByFourPatch) {
    const std::vector<BezierPatch> patches{grid_patch(0.0)};
    const OverlayStyle style;
    OverlayBatch out;
    add_control_nets(patches, style, out);
    ASSERT_EQ(out.lines.size(), 24u);
    ASSERT_EQ(out.points.size(), 16u);
    EXPECT_TRUE(out.triangles.empty());
    // Every line joins grid neighbours, and each neighbour pair appears exactly once.
    std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> seen;
    for (const auto& l : out.lines) {
        EXPECT_EQ(l.color, style.control_net);
        EXPECT_EQ(std::abs(l.a.x - l.b.x) + std::abs(l.a.y - l.b.y), 1.0);
        auto ea = std::make_pair(l.a.x, l.a.y);
        auto eb = std::make_pair(l.b.x, l.b.y);
        if (eb < ea) {
            std::swap(ea, eb);
        }
        EXPECT_TRUE(seen.insert({ea, eb}).second);
    }
    for (std::size_t i = 0; i < 16; ++i) {
        EXPECT_EQ(out.points[i].p, patches[0].control_points[i]);
        EXPECT_EQ(out.points[i].color, style.control_net);
        EXPECT_LT(out.points[i].size_px, style.vertex_size_px);  // "small" discs
    }
}

TEST(ControlNets, SeveralPatchesAndMalformedOnes) {
    BezierPatch bad = grid_patch(1.0);
    bad.control_points.pop_back();  // 15 points for a 4 × 4 grid
    BezierPatch small;
    small.rows = 2;
    small.cols = 3;
    small.control_points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    const std::vector<BezierPatch> patches{grid_patch(0.0), bad, small, grid_patch(2.0)};
    OverlayBatch out;
    add_control_nets(patches, OverlayStyle{}, out);
    EXPECT_EQ(out.lines.size(), 24u + (2u * 2u + 3u * 1u) + 24u);
    EXPECT_EQ(out.points.size(), 16u + 6u + 16u);
}

TEST(ControlNets, NoPatchesNothing) {
    OverlayBatch out;
    add_control_nets({}, OverlayStyle{}, out);
    EXPECT_TRUE(out.empty());
}

TEST(Overlay, LoopMarksNearTheSelectionOnly) {
    // Phase 1 of a phased Loop on a sphere: a target per vertex, an edge point per edge.
    Mesh mesh = shapes::icosphere(3);
    ASSERT_TRUE(check_loop_step(mesh));
    loop_step(mesh);
    OverlayBatch all, near_batch;
    const OverlayStyle style;
    add_loop_phase_marks(mesh, style, all);
    const std::vector<std::uint8_t> near = vertices_near(mesh, ElementRef::vertex(Vertex(0)), 2);
    add_loop_phase_marks(mesh, style, near_batch, near);
    // Vertex 0 (valence 5) and two rings: 1 + 5 + 10 vertices; their targets and the edge
    // points of the edges among them.
    std::size_t chosen = 0;
    for (const std::uint8_t n : near) {
        chosen += n;
    }
    EXPECT_EQ(chosen, 16u);
    EXPECT_EQ(all.points.size(), mesh.n_vertices() + mesh.n_edges());
    EXPECT_LT(near_batch.points.size(), all.points.size() / 10);
    EXPECT_GE(near_batch.points.size(), chosen);
    // None is far from vertex 0: two rings of edges on a unit sphere of 642 vertices.
    for (const auto& p : near_batch.points) {
        EXPECT_LT(norm(p.p - mesh.position(Vertex(0))), 0.35);
    }
}

TEST(Overlay, PatchStepsAlongUThenVEndAtTheEvaluatedPoint) {
    // A 4 × 4 patch with every control point different: three steps along u, three along v.
    BezierPatch patch;
    patch.rows = patch.cols = 4;
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            patch.control_points.push_back({c * 1.0, r * 1.0, 0.1 * (r * c % 3)});
        }
    }
    const OverlayStyle style;
    OverlayBatch none, rows_done, all;
    EXPECT_EQ(add_patch_steps(patch, 0.3, 0.7, 0, style, none), 6);
    EXPECT_TRUE(none.points.empty());
    add_patch_steps(patch, 0.3, 0.7, 3, style, rows_done);
    // Each row: levels of 3, 2 and 1 points; then the curve in v's control points (level 0).
    EXPECT_EQ(rows_done.points.size(), 4u * (3 + 2 + 1) + 4u);
    add_patch_steps(patch, 0.3, 0.7, 6, style, all);
    EXPECT_EQ(all.points.size(), 4u * 6 + 4 + 3 + 2 + 1);
    // The last point is S(u, v), exactly as BezierPatch evaluates it.
    EXPECT_EQ(all.points.back().p, patch.evaluate(0.3, 0.7));
    EXPECT_EQ(all.points.back().color, style.evaluated_point);
}

// The Problems panel's marks: a load cut's vertex a dot through the surface, a hole its
// whole loop, a small part every face tinted, an inside-out part its edges (a tint would sink
// under inward faces), a dropped face (no place) nothing; each in its kind's colour.
TEST(Overlay, ProblemMarksDrawEachKindWhereItIs) {
    const Mesh grid = shapes::grid(2, 2);
    Edge border;
    for (const Edge e : grid.edges()) {
        if (grid.is_boundary(e)) {
            border = e;
        }
    }
    std::size_t border_edges = 0;
    for (const Edge e : grid.edges()) {
        border_edges += grid.is_boundary(e) ? 1 : 0;
    }
    ProblemReport report;
    report.problems = {{ProblemKind::LoadCut, ElementRef::vertex(Vertex(4)), 1, ""},
                       {ProblemKind::LoadCut, ElementRef{}, 1, "a dropped face"},
                       {ProblemKind::Hole, ElementRef::edge(border), border_edges, ""},
                       {ProblemKind::SmallPart, ElementRef::face(Face(0)), grid.n_faces(), ""}};
    const OverlayStyle style;
    OverlayBatch out;
    add_problem_marks(grid, report, style, out);
    ASSERT_EQ(out.points.size(), 1u);
    EXPECT_EQ(out.points[0].p, grid.position(Vertex(4)));
    EXPECT_EQ(out.points[0].color, style.problems[0]);
    EXPECT_TRUE(out.points[0].xray);
    ASSERT_EQ(out.lines.size(), border_edges);
    for (const OverlayBatch::Line& line : out.lines) {
        EXPECT_EQ(line.color, style.problems[1]);
        EXPECT_EQ(line.width_px, style.problem_width_px);
        EXPECT_TRUE(line.xray);
    }
    EXPECT_EQ(out.triangles.size(), grid.n_faces());  // triangles: one tint each
    for (const OverlayBatch::Triangle& t : out.triangles) {
        EXPECT_EQ(t.color[0], style.problems[4][0]);
    }

    const Mesh cube = shapes::cube();
    ProblemReport inward;
    inward.problems = {{ProblemKind::InsideOut, ElementRef::face(Face(3)), cube.n_faces(), ""}};
    OverlayBatch edges;
    add_problem_marks(cube, inward, style, edges);
    EXPECT_EQ(edges.lines.size(), cube.n_edges()) << "each edge of the part once";
    EXPECT_TRUE(edges.triangles.empty());
}

}  // namespace
}  // namespace meshedit
