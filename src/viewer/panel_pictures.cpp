// Pictures the panels draw with Dear ImGui: overlay labels over the 3-D view, and the
// rewiring panel's diagram (render/op_diagram.h), an OverlayBatch in the plane painted into
// a panel the way meshedit-render's GL overlay draws it headless.

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <vector>

#include "meshedit/overlay/label_layout.h"
#include "panels.h"

namespace meshedit::viewer {
namespace {

ImU32 rgba(const Color& c, float alpha_scale = 1.0f) {
    const auto channel = [](float x) {
        return static_cast<int>(255.0f * std::clamp(x, 0.0f, 1.0f));
    };
    return IM_COL32(channel(c[0]), channel(c[1]), channel(c[2]), channel(c[3] * alpha_scale));
}

// A label: light text on a dark box beside, left of or centred on `at` (window pixels).
// Where `label` would go alone beside its point `at`, as a box about its text.
LabelRect label_box(ImVec2 at, const OverlayBatch::Label& label) {
    const float gap = ImGui::GetFontSize() * 0.5f;
    const ImVec2 size = ImGui::CalcTextSize(label.text.c_str());
    ImVec2 corner(at.x + gap, at.y - size.y - 2.0f);
    if (label.side == OverlayBatch::Label::Side::Left) {
        corner.x = at.x - gap - size.x;
    } else if (label.side == OverlayBatch::Label::Side::Centre) {
        corner = ImVec2(at.x - 0.5f * size.x, at.y - 0.5f * size.y);
    }
    return {corner.x - 2.0f, corner.y - 1.0f, size.x + 4.0f, size.y + 2.0f};
}

// `labels` at their points `at`, none covering another (label_layout.h): a label with no
// free place near its point is left out. `width` × `height`: the area they must stay in,
// from `origin`.
void draw_placed_labels(ImDrawList* draw, const std::vector<const OverlayBatch::Label*>& labels,
                        const std::vector<ImVec2>& at, ImVec2 origin, ImVec2 area) {
    std::vector<LabelSpot> spots;
    for (std::size_t i = 0; i < labels.size(); ++i) {
        LabelRect r = label_box(at[i], *labels[i]);
        r.x -= origin.x;
        r.y -= origin.y;
        spots.push_back({r, labels[i]->side, labels[i]->fixed});
    }
    const auto placed = place_labels(spots, ImGui::GetFontSize() * 0.5f, -2.0f, area.x, area.y);
    for (std::size_t i = 0; i < labels.size(); ++i) {
        if (!placed[i]) {
            continue;
        }
        const ImVec2 lo(origin.x + placed[i]->x, origin.y + placed[i]->y);
        const ImVec2 hi(lo.x + placed[i]->w, lo.y + placed[i]->h);
        // A label the surface hides is drawn faded, as the x-ray marks are.
        const float fade = labels[i]->hidden ? 0.4f : 1.0f;
        draw->AddRectFilled(lo, hi, IM_COL32(13, 13, 20, static_cast<int>(180 * fade)), 2.0f);
        const Color& c = labels[i]->color;
        const Color light{0.5f + 0.5f * c[0], 0.5f + 0.5f * c[1], 0.5f + 0.5f * c[2], fade};
        draw->AddText(ImVec2(lo.x + 2.0f, lo.y + 1.0f), rgba(light), labels[i]->text.c_str());
    }
}

// `batch` (z = 0) with [min, max] fitted into the rectangle at `corner` of `size`.
void draw_batch_2d(ImDrawList* draw, const OverlayBatch& batch, const Vec3& min, const Vec3& max,
                   ImVec2 corner, ImVec2 size) {
    const double scale = std::min(size.x / (max.x - min.x), size.y / (max.y - min.y));
    const double left = corner.x + 0.5 * (size.x - scale * (max.x - min.x));
    const double top = corner.y + 0.5 * (size.y - scale * (max.y - min.y));
    const auto to_screen = [&](const Vec3& p) {
        return ImVec2(static_cast<float>(left + scale * (p.x - min.x)),
                      static_cast<float>(top + scale * (max.y - p.y)));
    };
    // Face tints are fans: antialiased, their shared sides would show as seams.
    const ImDrawListFlags flags = draw->Flags;
    draw->Flags &= ~ImDrawListFlags_AntiAliasedFill;
    for (const auto& t : batch.triangles) {
        draw->AddTriangleFilled(to_screen(t.a), to_screen(t.b), to_screen(t.c), rgba(t.color));
    }
    draw->Flags = flags;
    for (const auto& l : batch.lines) {
        draw->AddLine(to_screen(l.a), to_screen(l.b), rgba(l.color), l.width_px);
    }
    for (const auto& a : batch.arrowheads) {
        const ImVec2 tip = to_screen(a.tip), tail = to_screen(a.tail);
        const float dx = tip.x - tail.x, dy = tip.y - tail.y;
        const float length = std::max(std::sqrt(dx * dx + dy * dy), 1e-6f);
        const float ux = dx / length, uy = dy / length;
        const float back = std::min(a.length_px, length), half = a.half_width_px;
        const ImVec2 base(tip.x - ux * back, tip.y - uy * back);
        draw->AddTriangleFilled(tip, ImVec2(base.x - uy * half, base.y + ux * half),
                                ImVec2(base.x + uy * half, base.y - ux * half), rgba(a.color));
    }
    for (const auto& p : batch.points) {
        draw->AddCircleFilled(to_screen(p.p), 0.5f * p.size_px, rgba(p.color));
    }
    std::vector<const OverlayBatch::Label*> labels;
    std::vector<ImVec2> at;
    for (const auto& label : batch.labels) {
        labels.push_back(&label);
        at.push_back(to_screen(label.at));
    }
    draw_placed_labels(draw, labels, at, corner, size);
}

}  // namespace

void draw_labels(const std::vector<OverlayBatch::Label>& labels, const Camera& camera, int width,
                 int height) {
    std::vector<const OverlayBatch::Label*> shown;
    std::vector<ImVec2> points;
    for (const OverlayBatch::Label& label : labels) {
        if (const auto at = project_to_pixels(camera, label.at, width, height)) {
            shown.push_back(&label);
            points.emplace_back(at->x, at->y);
        }
    }
    draw_placed_labels(ImGui::GetBackgroundDrawList(), shown, points, ImVec2(0, 0),
                       ImVec2(static_cast<float>(width), static_cast<float>(height)));
}

void Panels::draw_field(Editor& editor, const FieldDisplay& field, PanelRequests& requests) {
    if (!ImGui::CollapsingHeader("Field (Alt+F)", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    const FieldInfo& info = *field.info;
    ImGui::Text("%s%s%s%s", std::string(info.title).c_str(), info.unit.empty() ? "" : " (",
                std::string(info.unit).c_str(), info.unit.empty() ? "" : ")");
    ImGui::TextWrapped("%s", std::string(info.description).c_str());
    if (info.name == "distance") {
        ImGui::Text("from vertex %u (select a vertex to move it)", field.source.idx());
    }
    // The colour bar, its ends' values under it.
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    const float height = ImGui::GetFontSize();
    constexpr int kSteps = 32;
    for (int i = 0; i < kSteps; ++i) {
        const float x0 = corner.x + width * static_cast<float>(i) / kSteps;
        const float x1 = corner.x + width * static_cast<float>(i + 1) / kSteps;
        draw->AddRectFilledMultiColor(
            ImVec2(x0, corner.y), ImVec2(x1, corner.y + height),
            rgba(colormap_color(field.coloring.map, static_cast<double>(i) / kSteps)),
            rgba(colormap_color(field.coloring.map, static_cast<double>(i + 1) / kSteps)),
            rgba(colormap_color(field.coloring.map, static_cast<double>(i + 1) / kSteps)),
            rgba(colormap_color(field.coloring.map, static_cast<double>(i) / kSteps)));
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::Text("%.4g", field.coloring.lo);
    char hi[32];
    std::snprintf(hi, sizeof hi, "%.4g", field.coloring.hi);
    ImGui::SameLine(std::max(0.0f, width - ImGui::CalcTextSize(hi).x));
    ImGui::TextUnformatted(hi);
    char summary[160];
    std::snprintf(summary, sizeof summary, "min %.4g, mean %.4g, max %.4g (%zu values)",
                  field.stats.min, field.stats.mean, field.stats.max, field.stats.count);
    text_wrapped_at_spaces(summary);

    // Under the cursor: the hovered element's value, or those of the field's elements it
    // touches (a face's corners for a vertex field, say).
    const ElementRef& hover = editor.hover();
    const auto near = field_values_at(editor.mesh(), info.site, field.values, hover);
    if (near.empty()) {
        text_wrapped_at_spaces("hover the mesh to read the values under the cursor", true);
    } else {
        ImGui::TextUnformatted("under the cursor:");
        constexpr std::size_t kShown = 6;
        for (std::size_t i = 0; i < std::min(near.size(), kShown); ++i) {
            ImGui::Text("  %s %u: %.6g", kind_name(near[i].first.kind), near[i].first.index,
                        near[i].second);
        }
        if (near.size() > kShown) {
            ImGui::TextDisabled("  … and %zu more", near.size() - kShown);
        }
    }

    // A histogram of the values within the range.
    constexpr int kBins = 40;
    std::array<float, kBins> bins{};
    const double span = field.coloring.hi - field.coloring.lo;
    for (const double x : field.values) {
        if (std::isfinite(x) && span > 0.0) {
            const int bin = static_cast<int>((x - field.coloring.lo) / span * kBins);
            bins[static_cast<std::size_t>(std::clamp(bin, 0, kBins - 1))] += 1.0f;
        }
    }
    ImGui::PlotHistogram("##histogram", bins.data(), kBins, 0, nullptr, 0.0f, FLT_MAX,
                         ImVec2(width, 3.0f * height));

    ViewState& view = editor.view();
    const std::string current =
        view.colormap ? std::string(colormap_name(*view.colormap)) : "default";
    if (ImGui::BeginCombo("colour map", current.c_str())) {
        if (ImGui::Selectable("default", !view.colormap)) {
            view.colormap.reset();
            requests.field_changed = true;
        }
        for (const ColorMap map : {ColorMap::Viridis, ColorMap::Magma, ColorMap::Diverging}) {
            if (ImGui::Selectable(std::string(colormap_name(map)).c_str(), view.colormap == map)) {
                view.colormap = map;
                requests.field_changed = true;
            }
        }
        ImGui::EndCombo();
    }
    float percent = 100.0f * view.field_clip;
    if (ImGui::SliderFloat("clip %", &percent, 0.0f, 25.0f, "%.1f")) {
        view.field_clip = percent / 100.0f;
        requests.field_changed = true;
    }
}

// The field's legend in the view's bottom-right corner, as meshedit-render draws it: the
// title and unit, the colour bar, the values at its ends. Shown with the info panel hidden too.
void Panels::draw_field_legend(const FieldDisplay& field) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const FieldInfo& info = *field.info;
    const std::string title =
        std::string(info.title) + (info.unit.empty() ? "" : " (" + std::string(info.unit) + ")");
    const float font = ImGui::GetFontSize();
    const float width = std::max(200.0f * scale_, ImGui::CalcTextSize(title.c_str()).x);
    const float bar = 0.8f * font;
    const ImVec2 corner(viewport->WorkPos.x + viewport->WorkSize.x - width - font,
                        viewport->WorkPos.y + viewport->WorkSize.y - 3.6f * font - bar);
    draw->AddRectFilled(ImVec2(corner.x - 0.5f * font, corner.y - 0.4f * font),
                        ImVec2(corner.x + width + 0.5f * font, corner.y + 2.6f * font + bar),
                        IM_COL32(246, 246, 248, 220), 4.0f);
    draw->AddText(corner, IM_COL32(30, 30, 40, 255), title.c_str());
    const float top = corner.y + 1.2f * font;
    constexpr int kSteps = 32;
    for (int i = 0; i < kSteps; ++i) {
        const float x0 = corner.x + width * static_cast<float>(i) / kSteps;
        const float x1 = corner.x + width * static_cast<float>(i + 1) / kSteps;
        const ImU32 left = rgba(colormap_color(field.coloring.map, double(i) / kSteps));
        const ImU32 right = rgba(colormap_color(field.coloring.map, double(i + 1) / kSteps));
        draw->AddRectFilledMultiColor(ImVec2(x0, top), ImVec2(x1, top + bar), left, right, right,
                                      left);
    }
    char lo[32], hi[32];
    std::snprintf(lo, sizeof lo, "%.3g", field.coloring.lo);
    std::snprintf(hi, sizeof hi, "%.3g", field.coloring.hi);
    draw->AddText(ImVec2(corner.x, top + bar + 0.2f * font), IM_COL32(30, 30, 40, 255), lo);
    draw->AddText(ImVec2(corner.x + width - ImGui::CalcTextSize(hi).x, top + bar + 0.2f * font),
                  IM_COL32(30, 30, 40, 255), hi);
}

void Panels::draw_shader_errors() {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x * 0.5f,
                                   viewport->WorkPos.y + viewport->WorkSize.y - 90.0f * scale_),
                            ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowSize(ImVec2(std::min(720.0f * scale_, viewport->WorkSize.x - 20.0f), 0.0f));
    if (ImGui::Begin("Shader errors (Ctrl+R recompiles)")) {
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 140, 120, 255));
        ImGui::TextWrapped("%s", shader_errors_.c_str());
        ImGui::PopStyleColor();
    }
    remember_rect();
    ImGui::End();
}

