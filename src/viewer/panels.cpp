#include "panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

#include "meshedit/render/shading.h"
#include "meshedit/viewer/paths.h"

namespace meshedit::viewer {

namespace {

constexpr ImGuiWindowFlags kOverlayFlags =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
    ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;

void rows_table(const char* id, const std::vector<std::pair<std::string, std::string>>& rows) {
    if (ImGui::BeginTable(id, 2, ImGuiTableFlags_SizingFixedFit)) {
        for (const auto& [name, value] : rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", name.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(value.c_str());
        }
        ImGui::EndTable();
    }
}

}  // namespace

void Panels::ask_path(Prompt prompt, const std::filesystem::path& document) {
    prompt_ = prompt;
    prompt_fresh_ = true;
    place_cursor_ = true;
    path_ = prompt_start(document, prompt == Prompt::SaveAs);
    folder_ = std::filesystem::path(prompt_start(document, false));
    candidates_.clear();
}

int Panels::on_prompt_input(ImGuiInputTextCallbackData* data) {
    auto* self = static_cast<Panels*>(data->UserData);
    if (data->EventFlag == ImGuiInputTextFlags_CallbackAlways && self->place_cursor_) {
        // Whatever ImGui did on activation (it selects all on the first focus), the field
        // starts the same way every time: the cursor after the text, nothing selected.
        data->CursorPos = data->SelectionStart = data->SelectionEnd = data->BufTextLen;
        self->place_cursor_ = false;
    } else if (data->EventFlag == ImGuiInputTextFlags_CallbackCompletion) {
        const Completion c = complete_path(std::string(data->Buf, data->BufTextLen), self->folder_);
        self->candidates_ = c.candidates.size() > 1 ? c.candidates : std::vector<std::string>{};
        data->DeleteChars(0, data->BufTextLen);
        data->InsertChars(0, c.text.c_str());
    }
    return 0;
}

bool Panels::contains(glm::vec2 point) const {
    return std::any_of(rects_.begin(), rects_.end(), [&](const auto& r) {
        return point.x >= r.first.x && point.y >= r.first.y && point.x < r.second.x &&
               point.y < r.second.y;
    });
}

void Panels::remember_rect() {
    const ImVec2 pos = ImGui::GetWindowPos();
    const ImVec2 size = ImGui::GetWindowSize();
    rects_.emplace_back(glm::vec2(pos.x, pos.y), glm::vec2(pos.x + size.x, pos.y + size.y));
}

PanelRequests Panels::draw(Editor& editor, const FrameStats& stats, const std::string& status,
                           bool status_error) {
    PanelRequests requests;
    rects_.clear();
    if (editor.view().show_info) {
        draw_info(editor, stats, requests);
    }
    if (editor.view().show_help) {
        draw_help(editor.mode());
    }
    draw_status(editor, status, status_error);
    draw_prompt(requests);
    return requests;
}

void Panels::draw_info(Editor& editor, const FrameStats& stats, PanelRequests& requests) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(280, 0), ImVec2(640, 10000));
    if (!ImGui::Begin("Info (I)", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        remember_rect();
        ImGui::End();
        return;
    }
    const Document& doc = editor.document();
    ImGui::TextDisabled("%s", mode_description(doc.mode));
    if (doc.mode == Mode::Curve) {
        ImGui::Text("control points %zu, degree %d", doc.curve.control_points.size(),
                    doc.curve.degree());
        ImGui::Text("t = %.3f, level %d", editor.view().t, editor.view().level);
    } else {
        const Mesh& mesh = editor.mesh();
        ImGui::Text("V %zu  E %zu  F %zu", mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
        ImGui::Text("triangles drawn %zu", stats.triangles);
        if (doc.mode == Mode::Surface) {
            ImGui::Text("%zu patches, density %d", doc.patches.size(), doc.density);
        }
    }
    const History& history = editor.history();
    ImGui::Text("undo %zu, redo %zu (%.1f of %zu MiB)", history.undo_steps(), history.redo_steps(),
                static_cast<double>(history.bytes()) / (1 << 20), history.limits().max_bytes >> 20);
    ImGui::Text("frame %.1f ms, pick %.1f ms", stats.frame_ms, stats.pick_ms);
    ImGui::Text("%d × %d px", stats.width, stats.height);

    ImGui::Separator();
    ImGui::TextDisabled("Selection");
    const ElementRef& selection = editor.selection();
    if (selection.is_none()) {
        ImGui::TextDisabled("nothing selected (click an element)");
    } else if (doc.mode == Mode::Curve) {
        rows_table("selection", control_point_info(doc.curve, selection.index));
    } else {
        rows_table("selection", element_info(editor.mesh(), selection));
    }

    if (doc.mode != Mode::Curve && ImGui::CollapsingHeader("Shading")) {
        RenderOptions& render = editor.view().render;
        bool changed = false;
        const ShadingMode& current = kShadingModes[static_cast<std::size_t>(render.shading)];
        if (ImGui::BeginCombo("mode", std::string(current.name).c_str())) {
            for (const ShadingMode& mode : kShadingModes) {
                char label[64];
                std::snprintf(label, sizeof label, "%d %s", mode.number,
                              std::string(mode.name).c_str());
                if (ImGui::Selectable(label, mode.number == render.shading)) {
                    render.shading = mode.number;
                    changed = true;
                }
            }
            ImGui::EndCombo();
        }
        changed |= ImGui::Checkbox("smooth (Q)", &render.smooth);
        ImGui::SameLine();
        changed |= ImGui::Checkbox("wireframe (W)", &render.wireframe);
        PhongParams& phong = render.phong;
        ImGui::TextDisabled("Blinn-Phong (mode 1)");
        changed |= ImGui::SliderFloat("ambient", &phong.ambient, 0.0f, 3.0f);
        changed |= ImGui::SliderFloat("diffuse", &phong.diffuse, 0.0f, 1.5f);
        changed |= ImGui::SliderFloat("specular", &phong.specular, 0.0f, 1.5f);
        changed |= ImGui::SliderFloat("shininess", &phong.shininess, 1.0f, 256.0f, "%.0f",
                                      ImGuiSliderFlags_Logarithmic);
        changed |= ImGui::SliderFloat3("light dir", phong.light_dir.data(), -1.0f, 1.0f);
        changed |= ImGui::ColorEdit3("light", phong.light_color.data());
        changed |= ImGui::ColorEdit3("surface", render.base_color.data());
        changed |= ImGui::ColorEdit3("wire", render.wire_color.data());
        if (ImGui::Button("defaults")) {
            phong = PhongParams{};
            render.base_color = RenderOptions{}.base_color;
            render.wire_color = RenderOptions{}.wire_color;
            changed = true;
        }
        requests.view_changed |= changed;
    }
    remember_rect();
    ImGui::End();
}

void Panels::draw_help(Mode mode) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(
        ImVec2(viewport->WorkPos.x + viewport->WorkSize.x * 0.5f, viewport->WorkPos.y + 10),
        ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0),
                                        ImVec2(viewport->WorkSize.x, viewport->WorkSize.y - 60));
    if (!ImGui::Begin("Keys and mouse (? or F1 to close)", nullptr,
                      ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                          ImGuiWindowFlags_NoCollapse)) {
        remember_rect();
        ImGui::End();
        return;
    }
    // Two columns of sections by mode, so the list fits a laptop screen.
    // Only what works in the current mode: its own keys first, then the keys of every mode
    // and the mouse.
    const char* mode_word = mode == Mode::Mesh      ? "mesh"
                            : mode == Mode::Surface ? "surface"
                                                    : "curve";
    std::vector<HelpRow> rows;
    for (HelpRow& row : help_rows()) {
        if (row.modes.empty() || row.modes.find(mode_word) != std::string::npos) {
            rows.push_back(std::move(row));
        }
    }
    std::vector<std::string> sections;
    for (const HelpRow& row : rows) {
        if (!row.modes.empty() &&
            std::find(sections.begin(), sections.end(), row.modes) == sections.end()) {
            sections.push_back(row.modes);
        }
    }
    sections.push_back("");
    for (std::size_t s = 0; s < sections.size(); ++s) {
        ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "%s",
                           sections[s].empty() ? "everywhere" : sections[s].c_str());
        if (ImGui::BeginTable(sections[s].c_str(), 2, ImGuiTableFlags_SizingFixedFit)) {
            for (const HelpRow& row : rows) {
                if (row.modes != sections[s]) {
                    continue;
                }
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(row.keys.c_str());
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(row.action.c_str());
            }
            ImGui::EndTable();
        }
        ImGui::Spacing();
    }
    remember_rect();
    ImGui::End();
}

