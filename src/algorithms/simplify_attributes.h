#pragma once
// Private to meshedit_algorithms: the attribute side of QEM simplification
// (SimplifyAttributes::Aware, docs/simplify.md "Attributes"). Hoppe's memory-efficient
// attribute quadrics (1999) for texture coordinates (each set of kTexCoordSets, with a quadric
// of its own) and vertex colours, seams found from the corners (a seam of either set is a
// seam), and the corner values a collapse leaves (every set by the same plan).
//
// Each face adds, per attribute channel j, the squared difference between the value s_j at
// the survivor and the face's own linear field f_j(p) = g_j·p + d_j, weighted by its area.
// Summed, per vertex and group (UV, colour):
//
//     E(p, s) = pᵀMp + 2m·p + k + Σ_j (W s_j² − 2 s_j (G_j·p + D_j))
//
// whose best s_j for a p is (G_j·p + D_j) / W, leaving a 3 × 3 quadric in p alone that adds
// to the position quadric. A seam vertex (on a UV seam or a material border) keeps no UV
// group: its corners belong to charts whose fields do not agree, and it never moves off its
// place (the crease rule of simplify.cpp pins it).

#include <array>
#include <cstdint>
#include <iterator>
#include <optional>
#include <vector>

#include "meshedit/core/attribute_summary.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/memory.h"
#include "meshedit/core/mesh.h"
#include "simplify_quadric.h"

namespace meshedit::qem {

/// The attribute quadric of N channels (2: UV, 4: RGBA).
template <int N>
struct AttributeQuadric {
    static constexpr int kChannels = N;
    double m00 = 0, m01 = 0, m02 = 0, m11 = 0, m12 = 0, m22 = 0;
    Vec3 m;
    double k = 0, w = 0;
    Vec3 g[N];
    double d[N] = {};

    void add(const AttributeQuadric& o) {
        m00 += o.m00, m01 += o.m01, m02 += o.m02, m11 += o.m11, m12 += o.m12, m22 += o.m22;
        m = m + o.m, k += o.k, w += o.w;
        for (int j = 0; j < N; ++j) {
            g[j] = g[j] + o.g[j], d[j] += o.d[j];
        }
    }
    // One face of area `area` whose channel j is the field grad[j]·p + offset[j].
    void add_face(double area, const Vec3* grad, const double* offset) {
        for (int j = 0; j < N; ++j) {
            const Vec3& q = grad[j];
            m00 += area * q.x * q.x, m01 += area * q.x * q.y, m02 += area * q.x * q.z;
            m11 += area * q.y * q.y, m12 += area * q.y * q.z, m22 += area * q.z * q.z;
            m = m + q * (area * offset[j]);
            k += area * offset[j] * offset[j];
            g[j] = g[j] + q * area;
            d[j] += area * offset[j];
        }
        w += area;
    }
    // Adds min over s of the E(p, s) of x + y to q as a quadric in p, for the first
    // `channels` channels (the others hold nothing: constant over the mesh).
    static void reduce_into(const AttributeQuadric& x, const AttributeQuadric& y, Quadric& q,
                            int channels = N) {
        const double w = x.w + y.w;
        if (!(w > 0.0)) {
            return;
        }
        const double inv = 1.0 / w;
        double r00 = x.m00 + y.m00, r01 = x.m01 + y.m01, r02 = x.m02 + y.m02;
        double r11 = x.m11 + y.m11, r12 = x.m12 + y.m12, r22 = x.m22 + y.m22;
        Vec3 b = x.m + y.m;
        double c = x.k + y.k;
        for (int j = 0; j < channels; ++j) {
            const Vec3 G = x.g[j] + y.g[j];
            const double D = x.d[j] + y.d[j];
            r00 -= G.x * G.x * inv, r01 -= G.x * G.y * inv, r02 -= G.x * G.z * inv;
            r11 -= G.y * G.y * inv, r12 -= G.y * G.z * inv, r22 -= G.z * G.z * inv;
            b = b - G * (D * inv);
            c -= D * D * inv;
        }
        q.a00 += r00, q.a01 += r01, q.a02 += r02, q.a11 += r11, q.a12 += r12, q.a22 += r22;
        q.a03 += b.x, q.a13 += b.y, q.a23 += b.z, q.a33 += c;
    }
    // Adds E(p, s) for the fixed values s to q as a quadric in p.
    void fix_into(Quadric& q, const double* s) const {
        q.a00 += m00, q.a01 += m01, q.a02 += m02, q.a11 += m11, q.a12 += m12, q.a22 += m22;
        Vec3 b = m;
        double c = k;
        for (int j = 0; j < N; ++j) {
            b = b - g[j] * s[j];
            c += w * s[j] * s[j] - 2.0 * s[j] * d[j];
        }
        q.a03 += b.x, q.a13 += b.y, q.a23 += b.z, q.a33 += c;
    }
    // The best value of channel j at p (false without faces).
    bool optimum(const Vec3& p, double* out) const {
        if (!(w > 0.0)) {
            return false;
        }
        for (int j = 0; j < N; ++j) {
            out[j] = (dot(g[j], p) + d[j]) / w;
        }
        return true;
    }
};

using UvQuadric = AttributeQuadric<2>;
using ColorQuadric = AttributeQuadric<4>;

/// What a planned collapse does to the attributes, or why it cannot.
enum class CornerPlan : std::uint8_t { Ok, Seam, UvFlip };

class AttributeSimplifier {
public:
    /// `diagonal`: the (scaled) mesh's bounding-box diagonal; attributes weigh relative to it.
    AttributeSimplifier(Mesh& mesh, double diagonal);

