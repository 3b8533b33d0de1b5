// Attribute-aware QEM (docs/simplify.md, "Attributes"): on meshes with UV seams, colours and
// material borders, simplification to 10% turns no UV triangle over, keeps every seam
// between the charts it separated, keeps colours within the input's range and material
// borders on their lines; blind simplification is today's, bit for bit.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/simplify.h"
#include "meshedit/core/validate.h"
#include "meshedit/io/io.h"
#include "support/textured_torus.h"

namespace meshedit {
namespace {

// Each helper reads the texture coordinate set `set` (kTexCoordSets).
double uv_area(const Mesh& mesh, Face f, const char* set = kTexCoordProperty) {
    const auto uv = mesh.get_property<Halfedge, Vec2>(set);
    const Halfedge h = mesh.halfedge(f);
    const Vec2 a = uv[h], b = uv[mesh.next(h)], c = uv[mesh.prev(h)];
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool corners_differ(const Mesh& mesh, Edge e, const char* set = kTexCoordProperty) {
    const auto uv = mesh.get_property<Halfedge, Vec2>(set);
    const Halfedge h = mesh.halfedge(e, 0), t = mesh.halfedge(e, 1);
    return !(uv[h] == uv[mesh.prev(t)]) || !(uv[mesh.prev(h)] == uv[t]);
}

// Each face's chart: faces joined across edges whose corners agree at both ends.
std::vector<int> charts(const Mesh& mesh, const char* set = kTexCoordProperty) {
    std::vector<int> chart(mesh.faces_size(), -1);
    int next = 0;
    for (Face start : mesh.faces()) {
        if (chart[start.idx()] >= 0) {
            continue;
        }
        std::vector<Face> stack{start};
        chart[start.idx()] = next;
        while (!stack.empty()) {
            const Face f = stack.back();
            stack.pop_back();
            for (Halfedge h : mesh.halfedges(f)) {
                const Face g = mesh.face(mesh.twin(h));
                if (g.is_valid() && chart[g.idx()] < 0 &&
                    !corners_differ(mesh, Mesh::edge(h), set)) {
                    chart[g.idx()] = next;
                    stack.push_back(g);
                }
            }
        }
        ++next;
    }
    return chart;
}

struct Breaks {
    std::size_t flipped = 0;    // faces whose UV area changed sign
    std::size_t mixed = 0;      // edges between two charts that are no longer seams
    std::size_t off_range = 0;  // colours outside the input's range
};

// What `after` (simplified from `before`; faces keep their indices) broke.
Breaks breaks(const Mesh& before, const Mesh& after, const char* set = kTexCoordProperty) {
    Breaks b;
    if (before.get_property<Halfedge, Vec2>(set)) {
        const std::vector<int> chart = charts(before, set);
        for (Face f : after.faces()) {
            const double was = uv_area(before, f, set), now = uv_area(after, f, set);
            // Turned over beyond rounding (a sliver may come out at ±1e-19).
            b.flipped += was * now < 0.0 && std::abs(now) > 1e-9 * std::abs(was);
        }
        for (Edge e : after.edges()) {
            if (!after.is_boundary(e) &&
                chart[after.face(e, 0).idx()] != chart[after.face(e, 1).idx()]) {
                b.mixed += !corners_differ(after, e, set);
            }
        }
    }
    if (const auto in = before.get_property<Vertex, Vec4>(kColorProperty)) {
        const auto out = after.get_property<Vertex, Vec4>(kColorProperty);
        Vec4 low{1e9, 1e9, 1e9, 1e9}, high{-1e9, -1e9, -1e9, -1e9};
        for (Vertex v : before.vertices()) {
            const Vec4& c = in[v];
            low = {std::min(low.x, c.x), std::min(low.y, c.y), std::min(low.z, c.z),
                   std::min(low.w, c.w)};
            high = {std::max(high.x, c.x), std::max(high.y, c.y), std::max(high.z, c.z),
                    std::max(high.w, c.w)};
        }
        for (Vertex v : after.vertices()) {
            const Vec4& c = out[v];
            b.off_range += c.x < low.x || c.y < low.y || c.z < low.z || c.w < low.w ||
                           c.x > high.x || c.y > high.y || c.z > high.z || c.w > high.w;
        }
    }
    return b;
}

// The mean distance, in UV, from each corner's value to the angles of its vertex's place
// (the torus's texture as test::uv_torus() maps it), modulo the wrap.
double uv_slide(const Mesh& mesh) {
    const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    double sum = 0;
    std::size_t n = 0;
    const auto wrapped = [](double d) { return std::abs(d - std::round(d)); };
    for (Halfedge h : mesh.halfedges()) {
        if (!mesh.face(h).is_valid()) {
            continue;
        }
        const Vec3& p = mesh.position(mesh.to_vertex(h));
        const double u = std::atan2(p.y, p.x) / (2 * std::numbers::pi);
        const double v = std::atan2(p.z, std::hypot(p.x, p.y) - 1.0) / (2 * std::numbers::pi);
        sum += std::hypot(wrapped(uv[h].x - u), wrapped(uv[h].y - v));
        ++n;
    }
    return sum / static_cast<double>(n);
}

Mesh simplified(const Mesh& mesh, double share, SimplifyAttributes mode,
                SimplifyReport* report = nullptr) {
    Mesh out = mesh;
    SimplifyOptions options;
    options.target_faces = static_cast<std::size_t>(share * static_cast<double>(mesh.n_faces()));
    options.attributes = mode;
    EXPECT_TRUE(check_simplify(out, options));
    const SimplifyReport r = simplify(out, options);
    EXPECT_FALSE(validate(out));
    if (report != nullptr) {
        *report = r;
    }
    return out;
}

TEST(SimplifyAttributes, TorusSeamsHoldAndNoUvTriangleTurns) {
    Mesh torus = test::uv_torus(60, 30);  // 3,600 triangles, seams along two loops
    test::add_colors(torus);
    ASSERT_GT(std::count_if(torus.edges().begin(), torus.edges().end(),
                            [&](Edge e) { return corners_differ(torus, e); }),
              0);
    SimplifyReport report;
    const Mesh aware = simplified(torus, 0.1, SimplifyAttributes::Aware, &report);
    EXPECT_LE(aware.n_faces(), 400u);
    const Breaks b = breaks(torus, aware);
    EXPECT_EQ(b.flipped, 0u);
    EXPECT_EQ(b.mixed, 0u);
    EXPECT_EQ(b.off_range, 0u);
    // The seams are loops still: every seam vertex has exactly two seam edges.
    for (Vertex v : aware.vertices()) {
        int seams = 0;
        for (Edge e : aware.edges(v)) {
            seams += corners_differ(aware, e);
        }
        EXPECT_TRUE(seams == 0 || seams == 2 || seams == 4) << "vertex " << v.idx();
    }
    // Blind keeps the seams too (collapse() carries each face's corners) but leaves the
    // corners where the vertices were: the texture slides over the surface.
    const Mesh blind = simplified(torus, 0.1, SimplifyAttributes::Blind);
    const double aware_error = uv_slide(aware), blind_error = uv_slide(blind);
    EXPECT_LT(aware_error, 0.5 * blind_error) << aware_error << " vs " << blind_error;
}

// UV = an affine function of position on a flat grid: the aware result keeps it exactly
// (each new corner at the quadric's best value, not a copy of an end's); in the second set
// too, another affine function, alone and beside the first.
TEST(SimplifyAttributes, AffineUvStaysAffine) {
    const auto affine0 = [](const Vec3& p) {
        return Vec2{0.3 * p.x + 0.1 * p.y + 0.2, -0.2 * p.x + 0.5 * p.y};
    };
    const auto affine1 = [](const Vec3& p) {
        return Vec2{-0.7 * p.y + 3.0, 0.4 * p.x + 0.05 * p.y};
    };
    for (const bool first_set : {true, false}) {
        SCOPED_TRACE(first_set ? "both sets" : "the second set alone");
        Mesh grid = shapes::grid(30, 30);
        auto uv0 = first_set ? grid.add_property<Halfedge, Vec2>(kTexCoordProperty)
                             : HalfedgeProperty<Vec2>();
        auto uv1 = grid.add_property<Halfedge, Vec2>(kTexCoord1Property);
        for (Halfedge h : grid.halfedges()) {
            if (grid.face(h).is_valid()) {
                if (uv0) {
                    uv0[h] = affine0(grid.position(grid.to_vertex(h)));
                }
                uv1[h] = affine1(grid.position(grid.to_vertex(h)));
            }
        }
        const Mesh out = simplified(grid, 0.1, SimplifyAttributes::Aware);
        EXPECT_LE(out.n_faces(), grid.n_faces() / 10 + 1);
        for (const auto& [set, affine] :
             {std::pair<const char*, Vec2 (*)(const Vec3&)>{kTexCoordProperty, +affine0},
              std::pair<const char*, Vec2 (*)(const Vec3&)>{kTexCoord1Property, +affine1}}) {
            const auto out_uv = out.get_property<Halfedge, Vec2>(set);
            if (!out_uv) {
                EXPECT_FALSE(first_set && set == kTexCoordProperty);
                continue;
            }
            double worst = 0;
            for (Halfedge h : out.halfedges()) {
                if (out.face(h).is_valid()) {
                    const Vec2 want = affine(out.position(out.to_vertex(h)));
                    worst = std::max(
                        {worst, std::abs(out_uv[h].x - want.x), std::abs(out_uv[h].y - want.y)});
                }
            }
            EXPECT_LT(worst, 1e-9) << set;
        }
    }
}

// A second set whose seams lie elsewhere (the torus's angles less 0.31 of a turn): the
// aware result turns no triangle over and mixes no charts in either set, and both sets' seams
// stay loops.
TEST(SimplifyAttributes, SecondSetSeamsHoldLikeTheFirst) {
    Mesh torus = test::uv_torus(60, 30);
    test::add_angle_uvs(torus, kTexCoord1Property, 0.31);  // no vertex on its seams
    const Mesh aware = simplified(torus, 0.1, SimplifyAttributes::Aware);
    EXPECT_LE(aware.n_faces(), 400u);
    for (const char* set : kTexCoordSets) {
        SCOPED_TRACE(set);
        ASSERT_GT(std::count_if(torus.edges().begin(), torus.edges().end(),
                                [&](Edge e) { return corners_differ(torus, e, set); }),
                  0);
        const Breaks b = breaks(torus, aware, set);
        EXPECT_EQ(b.flipped, 0u);
        EXPECT_EQ(b.mixed, 0u);
        for (Vertex v : aware.vertices()) {
            int seams = 0;
            for (Edge e : aware.edges(v)) {
                seams += corners_differ(aware, e, set);
            }
            EXPECT_TRUE(seams == 0 || seams == 2 || seams == 4) << "vertex " << v.idx();
        }
    }
}

// Material borders are held as seams (no collapse across one) and by the boundary's penalty
// planes: every vertex between two materials afterwards lies near the border line it had.
double segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return distance(p, a + ab * t);
}

TEST(SimplifyAttributes, MaterialBordersStay) {
    Mesh torus = shapes::torus(60, 30);
    auto material = torus.add_property<Face, std::uint32_t>(kMaterialProperty);
    for (Face f : torus.faces()) {
        Vec3 c;
        for (Vertex v : torus.vertices(f)) {
            c = c + torus.position(v);
        }
        material[f] = c.x + 0.3 * c.y > 0 ? 1 : 0;
    }
    const auto border_edges = [](const Mesh& mesh) {
        const auto m = mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
        std::vector<Edge> out;
        for (Edge e : mesh.edges()) {
            if (m[mesh.face(e, 0)] != m[mesh.face(e, 1)]) {
                out.push_back(e);
            }
        }
        return out;
    };
    const std::vector<Edge> border = border_edges(torus);
    ASSERT_GT(border.size(), 20u);
    // How far the vertices between two materials lie from the input's border line.
    const auto drift = [&](const Mesh& out) {
        double farthest = 0;
        for (Edge e : border_edges(out)) {
            for (const Vertex v : {out.vertex(e, 0), out.vertex(e, 1)}) {
                double nearest = 1e9;
                for (Edge g : border) {
                    nearest =
                        std::min(nearest, segment_distance(out.position(v),
                                                           torus.position(torus.vertex(g, 0)),
                                                           torus.position(torus.vertex(g, 1))));
                }
                farthest = std::max(farthest, nearest);
            }
        }
        return farthest;
    };
    const Mesh aware = simplified(torus, 0.1, SimplifyAttributes::Aware);
    EXPECT_LE(aware.n_faces(), 400u);
    const double held = drift(aware);
    const double free = drift(simplified(torus, 0.1, SimplifyAttributes::Blind));
    // The border's penalty planes hold it as a mesh boundary is held (within 0.5% of the
    // torus's size of 2.8 here; the chords of a curved line); blind lets it wander.
    EXPECT_LT(held, 0.015);
    EXPECT_LT(held, 0.3 * free) << held << " vs " << free;
}

// Blind, and aware on a mesh without attributes, are the simplification of before this
// option, bit for bit: the same positions and faces (the FNV-1a hash of the output of the
// algorithm before attribute-aware QEM existed) whatever attributes ride along.
std::uint64_t geometry_hash(const Mesh& mesh) {
    std::uint64_t h = 1469598103934665603ull;
    const auto add = [&h](const void* data, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            h = (h ^ static_cast<const unsigned char*>(data)[i]) * 1099511628211ull;
        }
    };
    for (Vertex v : mesh.vertices()) {
        add(&mesh.position(v), sizeof(Vec3));
    }
    for (Face f : mesh.faces()) {
        for (Vertex v : mesh.vertices(f)) {
            const std::uint32_t i = v.idx();
            add(&i, sizeof i);
        }
    }
    return h;
}

// shapes::torus(60, 30) to 360 faces before this option existed (the CLI's outputs of both
// builds compared byte for byte on the same torus, docs/simplify.md).
constexpr std::uint64_t kTodaysTorusHash = 10939729130916594005ull;

TEST(SimplifyAttributes, BlindIsTodaysOutput) {
    const Mesh plain = shapes::torus(60, 30);
    const std::uint64_t today = geometry_hash(simplified(plain, 0.1, SimplifyAttributes::Aware));
    EXPECT_EQ(today, geometry_hash(simplified(plain, 0.1, SimplifyAttributes::Blind)));
    EXPECT_EQ(today, kTodaysTorusHash);
    Mesh textured = test::uv_torus(60, 30);
    test::add_colors(textured);
    EXPECT_EQ(today, geometry_hash(simplified(textured, 0.1, SimplifyAttributes::Blind)));
    EXPECT_NE(today, geometry_hash(simplified(textured, 0.1, SimplifyAttributes::Aware)));
}

// The real duck (COLLADA, one texture, seams): no UV triangle turned, no chart mixed.
TEST(SimplifyAttributes, RealDuck) {
    const std::filesystem::path file = "/usr/share/assimp/models/Collada/duck.dae";
    if (!std::filesystem::exists(file)) {
        GTEST_SKIP() << file << " missing (assimp-testmodels)";
    }
    Mesh duck = read_mesh(file).mesh;
    if (!duck.is_triangle_mesh()) {
        triangulate(duck);
    }
    ASSERT_TRUE(static_cast<bool>(duck.get_property<Halfedge, Vec2>(kTexCoordProperty)));
    for (const double share : {0.1, 0.02}) {
        SimplifyReport report;
        const Mesh out = simplified(duck, share, SimplifyAttributes::Aware, &report);
        const Breaks b = breaks(duck, out);
        EXPECT_EQ(b.flipped, 0u) << share;
        EXPECT_EQ(b.mixed, 0u) << share;
        EXPECT_LE(out.n_faces(),
                  static_cast<std::size_t>(1.5 * share * static_cast<double>(duck.n_faces())))
            << share;
    }
}

}  // namespace
}  // namespace meshedit
