#include "meshedit/overlay/overlay.h"

#include <cstddef>
#include <cstdint>
#include <vector>

#include "meshedit/core/attribute_summary.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/display_fan.h"
#include "meshedit/core/loop_steps.h"
#include "meshedit/core/normals.h"

namespace meshedit {

namespace {

// Sizes of the secondary primitives, derived from the style's main sizes so a single style
// change (e.g. HiDPI scaling of the whole palette) scales every overlay consistently.

/// Halfedge shafts are cut back this fraction of the edge at each end, so arrows of the
/// halfedges around a vertex do not touch each other.
constexpr double kShaftShorten = 0.15;
/// Face tints are lifted off the surface by this fraction of the bounding-box diagonal, so
/// they win the depth test against the shaded face without visibly floating.
constexpr double kFaceOffset = 1e-3;
/// Samples of the full curve: fine enough to look smooth at any zoom the viewer allows.
constexpr int kCurveSamples = 200;

float level_point_size(const OverlayStyle& s) {
    return s.vertex_size_px * (2.0f / 3.0f);
}
float evaluated_point_size(const OverlayStyle& s) {
    return s.vertex_size_px * 1.25f;
}
float level_line_width(const OverlayStyle& s) {
    return s.feature_width_px;
}
float curve_line_width(const OverlayStyle& s) {
    return s.edge_width_px * 0.75f;
}
float net_line_width(const OverlayStyle& s) {
    return s.feature_width_px * 0.6f;
}
float net_point_size(const OverlayStyle& s) {
    return s.vertex_size_px * 0.5f;
}

/// Curves are 2D (docs/spec.md §4): drop any z so every curve overlay lies in the z = 0 plane even
/// if a file carried a stray z.
Vec3 flat(const Vec3& p) {
    return {p.x, p.y, 0.0};
}

void add_halfedge_arrow(const Mesh& m, Halfedge h, const Color& color, const OverlayStyle& style,
                        OverlayBatch& out) {
    const Vec3 a = m.position(m.from_vertex(h));
    const Vec3 b = m.position(m.to_vertex(h));
    const Vec3 d = b - a;
    const double dd = dot(d, d);

    // The face the arrow sits in: its own, or for a boundary halfedge the twin's face, whose
    // centroid is then mirrored across the edge so the arrow lies outside, on h's side.
    Face f = m.face(h);
    const bool mirrored = !f.is_valid();
    if (mirrored) {
        f = m.face(Mesh::twin(h));
    }

    const Vec3 tail = lerp(a, b, kShaftShorten);
    const Vec3 head = lerp(a, b, 1.0 - kShaftShorten);
    if (!f.is_valid() || dd == 0.0) {
        // A dangling edge with no face on either side: no plane to inset into, so on the edge.
        out.lines.push_back({tail, head, color, style.edge_width_px});
        out.arrowheads.push_back(
            {head, tail, Vec3{}, color, style.arrowhead_length_px, style.arrowhead_half_width_px});
        return;
    }

    Vec3 c = face_centroid(m, f);
    const Vec3 foot = a + d * (dot(c - a, d) / dd);  // centroid projected onto the edge line
    if (mirrored) {
        c = 2.0 * foot - c;
    }
    const double s = style.halfedge_inset;
    const Vec3 shaft_a = tail + s * (c - tail);
    const Vec3 shaft_b = head + s * (c - head);
    out.lines.push_back({shaft_a, shaft_b, color, style.edge_width_px});
    // The head is sized in pixels by the renderer, so it reads at every zoom; it lies in the
    // face's plane (across: from the edge towards the centroid).
    out.arrowheads.push_back({shaft_b, shaft_a, normalize(c - foot), color,
                              style.arrowhead_length_px, style.arrowhead_half_width_px});
}

// `diagonal`: the mesh's bounding-box diagonal (measured once by the caller: it walks
// every vertex).
void add_face_tint(const Mesh& m, Face f, const Color& color, const OverlayStyle& style,
                   double diagonal, OverlayBatch& out) {
    const Vec3 lift = face_normal(m, f) * (kFaceOffset * diagonal);
    Color tint = color;
    tint[3] = style.face_tint_alpha;

    // The surface's own triangles, lifted: on a non-planar polygon any other cut would
    // cross the surface and hide part of the tint.
    for_each_fan_triangle(m, f, [&](std::size_t, Vertex c0, Halfedge h) {
        out.triangles.push_back({m.position(c0) + lift, m.position(m.from_vertex(h)) + lift,
                                 m.position(m.to_vertex(h)) + lift, tint});
    });
}

}  // namespace

void OverlayBatch::append(const OverlayBatch& other) {
    points.insert(points.end(), other.points.begin(), other.points.end());
    lines.insert(lines.end(), other.lines.begin(), other.lines.end());
    triangles.insert(triangles.end(), other.triangles.begin(), other.triangles.end());
    arrowheads.insert(arrowheads.end(), other.arrowheads.begin(), other.arrowheads.end());
    labels.insert(labels.end(), other.labels.begin(), other.labels.end());
}

void add_feature_edges(const Mesh& mesh, const OverlayStyle& style, OverlayBatch& out, bool seams,
                       bool borders) {
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    const auto uv =
        seams ? mesh.get_property<Halfedge, Vec2>(kTexCoordProperty) : HalfedgeProperty<Vec2>();
    const auto material = borders ? mesh.get_property<Face, std::uint32_t>(kMaterialProperty)
                                  : FaceProperty<std::uint32_t>();
    for (Edge e : mesh.edges()) {
        // Boundary wins over crease, crease over seam, seam over material border: a boundary
        // edge is sharp anyway, and the boundary is the more important thing to see.
        const Color* color = mesh.is_boundary(e)             ? &style.boundary
                             : crease && crease[e] != 0      ? &style.crease
                             : uv && is_uv_seam(mesh, e, uv) ? &style.uv_seam
                             : material && is_material_border(mesh, e, material)
                                 ? &style.material_border
                                 : nullptr;
        if (color != nullptr) {
            out.lines.push_back({mesh.position(mesh.vertex(e, 0)), mesh.position(mesh.vertex(e, 1)),
                                 *color, style.feature_width_px});
        }
    }
}

std::vector<std::uint8_t> vertices_near(const Mesh& mesh, ElementRef element, int rings) {
    std::vector<std::uint8_t> near(mesh.vertices_size(), 0);
    if (!is_live(mesh, element)) {
        return near;
    }
    std::vector<Vertex> front;
    const auto take = [&](Vertex v) {
        if (near[v.idx()] == 0) {
            near[v.idx()] = 1;
            front.push_back(v);
        }
    };
    switch (element.kind) {
        case ElementRef::Kind::Vertex:
            take(Vertex(element.index));
            break;
        case ElementRef::Kind::Edge:
            take(mesh.vertex(Edge(element.index), 0));
            take(mesh.vertex(Edge(element.index), 1));
            break;
        case ElementRef::Kind::Halfedge:
            take(mesh.from_vertex(Halfedge(element.index)));
            take(mesh.to_vertex(Halfedge(element.index)));
            break;
        case ElementRef::Kind::Face:
            for (const Vertex v : mesh.vertices(Face(element.index))) {
                take(v);
            }
            break;
        case ElementRef::Kind::None:
            break;
    }
    for (int ring = 0; ring < rings; ++ring) {
        std::vector<Vertex> here;
        here.swap(front);
        for (const Vertex v : here) {
            if (!mesh.is_isolated(v)) {
                for (const Vertex w : mesh.vertices(v)) {
                    take(w);
                }
            }
        }
    }
    return near;
}

void add_loop_phase_marks(const Mesh& mesh, const OverlayStyle& style, OverlayBatch& out,
                          std::span<const std::uint8_t> near) {
    const auto shown = [&](Vertex v) { return near.empty() || near[v.idx()] != 0; };
    const auto target = mesh.get_property<Vertex, Vec3>(kLoopTarget);
    const auto has_target = mesh.get_property<Vertex, std::uint8_t>(kLoopHasTarget);
    if (!target || !has_target) {
        return;
    }
    const auto is_new = mesh.get_property<Vertex, std::uint8_t>(kLoopNewVertex);
    const auto new_edge = mesh.get_property<Edge, std::uint8_t>(kLoopNewEdge);
    const auto flipped = mesh.get_property<Edge, std::uint8_t>(kLoopFlippedEdge);
    const float thin = style.feature_width_px;
    for (Edge e : mesh.edges()) {
        const bool turned = flipped && flipped[e] != 0;
        if (!shown(mesh.vertex(e, 0)) || !shown(mesh.vertex(e, 1))) {
            continue;
        }
        if (turned || (new_edge && new_edge[e] != 0)) {
            out.lines.push_back({mesh.position(mesh.vertex(e, 0)), mesh.position(mesh.vertex(e, 1)),
                                 turned ? style.loop_flipped : style.loop_new, thin});
        }
    }
    if (const auto edge_point = mesh.get_property<Edge, Vec3>(kLoopEdgePoint)) {
        for (Edge e : mesh.edges()) {
            if (shown(mesh.vertex(e, 0)) && shown(mesh.vertex(e, 1))) {
                out.points.push_back({edge_point[e], style.loop_new, style.loop_point_px, true});
            }
        }
    }
    for (Vertex v : mesh.vertices()) {
        if (has_target[v] == 0 || !shown(v)) {
            continue;
        }
        if (is_new && is_new[v] != 0) {
            out.points.push_back({mesh.position(v), style.loop_new, style.loop_point_px});
        }
        // X-ray: on a convex mesh the new positions lie inside it.
        if (target[v] != mesh.position(v)) {
            out.lines.push_back({mesh.position(v), target[v], style.loop_target, thin, true});
        }
        out.points.push_back({target[v], style.loop_target, style.loop_point_px, true});
    }
}

namespace {

// add_element_highlight() with the mesh's diagonal given (faces' tints are lifted by it).
void highlight(const Mesh& mesh, ElementRef element, const Color& color, const OverlayStyle& style,
               double diagonal, OverlayBatch& out) {
    // The viewer may pass a stale reference (an element deleted or collected by an edit).
    if (!is_live(mesh, element)) {
        return;
    }
    switch (element.kind) {
        case ElementRef::Kind::None:
            return;
        case ElementRef::Kind::Vertex: {
            const Vertex v(element.index);
            out.points.push_back({mesh.position(v), color, style.vertex_size_px});
            return;
        }
        case ElementRef::Kind::Edge: {
            const Edge e(element.index);
            out.lines.push_back({mesh.position(mesh.vertex(e, 0)), mesh.position(mesh.vertex(e, 1)),
                                 color, style.edge_width_px});
            return;
        }
        case ElementRef::Kind::Halfedge:
            add_halfedge_arrow(mesh, Halfedge(element.index), color, style, out);
            return;
        case ElementRef::Kind::Face:
            add_face_tint(mesh, Face(element.index), color, style, diagonal, out);
            return;
    }
}

}  // namespace

void add_element_highlight(const Mesh& mesh, ElementRef element, const Color& color,
                           const OverlayStyle& style, OverlayBatch& out) {
    const bool face = element.kind == ElementRef::Kind::Face && is_live(mesh, element);
    highlight(mesh, element, color, style, face ? mesh.bounds().diagonal() : 0.0, out);
}

void add_element_highlights(const Mesh& mesh, std::span<const ElementRef> elements,
                            const Color& color, const OverlayStyle& style, OverlayBatch& out) {
    double diagonal = 0.0;
    for (const ElementRef& e : elements) {
        if (e.kind == ElementRef::Kind::Face) {
            diagonal = mesh.bounds().diagonal();
            break;
        }
    }
    for (const ElementRef& e : elements) {
        highlight(mesh, e, color, style, diagonal, out);
    }
}

void add_bezier_curve(const BezierCurve& curve, double t, int max_level, bool show_curve,
                      const OverlayStyle& style, OverlayBatch& out) {
    if (curve.control_points.empty()) {
        return;
    }
    // Only the levels shown: all of a long curve's levels hold n(n+1)/2 points.
    const int last = static_cast<int>(curve.control_points.size()) - 1;
    const int shown = max_level < 0 || max_level > last ? last : max_level;
    const auto levels = de_casteljau_levels(curve.control_points, t, shown);
    for (int k = 0; k <= shown; ++k) {
        const auto& level = levels[static_cast<std::size_t>(k)];
        if (k == last) {
            // The single point of the last level is B(t) itself: drawn once, as the evaluated
            // point, rather than also as a level disc.
            out.points.push_back(
                {flat(level[0]), style.evaluated_point, evaluated_point_size(style)});
            break;
        }
        const Color& color = style.levels.empty()
                                 ? style.curve
                                 : style.levels[static_cast<std::size_t>(k) % style.levels.size()];
        for (std::size_t i = 0; i + 1 < level.size(); ++i) {
            out.lines.push_back(
                {flat(level[i]), flat(level[i + 1]), color, level_line_width(style)});
        }
        for (const Vec3& p : level) {
            out.points.push_back({flat(p), color, level_point_size(style)});
        }
    }
    if (show_curve && curve.degree() >= 1) {
        const auto samples = curve.polyline(kCurveSamples);
        for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
            out.lines.push_back(
                {flat(samples[i]), flat(samples[i + 1]), style.curve, curve_line_width(style)});
        }
    }
}

