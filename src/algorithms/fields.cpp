// Scalar fields (fields.h). Curvature passes over the display triangulation's triangles
// once, gathering per vertex the corner angles, the mixed Voronoi area and the cotangent
// Laplacian; the others read one element at a time. Everything that squares lengths works on
// positions scaled by a power of two into (−1, 1) (unit_scale.h) and scales the result back:
// at 1e200 a cross product overflows and every angle came out as atan2(inf, inf).

#include "meshedit/core/fields.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <queue>

#include "mesh/unit_scale.h"
#include "meshedit/core/display_fan.h"
#include "meshedit/core/normals.h"
#include "stored_fields.h"

namespace meshedit {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = std::numbers::pi;

constexpr FieldInfo kFields[] = {
    {"gauss", "Gaussian curvature", "1/length²", FieldSite::Vertex, true,
     "angle defect (2 pi − the angles at the vertex) over the mixed Voronoi area; none on the "
     "boundary"},
    {"mean", "mean curvature", "1/length", FieldSite::Vertex, true,
     "half the cotangent Laplacian of the position along the vertex normal, over the mixed "
     "Voronoi area; positive where the surface bulges towards its normal"},
    {"valence", "valence", "", FieldSite::Vertex, false,
     "edges at the vertex (6 is regular for triangles, 4 for quads: the others are "
     "extraordinary, where Loop and Catmull-Clark lose smoothness)"},
    {"aspect", "triangle aspect ratio", "", FieldSite::Face, false,
     "circumradius over twice the inradius: 1 for an equilateral triangle, growing as it "
     "degenerates; none for polygons"},
    {"min_angle", "minimum angle", "°", FieldSite::Face, false,
     "the face's smallest corner angle (60° at best for a triangle)"},
    {"dihedral", "dihedral angle", "°", FieldSite::Edge, false,
     "how far the two faces' normals turn across the edge (0 flat); none on the boundary"},
    {"edge_length", "edge length", "length", FieldSite::Edge, false, "the edge's length"},
    {"face_area", "face area", "length²", FieldSite::Face, false,
     "the face's area (Newell's formula)"},
    {"distance", "distance", "length", FieldSite::Vertex, false,
     "shortest path along the edges from the source vertex (Dijkstra); none where it cannot "
     "reach"},
};

double angle_between(const Vec3& a, const Vec3& b) {
    return std::atan2(norm(cross(a, b)), dot(a, b));
}

// Per vertex: corner angle sum, mixed Voronoi area, cotangent Laplacian Σ cot·(pj − pi).
struct Curvature {
    std::vector<double> angles, areas;
    std::vector<Vec3> laplacian;
};

// Angles are the mesh's own, areas and the Laplacian those of the mesh scaled by 2^−exponent.
Curvature gather_curvature(const Mesh& mesh, int exponent) {
    Curvature c;
    c.angles.assign(mesh.vertices_size(), 0.0);
    c.areas.assign(mesh.vertices_size(), 0.0);
    c.laplacian.assign(mesh.vertices_size(), Vec3{});
    for (Face f : mesh.faces()) {
        for_each_fan_triangle(mesh, f, [&](std::size_t, Vertex c0, Halfedge h) {
            const std::uint32_t v[3] = {c0.idx(), mesh.from_vertex(h).idx(),
                                        mesh.to_vertex(h).idx()};
            Vec3 p[3];
            for (int k = 0; k < 3; ++k) {
                p[k] = scaled_point(mesh.position(Vertex(v[k])), -exponent);
            }
            const double twice_area = norm(cross(p[1] - p[0], p[2] - p[0]));
            if (twice_area == 0.0) {
                return;  // degenerate: no angles, no area
            }
            double angle[3], cot[3];
            for (int k = 0; k < 3; ++k) {
                const Vec3 a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
                angle[k] = angle_between(a, b);
                cot[k] = dot(a, b) / twice_area;
            }
            const bool obtuse = angle[0] > kPi / 2 || angle[1] > kPi / 2 || angle[2] > kPi / 2;
            for (int k = 0; k < 3; ++k) {
                const int j = (k + 1) % 3, l = (k + 2) % 3;
                c.angles[v[k]] += angle[k];
                // The edge k–j is opposite corner l; k–l opposite j.
                c.laplacian[v[k]] += cot[l] * (p[j] - p[k]) + cot[j] * (p[l] - p[k]);
                if (!obtuse) {
                    c.areas[v[k]] +=
                        (sqrnorm(p[j] - p[k]) * cot[l] + sqrnorm(p[l] - p[k]) * cot[j]) / 8.0;
                } else {
                    c.areas[v[k]] += twice_area / 2.0 / (angle[k] > kPi / 2 ? 2.0 : 4.0);
                }
            }
        });
    }
    return c;
}

std::vector<double> vertex_curvature(const Mesh& mesh, bool gauss) {
    const int exponent = unit_exponent(mesh);
    const Curvature c = gather_curvature(mesh, exponent);
    const std::vector<Vec3> normals = gauss ? std::vector<Vec3>{} : vertex_normals(mesh);
    std::vector<double> out(mesh.vertices_size(), kNaN);
    for (Vertex v : mesh.vertices()) {
        const double area = c.areas[v.idx()];
        if (mesh.is_boundary(v) || area <= 0.0) {
            continue;
        }
        // Gaussian curvature is per length², mean curvature per length.
        out[v.idx()] = gauss
                           ? std::ldexp((2.0 * kPi - c.angles[v.idx()]) / area, -2 * exponent)
                           : std::ldexp(-dot(c.laplacian[v.idx()], normals[v.idx()]) / (4.0 * area),
                                        -exponent);
    }
    return out;
}

std::vector<double> per_face(const Mesh& mesh, const std::function<double(Face)>& fn) {
    std::vector<double> out(mesh.faces_size(), kNaN);
    for (Face f : mesh.faces()) {
        out[f.idx()] = fn(f);
    }
    return out;
}

std::vector<double> per_edge(const Mesh& mesh, const std::function<double(Edge)>& fn) {
    std::vector<double> out(mesh.edges_size(), kNaN);
    for (Edge e : mesh.edges()) {
        out[e.idx()] = fn(e);
    }
    return out;
}

// Scale-free: computed on the positions scaled by 2^−exponent.
double aspect_ratio(const Mesh& mesh, Face f, int exponent) {
    if (!mesh.is_triangle(f)) {
        return kNaN;
    }
    const Halfedge h = mesh.halfedge(f);
    const Vec3 a = scaled_point(mesh.position(mesh.from_vertex(h)), -exponent);
    const Vec3 b = scaled_point(mesh.position(mesh.to_vertex(h)), -exponent);
    const Vec3 c = scaled_point(mesh.position(mesh.to_vertex(mesh.next(h))), -exponent);
    const double la = distance(b, c), lb = distance(c, a), lc = distance(a, b);
    const double area = norm(cross(b - a, c - a)) / 2.0;
    // R = abc / 4T, r = T / s: R / 2r = abc·s / 8T².
    return area > 0.0 ? la * lb * lc * (la + lb + lc) / 2.0 / (8.0 * area * area)
                      : std::numeric_limits<double>::infinity();
}

double min_angle_deg(const Mesh& mesh, Face f, int exponent) {
    double smallest = kPi;
    const auto at = [&](Vertex v) { return scaled_point(mesh.position(v), -exponent); };
    for (Halfedge h : mesh.halfedges(f)) {
        const Vec3 p = at(mesh.to_vertex(h));
        const Vec3 back = at(mesh.from_vertex(h)) - p;
        const Vec3 ahead = at(mesh.to_vertex(mesh.next(h))) - p;
        smallest = std::min(smallest, angle_between(back, ahead));
    }
    return smallest * 180.0 / kPi;
}

// Adds the area of face f's display triangles, of the mesh scaled by 2^−exponent, to `area`.
void add_scaled_face_area(const Mesh& mesh, Face f, int exponent, double& area) {
    for_each_fan_triangle(mesh, f, [&](std::size_t, Vertex c0, Halfedge h) {
        const Vec3 p = scaled_point(mesh.position(c0), -exponent);
        area += norm(cross(scaled_point(mesh.position(mesh.from_vertex(h)), -exponent) - p,
                           scaled_point(mesh.position(mesh.to_vertex(h)), -exponent) - p)) /
                2.0;
    });
}

// |a − b| without overflow: 1e200-sized coordinates give 1e200, not inf.
double scaled_distance(const Vec3& a, const Vec3& b, int exponent) {
    return std::ldexp(distance(scaled_point(a, -exponent), scaled_point(b, -exponent)), exponent);
}

std::vector<double> distances(const Mesh& mesh, Vertex source) {
    const int exponent = unit_exponent(mesh);
    std::vector<double> out(mesh.vertices_size(), kNaN);
    if (source.idx() >= mesh.vertices_size() || mesh.is_deleted(source)) {
        return out;
    }
    std::vector<double> best(mesh.vertices_size(), std::numeric_limits<double>::infinity());
    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    best[source.idx()] = 0.0;
    queue.push({0.0, source.idx()});
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > best[v] || mesh.is_isolated(Vertex(v))) {
            continue;
        }
        for (Halfedge h : mesh.halfedges(Vertex(v))) {
            const std::uint32_t w = mesh.to_vertex(h).idx();
            const double through =
                d + scaled_distance(mesh.position(Vertex(v)), mesh.position(Vertex(w)), exponent);
            if (through < best[w]) {
                best[w] = through;
                queue.push({through, w});
            }
        }
    }
    for (Vertex v : mesh.vertices()) {
        if (std::isfinite(best[v.idx()])) {
            out[v.idx()] = best[v.idx()];
        }
    }
    return out;
}

}  // namespace

