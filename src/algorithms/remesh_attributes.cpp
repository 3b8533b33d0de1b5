// Remeshing's attributes: seams as features and projection onto the input (remesh_attributes.h).

#include "remesh_attributes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <utility>

#include "meshedit/core/attribute_summary.h"
#include "meshedit/core/attributes.h"

namespace meshedit::remeshing {
namespace {

double distance2(const Vec3& a, const Vec3& b) {
    return dot(a - b, a - b);
}

// Barycentric weights of p (on or near the triangle's plane) in triangle (a, b, c); a
// degenerate triangle gives its nearest corner all the weight.
std::array<double, 3> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 v0 = b - a, v1 = c - a, v2 = p - a;
    const double d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1);
    const double d20 = dot(v2, v0), d21 = dot(v2, v1);
    const double det = d00 * d11 - d01 * d01;
    if (!(det > 1e-300)) {
        const double da = distance2(p, a), db = distance2(p, b), dc = distance2(p, c);
        return da <= db && da <= dc ? std::array<double, 3>{1, 0, 0}
               : db <= dc           ? std::array<double, 3>{0, 1, 0}
                                    : std::array<double, 3>{0, 0, 1};
    }
    const double v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
    return {1.0 - v - w, v, w};
}

// Where a point lies on the input: its triangle (= the source's face) and the weights of
// that face's corners, in the order of corners().
struct Place {
    Face face;
    std::array<double, 3> weight{};
};

class Projector {
public:
    Projector(Mesh& mesh, const Mesh& source, const TriangleTree& tree)
        : mesh_(mesh), source_(source), tree_(tree), seams_(mesh), source_seams_(source) {
        for (const std::string_view name : kTexCoordSets) {
            const auto to = mesh.get_property<Halfedge, Vec2>(name);
            const auto from = source.get_property<Halfedge, Vec2>(name);
            if (to && from) {
                vec2_.push_back({to, from});
            }
        }
        normal_to_ = mesh.get_property<Halfedge, Vec3>(kCornerNormalProperty);
        normal_from_ = source.get_property<Halfedge, Vec3>(kCornerNormalProperty);
        color_to_ = mesh.get_property<Vertex, Vec4>(kColorProperty);
        color_from_ = source.get_property<Vertex, Vec4>(kColorProperty);
        material_to_ = mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
        material_from_ = source.get_property<Face, std::uint32_t>(kMaterialProperty);
        face_color_to_ = mesh.get_property<Face, Vec4>(kFaceColorProperty);
        face_color_from_ = source.get_property<Face, Vec4>(kFaceColorProperty);
    }

    void run(const std::function<bool(Face)>& changes, const std::function<bool(Vertex)>& moves,
             const std::vector<std::uint32_t>& hints) {
        hints_ = &hints;
        const bool faces = (material_to_ && material_from_) || (face_color_to_ && face_color_from_);
        const bool corners = !vec2_.empty() || (normal_to_ && normal_from_);
        const bool colors = color_to_ && color_from_;
        for (const Face f : mesh_.faces()) {
            if (faces && changes(f)) {
                const Face home(tree_.closest(centre(f)).triangle);
                if (material_to_ && material_from_) {
                    material_to_[f] = material_from_[home];
                }
                if (face_color_to_ && face_color_from_) {
                    face_color_to_[f] = face_color_from_[home];
                }
            }
        }
        for (const Vertex v : mesh_.vertices()) {
            if (mesh_.is_isolated(v) || !moves(v)) {
                continue;
            }
            corners_.clear();
            for (const Halfedge h : mesh_.halfedges(v)) {
                // The corner at v of face(h) (h leaves v) is prev(h).
                if (!mesh_.is_boundary(h) && changes(mesh_.face(h))) {
                    corners_.push_back(mesh_.prev(h));
                }
            }
            if (corners_.empty()) {
                continue;
            }
            const Place at = place_beside(v, mesh_.face(corners_[0]));
            if (corners) {
                project_corners(v, at);
            }
            if (colors) {
                // Colours are continuous: the place on any side of a seam gives the same.
                const auto c = corners_of(at.face);
                Vec4 sum{0, 0, 0, 0};
                for (int i = 0; i < 3; ++i) {
                    const Vec4& x = color_from_[source_.to_vertex(c[i])];
                    const double w = at.weight[i];
                    sum = {sum.x + w * x.x, sum.y + w * x.y, sum.z + w * x.z, sum.w + w * x.w};
                }
                color_to_[v] = sum;
            }
        }
    }

private:
    Vec3 centre(Face f) const {
        Vec3 c;
        double n = 0.0;
        for (const Vertex v : mesh_.vertices(f)) {
            c += mesh_.position(v);
            n += 1.0;
        }
        return c * (1.0 / n);
    }