void add_control_nets(std::span<const BezierPatch> patches, const OverlayStyle& style,
                      OverlayBatch& out) {
    for (const BezierPatch& patch : patches) {
        // A malformed patch (grid size disagreeing with its point count) is skipped rather
        // than read out of bounds.
        if (patch.rows < 1 || patch.cols < 1 ||
            patch.control_points.size() !=
                static_cast<std::size_t>(patch.rows) * static_cast<std::size_t>(patch.cols)) {
            continue;
        }
        const float width = net_line_width(style);
        for (int r = 0; r < patch.rows; ++r) {
            for (int c = 0; c + 1 < patch.cols; ++c) {
                out.lines.push_back({patch.cp(r, c), patch.cp(r, c + 1), style.control_net, width});
            }
        }
        for (int c = 0; c < patch.cols; ++c) {
            for (int r = 0; r + 1 < patch.rows; ++r) {
                out.lines.push_back({patch.cp(r, c), patch.cp(r + 1, c), style.control_net, width});
            }
        }
        for (const Vec3& p : patch.control_points) {
            out.points.push_back({p, style.control_net, net_point_size(style)});
        }
    }
}

int add_patch_steps(const BezierPatch& patch, double u, double v, int step,
                    const OverlayStyle& style, OverlayBatch& out) {
    if (patch.rows < 1 || patch.cols < 1 ||
        patch.control_points.size() !=
            static_cast<std::size_t>(patch.rows) * static_cast<std::size_t>(patch.cols)) {
        return 0;
    }
    const int u_steps = patch.cols - 1, v_steps = patch.rows - 1;
    const auto color = [&](int level) {
        return style.levels.empty()
                   ? style.curve
                   : style.levels[static_cast<std::size_t>(level) % style.levels.size()];
    };
    // A level's points joined in order, in its colour.
    const auto draw_level = [&](const std::vector<Vec3>& points, int level) {
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            out.lines.push_back(
                {points[i], points[i + 1], color(level), level_line_width(style), true});
        }
        for (const Vec3& p : points) {
            out.points.push_back({p, color(level), level_point_size(style), true});
        }
    };
    // Along u: every row at once, up to step min(step, u_steps); the rows' last points are
    // the curve in v.
    std::vector<Vec3> column;
    for (int r = 0; r < patch.rows; ++r) {
        const std::span<const Vec3> row(&patch.control_points[static_cast<std::size_t>(r) *
                                                              static_cast<std::size_t>(patch.cols)],
                                        static_cast<std::size_t>(patch.cols));
        const auto levels = de_casteljau_levels(row, u, u_steps);
        for (int k = 1; k <= std::min(step, u_steps); ++k) {
            draw_level(levels[static_cast<std::size_t>(k)], k);
        }
        column.push_back(levels.back()[0]);
    }
    if (step >= u_steps && v_steps > 0) {
        const auto levels = de_casteljau_levels(column, v, v_steps);
        for (int k = 0; k <= std::min(step - u_steps, v_steps); ++k) {
            const auto& level = levels[static_cast<std::size_t>(k)];
            if (k == v_steps) {
                out.points.push_back(
                    {level[0], style.evaluated_point, evaluated_point_size(style), true});
            } else {
                draw_level(level, u_steps + k);
            }
        }
    }
    return u_steps + v_steps;
}

void add_unit_square(const OverlayStyle& style, OverlayBatch& out) {
    const Vec3 c[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (int i = 0; i < 4; ++i) {
        out.lines.push_back({c[i], c[(i + 1) % 4], style.unit_square, 1.0f});
    }
}

}  // namespace meshedit