std::span<const FieldInfo> field_infos() {
    return kFields;
}

const FieldInfo* find_field(std::string_view name) {
    for (const FieldInfo& info : kFields) {
        if (info.name == name) {
            return &info;
        }
    }
    return nullptr;
}

std::vector<double> compute_field(const Mesh& mesh, const FieldInfo& info,
                                  const FieldOptions& options) {
    if (!info.property.empty()) {
        return stored_field_values(mesh, info);
    }
    const std::string_view n = info.name;
    if (n == "gauss" || n == "mean") {
        return vertex_curvature(mesh, n == "gauss");
    }
    if (n == "valence") {
        std::vector<double> out(mesh.vertices_size(), kNaN);
        for (Vertex v : mesh.vertices()) {
            out[v.idx()] = static_cast<double>(mesh.valence(v));
        }
        return out;
    }
    const int exponent = unit_exponent(mesh);
    if (n == "aspect") {
        return per_face(mesh, [&](Face f) { return aspect_ratio(mesh, f, exponent); });
    }
    if (n == "min_angle") {
        return per_face(mesh, [&](Face f) { return min_angle_deg(mesh, f, exponent); });
    }
    if (n == "face_area") {
        return per_face(mesh, [&](Face f) {
            const Vec3 area = face_area_vector(mesh, f);
            if (is_finite(area)) {
                return norm(area) / 2.0;
            }
            double scaled = 0.0;
            add_scaled_face_area(mesh, f, exponent, scaled);
            return std::ldexp(scaled, 2 * exponent);  // inf only past 1.8e308
        });
    }
    if (n == "dihedral") {
        return per_edge(mesh, [&](Edge e) {
            return mesh.is_boundary(e) ? kNaN
                                       : angle_between(face_normal(mesh, mesh.face(e, 0)),
                                                       face_normal(mesh, mesh.face(e, 1))) *
                                             180.0 / kPi;
        });
    }
    if (n == "edge_length") {
        return per_edge(mesh, [&](Edge e) {
            return scaled_distance(mesh.position(mesh.vertex(e, 0)),
                                   mesh.position(mesh.vertex(e, 1)), exponent);
        });
    }
    return distances(mesh, options.source);
}

