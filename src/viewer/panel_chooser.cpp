// The file chooser's window: FileChooser (file_chooser.h) holds the listing and the field and
// takes the keys; this file only feeds it GLFW's keys and draws it.

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <optional>
#include <system_error>
#include <utility>

#include "meshedit/viewer/paths.h"
#include "panels.h"

namespace meshedit::viewer {

namespace {

// The typed path field, drawn by hand: an ImGui InputText would edit its own copy of the text
// from keys polled once per frame. The cursor stays in view when the text is wider.
void draw_path_field(const FileChooser& chooser, float width) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const ImVec2 size(width, ImGui::GetFrameHeight());
    ImGui::Dummy(size);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 end(at.x + size.x, at.y + size.y);
    draw->AddRectFilled(at, end, ImGui::GetColorU32(ImGuiCol_FrameBg), style.FrameRounding);
    draw->AddRect(at, end, ImGui::GetColorU32(ImGuiCol_Border), style.FrameRounding);

    const std::string& text = chooser.field();
    const char* s = text.c_str();
    const auto x_of = [&](std::size_t bytes) { return ImGui::CalcTextSize(s, s + bytes).x; };
    const float room = width - 2.0f * style.FramePadding.x - 2.0f;
    const float shift = std::max(0.0f, x_of(chooser.cursor()) - room);
    const ImVec2 origin(at.x + style.FramePadding.x - shift, at.y + style.FramePadding.y);
    const float line = ImGui::GetTextLineHeight();
    draw->PushClipRect(at, end, true);
    if (chooser.selection_begin() != chooser.selection_end()) {
        draw->AddRectFilled(ImVec2(origin.x + x_of(chooser.selection_begin()), origin.y),
                            ImVec2(origin.x + x_of(chooser.selection_end()), origin.y + line),
                            ImGui::GetColorU32(ImGuiCol_TextSelectedBg));
    }
    draw->AddText(origin, ImGui::GetColorU32(ImGuiCol_Text), s, s + text.size());
    const float cursor_x = origin.x + x_of(chooser.cursor());
    draw->AddLine(ImVec2(cursor_x, origin.y), ImVec2(cursor_x, origin.y + line),
                  ImGui::GetColorU32(ImGuiCol_Text), 1.5f);
    draw->PopClipRect();
}

std::string joined(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) {
        out += (out.empty() ? "" : " ") + w;
    }
    return out;
}

}  // namespace

void Panels::ask_path(ChooserPurpose purpose, const std::filesystem::path& document, Mode mode,
                      std::string warning) {
    prompt_warning_ = std::move(warning);
    std::vector<std::string> extensions = chooser_extensions(purpose, mode);
    std::string name;
    if (purpose != ChooserPurpose::Open) {
        name = document.empty() ? "untitled" + extensions.front() : document.filename().string();
    }
    chooser_.start(purpose, prompt_start(document, false), std::move(name), std::move(extensions));
    prompting_ = true;
    prompt_fresh_ = true;
}

void Panels::prompt_key(int glfw_key, int mods) {
    FieldKey key;
    key.shift = (mods & GLFW_MOD_SHIFT) != 0;
    const bool ctrl = (mods & GLFW_MOD_CONTROL) != 0;
    switch (glfw_key) {
        case GLFW_KEY_BACKSPACE:
            key.kind = ctrl ? FieldKey::DeleteWord : FieldKey::Backspace;
            break;
        case GLFW_KEY_DELETE:
            key.kind = FieldKey::Delete;
            break;
        case GLFW_KEY_LEFT:
            key.kind = FieldKey::Left;
            break;
        case GLFW_KEY_RIGHT:
            key.kind = FieldKey::Right;
            break;
        case GLFW_KEY_HOME:
            key.kind = FieldKey::Home;
            break;
        case GLFW_KEY_END:
            key.kind = FieldKey::End;
            break;
        case GLFW_KEY_UP:
            key.kind = FieldKey::Up;
            break;
        case GLFW_KEY_DOWN:
            key.kind = FieldKey::Down;
            break;
        case GLFW_KEY_TAB:
            key.kind = FieldKey::Tab;
            break;
        case GLFW_KEY_ENTER:
        case GLFW_KEY_KP_ENTER:
            key.kind = FieldKey::Enter;
            break;
        case GLFW_KEY_ESCAPE:
            key.kind = FieldKey::Escape;
            break;
        case GLFW_KEY_A:
            if (!ctrl) {
                return;  // the character comes through prompt_char()
            }
            key.kind = FieldKey::SelectAll;
            break;
        default:
            return;
    }
    scroll_to_row_ = scroll_to_row_ || key.kind == FieldKey::Up || key.kind == FieldKey::Down;
    chooser_.push(key);
}

