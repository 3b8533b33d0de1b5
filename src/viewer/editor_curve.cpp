// The editor's curve and surface commands: de Casteljau levels and t, control points added
// and removed, tessellation density and control nets.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "meshedit/core/budget.h"
#include "meshedit/core/normals.h"
#include "meshedit/overlay/overlay.h"
#include "meshedit/viewer/editor.h"

namespace meshedit::viewer {

namespace {

/// Surface tessellation densities the +/- keys step through.
constexpr std::array<int, 12> kDensities{1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64};

/// The control point a curve command acts on: the selected one, else the last.
std::size_t acted_on(const ElementRef& s, std::size_t n) {
    return (s.kind == ElementRef::Kind::Vertex && s.index < n) ? std::size_t{s.index} : n - 1;
}

}  // namespace

Outcome Editor::run_curve(Action action) {
    const std::size_t n = doc_.curve.control_points.size();
    const int last_level = static_cast<int>(n) - 1;
    const int level = view_.level < 0 ? last_level : std::min(view_.level, last_level);
    const auto level_message = [&] {
        return "de Casteljau level " + std::to_string(view_.level) + " of " +
               std::to_string(last_level);
    };
    const auto no_refusal = [] { return OpStatus::ok(); };

    switch (action.command) {
        case Command::LevelDown:
            if (level >= last_level) {
                return refused("already at the last level (B(t))");
            }
            if (const auto over = over_budget(128.0 * de_casteljau_level_points(n, level + 1))) {
                return refused("showing level " + std::to_string(level + 1) + " " + *over);
            }
            view_.level = level + 1;
            return {kDisplay, level_message()};
        case Command::LevelUp:
            if (level <= 0) {
                return refused("already at the control polygon");
            }
            view_.level = level - 1;
            return {kDisplay, level_message()};
        case Command::ToggleCurve:
            view_.show_curve = !view_.show_curve;
            return {kDisplay, view_.show_curve ? "curve shown" : "curve hidden"};
        case Command::DecreaseT:
        case Command::IncreaseT: {
            const double step = action.command == Command::IncreaseT ? 0.01 : -0.01;
            // Rounded to 1e-9 so a hundred steps land exactly on 0 and 1.
            return set_t(std::round((view_.t + step) * 1e9) / 1e9);
        }
        case Command::AddPoint: {
            // Midway to the next point, or past the last one by half the last segment.
            const bool at_bottom = level >= last_level;
            Outcome outcome = edit(no_refusal, [&](Document& doc) {
                std::vector<Vec3>& points = doc.curve.control_points;
                if (points.empty()) {
                    points.push_back(Vec3{});
                    return Edited{kCurve | kSelection | kDisplay,
                                  "added control point 0 (1 points)",
                                  ElementRef::vertex(Vertex(0)),
                                  {}};
                }
                const std::size_t i = acted_on(doc.selection, n);
                Vec3 p = i + 1 < n ? 0.5 * (points[i] + points[i + 1])
                         : n >= 2  ? points[i] + 0.5 * (points[i] - points[i - 1])
                                   : points[i] + Vec3{0.5, 0.0, 0.0};
                // Rounded to 1e-9, as dragged points are rounded to the pixel: a midpoint of
                // 0.7 and 1.0 is saved as 0.85, not 0.8500000000000001 (issue 40).
                for (int k = 0; k < 3; ++k) {
                    p[k] = std::round(p[k] * 1e9) / 1e9;
                }
                points.insert(points.begin() + static_cast<std::ptrdiff_t>(i + 1), p);
                return Edited{kCurve | kSelection | kDisplay,
                              "added control point " + std::to_string(i + 1) + " (" +
                                  std::to_string(points.size()) + " points)",
                              ElementRef::vertex(Vertex(static_cast<std::uint32_t>(i + 1))),
                              {}};
            });
            if (n > 0 && at_bottom && view_.level >= 0) {
                view_.level = last_level + 1;  // keep showing B(t)
            }
            return outcome;
        }
        case Command::RemovePoint: {
            const auto check = [&] {
                return n <= 2 ? OpStatus::refused("a curve needs at least 2 control points")
                              : OpStatus::ok();
            };
            Outcome outcome = edit(check, [&](Document& doc) {
                const std::size_t i = acted_on(doc.selection, n);
                doc.curve.control_points.erase(doc.curve.control_points.begin() +
                                               static_cast<std::ptrdiff_t>(i));
                return Edited{kCurve | kSelection | kDisplay,
                              "removed control point " + std::to_string(i) + " (" +
                                  std::to_string(n - 1) + " points)",
                              ElementRef{},
                              {}};
            });
            if (!outcome.refused) {
                view_.level = std::min(view_.level, last_level - 1);
            }
            return outcome;
        }
        default:
            break;
    }
    return {};
}

Outcome Editor::set_t(double t) {
    if (std::optional<Outcome> busy = refuse_if_busy()) {
        return *busy;
    }
    if (doc_.mode != Mode::Curve) {
        return refused("t belongs to curves");
    }
    if (!std::isfinite(t)) {
        return refused("t must be a number");
    }
    view_.t = std::clamp(t, 0.0, 1.0);
    char buf[32];
    std::snprintf(buf, sizeof buf, "t = %.2f", view_.t);
    return {kDisplay, buf};
}

namespace {

// Where a selected element is: a vertex's position, an edge's (or halfedge's) midpoint, a
// face's centre; nothing for no (or a stale) selection.
std::optional<Vec3> point_of(const Mesh& mesh, const ElementRef& e) {
    if (!is_live(mesh, e)) {
        return std::nullopt;
    }
    switch (e.kind) {
        case ElementRef::Kind::Vertex:
            return mesh.position(Vertex(e.index));
        case ElementRef::Kind::Edge:
        case ElementRef::Kind::Halfedge: {
            const Halfedge h = e.kind == ElementRef::Kind::Edge ? Mesh::halfedge(Edge(e.index), 0)
                                                                : Halfedge(e.index);
            return 0.5 * (mesh.position(mesh.from_vertex(h)) + mesh.position(mesh.to_vertex(h)));
        }
        case ElementRef::Kind::Face:
            return face_centroid(mesh, Face(e.index));
        default:
            return std::nullopt;
    }
}

}  // namespace

// Shift+U: the first press finds the patch and (u, v) nearest the selection (the tessellated
// point closest to the selected vertex, edge midpoint or face centre; patch 0 at the middle
// when nothing is selected), each press shows one more de Casteljau step, past the last off.
Outcome Editor::step_patch() {
    if (doc_.patches.empty()) {
        return refused("no patches to evaluate");
    }
    if (view_.patch_step < 0) {
        view_.patch = 0;
        view_.patch_u = view_.patch_v = 0.5;
        if (const std::optional<Vec3> at = point_of(doc_.mesh, doc_.selection)) {
            constexpr int kGrid = 32;
            double best = INFINITY;
            for (std::size_t k = 0; k < doc_.patches.size(); ++k) {
                for (int j = 0; j <= kGrid; ++j) {
                    for (int i = 0; i <= kGrid; ++i) {
                        const double u = double(i) / kGrid, v = double(j) / kGrid;
                        const double d = distance(doc_.patches[k].evaluate(u, v), *at);
                        if (d < best) {
                            best = d;
                            view_.patch = k;
                            view_.patch_u = u;
                            view_.patch_v = v;
                        }
                    }
                }
            }
        }
    }
    OverlayBatch scratch;
    const int steps = add_patch_steps(doc_.patches[view_.patch], view_.patch_u, view_.patch_v,
                                      1 << 20, OverlayStyle(), scratch);
    if (++view_.patch_step > steps) {  // steps 0 (the net) … steps (S(u, v))
        view_.patch_step = -1;
        return {kDisplay, "patch evaluation off"};
    }
    const BezierPatch& patch = doc_.patches[view_.patch];
    const int along_u = patch.cols - 1;
    char where[96];
    std::snprintf(where, sizeof where, "patch %zu at (u, v) = (%.3g, %.3g): ", view_.patch,
                  view_.patch_u, view_.patch_v);
    const std::string what =
        view_.patch_step == 0         ? "the control net"
        : view_.patch_step <= along_u ? "level " + std::to_string(view_.patch_step) + " along u"
        : view_.patch_step + 1 < steps
            ? "level " + std::to_string(view_.patch_step - along_u) + " along v"
            : "S(u, v)";
    return {kDisplay, where + what + " (step " + std::to_string(view_.patch_step) + " of " +
                          std::to_string(steps) + "; Shift+U: next)"};
}

Outcome Editor::run_surface(Command command) {
    if (command == Command::PatchStep) {
        return step_patch();
    }
    if (command == Command::ToggleNets) {
        view_.show_nets = !view_.show_nets;
        return {kDisplay, view_.show_nets ? "control nets shown" : "control nets hidden"};
    }
    int density = 0;
    if (command == Command::DensityUp) {
        const auto it = std::upper_bound(kDensities.begin(), kDensities.end(), doc_.density);
        if (it == kDensities.end()) {
            return refused("density is already at the maximum (" +
                           std::to_string(kDensities.back()) + ")");
        }
        density = *it;
    } else {
        const auto it = std::lower_bound(kDensities.begin(), kDensities.end(), doc_.density);
        if (it == kDensities.begin()) {
            return refused("density is already at the minimum (" +
                           std::to_string(kDensities.front()) + ")");
        }
        density = *(it - 1);
    }
    const bool had_edits = pristine_revisions_.count(doc_.revision) == 0;
    Outcome outcome = edit([] { return OpStatus::ok(); },
                           [&](Document& doc) {
                               TessellationOptions options;
                               options.density = density;
                               doc.mesh = tessellate(doc.patches, options);
                               doc.density = density;
                               return Edited{kTopology | kSelection,
                                             "density " + std::to_string(density) + ": " +
                                                 std::to_string(doc.mesh.n_faces()) + " faces" +
                                                 (had_edits ? " (mesh edits replaced)" : ""),
                                             ElementRef{},
                                             {}};
                           });
    if (!outcome.refused) {
        pristine_revisions_.insert(doc_.revision);
    }
    return outcome;
}

}  // namespace meshedit::viewer