FieldStats field_stats(std::span<const double> values) {
    FieldStats s;
    double sum = 0.0;
    for (const double x : values) {
        if (!std::isfinite(x)) {
            continue;
        }
        s.min = s.count == 0 ? x : std::min(s.min, x);
        s.max = s.count == 0 ? x : std::max(s.max, x);
        sum += x;
        ++s.count;
    }
    s.mean = s.count > 0 ? sum / static_cast<double>(s.count) : 0.0;
    if (s.count > 0 && !std::isfinite(s.mean)) {
        // Finite values whose sum overflowed (edge lengths near 1e308): the mean of each
        // value's share instead, which stays between min and max.
        s.mean = 0.0;
        for (const double x : values) {
            s.mean += std::isfinite(x) ? x / static_cast<double>(s.count) : 0.0;
        }
    }
    return s;
}

double field_percentile(std::span<const double> values, double fraction) {
    std::vector<double> finite;
    for (const double x : values) {
        if (std::isfinite(x)) {
            finite.push_back(x);
        }
    }
    if (finite.empty()) {
        return 0.0;
    }
    const auto rank = static_cast<std::size_t>(
        std::clamp(fraction, 0.0, 1.0) * static_cast<double>(finite.size() - 1) + 0.5);
    std::nth_element(finite.begin(), finite.begin() + static_cast<std::ptrdiff_t>(rank),
                     finite.end());
    return finite[rank];
}

