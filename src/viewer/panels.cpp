#include "panels.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "meshedit/core/attribute_summary.h"
#include "meshedit/core/normals.h"
#include "meshedit/io/io.h"
#include "meshedit/overlay/shading.h"

namespace meshedit::viewer {

namespace {

constexpr ImGuiWindowFlags kOverlayFlags =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
    ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;

// Name and value columns; values wrap inside the panel's fixed width. The inspector: rows
// with `links` (element_links()) show each element as a small button; hovering one
// highlights it in the view, clicking selects it. What is not an element ("none", "… (40 in
// all)") follows as plain text.
void rows_table(const char* id, const std::vector<std::pair<std::string, std::string>>& rows,
                const std::vector<std::pair<std::string, std::vector<ElementRef>>>& links = {},
                PanelRequests* requests = nullptr) {
    if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_SizingStretchProp)) {
        return;
    }
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch);
    for (const auto& [name, value] : rows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextDisabled("%s", name.c_str());
        ImGui::TableNextColumn();
        // An init-capture: clang 14 cannot capture a structured binding itself.
        const auto row_links = std::find_if(
            links.begin(), links.end(), [&row = name](const auto& l) { return l.first == row; });
        if (row_links == links.end() || row_links->second.empty()) {
            ImGui::TextWrapped("%s", value.c_str());
            continue;
        }
        ImGui::PushID(name.c_str());
        const float right = ImGui::GetContentRegionMax().x;
        for (std::size_t i = 0; i < row_links->second.size(); ++i) {
            const ElementRef ref = row_links->second[i];
            const std::string label = std::to_string(ref.index);
            const float width =
                ImGui::CalcTextSize(label.c_str()).x + 2.0f * ImGui::GetStyle().FramePadding.x;
            if (i > 0) {
                ImGui::SameLine();
                if (ImGui::GetCursorPosX() + width > right) {
                    ImGui::NewLine();  // wrap, as the plain rows do
                }
            }
            ImGui::PushID(static_cast<int>(i));
            if (ImGui::SmallButton(label.c_str()) && requests != nullptr) {
                requests->select = ref;
            }
            if (ImGui::IsItemHovered() && requests != nullptr) {
                requests->hover = ref;
            }
            ImGui::PopID();
        }
        for (const std::string_view rest : {"none (boundary)", "none", "…"}) {
            if (const std::size_t at = value.find(rest); at != std::string::npos) {
                ImGui::SameLine();
                ImGui::TextDisabled("%s", value.substr(at).c_str());
                break;
            }
        }
        ImGui::PopID();
    }
    ImGui::EndTable();
}

// Select by trait (Shift+G): which trait, and its number.
void draw_trait_choice(TraitQuery& trait, PanelRequests& requests) {
    static constexpr const char* kNames[] = {"the border", "creases", "vertices of valence k",
                                             "faces of k corners", "faces turned away"};
    int chosen = static_cast<int>(trait.trait);
    ImGui::SetNextItemWidth(170);
    if (ImGui::Combo("##trait", &chosen, kNames, IM_ARRAYSIZE(kNames))) {
        trait.trait = static_cast<Trait>(chosen);
    }
    ImGui::SameLine();
    if (ImGui::Button("select (Shift+G)")) {
        requests.action = Action{Command::SelectTrait};
    }
    if (trait.trait == Trait::Valence || trait.trait == Trait::Degree) {
        int k = static_cast<int>(trait.k);
        ImGui::SetNextItemWidth(120);
        if (ImGui::InputInt("k", &k)) {
            trait.k = static_cast<std::size_t>(std::clamp(k, 1, 1000));
        }
    } else if (trait.trait == Trait::FacingAway) {
        float angle = static_cast<float>(trait.angle_deg);
        ImGui::SetNextItemWidth(170);
        if (ImGui::SliderFloat("degrees", &angle, 0.0f, 180.0f, "%.0f")) {
            trait.angle_deg = angle;
        }
    }
}

}  // namespace

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

void text_wrapped_at_spaces(const std::string& text, bool disabled) {
    const float width = std::max(40.0f, ImGui::GetContentRegionAvail().x);
    const auto emit = [disabled](const std::string& line) {
        if (disabled) {
            ImGui::TextDisabled("%s", line.c_str());
        } else {
            ImGui::TextUnformatted(line.c_str());
        }
    };
    std::string line;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t space = std::min(text.find(' ', start), text.size());
        const std::string word = text.substr(start, space - start);
        const std::string longer = line.empty() ? word : line + " " + word;
        if (!line.empty() && ImGui::CalcTextSize(longer.c_str()).x > width) {
            emit(line);
            line = word;
        } else {
            line = longer;
        }
        start = space + 1;
    }
    if (!line.empty()) {
        emit(line);
    }
}

