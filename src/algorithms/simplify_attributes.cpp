// The attribute side of QEM simplification: see simplify_attributes.h.

#include "simplify_attributes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace meshedit::qem {
namespace {

// An attribute difference of 1 (a whole texture, a colour from black to white) weighs as a
// distance of this share of the bounding-box diagonal. Texture coordinates weigh more: a
// stretched chart shows at once in a textured render, a blurred colour less.
constexpr double kUvWeight = 1.0;
constexpr double kColorWeight = 0.5;

// Twice the signed area of a UV triangle.
double uv_area(const Vec2& a, const Vec2& b, const Vec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

double channel(const Vec2& x, int j) {
    return j == 0 ? x.x : x.y;
}
double channel(const Vec4& x, int j) {
    return j == 0 ? x.x : j == 1 ? x.y : j == 2 ? x.z : x.w;
}

// The linear field over the triangle p[0..2] taking the values v[0..2]: its gradient in the
// triangle's plane and its offset (value = g·p + d). `inv_det`, e1, e2: the triangle's edge
// frame (see gather()).
void field(const Vec3& p0, const Vec3& e1, const Vec3& e2, double a11, double a12, double a22,
           double inv_det, const double* v, Vec3& g, double& d) {
    const double d1 = v[1] - v[0], d2 = v[2] - v[0];
    const double alpha = (a22 * d1 - a12 * d2) * inv_det;
    const double beta = (a11 * d2 - a12 * d1) * inv_det;
    g = e1 * alpha + e2 * beta;
    d = v[0] - dot(g, p0);
}

}  // namespace

AttributeSimplifier::AttributeSimplifier(Mesh& mesh, double diagonal)
    : mesh_(mesh),
      uv_weight_(kUvWeight * diagonal),
      color_weight_(kColorWeight * diagonal),
      uv_(mesh.get_property<Halfedge, Vec2>(kTexCoordProperty)),
      color_(mesh.get_property<Vertex, Vec4>(kColorProperty)),
      material_(mesh.get_property<Face, std::uint32_t>(kMaterialProperty)) {}

bool AttributeSimplifier::applies(const Mesh& mesh) {
    return mesh.get_property<Halfedge, Vec2>(kTexCoordProperty) ||
           mesh.get_property<Vertex, Vec4>(kColorProperty) ||
           mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
}

void AttributeSimplifier::gather() {
    if (uv_) {
        uvq_.assign(mesh_.vertices_size(), UvQuadric{});
    }
    if (color_) {
        colorq_.assign(mesh_.vertices_size(), ColorQuadric{});
        const double inf = std::numeric_limits<double>::infinity();
        color_low_ = {inf, inf, inf, inf};
        color_high_ = {-inf, -inf, -inf, -inf};
        for (Vertex v : mesh_.vertices()) {
            const Vec4& c = color_[v];
            color_low_ = {std::min(color_low_.x, c.x), std::min(color_low_.y, c.y),
                          std::min(color_low_.z, c.z), std::min(color_low_.w, c.w)};
            color_high_ = {std::max(color_high_.x, c.x), std::max(color_high_.y, c.y),
                           std::max(color_high_.z, c.z), std::max(color_high_.w, c.w)};
        }
    }
    if (!uv_ && !color_) {
        return;
    }
    for (Face f : mesh_.faces()) {
        const Halfedge h[3] = {mesh_.halfedge(f), mesh_.next(mesh_.halfedge(f)),
                               mesh_.prev(mesh_.halfedge(f))};
        const Vertex v[3] = {mesh_.to_vertex(h[0]), mesh_.to_vertex(h[1]), mesh_.to_vertex(h[2])};
        const Vec3& p0 = mesh_.position(v[0]);
        const Vec3 e1 = mesh_.position(v[1]) - p0, e2 = mesh_.position(v[2]) - p0;
        const double a11 = dot(e1, e1), a12 = dot(e1, e2), a22 = dot(e2, e2);
        const double det = a11 * a22 - a12 * a12;  // |e1 × e2|²
        // A sliver's gradients are huge and meaningless: it carries no attribute field.
        if (!(det > 1e-12 * a11 * a22)) {
            continue;
        }
        const double area = 0.5 * std::sqrt(det), inv_det = 1.0 / det;
        // Each channel's field over the face, added to the quadric of each of its corners.
        const auto add = [&](auto& quadrics, auto value_of) {
            constexpr int N = std::remove_reference_t<decltype(quadrics[0])>::kChannels;
            Vec3 g[N];
            double d[N];
            for (int j = 0; j < N; ++j) {
                const double value[3] = {value_of(0, j), value_of(1, j), value_of(2, j)};
                field(p0, e1, e2, a11, a12, a22, inv_det, value, g[j], d[j]);
            }
            for (const Vertex u : v) {
                quadrics[u.idx()].add_face(area, g, d);
            }
        };
        if (uv_) {
            add(uvq_, [&](int i, int j) { return uv_weight_ * channel(uv_[h[i]], j); });
        }
        if (color_) {
            add(colorq_, [&](int i, int j) { return color_weight_ * channel(color_[v[i]], j); });
        }
    }
    if (uv_) {
        for (Vertex v : mesh_.vertices()) {
            if (on_seam(v)) {
                uvq_[v.idx()] = UvQuadric{};
            }
        }
    }
}

bool AttributeSimplifier::on_seam(Vertex v) const {
    for (Edge g : mesh_.edges(v)) {
        if (is_seam(g)) {
            return true;
        }
    }
    return false;
}

void AttributeSimplifier::reduce_into(Vertex a, Vertex b, Quadric& q) const {
    if (uv_) {
        UvQuadric u = uvq_[a.idx()];
        u.add(uvq_[b.idx()]);
        u.reduce_into(q);
    }
    if (color_) {
        ColorQuadric c = colorq_[a.idx()];
        c.add(colorq_[b.idx()]);
        c.reduce_into(q);
    }
}

// The halfedge of f pointing at v (f is a triangle holding v).
Halfedge AttributeSimplifier::corner(Face f, Vertex v) const {
    Halfedge h = mesh_.halfedge(f);
    while (mesh_.to_vertex(h) != v) {
        h = mesh_.next(h);
    }
    return h;
}

// Gives `value` to every corner of y = to_vertex(start) reachable from start's face without
// crossing a seam or the boundary (start's own face is the collapse's and not planned).
// False when a corner so reached was planned another value: the collapse would mix charts.
bool AttributeSimplifier::spread_run(Halfedge start, const Vec2& value, Face f0, Face f1) {
    queue_.assign(1, start);
    while (!queue_.empty()) {
        const Halfedge h = queue_.back();
        queue_.pop_back();
        // The two faces beside face(h) around y: across edge(h) and across edge(next(h)).
        const Halfedge across[2] = {mesh_.prev(mesh_.twin(h)), mesh_.twin(mesh_.next(h))};
        const Edge by[2] = {Mesh::edge(h), Mesh::edge(mesh_.next(h))};
        for (int i = 0; i < 2; ++i) {
            const Face f = mesh_.face(across[i]);
            if (!f.is_valid() || is_seam(by[i]) || f == f0 || f == f1) {
                continue;
            }
            const auto planned = std::find_if(corners_.begin(), corners_.end(),
                                              [f](const auto& c) { return c.face == f; });
            if (planned != corners_.end()) {
                if (!(planned->uv == value)) {
                    return false;
                }
                continue;
            }
            corners_.push_back({f, across[i], value});
            queue_.push_back(across[i]);
        }
    }
    return true;
}

CornerPlan AttributeSimplifier::plan(Edge e, const Vec3& p, Vertex at) {
    const Vertex a = mesh_.vertex(e, 0), b = mesh_.vertex(e, 1);
    const bool pinned = at.is_valid();
    if (color_) {
        ColorQuadric q = colorq_[a.idx()];
        q.add(colorq_[b.idx()]);
        double c[4];
        if (q.optimum(p, c)) {
            const double s = 1.0 / color_weight_;
            // Bounded: never outside the colours the input had.
            planned_color_ = {std::clamp(c[0] * s, color_low_.x, color_high_.x),
                              std::clamp(c[1] * s, color_low_.y, color_high_.y),
                              std::clamp(c[2] * s, color_low_.z, color_high_.z),
                              std::clamp(c[3] * s, color_low_.w, color_high_.w)};
        } else {
            planned_color_ = color_[pinned ? at : a];
        }
    }
    corners_.clear();
    if (!uv_) {
        return CornerPlan::Ok;
    }
    const Vertex x = pinned ? at : a, y = x == a ? b : a;
    std::optional<Vec2> best;
    if (!pinned) {
        UvQuadric q = uvq_[a.idx()];
        q.add(uvq_[b.idx()]);
        if (double s[2]; q.optimum(p, s)) {
            best = Vec2{s[0] / uv_weight_, s[1] / uv_weight_};
        }
    }
    const Face f0 = mesh_.face(e, 0), f1 = mesh_.face(e, 1);
    std::size_t around_y = 0;
    for (Halfedge h : mesh_.halfedges(y)) {
        const Face f = mesh_.face(h);
        around_y += f.is_valid() && f != f0 && f != f1;
    }
    for (Halfedge h : mesh_.halfedges(x)) {
        const Face f = mesh_.face(h);
        if (f.is_valid() && f != f0 && f != f1) {
            corners_.push_back({f, mesh_.prev(h), best ? *best : uv_[mesh_.prev(h)]});
        }
    }
    // Around y, the run of corners holding f0 takes x's corner in f0, the run holding f1
    // x's corner in f1: each side of a seam keeps its own chart.
    const std::size_t from_x = corners_.size();
    for (const Face f : {f0, f1}) {
        if (f.is_valid() && !spread_run(corner(f, y), best ? *best : uv_[corner(f, x)], f0, f1)) {
            return CornerPlan::Seam;
        }
    }
    if (corners_.size() - from_x != around_y) {
        return CornerPlan::Seam;  // y has a chart beside neither face: a corner of charts
    }
    for (const PlannedCorner& c : corners_) {
        const Vec2& u1 = uv_[mesh_.next(c.corner)];
        const Vec2& u2 = uv_[mesh_.prev(c.corner)];
        const double before = uv_area(uv_[c.corner], u1, u2);
        const double after = uv_area(c.uv, u1, u2);
        if (before != 0.0 && !(before > 0.0 ? after > 0.0 : after < 0.0)) {
            return CornerPlan::UvFlip;
        }
    }
    return CornerPlan::Ok;
}

void AttributeSimplifier::apply(Vertex a, Vertex b, Vertex s) {
    if (color_) {
        ColorQuadric q = colorq_[a.idx()];
        q.add(colorq_[b.idx()]);
        colorq_[s.idx()] = q;
        mesh_.touch(s);
        color_[s] = planned_color_;
    }
    if (!uv_) {
        return;
    }
    UvQuadric q = uvq_[a.idx()];
    q.add(uvq_[b.idx()]);
    uvq_[s.idx()] = q;
    // The faces keep their indices through collapse(); the halfedge at a corner may not.
    for (Halfedge h : mesh_.halfedges(s)) {
        const Face f = mesh_.face(h);
        if (!f.is_valid()) {
            continue;
        }
        const auto planned = std::find_if(corners_.begin(), corners_.end(),
                                          [f](const auto& c) { return c.face == f; });
        if (planned != corners_.end()) {
            const Halfedge at_s = mesh_.prev(h);
            mesh_.touch(at_s);
            uv_[at_s] = planned->uv;
        }
    }
    if (on_seam(s)) {
        uvq_[s.idx()] = UvQuadric{};
    }
}

}  // namespace meshedit::qem