void Panels::draw_status(const Editor& editor, const std::string& status, bool status_error) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(
        ImVec2(viewport->WorkPos.x + 8, viewport->WorkPos.y + viewport->WorkSize.y - 8),
        ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.7f);
    if (ImGui::Begin("status", nullptr, kOverlayFlags)) {
        const ElementRef& hover = editor.hover();
        if (!hover.is_none() && editor.mode() != Mode::Curve) {
            ImGui::TextDisabled("under the cursor: %s", describe(editor.mesh(), hover).c_str());
        }
        if (!status.empty()) {
            if (status_error) {
                ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", status.c_str());
            } else {
                ImGui::TextUnformatted(status.c_str());
            }
        } else {
            ImGui::TextDisabled("? or F1: keys and mouse");
        }
    }
    remember_rect();
    ImGui::End();
}

void Panels::draw_prompt(PanelRequests& requests) {
    if (prompt_ == Prompt::None) {
        return;
    }
    const char* title = prompt_ == Prompt::SaveAs ? "Save as" : "Open";
    if (prompt_fresh_) {
        ImGui::OpenPopup(title);
    }
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(viewport->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted(prompt_ == Prompt::SaveAs
                                   ? "File name (.dae .obj .gltf .glb for meshes, .bzc for curves):"
                                   : "File to open (.dae .obj .gltf .glb .bez .bzc):");
        if (prompt_fresh_) {
            ImGui::SetKeyboardFocusHere();
            prompt_fresh_ = false;
        }
        ImGui::SetNextItemWidth(520);
        const bool entered = ImGui::InputText("##path", &path_,
                                              ImGuiInputTextFlags_EnterReturnsTrue |
                                                  ImGuiInputTextFlags_CallbackAlways |
                                                  ImGuiInputTextFlags_CallbackCompletion,
                                              &Panels::on_prompt_input, this);
        if (!candidates_.empty()) {
            std::string shown;
            for (std::size_t i = 0; i < candidates_.size() && i < 12; ++i) {
                shown += (i ? "   " : "") + candidates_[i];
            }
            if (candidates_.size() > 12) {
                shown += "   … (" + std::to_string(candidates_.size()) + ")";
            }
            ImGui::TextDisabled("%s", shown.c_str());
        }
        ImGui::TextDisabled("Tab completes a name; ~ is your home folder");
        const bool ok = ImGui::Button(prompt_ == Prompt::SaveAs ? "Save" : "Open") || submit_;
        ImGui::SameLine();
        const bool cancel = ImGui::Button("Cancel") || cancel_;
        submit_ = cancel_ = false;
        if ((entered || ok) && !path_.empty()) {
            (prompt_ == Prompt::SaveAs ? requests.save_as : requests.open) =
                resolve_prompt_path(path_, folder_);
            prompt_ = Prompt::None;
            ImGui::CloseCurrentPopup();
        } else if (cancel) {
            prompt_ = Prompt::None;
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    } else if (!prompt_fresh_) {
        prompt_ = Prompt::None;
    }
}

}  // namespace meshedit::viewer
