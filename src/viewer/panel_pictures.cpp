// Pictures the panels draw with Dear ImGui: overlay labels over the 3-D view, and the
// rewiring panel's diagram (render/op_diagram.h), an OverlayBatch in the plane painted into
// a panel the way meshedit-render's GL overlay draws it headless.

#include <imgui.h>

#include <algorithm>
#include <cmath>

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
void draw_label(ImDrawList* draw, ImVec2 at, const OverlayBatch::Label& label) {
    const float gap = ImGui::GetFontSize() * 0.5f;
    const ImVec2 size = ImGui::CalcTextSize(label.text.c_str());
    ImVec2 corner(at.x + gap, at.y - size.y - 2.0f);
    if (label.side == OverlayBatch::Label::Side::Left) {
        corner.x = at.x - gap - size.x;
    } else if (label.side == OverlayBatch::Label::Side::Centre) {
        corner = ImVec2(at.x - 0.5f * size.x, at.y - 0.5f * size.y);
    }
    draw->AddRectFilled(ImVec2(corner.x - 2.0f, corner.y - 1.0f),
                        ImVec2(corner.x + size.x + 2.0f, corner.y + size.y + 1.0f),
                        IM_COL32(13, 13, 20, 180), 2.0f);
    const Color light{0.5f + 0.5f * label.color[0], 0.5f + 0.5f * label.color[1],
                      0.5f + 0.5f * label.color[2], 1.0f};
    draw->AddText(corner, rgba(light), label.text.c_str());
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
    for (const auto& label : batch.labels) {
        draw_label(draw, to_screen(label.at), label);
    }
}

}  // namespace

void draw_labels(const std::vector<OverlayBatch::Label>& labels, const Camera& camera, int width,
                 int height) {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    for (const OverlayBatch::Label& label : labels) {
        if (const auto at = project_to_pixels(camera, label.at, width, height)) {
            draw_label(draw, ImVec2(at->x, at->y), label);
        }
    }
}

void Panels::draw_diagram(const OpDiagram& diagram) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const ImVec2 size(500.0f * scale_, 430.0f * scale_);
    ImGui::SetNextWindowPos(
        ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10.0f, viewport->WorkPos.y + 10.0f),
        ImGuiCond_FirstUseEver, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowSize(size, ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Rewiring (Alt+R)")) {
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