    /// Whether the mesh has anything for the aware path: texture coordinates, vertex colours
    /// or more than one material.
    static bool applies(const Mesh& mesh);
    /// Before the first collapse: the quadrics and the colours' range. A seam vertex's
    /// texture error goes into its `position` quadric (its corners stay as they are).
    void gather(memory::Array<Quadric>& position);

    /// An interior edge whose faces give either end different texture coordinates, or whose
    /// faces have different materials.
    bool is_seam(Edge e) const {
        if (is_material_border(e)) {
            return true;
        }
        for (const HalfedgeProperty<Vec2>& uv : uv_) {
            if (uv && is_uv_seam(mesh_, e, uv)) {
                return true;
            }
        }
        return false;
    }
    /// An interior edge between faces of two materials.
    bool is_material_border(Edge e) const {
        return material_ && meshedit::is_material_border(mesh_, e, material_);
    }

    /// Adds the attribute quadrics of a and b, each at its best values, to q.
    void reduce_into(Vertex a, Vertex b, Quadric& q) const;

    /// Works out the corners and colour the collapse of e leaves with the survivor at p
    /// (`at`: the end a crease pins it to, if any). Without a seam at either end, every
    /// corner takes the UV quadric's best value (or an end's, or their mean: the first that
    /// turns nothing over). Along a seam, each side's two corners are interpolated where p
    /// projects onto the edge. Else one end (the seam end) keeps its corners and each run of
    /// the other's corners takes the kept corner on its side. Refuses a collapse that would
    /// mix two charts at one corner (Seam) or turn a UV triangle over (UvFlip). Call before
    /// collapse().
    CornerPlan plan(Edge e, const Vec3& p, Vertex at);
    /// After collapse() made `s` of a and b: writes the planned values and the merged
    /// quadrics (`position`: s's, which takes a new seam vertex's texture error).
    void apply(Vertex a, Vertex b, Vertex s, Quadric& position);

    /// Bytes per vertex it holds (for the simplifier's budget).
    static double bytes_per_vertex() { return kSets * sizeof(UvQuadric) + sizeof(ColorQuadric); }

private:
    static constexpr std::size_t kSets = std::size(kTexCoordSets);
    using Uvs = std::array<Vec2, kSets>;  // a corner's value in each set (absent sets: 0)

    bool any_uv() const { return uv_[0] || uv_[1]; }
    bool on_seam(Vertex v) const;
    Halfedge corner(Face f, Vertex v) const;
    Uvs uvs(Halfedge h) const;
    CornerPlan plan_free(Vertex a, Vertex b, Face f0, Face f1, const Vec3& p);
    CornerPlan plan_along(Vertex a, Vertex b, Face f0, Face f1, double t);
    CornerPlan plan_kept(Vertex x, Vertex y, Face f0, Face f1);
    std::size_t faces_beside(Vertex v, Face f0, Face f1) const;
    bool turns_over() const;
    bool turns_over(std::size_t set) const;
    bool spread_run(Halfedge start, const Uvs& value, Face f0, Face f1);

    Mesh& mesh_;
    double uv_scale_, color_weight_;
    std::array<double, kSets> uv_weight_;
    std::array<HalfedgeProperty<Vec2>, kSets> uv_;  // per set of kTexCoordSets, if the mesh has it
    VertexProperty<Vec4> color_;
    FaceProperty<std::uint32_t> material_;
    std::array<memory::Array<UvQuadric>, kSets> uvq_;
    memory::Array<ColorQuadric> colorq_;
    Vec4 color_low_, color_high_;
    int color_channels_ = 4;  // the last non-constant colour channel + 1 (alpha often is)
    // The plan: each face around the edge's ends but its own two, its corner there and the
    // value it gets; and the survivor's colour.
    struct PlannedCorner {
        Face face;
        Halfedge corner;  ///< before the collapse
        Uvs uv;
    };
    std::vector<std::uint8_t> seam_;  // per vertex: on a seam (kept up to date by apply())
    bool planned_free_ = false;       // the plan had no seam at either end
    std::vector<PlannedCorner> corners_;
    std::vector<Halfedge> queue_;
    Vec4 planned_color_;
    Uvs kept_uv_;  // plan_kept(): the value the other end's faces took
};

}  // namespace meshedit::qem
