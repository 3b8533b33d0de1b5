// The attribute side of QEM simplification: see simplify_attributes.h.

#include "simplify_attributes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "meshedit/core/normals.h"

namespace meshedit::qem {
namespace {

// A UV difference weighs as this share of the surface distance it spans (gather()), a colour
// difference of 1 (black to white) as this share of the bounding-box diagonal. At 0.1 the
// textured renders of docs/simplify.md were best: above, the texture's pull costs more shape
// than it saves (the duck's 10% render lost 1.6 dB at 0.3, 4 dB at 1); below, it stretches.
constexpr double kUvWeight = 0.1;
constexpr double kColorWeight = 0.5;

Vec2 operator-(const Vec2& a, const Vec2& b) {
    return {a.x - b.x, a.y - b.y};
}
double norm2(const Vec2& a) {
    return a.x * a.x + a.y * a.y;
}

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
      uv_scale_(kUvWeight),
      color_weight_(kColorWeight * diagonal),
      color_(mesh.get_property<Vertex, Vec4>(kColorProperty)),
      material_(mesh.get_property<Face, std::uint32_t>(kMaterialProperty)) {
    for (std::size_t k = 0; k < kSets; ++k) {
        uv_weight_[k] = uv_scale_ * diagonal;
        uv_[k] = mesh.get_property<Halfedge, Vec2>(kTexCoordSets[k]);
    }
}

bool AttributeSimplifier::applies(const Mesh& mesh) {
    return mesh.get_property<Halfedge, Vec2>(kTexCoordProperty) ||
           mesh.get_property<Halfedge, Vec2>(kTexCoord1Property) ||
           mesh.get_property<Vertex, Vec4>(kColorProperty) ||
           mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
}

AttributeSimplifier::Uvs AttributeSimplifier::uvs(Halfedge h) const {
    Uvs out{};
    for (std::size_t k = 0; k < kSets; ++k) {
        out[k] = uv_[k] ? uv_[k][h] : Vec2{};
    }
    return out;
}

void AttributeSimplifier::gather(memory::Array<Quadric>& position) {
    for (std::size_t k = 0; k < kSets; ++k) {
        if (uv_[k]) {
            uvq_[k].assign(mesh_.vertices_size(), UvQuadric{});
        }
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
        // A channel constant over the mesh adds nothing (its value comes back by the clamp to
        // the input's range): the quadrics leave it out, and the last ones are not reduced.
        color_channels_ = 0;
        for (int j = 0; j < 4; ++j) {
            if (channel(color_low_, j) != channel(color_high_, j)) {
                color_channels_ = j + 1;
            }
        }
    }
    if (!any_uv() && !color_) {
        return;
    }
    seam_.assign(mesh_.vertices_size(), 0);
    if (any_uv()) {
        for (Vertex v : mesh_.vertices()) {
            seam_[v.idx()] = on_seam(v);
        }
    }
    for (std::size_t k = 0; k < kSets; ++k) {
        if (!uv_[k]) {
            continue;
        }
        // A UV difference weighs as the distance it spans on the surface (the root of the
        // ratio of the surface's area to the texture's): scale-free, and the same for a
        // small textured part in a large scene. Each set by its own texture's area.
        const HalfedgeProperty<Vec2>& uv = uv_[k];
        double surface = 0.0, texture = 0.0;
        for (Face f : mesh_.faces()) {
            const Halfedge h = mesh_.halfedge(f);
            surface += norm(face_area_vector(mesh_, f));
            texture += std::abs(uv_area(uv[h], uv[mesh_.next(h)], uv[mesh_.prev(h)]));
        }
        if (surface > 0.0 && texture > 0.0) {
            uv_weight_[k] = uv_scale_ * std::sqrt(surface / texture);
        }
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
        // Each channel's field over the face (value = g·p + d).
        const auto fields = [&](Vec3* g, double* d, int n, auto value_of) {
            for (int j = 0; j < n; ++j) {
                const double value[3] = {value_of(0, j), value_of(1, j), value_of(2, j)};
                field(p0, e1, e2, a11, a12, a22, inv_det, value, g[j], d[j]);
            }
        };
        for (std::size_t k = 0; k < kSets; ++k) {
            if (!uv_[k]) {
                continue;
            }
            const HalfedgeProperty<Vec2>& uv = uv_[k];
            const double weight = uv_weight_[k];
            Vec3 g[2];
            double d[2];
            fields(g, d, 2, [&](int i, int j) { return weight * channel(uv[h[i]], j); });
            for (int i = 0; i < 3; ++i) {
                if (seam_[v[i].idx()] == 0) {
                    uvq_[k][v[i].idx()].add_face(area, g, d);
                    continue;
                }
                // A seam vertex keeps its corners: moving it slides the texture, by the
                // field's change from its place (g·p + d − its corner's value).
                for (int j = 0; j < 2; ++j) {
                    position[v[i].idx()].add_plane(g[j], d[j] - weight * channel(uv[h[i]], j),
                                                   area);
                }
            }
        }
        if (color_) {
            Vec3 g[4];
            double d[4];
            fields(g, d, 4, [&](int i, int j) {
                return channel(color_low_, j) == channel(color_high_, j)
                           ? 0.0
                           : color_weight_ * channel(color_[v[i]], j);
            });
            for (const Vertex u : v) {
                colorq_[u.idx()].add_face(area, g, d);
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
    for (std::size_t k = 0; k < kSets; ++k) {
        if (uv_[k]) {
            UvQuadric::reduce_into(uvq_[k][a.idx()], uvq_[k][b.idx()], q);
        }
    }
    if (color_) {
        ColorQuadric::reduce_into(colorq_[a.idx()], colorq_[b.idx()], q, color_channels_);
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
bool AttributeSimplifier::spread_run(Halfedge start, const Uvs& value, Face f0, Face f1) {
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
                for (std::size_t k = 0; k < kSets; ++k) {
                    if (!(planned->uv[k] == value[k])) {
                        return false;
                    }
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
            planned_color_ = color_[at.is_valid() ? at : a];
        }
    }
    if (!any_uv()) {
        return CornerPlan::Ok;
    }
    const Face f0 = mesh_.face(e, 0), f1 = mesh_.face(e, 1);
    const bool seam_a = seam_[a.idx()] != 0, seam_b = seam_[b.idx()] != 0;
    planned_free_ = !seam_a && !seam_b;
    if (planned_free_) {
        return plan_free(a, b, f0, f1, p);
    }
    CornerPlan why = CornerPlan::Seam;
    if (is_seam(e)) {
        // Along a seam, both ends on it: each side's corners take that side's two corners
        // interpolated where p projects onto the edge.
        const Vec3& pa = mesh_.position(a);
        const Vec3 ab = mesh_.position(b) - pa;
        const double length2 = dot(ab, ab);
        const double t = length2 > 0.0 ? std::clamp(dot(p - pa, ab) / length2, 0.0, 1.0) : 0.0;
        if ((why = plan_along(a, b, f0, f1, t)) == CornerPlan::Ok) {
            return why;
        }
    }
    // One end keeps its corners (the seam end, or either): around the other, the run of
    // corners holding f0 takes the kept end's corner in f0, the run holding f1 its corner in
    // f1; a chart the kept end does not share refuses.
    for (const Vertex x : {a, b}) {
        const bool may_keep = at.is_valid() ? x == at : (x == a ? seam_a : seam_b);
        if (may_keep) {
            if (const CornerPlan kept = plan_kept(x, x == a ? b : a, f0, f1);
                kept == CornerPlan::Ok) {
                return kept;
            } else if (kept == CornerPlan::UvFlip) {
                why = kept;
            }
        }
    }
    return why;
}

CornerPlan AttributeSimplifier::plan_free(Vertex a, Vertex b, Face f0, Face f1, const Vec3& p) {
    // No seam at either end: one chart, one value for every corner, in each set; the set's
    // quadric's best, else the first of the ends' values and their mean that turns no UV
    // triangle of that set over.
    corners_.clear();
    for (const Vertex v : {a, b}) {
        for (Halfedge h : mesh_.halfedges(v)) {
            const Face g = mesh_.face(h);
            if (g.is_valid() && g != f0 && g != f1) {
                corners_.push_back({g, mesh_.prev(h), Uvs{}});
            }
        }
    }
    const Face f = f0.is_valid() ? f0 : f1;
    for (std::size_t k = 0; k < kSets; ++k) {
        if (!uv_[k]) {
            continue;
        }
        Vec2 tries[4];
        int n = 0;
        UvQuadric q = uvq_[k][a.idx()];
        q.add(uvq_[k][b.idx()]);
        if (double s[2]; q.optimum(p, s)) {
            tries[n++] = Vec2{s[0] / uv_weight_[k], s[1] / uv_weight_[k]};
        }
        const Vec2 ua = uv_[k][corner(f, a)], ub = uv_[k][corner(f, b)];
        tries[n++] = ua, tries[n++] = ub, tries[n++] = (ua + ub) * 0.5;
        bool found = false;
        for (int i = 0; i < n && !found; ++i) {
            for (PlannedCorner& c : corners_) {
                c.uv[k] = tries[i];
            }
            found = !turns_over(k);
        }
        if (!found) {
            return CornerPlan::UvFlip;
        }
    }
    return CornerPlan::Ok;
}

CornerPlan AttributeSimplifier::plan_along(Vertex a, Vertex b, Face f0, Face f1, double t) {
    corners_.clear();
    for (const Face f : {f0, f1}) {
        if (!f.is_valid()) {
            continue;
        }
        Uvs value = uvs(corner(f, a));
        const Uvs at_b = uvs(corner(f, b));
        for (std::size_t k = 0; k < kSets; ++k) {
            value[k] = value[k] * (1.0 - t) + at_b[k] * t;
        }
        if (!spread_run(corner(f, a), value, f0, f1) || !spread_run(corner(f, b), value, f0, f1)) {
            return CornerPlan::Seam;
        }
    }
    if (corners_.size() != faces_beside(a, f0, f1) + faces_beside(b, f0, f1)) {
        return CornerPlan::Seam;  // an end has a chart beside neither face: charts meet there
    }
    return turns_over() ? CornerPlan::UvFlip : CornerPlan::Ok;
}

CornerPlan AttributeSimplifier::plan_kept(Vertex x, Vertex y, Face f0, Face f1) {
    corners_.clear();
    for (Halfedge h : mesh_.halfedges(x)) {
        const Face f = mesh_.face(h);
        if (f.is_valid() && f != f0 && f != f1) {
            corners_.push_back({f, mesh_.prev(h), uvs(mesh_.prev(h))});
        }
    }
    const std::size_t from_x = corners_.size();
    for (const Face f : {f0, f1}) {
        if (f.is_valid() && !spread_run(corner(f, y), uvs(corner(f, x)), f0, f1)) {
            return CornerPlan::Seam;
        }
    }
    if (corners_.size() - from_x != faces_beside(y, f0, f1)) {
        return CornerPlan::Seam;  // y has a chart beside neither face
    }
    kept_uv_ = uvs(corner(f0.is_valid() ? f0 : f1, x));
    return turns_over() ? CornerPlan::UvFlip : CornerPlan::Ok;
}

std::size_t AttributeSimplifier::faces_beside(Vertex v, Face f0, Face f1) const {
    std::size_t n = 0;
    for (Halfedge h : mesh_.halfedges(v)) {
        const Face f = mesh_.face(h);
        n += f.is_valid() && f != f0 && f != f1;
    }
    return n;
}

// Whether a planned corner turns its UV triangle over in any set.
bool AttributeSimplifier::turns_over() const {
    for (std::size_t k = 0; k < kSets; ++k) {
        if (uv_[k] && turns_over(k)) {
            return true;
        }
    }
    return false;
}

// Whether a planned corner turns its UV triangle of `set` over (or flattens one that was not
// flat).
bool AttributeSimplifier::turns_over(std::size_t set) const {
    const HalfedgeProperty<Vec2>& uv = uv_[set];
    for (const PlannedCorner& c : corners_) {
        const Vec2& u1 = uv[mesh_.next(c.corner)];
        const Vec2& u2 = uv[mesh_.prev(c.corner)];
        const Vec2& to = c.uv[set];
        const double before = uv_area(uv[c.corner], u1, u2);
        const double after = uv_area(to, u1, u2);
        // Turned over, beyond rounding: the 3D guard lets a triangle become a sliver, whose
        // UV area is then ±1e-19 (it has no side to keep).
        const double size = std::max({norm2(u1 - uv[c.corner]), norm2(u2 - uv[c.corner]),
                                      norm2(to - u1), norm2(to - u2), norm2(u2 - u1)});
        if (before * after < 0.0 && std::abs(before) > 1e-10 * size &&
            std::abs(after) > 1e-10 * size) {
            return true;
        }
    }
    return false;
}

void AttributeSimplifier::apply(Vertex a, Vertex b, Vertex s, Quadric& position) {
    if (color_) {
        ColorQuadric q = colorq_[a.idx()];
        q.add(colorq_[b.idx()]);
        colorq_[s.idx()] = q;
        mesh_.touch(s);
        color_[s] = planned_color_;
    }
    if (!any_uv()) {
        return;
    }
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
            for (std::size_t k = 0; k < kSets; ++k) {
                if (uv_[k]) {
                    uv_[k][at_s] = planned->uv[k];
                }
            }
        }
    }
    // Both ends off seams: so is s (its merged edges join corners of one chart). Else see;
    // no other vertex changes (each merged edge keeps both sides' values).
    seam_[s.idx()] = !planned_free_ && on_seam(s);
    for (std::size_t k = 0; k < kSets; ++k) {
        if (!uv_[k]) {
            continue;
        }
        UvQuadric q = uvq_[k][a.idx()];
        q.add(uvq_[k][b.idx()]);
        if (seam_[s.idx()] != 0) {
            // The free end's faces joined a seam vertex at the kept corner's value: their
            // error is now the position's (as gather() does for seam vertices).
            const double kept[2] = {uv_weight_[k] * kept_uv_[k].x, uv_weight_[k] * kept_uv_[k].y};
            q.fix_into(position, kept);
            q = UvQuadric{};
        }
        uvq_[k][s.idx()] = q;
    }
}

}  // namespace meshedit::qem
