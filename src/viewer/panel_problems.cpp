// The info panel's Problems section (panels.h): what find_problems() (repair/problems.h)
// names, one row each; a click selects the element that shows it and frames it.

#include <imgui.h>

#include <cstdint>
#include <string>

#include "panels.h"

namespace meshedit::viewer {

void draw_problems(Editor& editor, PanelRequests& requests, std::uint64_t& opened_at) {
    const ProblemReport* report = editor.problems();
    // Opens by itself when a list is new: Alt+V, or a load that repaired something (the list
    // starts with its cuts).
    if (report != nullptr && opened_at != editor.document().revision + 1) {
        ImGui::SetNextItemOpen(true);
        opened_at = editor.document().revision + 1;
    }
    if (!ImGui::CollapsingHeader("Problems (Alt+V)")) {
        return;
    }
    if (ImGui::Button(report == nullptr ? "find problems" : "find again")) {
        requests.action = Action{Command::FindProblems};
    }
    if (report == nullptr) {
        ImGui::SameLine();
        ImGui::TextDisabled("not looked for since the last edit");
        return;
    }
    text_wrapped_at_spaces(report->summary());
    if (report->problems.empty()) {
        return;
    }
    ImGui::BeginChild("problem list", ImVec2(0, 160), true, ImGuiWindowFlags_HorizontalScrollbar);
    for (std::size_t i = 0; i < report->problems.size(); ++i) {
        const Problem& p = report->problems[i];
        ImGui::PushID(static_cast<int>(i));
        const std::string label = std::string(problem_kind_name(p.kind)) + ": " + p.text;
        if (ImGui::Selectable(label.c_str(), false) && !p.where.is_none()) {
            requests.select = p.where;
            requests.frame = true;
        }
        if (ImGui::IsItemHovered()) {
            ImGui::SetTooltip("%s", label.c_str());  // the row is cut at the panel's edge
            if (!p.where.is_none()) {
                requests.hover = p.where;
            }
        }
        ImGui::PopID();
    }
    ImGui::EndChild();
}

}  // namespace meshedit::viewer