double total_angle_defect(const Mesh& mesh) {
    const Curvature c = gather_curvature(mesh, unit_exponent(mesh));
    double total = 0.0;
    for (Vertex v : mesh.vertices()) {
        if (!mesh.is_isolated(v)) {
            total += (mesh.is_boundary(v) ? kPi : 2.0 * kPi) - c.angles[v.idx()];
        }
    }
    return total;
}

double surface_area(const Mesh& mesh) {
    const int exponent = unit_exponent(mesh);
    double area = 0.0;
    for (Face f : mesh.faces()) {
        add_scaled_face_area(mesh, f, exponent, area);
    }
    return std::ldexp(area, 2 * exponent);  // inf only when the area itself is past 1.8e308
}

std::vector<std::pair<ElementRef, double>> field_values_at(const Mesh& mesh, FieldSite site,
                                                           std::span<const double> values,
                                                           ElementRef element) {
    std::vector<std::pair<ElementRef, double>> out;
    if (!is_live(mesh, element)) {
        return out;
    }
    const auto add = [&](ElementRef r) {
        if (r.index < values.size() && is_live(mesh, r)) {
            out.emplace_back(r, values[r.index]);
        }
    };
    const auto of_site = [&](Halfedge h) {  // the site's element of halfedge h
        return site == FieldSite::Vertex ? ElementRef::vertex(mesh.to_vertex(h))
               : site == FieldSite::Edge ? ElementRef::edge(Mesh::edge(h))
                                         : ElementRef::face(mesh.face(h));
    };
    using Kind = ElementRef::Kind;
    const Kind own = site == FieldSite::Vertex ? Kind::Vertex
                     : site == FieldSite::Edge ? Kind::Edge
                                               : Kind::Face;
    if (element.kind == own) {
        add(element);
    } else if (element.kind == Kind::Halfedge) {
        add(of_site(Halfedge(element.index)));
    } else if (element.kind == Kind::Face) {
        for (const Halfedge h : mesh.halfedges(Face(element.index))) {
            add(of_site(h));
        }
    } else if (element.kind == Kind::Edge) {
        for (unsigned i = 0; i < 2; ++i) {
            const Halfedge h = Mesh::halfedge(Edge(element.index), i);
            if (site == FieldSite::Vertex || !mesh.is_boundary(h)) {
                add(of_site(h));
            }
        }
    } else if (element.kind == Kind::Vertex && !mesh.is_isolated(Vertex(element.index))) {
        for (const Halfedge h : mesh.halfedges(Vertex(element.index))) {
            if (site == FieldSite::Edge || !mesh.is_boundary(h)) {
                add(of_site(h));
            }
        }
    }
    return out;
}

}  // namespace meshedit
