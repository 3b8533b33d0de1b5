#pragma once
// Private: the Dear ImGui panels of the viewer — info (selection, statistics, shading
// options), help overlay (from the binding table), status line and the file chooser of
// open, save as and export session. Reads the Editor, changes only its ViewState.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "meshedit/overlay/camera.h"
#include "meshedit/overlay/display_data.h"
#include "meshedit/overlay/overlay.h"
#include "meshedit/viewer/editor.h"
#include "meshedit/viewer/file_chooser.h"

namespace meshedit::viewer {

struct FrameStats {
    double frame_ms = 0.0;  ///< CPU + GPU time of the last drawn frame
    double pick_ms = 0.0;   ///< the last pick (a ray into the face BVH; a rebuild included)
    int width = 0, height = 0;
    std::size_t triangles = 0;
};

/// What the user asked for in a panel this frame.
struct PanelRequests {
    std::optional<std::filesystem::path> save_as;
    std::optional<std::filesystem::path> open;
    std::optional<std::filesystem::path> export_session;
    bool view_changed = false;         ///< a shading control moved
    bool normals_changed = false;      ///< which edges split smooth shading
    bool field_changed = false;        ///< the field's colour map or clipping
    std::optional<Action> action;      ///< a control that stands for a key (up axis, orbit)
    std::optional<ElementRef> select;  ///< an index clicked in the inspector
    std::optional<ElementRef> hover;   ///< an index under the mouse in the inspector
    bool frame = false;                ///< frame `select` once it is selected
};

/// The info panel's Problems section (panel_problems.cpp); `opened_at` remembers which list
/// it last opened for (0: none).
void draw_problems(Editor& editor, PanelRequests& requests, std::uint64_t& opened_at);

/// `text` wrapped at spaces only, to the width left in the window (ImGui's own wrapping also
/// breaks after a '.', splitting 0.075 into "0." and "075"); greyed with `disabled`.
void text_wrapped_at_spaces(const std::string& text, bool disabled = false);

/// Draws overlay labels (a stencil's weights) under the panels, each beside where its point
/// lands in a `width` × `height` window seen through `camera`: light text on a dark box, as
/// meshedit-render draws them (render/labels.h).
void draw_labels(const std::vector<OverlayBatch::Label>& labels, const Camera& camera, int width,
                 int height);

class Panels {
public:
    /// Shows the file chooser (panel_chooser.cpp, file_chooser.h) for the document at
    /// `document`, a `mode` document: it lists the document's folder (the current one when
    /// there is none), the field holds the suggested name (the document's, for the saves).
    /// `warning`, when not empty, stands above the buttons (what choosing would discard).
    void ask_path(ChooserPurpose purpose, const std::filesystem::path& document, Mode mode,
                  std::string warning = {});
    bool prompting() const { return prompting_; }
    /// A key pressed (or repeated) and a character typed while the chooser shows, straight
    /// from the GLFW callbacks: the chooser queues them and applies all of them in the next
    /// frame, where ImGui 1.86 would see one Backspace a frame.
    void prompt_key(int glfw_key, int mods);
    void prompt_char(unsigned codepoint);

    /// The status line's place during a long whole-mesh operation: "verb: 42% (3.1 s)" and a
    /// bar. Reads nothing of the document.
    void draw_progress(const std::string& verb, double fraction, double seconds);

    /// True if `point` (window coordinates) lies on a panel drawn in the last frame.
    bool contains(glm::vec2 point) const;

    /// Sizes of panels: Dear ImGui's style is scaled by `scale` (the monitor's content scale).
    void set_scale(float scale) { scale_ = scale; }
    /// The info panel's right edge in window coordinates: where the free view begins (the
    /// expected edge until the panel is first drawn; 0 once it is dragged off the left edge).
    float info_right_edge() const;
    /// The Rewiring panel's left edge in window coordinates when it was drawn last frame
    /// against the window's right edge (where it opens), so the view keeps room for it; 0
    /// when it is hidden or dragged away.
    float diagram_left_edge() const { return diagram_left_; }

    /// The errors of the last shader reload (or of a user shader that does not compile), shown
    /// in their own panel until a reload succeeds; empty: no panel.
    void set_shader_errors(std::string errors) { shader_errors_ = std::move(errors); }

    /// Draws every visible panel; call between ImGui::NewFrame() and ImGui::Render().
    PanelRequests draw(Editor& editor, const FrameStats& stats, const std::string& status,
                       bool status_error, const FieldDisplay& field);

private:
    void draw_info(Editor& editor, const FrameStats& stats, const FieldDisplay& field,
                   PanelRequests& requests);
    void draw_stencil(const Editor& editor);
    void draw_diagram(const OpDiagram& diagram);        // panel_pictures.cpp
    void draw_shader_errors();                          // same
    void draw_field_legend(const FieldDisplay& field);  // same
    void draw_field(Editor& editor, const FieldDisplay& field, PanelRequests& requests);  // same
    void draw_help(Mode mode);
    void draw_status(const Editor& editor, const std::string& status, bool status_error);
    void draw_prompt(PanelRequests& requests);

    /// Remembers the current ImGui window's rectangle (call between Begin and End).
    void remember_rect();

    static constexpr float kInfoWidth = 300.0f;  ///< before scaling
    static constexpr float kInfoMargin = 10.0f;
    float scale_ = 1.0f;
    float diagram_left_ = 0.0f;  ///< diagram_left_edge()
    /// The Attributes section's rows (attribute_summary.h), for the revision they describe.
    std::vector<std::pair<std::string, std::string>> attribute_rows_;
    std::uint64_t attributes_revision_ = UINT64_MAX;
    float info_left_ = 0.0f, info_right_ = 0.0f;          ///< last drawn edges; right 0 until drawn
    std::vector<std::pair<glm::vec2, glm::vec2>> rects_;  ///< min, max of last frame's panels
    bool prompting_ = false;
    std::uint64_t problems_opened_at_ = 0;  ///< draw_problems(): the list it last opened for
    bool prompt_fresh_ = false;             ///< open the popup next frame
    std::string prompt_warning_;            ///< ask_path()'s warning
    bool scroll_to_row_ = false;            ///< Up/Down moved the highlighted row
    FileChooser chooser_;
    std::string shader_errors_;
};

}  // namespace meshedit::viewer