    std::array<Halfedge, 3> corners_of(Face f) const {
        const Halfedge h = source_.halfedge(f);
        return {h, source_.next(h), source_.next(source_.next(h))};
    }

    Vec3 corner_point(Face f, int i) const {
        return tree_.points()[source_.to_vertex(corners_of(f)[i]).idx()];
    }

    Place place_on(Face f, const Vec3& p) const {
        return {f, barycentric(p, corner_point(f, 0), corner_point(f, 1), corner_point(f, 2))};
    }

    // Each corner of v (corners_) takes its values from the input on its own face's side of
    // the seams (`first`: the first corner's place). Corners whose values then differ by
    // rounding alone are given the same values, so no seam appears where the input had none.
    void project_corners(Vertex v, const Place& first) {
        bool seam = false;
        for (const Edge e : mesh_.edges(v)) {
            seam = seam || seams_.is_seam(e);
        }
        for (std::size_t i = 0; i < corners_.size(); ++i) {
            const Halfedge c = corners_[i];
            if (i == 0 || !seam) {
                write_corner(c, first);  // off the seams every face is on one side
                continue;
            }
            write_corner(c, place_beside(v, mesh_.face(c)));
            for (std::size_t j = 0; j < i; ++j) {
                if (same_values(corners_[j], c)) {
                    copy_values(corners_[j], c);
                    break;
                }
            }
        }
    }

    static bool near(double a, double b) { return std::abs(a - b) <= kSame; }
    bool same_values(Halfedge a, Halfedge b) const {
        for (const auto& [to, from] : vec2_) {
            if (!near(to[a].x, to[b].x) || !near(to[a].y, to[b].y)) {
                return false;
            }
        }
        if (normal_to_ && normal_from_) {
            const Vec3 d = normal_to_[a] - normal_to_[b];
            return near(d.x, 0.0) && near(d.y, 0.0) && near(d.z, 0.0);
        }
        return true;
    }
    void copy_values(Halfedge from, Halfedge to) {
        for (auto& [values, source] : vec2_) {
            values[to] = values[from];
        }
        if (normal_to_ && normal_from_) {
            normal_to_[to] = normal_to_[from];
        }
    }

    // Where v lies on the input on face f's side of the seams: from a point a little inside
    // f toward its centre (whose closest input triangle is on that side), the input triangles
    // reached across no seam and no farther from v than that one, the closest point among them.
    Place place_beside(Vertex v, Face f) {
        const Vec3& p = mesh_.position(v);
        const Vec3 inside = p + (centre(f) - p) * kInside;
        const std::uint32_t hint = v.idx() < hints_->size() ? (*hints_)[v.idx()] : kInvalidIndex;
        const Face first(tree_.closest(inside, hint).triangle);
        const auto distance_to = [&](Face g, Vec3& q) {
            q = closest_point_on_triangle(p, corner_point(g, 0), corner_point(g, 1),
                                          corner_point(g, 2));
            return distance2(p, q);
        };
        Vec3 best_point;
        double best = distance_to(first, best_point);
        Face best_face = first;
        const double reach = best * (1.0 + 1e-9) + 1e-300;
        seen_.clear();
        seen_.push_back(first);
        stack_.assign(1, first);
        while (!stack_.empty()) {
            const Face g = stack_.back();
            stack_.pop_back();
            for (const Halfedge h : source_.halfedges(g)) {
                const Face n = source_.face(Mesh::twin(h));
                if (!n.is_valid() || source_seams_.is_seam(Mesh::edge(h)) ||
                    std::find(seen_.begin(), seen_.end(), n) != seen_.end()) {
                    continue;
                }
                seen_.push_back(n);
                Vec3 q;
                const double d = distance_to(n, q);
                if (d > reach) {
                    continue;
                }
                stack_.push_back(n);
                if (d < best) {
                    best = d, best_point = q, best_face = n;
                }
            }
        }
        return place_on(best_face, best_point);
    }