void Panels::prompt_char(unsigned codepoint) {
    chooser_.push(FieldKey{FieldKey::Char, static_cast<char32_t>(codepoint), false});
}

void Panels::draw_prompt(PanelRequests& requests) {
    if (!prompting_) {
        return;
    }
    const ChooserPurpose purpose = chooser_.purpose();
    const char* title = purpose == ChooserPurpose::SaveAs          ? "Save as"
                        : purpose == ChooserPurpose::ExportSession ? "Export session"
                                                                   : "Open";
    if (prompt_fresh_) {
        ImGui::OpenPopup(title);
    }
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(viewport->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        prompting_ = prompt_fresh_;  // closed by ImGui itself
        return;
    }
    prompt_fresh_ = false;
    // Every key since the last frame, in order, before anything is drawn.
    FileChooser::Result result = chooser_.process();

    const float width = std::min(640.0f * scale_, viewport->Size.x - 60.0f * scale_);
    ImGui::TextDisabled("in");
    ImGui::SameLine();
    ImGui::TextUnformatted(chooser_.folder().c_str());
    std::optional<std::size_t> clicked;
    bool chose_by_click = false;
    const float rows = std::clamp(
        (viewport->Size.y - 260.0f * scale_) / ImGui::GetTextLineHeightWithSpacing(), 4.0f, 14.0f);
    ImGui::BeginChild("##listing", ImVec2(width, rows * ImGui::GetTextLineHeightWithSpacing()),
                      true);
    const ImVec4 folder_colour(0.55f, 0.75f, 1.0f, 1.0f);
    for (std::size_t i = 0; i < chooser_.entries().size(); ++i) {
        const ChooserEntry& entry = chooser_.entries()[i];
        const bool highlighted = static_cast<int>(i) == chooser_.highlighted();
        if (entry.folder) {
            ImGui::PushStyleColor(ImGuiCol_Text, folder_colour);
        }
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::Selectable(entry.folder ? (entry.name + "/").c_str() : entry.name.c_str(),
                              highlighted, ImGuiSelectableFlags_AllowDoubleClick)) {
            clicked = i;
            chose_by_click = !entry.folder && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
        }
        ImGui::PopID();
        if (entry.folder) {
            ImGui::PopStyleColor();
        }
        if (highlighted && scroll_to_row_) {
            ImGui::SetScrollHereY();
        }
    }
    scroll_to_row_ = false;
    if (chooser_.entries().empty()) {
        ImGui::TextDisabled("(nothing to list here)");
    }
    ImGui::EndChild();

    bool all = chooser_.show_all();
    if (ImGui::Checkbox("show all files", &all)) {
        chooser_.set_show_all(all);
    }
    if (!all) {
        ImGui::SameLine();
        ImGui::TextDisabled("(only %s)", joined(chooser_.extensions()).c_str());
    }
    ImGui::TextDisabled(purpose == ChooserPurpose::Open ? "file" : "save as");
    ImGui::SameLine();
    draw_path_field(chooser_, width - ImGui::GetCursorPosX() + ImGui::GetStyle().WindowPadding.x);
    if (!chooser_.message().empty()) {
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
        if (chooser_.message_is_error()) {
            ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", chooser_.message().c_str());
        } else {
            ImGui::TextDisabled("%s", chooser_.message().c_str());
        }
        ImGui::PopTextWrapPos();
    }
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
    ImGui::TextDisabled(
        "A name is in the folder above; a path from / or ~ (your home) replaces it. Enter "
        "opens a folder; Tab completes; Ctrl+A selects all; ↑ ↓ go through the list.");
    if (!prompt_warning_.empty()) {
        ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "%s", prompt_warning_.c_str());
    }
    ImGui::PopTextWrapPos();
    const char* verb = purpose == ChooserPurpose::SaveAs          ? "Save"
                       : purpose == ChooserPurpose::ExportSession ? "Export"
                                                                  : "Open";
    const bool ok = ImGui::Button(verb);
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel");

    if (clicked) {
        chooser_.click(*clicked);
    }
    if ((ok || chose_by_click) && chooser_.accept()) {
        result = FileChooser::Result::Chosen;
    }
    if (cancel) {
        result = FileChooser::Result::Cancelled;
    }
    if (result == FileChooser::Result::Chosen) {
        (purpose == ChooserPurpose::SaveAs          ? requests.save_as
         : purpose == ChooserPurpose::ExportSession ? requests.export_session
                                                    : requests.open) = chooser_.chosen();
    }
    if (result != FileChooser::Result::None) {
        prompting_ = false;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace meshedit::viewer