void Panels::draw_diagram(const OpDiagram& diagram) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const ImVec2 size(500.0f * scale_, 430.0f * scale_);
    ImGui::SetNextWindowPos(
        ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10.0f, viewport->WorkPos.y + 10.0f),
        ImGuiCond_FirstUseEver, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowSize(size, ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Rewiring (Alt+R)")) {
        // Against the window's right edge (where it opens): the view keeps room for it.
        const float right = ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
        const float window_right = viewport->WorkPos.x + viewport->WorkSize.x;
        if (right >= window_right - 40.0f * scale_) {
            diagram_left_ = ImGui::GetWindowPos().x;
        }
        ImGui::TextUnformatted(diagram.title.c_str());
        const ImVec2 corner = ImGui::GetCursorScreenPos();
        const ImVec2 room = ImGui::GetContentRegionAvail();
        const ImVec2 canvas(room.x, std::max(room.y * 0.62f, 120.0f * scale_));
        ImDrawList* draw = ImGui::GetWindowDrawList();
        draw->AddRectFilled(corner, ImVec2(corner.x + canvas.x, corner.y + canvas.y),
                            IM_COL32(246, 246, 244, 255), 4.0f);
        draw_batch_2d(draw, diagram.picture, diagram.min, diagram.max, corner, canvas);
        ImGui::Dummy(canvas);
        if (ImGui::BeginChild("changes")) {
            for (const std::string& line : diagram.changes) {
                ImGui::TextUnformatted(line.c_str());
            }
        }
        ImGui::EndChild();
    }
    remember_rect();
    ImGui::End();
}

}  // namespace meshedit::viewer