    void write_corner(Halfedge h, const Place& at) {
        const auto c = corners_of(at.face);
        for (auto& [to, from] : vec2_) {
            Vec2 sum{0, 0};
            for (int i = 0; i < 3; ++i) {
                sum = {sum.x + at.weight[i] * from[c[i]].x, sum.y + at.weight[i] * from[c[i]].y};
            }
            to[h] = sum;
        }
        if (normal_to_ && normal_from_) {
            Vec3 sum;
            for (int i = 0; i < 3; ++i) {
                sum += normal_from_[c[i]] * at.weight[i];
            }
            const double length = norm(sum);
            normal_to_[h] = length > 0.0 ? sum * (1.0 / length) : normal_from_[c[0]];
        }
    }

    // How far into a face, from a corner toward the centre, its side of a seam is looked for.
    static constexpr double kInside = 0.05;
    // Values this close are one value that rounding split (texture coordinates: far below a
    // texel of any texture; normals: unit vectors).
    static constexpr double kSame = 1e-9;

    Mesh& mesh_;
    const Mesh& source_;
    const TriangleTree& tree_;
    const AttributeSeams seams_, source_seams_;
    std::vector<std::pair<HalfedgeProperty<Vec2>, HalfedgeProperty<Vec2>>> vec2_;
    HalfedgeProperty<Vec3> normal_to_, normal_from_;
    VertexProperty<Vec4> color_to_, color_from_;
    FaceProperty<std::uint32_t> material_to_, material_from_;
    FaceProperty<Vec4> face_color_to_, face_color_from_;
    std::vector<Halfedge> corners_;  // of the vertex being projected
    const std::vector<std::uint32_t>* hints_ = nullptr;
    std::vector<Face> seen_, stack_;
};

}  // namespace

AttributeSeams::AttributeSeams(const Mesh& mesh) : mesh_(mesh) {
    for (const std::string_view name : kTexCoordSets) {
        if (const auto p = mesh.get_property<Halfedge, Vec2>(name)) {
            vec2_.push_back(p);
        }
    }
    normal_ = mesh.get_property<Halfedge, Vec3>(kCornerNormalProperty);
    material_ = mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
}

bool AttributeSeams::is_seam(Edge e) const {
    if (material_ && is_material_border(mesh_, e, material_)) {
        return true;
    }
    for (const auto& p : vec2_) {
        if (corners_differ(mesh_, e, p)) {
            return true;
        }
    }
    return normal_ && corners_differ(mesh_, e, normal_);
}

bool has_projected_attributes(const Mesh& mesh) {
    for (const std::string_view name : kTexCoordSets) {
        if (mesh.get_property<Halfedge, Vec2>(name)) {
            return true;
        }
    }
    return mesh.get_property<Halfedge, Vec3>(kCornerNormalProperty) ||
           mesh.get_property<Vertex, Vec4>(kColorProperty) ||
           mesh.get_property<Face, std::uint32_t>(kMaterialProperty) ||
           mesh.get_property<Face, Vec4>(kFaceColorProperty);
}

void project_attributes(Mesh& mesh, const Mesh& source, const TriangleTree& tree,
                        const std::function<bool(Face)>& changes,
                        const std::function<bool(Vertex)>& moves,
                        const std::vector<std::uint32_t>& hints) {
    Projector(mesh, source, tree).run(changes, moves, hints);
}

}  // namespace meshedit::remeshing
