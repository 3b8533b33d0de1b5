#pragma once
/// \file
/// Overlay geometry: everything drawn on top of the shaded mesh (selection and hover
/// highlights, boundary and crease edges, halfedge arrows, Bezier control polygons, de
/// Casteljau levels, curves, patch control nets) as plain coloured points, lines and
/// triangles in world space. Built on the CPU without any GL, so it is unit-tested directly;
/// the renderer draws any OverlayBatch the same way.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "meshedit/bezier/bezier_curve.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/stencil.h"
#include "meshedit/repair/problems.h"

namespace meshedit {

/// Linear RGBA colour, components in [0, 1].
using Color = std::array<float, 4>;

/// Coloured primitives in world space. Points are drawn as screen-space discs of
/// `point_size` pixels, lines as screen-space quads `line_width` pixels wide.
struct OverlayBatch {
    /// `xray`: drawn over the surface even where the surface hides it (a point inside a
    /// closed mesh, marks on its far side).
    struct Point {
        Vec3 p;
        Color color;
        float size_px;
        bool xray = false;
    };
    struct Line {
        Vec3 a, b;
        Color color;
        float width_px;
        bool xray = false;
    };
    struct Triangle {
        Vec3 a, b, c;
        Color color;
    };
    /// A filled arrowhead sized in pixels, whatever the zoom: its point at `tip`, its axis
    /// along `tail` → `tip` on screen, `length_px` long (at most the tail–tip distance on
    /// screen) and `half_width_px` wide on each side of the axis. `across` (a unit vector
    /// perpendicular to the axis; zero if there is none) spans, with the axis, the plane the
    /// head lies in, which gives its corners their depth: a head flat on screen would sink
    /// into a face seen at a slant.
    struct Arrowhead {
        Vec3 tip, tail, across;
        Color color;
        float length_px;
        float half_width_px;
    };
    std::vector<Point> points;
    std::vector<Line> lines;
    std::vector<Triangle> triangles;
    std::vector<Arrowhead> arrowheads;
    /// Text beside a point (a stencil's weights): drawn by the window with Dear ImGui and by
    /// meshedit-render on the finished image (render/labels.h), never by the GL renderer.
    struct Label {
        Vec3 at;
        std::string text;
        Color color;
        /// Where the text sits: starting right of the point, ending left of it, or centred
        /// on it.
        enum class Side { Right, Left, Centre };
        Side side = Side::Right;
        /// A title or a row of a list rather than a name beside a point: drawn where it is,
        /// never moved or left out; the other labels make room (label_layout.h).
        bool fixed = false;
        /// The surface is between the eye and its point (hide_labels_behind()): drawn faded
        /// and placed after the others.
        bool hidden = false;
    };
    std::vector<Label> labels;