PanelRequests Panels::draw(Editor& editor, const FrameStats& stats, const std::string& status,
                           bool status_error, const FieldDisplay& field) {
    PanelRequests requests;
    rects_.clear();
    if (editor.view().show_info) {
        draw_info(editor, stats, field, requests);
    }
    diagram_left_ = 0.0f;
    if (editor.view().show_diagram && editor.last_diagram() && editor.mode() != Mode::Curve) {
        draw_diagram(*editor.last_diagram());
    }
    if (!shader_errors_.empty()) {
        draw_shader_errors();
    }
    if (field.info != nullptr && editor.mode() != Mode::Curve) {
        draw_field_legend(field);
    }
    if (editor.view().show_help) {
        draw_help(editor.mode());
    }
    draw_status(editor, status, status_error);
    draw_prompt(requests);
    return requests;
}

float Panels::info_right_edge() const {
    if (info_right_ <= 0.0f) {
        return kInfoMargin + kInfoWidth * scale_;  // not drawn yet: where it will be
    }
    // Dragged away from the left edge, the panel floats over the view: keep no room for it.
    return info_left_ <= 4.0f * kInfoMargin * scale_ ? info_right_ : 0.0f;
}

void Panels::draw_info(Editor& editor, const FrameStats& stats, const FieldDisplay& field,
                       PanelRequests& requests) {
    // A fixed width, so a long row wraps instead of widening the panel over the model (the
    // camera's framing leaves this much room, App::free_view_fraction); as tall as its
    // open sections, scrolling when they do not fit.
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float width = kInfoWidth * scale_;
    ImGui::SetNextWindowPos(ImVec2(kInfoMargin, kInfoMargin), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(
        ImVec2(width, 0), ImVec2(width, std::max(viewport->WorkSize.y - 70.0f * scale_, 100.0f)));
    if (!ImGui::Begin("Info (I)", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        remember_rect();
        info_left_ = ImGui::GetWindowPos().x;
        info_right_ = info_left_ + ImGui::GetWindowSize().x;
        ImGui::End();
        return;
    }
    info_left_ = ImGui::GetWindowPos().x;
    info_right_ = info_left_ + width;
    const Document& doc = editor.document();
    // --student: the side by side's first difference, in the student's own numbering (the
    // Selection section's indices are the side by side's).
    if (const StudentComparison* c = editor.student_comparison();
        c != nullptr && ImGui::CollapsingHeader("Student code", ImGuiTreeNodeFlags_DefaultOpen)) {
        rows_table("student", {{"function", c->task},
                               {"on", c->input},
                               {"invariant", c->invariant.empty() ? "none broken" : c->invariant},
                               {"first difference", c->difference},
                               {"shown", "yours left, the reference's right; Esc steps back"}});
    }
    if (ImGui::CollapsingHeader("Document", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::TextDisabled("%s", mode_description(doc.mode));
        if (doc.mode == Mode::Curve) {
            ImGui::Text("control points %zu, degree %d", doc.curve.control_points.size(),
                        doc.curve.degree());
            ImGui::Text("t = %.3f, level %d", editor.view().t, editor.view().level);
        } else {
            const Mesh& mesh = editor.mesh();
            ImGui::Text("V %zu  E %zu  F %zu", mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
            const SurfaceColor shown = editor.view().render.color;
            ImGui::Text("surface colour: %s (Alt+C)",
                        kSurfaceColors[static_cast<std::size_t>(shown)].name.data());
            if (ImGui::TreeNode("Attributes")) {
                // O(edges) for the seam count: once per edit, not per frame.
                if (attributes_revision_ != doc.revision) {
                    attribute_rows_ = attribute_rows(mesh, summarize_attributes(mesh));
                    attributes_revision_ = doc.revision;
                }
                for (const auto& [name, value] : attribute_rows_) {
                    ImGui::TextWrapped("%s: %s", name.c_str(), value.c_str());
                }
                ImGui::TreePop();
            }
            if (doc.mode == Mode::Surface) {
                ImGui::Text("%zu patches, density %d", doc.patches.size(), doc.density);
            }
            // The same commands as the Y and O keys. Files are read into +Y up, so +Y is
            // what the file declares.
            const ViewState& view = editor.view();
            ImGui::TextUnformatted("up (Y)");
            ImGui::SameLine();
            if (ImGui::RadioButton("+Y, as declared", view.up == UpAxis::Y) &&
                view.up != UpAxis::Y) {
                requests.action = Action{Command::CycleUp};
            }
            ImGui::SameLine();
            if (ImGui::RadioButton("+Z", view.up == UpAxis::Z) && view.up != UpAxis::Z) {
                requests.action = Action{Command::CycleUp};
            }
            bool trackball = view.trackball;
            if (ImGui::Checkbox("trackball orbit (O)", &trackball)) {
                requests.action = Action{Command::ToggleTrackball};
            }
        }
        const History& history = editor.history();
        ImGui::Text("undo %zu, redo %zu", history.undo_steps(), history.redo_steps());
    }

    if (ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) {
        const ElementRef& selection = editor.selection();
        if (selection.is_none()) {
            ImGui::TextDisabled("nothing selected (click an element)");
        } else if (doc.mode == Mode::Curve) {
            rows_table("selection", control_point_info(doc.curve, selection.index));
        } else {
            rows_table("selection", element_info(editor.mesh(), selection),
                       element_links(editor.mesh(), selection), &requests);
            ImGui::TextDisabled("click an index to select it, hover to see it");
        }
        if (doc.mode != Mode::Curve) {
            draw_trait_choice(editor.tools().trait, requests);
        }
    }

    if (doc.mode != Mode::Curve) {
        draw_problems(editor, requests, problems_opened_at_);
    }
    if (editor.view().stencil && doc.mode != Mode::Curve) {
        draw_stencil(editor);
    }
    if (field.info != nullptr && doc.mode != Mode::Curve) {
        draw_field(editor, field, requests);
    }

    if (ImGui::CollapsingHeader("Statistics")) {
        if (doc.mode != Mode::Curve) {
            ImGui::Text("triangles drawn %zu", stats.triangles);
        }
        const History& history = editor.history();
        ImGui::Text("undo memory %.1f of %zu MiB", static_cast<double>(history.bytes()) / (1 << 20),
                    history.limits().max_bytes >> 20);
        ImGui::Text("frame %.1f ms, pick %.1f ms", stats.frame_ms, stats.pick_ms);
        ImGui::Text("%d × %d px", stats.width, stats.height);
    }

    if (doc.mode != Mode::Curve && ImGui::CollapsingHeader("Global operations")) {
        ToolSettings& tools = editor.tools();
        ToolSettings::Amounts& keep = tools.amounts("simplify");
        float ratio = static_cast<float>(keep[0]);
        // "keep [0.50 of the faces]": the label first, as the sentence reads (ImGui puts a
        // label after the slider, which read "0.50 of the faces keep").
        ImGui::TextUnformatted("keep");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(170);
        if (ImGui::SliderFloat("##keep", &ratio, 0.01f, 0.99f, "%.2f of the faces")) {
            keep[0] = ratio;
        }
        if (ImGui::Button("simplify (D)")) {
            requests.action = edit("simplify");
        }
        ToolSettings::Amounts& remesh = tools.amounts("remesh");
        float length = static_cast<float>(remesh[0]);
        if (ImGui::InputFloat("length", &length, 0.0f, 0.0f, "%.4g") && length >= 0.0f) {
            remesh[0] = length;
        }
        ImGui::TextDisabled("0: the mean edge length");
        int rounds = static_cast<int>(remesh[1]);
        if (ImGui::SliderInt("rounds", &rounds, 1, 20)) {
            remesh[1] = rounds;
        }
        if (ImGui::Button("remesh (Shift+R)")) {
            requests.action = edit("remesh");
        }
        ToolSettings::Amounts& smooth = tools.amounts("smooth");  // steps, λ, keep the volume
        int smooth_steps = static_cast<int>(smooth[0]);
        if (ImGui::SliderInt("steps", &smooth_steps, 1, 100)) {
            smooth[0] = smooth_steps;
        }
        float lambda = static_cast<float>(smooth[1]);
        if (ImGui::SliderFloat("lambda", &lambda, 0.01f, 1.0f, "%.2f")) {
            smooth[1] = lambda;
        }
        bool keep_volume = smooth[2] != 0.0;
        if (ImGui::Checkbox("keep the volume (closed meshes)", &keep_volume)) {
            smooth[2] = keep_volume ? 1.0 : 0.0;
        }
        if (ImGui::Button("smooth (Shift+M)")) {
            requests.action = edit("smooth");
        }
        // One angle for marking sharp edges and, when ticked, for simplify and remesh first.
        ToolSettings::Amounts& sharp = tools.amounts("crease_by_angle");
        float angle = static_cast<float>(sharp[0]);
        if (ImGui::SliderFloat("feature angle", &angle, 0.0f, 180.0f, "%.0f°")) {
            sharp[0] = angle;
        }
        bool keep_sharp = keep[2] != kNoFeatureAngle;
        ImGui::Checkbox("simplify and remesh keep edges sharper", &keep_sharp);
        keep[2] = remesh[2] = keep_sharp ? sharp[0] : kNoFeatureAngle;
        if (ImGui::Button("mark sharp edges as creases (Shift+K)")) {
            requests.action = edit("crease_by_angle");
        }
        if (ImGui::Button("Catmull-Clark (Shift+C)")) {
            requests.action = edit("catmull_clark");
        }
        ImGui::SameLine();
        if (ImGui::Button("Loop (L)")) {
            requests.action = edit("loop");
        }
        if (ImGui::Button("linear (Ctrl+L)")) {
            requests.action = edit("linear");
        }
        ImGui::SameLine();
        if (ImGui::Button("triangulate (Ctrl+T)")) {
            requests.action = edit("triangulate");
        }
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
        NormalSplit& normals = editor.view().normals;
        bool normals_changed = ImGui::Checkbox("split at creases", &normals.creases);
        bool auto_smooth = normals.auto_smooth_deg.has_value();
        ImGui::SameLine();
        if (ImGui::Checkbox("auto smooth", &auto_smooth)) {
            normals.auto_smooth_deg = auto_smooth ? std::optional<double>(30.0) : std::nullopt;
            normals_changed = true;
        }
        if (normals.auto_smooth_deg) {
            float angle = static_cast<float>(*normals.auto_smooth_deg);
            if (ImGui::SliderFloat("angle", &angle, 0.0f, 180.0f, "%.0f°")) {
                normals.auto_smooth_deg = angle;
                normals_changed = true;
            }
        }
        requests.normals_changed |= normals_changed;
        changed |= normals_changed;
        if (render.shading == 7) {
            changed |= ImGui::SliderFloat("exposure", &render.exposure, -6.0f, 6.0f, "%.1f EV");
            ImGui::TextDisabled("drop an image on the window for another environment");
        }
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

void Panels::draw_stencil(const Editor& editor) {
    if (!ImGui::CollapsingHeader("Stencil (Alt+W)", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    ImGui::TextDisabled("%s", scheme_name(*editor.view().stencil));
    const ElementRef element = editor.stencil_element();
    if (element.is_none()) {
        text_wrapped_at_spaces("hover a vertex or an edge to see what makes its new point");
        return;
    }
    const Mesh& mesh = editor.mesh();
    const Stencil stencil = subdivision_stencil(mesh, element, *editor.view().stencil);
    ImGui::Text("%s", describe(mesh, element).c_str());
    if (!stencil.ok()) {
        ImGui::TextWrapped("%s", stencil.status.text().c_str());
        return;
    }
    ImGui::Text("rule: %s", stencil.rule.c_str());
    for (const std::string& line : stencil.formula) {
        text_wrapped_at_spaces(line);
    }
    if (ImGui::BeginTable("stencil", 2, ImGuiTableFlags_SizingFixedFit)) {
        for (const StencilTerm& term : stencil.terms) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("vertex %u", term.vertex.idx());
            ImGui::TableNextColumn();
            ImGui::Text("%s", weight_label(term.weight).c_str());
        }
        ImGui::EndTable();
    }
}

void Panels::draw_help(Mode mode) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(
        ImVec2(viewport->WorkPos.x + viewport->WorkSize.x * 0.5f, viewport->WorkPos.y + 10),
        ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0),
                                        ImVec2(viewport->WorkSize.x, viewport->WorkSize.y - 60));
    ImGui::SetNextWindowBgAlpha(1.0f);  // opaque: the info panel must not show through
    if (!ImGui::Begin("Keys and mouse (? or F1 to close)", nullptr,
                      ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                          ImGuiWindowFlags_NoCollapse)) {
        remember_rect();
        ImGui::End();
        return;
    }
    // Only what works in the current mode, in two columns so it fits a laptop screen: the
    // mode's own keys and mouse on the left; what works everywhere and the colours on the
    // right. Long actions wrap.
    const std::vector<HelpRow> rows = help_rows(mode);
    std::vector<std::string> sections;
    for (const HelpRow& row : rows) {
        if (!row.modes.empty() &&
            std::find(sections.begin(), sections.end(), row.modes) == sections.end()) {
            sections.push_back(row.modes);
        }
    }
    const float column =
        std::clamp((viewport->WorkSize.x - 60.0f) / 2.0f, 300.0f * scale_, 560.0f * scale_);
    const ImVec4 heading(1.0f, 0.7f, 0.3f, 1.0f);
    // Each section is a table as wide as its column: the keys in a column no wider than a
    // third of it (a long mouse gesture wraps), the actions in the rest, wrapped at its edge
    // (issue 40: long keys pushed the actions past the column, where they were cut off).
    const auto section = [&](const std::string& modes) {
        ImGui::TextColored(heading, "%s", modes.empty() ? "everywhere" : modes.c_str());
        float widest = 0.0f;
        for (const HelpRow& row : rows) {
            if (row.modes == modes) {
                widest = std::max(widest, ImGui::CalcTextSize(row.keys.c_str()).x);
            }
        }
        if (ImGui::BeginTable(modes.empty() ? "everywhere" : modes.c_str(), 2,
                              ImGuiTableFlags_SizingFixedFit, ImVec2(column, 0.0f))) {
            ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed,
                                    std::min(widest, column / 3.0f));
            ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
            for (const HelpRow& row : rows) {
                if (row.modes != modes) {
                    continue;
                }
                ImGui::TableNextRow();
                for (const std::string* text : {&row.keys, &row.action}) {
                    ImGui::TableNextColumn();
                    ImGui::PushTextWrapPos(0.0f);  // the column's right edge
                    ImGui::TextUnformatted(text->c_str());
                    ImGui::PopTextWrapPos();
                }
            }
            ImGui::EndTable();
        }
        ImGui::Spacing();
    };
    if (ImGui::BeginTable("help", 2,
                          ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("mode", ImGuiTableColumnFlags_WidthFixed, column);
        ImGui::TableSetupColumn("everywhere", ImGuiTableColumnFlags_WidthFixed, column);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        for (const std::string& modes : sections) {
            section(modes);
        }
        ImGui::TableNextColumn();
        section("");
        ImGui::TextColored(heading, "colours");
        if (ImGui::BeginTable("colours", 2, ImGuiTableFlags_SizingFixedFit)) {
            for (const LegendRow& row : legend(mode, OverlayStyle{})) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                const ImVec4 c(row.color[0], row.color[1], row.color[2], 1.0f);
                ImGui::ColorButton(row.meaning.c_str(), c,
                                   ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoPicker,
                                   ImVec2(28.0f * scale_, 0));
                ImGui::TableNextColumn();
                ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + column * 0.8f);
                ImGui::TextUnformatted(row.meaning.c_str());
                ImGui::PopTextWrapPos();
            }
            ImGui::EndTable();
        }
        ImGui::EndTable();
    }
    remember_rect();
    ImGui::End();
}

// The status line's window, at the bottom left; End() it whatever this returns.
static bool begin_status_window() {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(
        ImVec2(viewport->WorkPos.x + 8, viewport->WorkPos.y + viewport->WorkSize.y - 8),
        ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowBgAlpha(0.7f);
    return ImGui::Begin("status", nullptr, kOverlayFlags);
}

void Panels::draw_progress(const std::string& verb, double fraction, double seconds) {
    if (begin_status_window()) {
        if (fraction < 0.0) {  // an operation that cannot tell how far it is (reading a file)
            ImGui::Text("%s (%.1f s)", verb.c_str(), seconds);
        } else {
            ImGui::Text("%s: %.0f%% (%.1f s)", verb.c_str(), 100.0 * fraction, seconds);
            ImGui::ProgressBar(static_cast<float>(fraction), ImVec2(240.0f * scale_, 0.0f), "");
        }
    }
    ImGui::End();
}

void Panels::draw_status(const Editor& editor, const std::string& status, bool status_error) {
    if (begin_status_window()) {
        // A long line (a refusal naming a file, a list of repairs) wraps inside the window
        // instead of running off its right edge (issue 40).
        ImGui::PushTextWrapPos(ImGui::GetMainViewport()->WorkSize.x - 40.0f);
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
        ImGui::PopTextWrapPos();
    }
    remember_rect();
    ImGui::End();
}

}  // namespace meshedit::viewer