    void clear() {
        points.clear();
        lines.clear();
        triangles.clear();
        arrowheads.clear();
        labels.clear();
    }
    bool empty() const {
        return points.empty() && lines.empty() && triangles.empty() && arrowheads.empty() &&
               labels.empty();
    }
    void append(const OverlayBatch& other);
};

/// The overlay palette (one place, so viewer, headless renders and docs agree).
struct OverlayStyle {
    Color selected{1.0f, 0.55f, 0.0f, 1.0f};          ///< orange
    Color hovered{0.2f, 0.75f, 1.0f, 1.0f};           ///< light blue
    Color boundary{0.85f, 0.1f, 0.1f, 1.0f};          ///< red
    Color crease{0.1f, 0.55f, 0.1f, 1.0f};            ///< green
    Color uv_seam{0.95f, 0.55f, 0.1f, 1.0f};          ///< orange: texture coordinates split here
    Color material_border{0.45f, 0.3f, 0.85f, 1.0f};  ///< violet: two materials meet
    float vertex_size_px = 12.0f;
    float control_point_px = 16.0f;  ///< a hovered or selected curve control point
    float edge_width_px = 4.0f;
    /// A selected or hovered halfedge's arrowhead: long and wide enough to read at any zoom.
    float arrowhead_length_px = 16.0f;
    float arrowhead_half_width_px = 7.0f;
    float feature_width_px = 2.5f;  ///< boundary and crease edges
    float face_tint_alpha = 0.45f;
    /// Halfedge arrows sit inside their face: pulled this fraction toward the face centre.
    float halfedge_inset = 0.2f;
    /// Colours of the de Casteljau levels: level k uses levels[k % size].
    std::vector<Color> levels{{0.3f, 0.3f, 0.3f, 1.0f},    {0.1f, 0.45f, 0.9f, 1.0f},
                              {0.1f, 0.65f, 0.3f, 1.0f},   {0.85f, 0.55f, 0.05f, 1.0f},
                              {0.75f, 0.15f, 0.55f, 1.0f}, {0.0f, 0.6f, 0.65f, 1.0f}};
    Color curve{0.05f, 0.05f, 0.05f, 1.0f};
    Color evaluated_point{0.9f, 0.1f, 0.1f, 1.0f};
    Color control_net{0.2f, 0.2f, 0.75f, 1.0f};
    Color unit_square{0.72f, 0.74f, 0.78f, 1.0f};
    /// A phased Loop (core/loop_steps.h): where vertices will go, what the split made, what
    /// the flips turned.
    Color loop_target{0.0f, 0.55f, 0.6f, 1.0f};    ///< teal: new positions and the way there
    Color loop_new{0.6f, 0.2f, 0.75f, 1.0f};       ///< purple: edge points, new vertices, edges
    Color loop_flipped{0.95f, 0.75f, 0.0f, 1.0f};  ///< yellow: flipped edges
    /// A subdivision stencil (core/stencil.h): its vertices and their weights.
    Color stencil{0.85f, 0.1f, 0.6f, 1.0f};  ///< magenta
    float loop_point_px = 8.0f;
    /// The Problems panel's places (repair/problems.h), in ProblemKind's order: load cuts
    /// magenta, holes yellow, degenerate faces cyan, inside-out parts blue, small parts
    /// brown, faces passing through each other violet.
    std::array<Color, kProblemKinds> problems{{{0.95f, 0.1f, 0.75f, 1.0f},
                                               {1.0f, 0.8f, 0.0f, 1.0f},
                                               {0.0f, 0.85f, 0.85f, 1.0f},
                                               {0.15f, 0.3f, 1.0f, 1.0f},
                                               {0.7f, 0.4f, 0.1f, 1.0f},
                                               {0.55f, 0.2f, 1.0f, 1.0f}}};
    float problem_width_px = 5.0f;  ///< a hole's loop
};

/// Marks in the view the places `report` lists (the Problems panel, `render --problems`), each
/// in its kind's colour and drawn through the surface: a load cut's vertex as a dot, a hole as
/// its whole boundary loop, a degenerate face as a dot at its centre and its tint, an inside-
/// out or small part as every face of the part tinted, a face passing through another tinted.
void add_problem_marks(const Mesh& mesh, const ProblemReport& report, const OverlayStyle& style,
                       OverlayBatch& out);

/// Boundary edges and crease edges ("e:crease") of `mesh`, with `seams` its UV seams and with
/// `borders` its material borders (attribute_summary.h), each edge once in the first of
/// those colours that applies.
void add_feature_edges(const Mesh& mesh, const OverlayStyle& style, OverlayBatch& out,
                       bool seams = false, bool borders = false);

/// The state of a phased Loop (core/loop_steps.h), if one is under way: after phase 1 every
/// vertex's new position (a teal dot, and a line from where it is) and every edge point
/// (purple), x-ray (they lie inside a convex mesh); after phase 2 the new vertices and the new
/// edges across the old faces (purple); after phase 3 the flipped edges (yellow). Nothing when no
/// phased Loop is under way.
/// `near`: by vertex index, which vertices' marks to draw (an edge's when both ends are);
/// empty: all of them.
void add_loop_phase_marks(const Mesh& mesh, const OverlayStyle& style, OverlayBatch& out,
                          std::span<const std::uint8_t> near = {});
/// By vertex index, 1 for the vertices of `element` and those within `rings` edges of them.
std::vector<std::uint8_t> vertices_near(const Mesh& mesh, ElementRef element, int rings);

/// A subdivision stencil: a disc on every contributing vertex labelled with its weight
/// (weight_label()), a thin line from each to the new point, and the new point (teal) with
/// the rule's name. Nothing for a stencil that is not ok().
void add_stencil_marks(const Mesh& mesh, const Stencil& stencil, const OverlayStyle& style,
                       OverlayBatch& out);

/// A weight as a reader checks it against the formula: an exact small fraction ("3/8",
/// "1/16", "-1/8") when there is one with a denominator up to 4096, else 4 significant digits.
std::string weight_label(double weight);

/// The highlight of one element in `color`: a vertex disc; an edge as a thick line; a
/// halfedge as an arrow (a line plus an Arrowhead sized in pixels) inset into its face towards the
/// face centre, as in CS184 (a boundary halfedge is inset towards the other side's face,
/// mirrored); a face as a translucent tint of its polygon (fan triangles, offset slightly
/// along the normal so it wins the depth test).
void add_element_highlight(const Mesh& mesh, ElementRef element, const Color& color,
                           const OverlayStyle& style, OverlayBatch& out);
/// The same for many elements (a region's selection): the mesh's size, which lifts the faces'
/// tints, is measured once, not once per face.
void add_element_highlights(const Mesh& mesh, std::span<const ElementRef> elements,
                            const Color& color, const OverlayStyle& style, OverlayBatch& out);

/// A Bezier curve at parameter `t`: the control polygon (level 0) and de Casteljau levels
/// 1 … `max_level` (each in its style colour, with its points), the evaluated point B(t)
/// when max_level reaches the last level, and the whole curve (sampled) if `show_curve`.
/// `max_level` < 0 means all levels.
void add_bezier_curve(const BezierCurve& curve, double t, int max_level, bool show_curve,
                      const OverlayStyle& style, OverlayBatch& out);

/// The faint outline of the unit square [0,1]² that curves are drawn in (curve mode).
void add_unit_square(const OverlayStyle& style, OverlayBatch& out);

/// The control nets of `patches`: the rows and columns of each control grid as lines, the
/// control points as small discs.
void add_control_nets(std::span<const BezierPatch> patches, const OverlayStyle& style,
                      OverlayBatch& out);

/// What a frame shows, apart from the camera and the shading options.
struct SceneContent {
    /// A mesh (mesh and surface documents), or nullptr for a curve.
    const Mesh* mesh = nullptr;
    /// Surface documents: the patches, whose control nets show when `show_nets`.
    std::span<const BezierPatch> patches;
    bool show_nets = false;
    /// A curve document: the curve at parameter `t`, de Casteljau levels up to `level`
    /// (−1: all, with B(t)), the whole curve when `show_curve`.
    const BezierCurve* curve = nullptr;
    double t = 0.5;
    int level = -1;
    bool show_curve = true;
    /// Mesh elements, or a curve's control points as Vertex refs.
    ElementRef selected;
    ElementRef hovered;
    /// Meshes: elements selected besides `selected` (drawn alike).
    std::span<const ElementRef> also_selected;
    /// Meshes: the stencil view's scheme; the hovered element's stencil is drawn (the
    /// selected one's when nothing is hovered).
    std::optional<StencilScheme> stencil;
    /// Meshes: a phased Loop's marks only within two rings of `selected` (dense meshes, where
    /// every vertex's target at once is a blur); all of them when nothing is selected.
    bool marks_near_selection = false;
    /// Meshes: the problems to mark (add_problem_marks()), or none.
    const ProblemReport* problems = nullptr;
    /// Meshes: UV seams and material borders among the feature lines (shown with the UV
    /// checker and with material colours).
    bool uv_seams = false;
    bool material_borders = false;
    /// Surfaces: patch `steps_patch` evaluated at (steps_u, steps_v) by de Casteljau up to
    /// step `steps` (add_patch_steps()); no steps when negative.
    int steps = -1;
    std::size_t steps_patch = 0;
    double steps_u = 0.5, steps_v = 0.5;
};

/// A Bezier patch evaluated at (u, v) by de Casteljau, as BezierPatch::evaluate() does it,
/// one step at a time (docs/teaching.md): step 0 is the control net; steps 1 … cols − 1 are
/// the levels along u on every row at once, until each row is one point (the control points
/// of the curve in v); the next rows − 1 steps are the levels along v on that curve, the last
/// one's point S(u, v). A larger step shows everything. \return how many steps there are.
int add_patch_steps(const BezierPatch& patch, double u, double v, int step,
                    const OverlayStyle& style, OverlayBatch& out);

/// Everything the overlay shows besides feature edges: control nets, the hovered and the
/// selected element (a hovered element that is also selected shows as selected), the stencil
/// of the hovered (else selected) element when `stencil` is set, or for a
/// curve the unit square, the curve with its levels and the marked control points.
void add_scene_marks(const SceneContent& scene, const OverlayStyle& style, OverlayBatch& out);

}  // namespace meshedit
