#pragma once
// Private: the viewer window. Owns the GLFW window, the GL renderers, the camera and the
// mouse; everything about the document and its commands is the Editor's (editor.h).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "meshedit/overlay/camera.h"
#include "meshedit/overlay/region_pick.h"
#include "meshedit/render/render_target.h"
#include "meshedit/render/scene.h"
#include "meshedit/viewer/editor.h"
#include "panels.h"
#include "still_frame.h"

struct GLFWwindow;

namespace meshedit::viewer {

struct ViewerOptions {
    std::filesystem::path file;  ///< empty: start with nothing open
    int width = 1280;            ///< window size in screen coordinates
    int height = 800;
    bool vsync = true;
    UpAxis up = UpAxis::Y;             ///< --up: which world axis starts up on the screen
    std::filesystem::path envmap;      ///< --envmap: shading 7's environment (empty: the default)
    std::filesystem::path shader_dir;  ///< --shader-dir: modes 8, 9 (empty: the per-user one)
    std::filesystem::path student;     ///< --student: a student library (empty: none)
};

/// Whether a dropped file is an image (an environment for shading 7) rather than a document.
bool is_environment_image(const std::filesystem::path& path);

class App {
public:
    /// Opens the window (throws std::runtime_error if GLFW or GL 3.3 is unavailable) and
    /// the file, if any; a file that does not open is reported and the window stays.
    explicit App(const ViewerOptions& options);
    App(const App&) = delete;
    App& operator=(const App&) = delete;
    ~App();

    /// The event loop; returns the exit status (0 on a normal quit).
    int run();

private:
    /// BoxArmed: B was pressed, the next left press starts a box; Box: drawing it; Lasso:
    /// a Ctrl+right-drag drawing an outline; BrushArmed: Alt+B was pressed, the circle
    /// follows the cursor; Brush: a left drag painting with it.
    enum class DragMode {
        None,
        Pending,
        Orbit,
        Pan,
        Element,
        BoxArmed,
        Box,
        Lasso,
        BrushArmed,
        Brush
    };

    // GLFW callbacks (installed before ImGui's, which chains to them).
    void on_key(int key, int action, int mods);
    /// Tells the editor where the eye is (select by trait: faces turned away).
    void tell_view_direction();
    void on_mouse_button(int button, int action, int mods);
    void on_cursor(double x, double y);
    void on_scroll(double dy);
    void on_drop(int count, const char** paths);
    void on_close_request();

    /// Reacts to what a command changed: uploads, overlay, camera, prompts, status line.
    void apply(const Outcome& outcome);
    /// `discard_confirmed`: the Open chooser told the user the unsaved changes are lost.
    void open_file(const std::filesystem::path& path, bool discard_confirmed = false);
    /// Makes `path` shading 7's environment and switches to mode 7; a bad image is reported
    /// in the status line and the environment stays (app_shading.cpp).
    void load_environment(const std::filesystem::path& path);
    /// Modes 8 and 9: writes the starter shaders into the user folder where missing (the
    /// first time either mode is chosen); Ctrl+R: recompiles every shader, showing errors.
    void prepare_user_shaders();
    void reload_shaders();
    /// The frame's render options: the view's, with the time and the selection for user
    /// shaders.
    RenderOptions frame_options();
    void set_status(std::string message, bool error);

    void upload_document();
    /// Uploads the overlay: display_'s features (boundary and crease edges, a phased Loop's
    /// marks), control nets or the curve, hover and selection highlights.
    void rebuild_overlay();
    /// Asks display_ for the scalar field shown (Alt+F) and colours the surface by it, or
    /// clears it (app_shading.cpp): display_ recomputes it when the mesh changed, else only
    /// if the field, its colour settings or distance's source vertex changed; `upload` gives
    /// the colours to a mesh just uploaded even when the values stand.
    void refresh_field(bool upload = false);
    void reset_camera();
    /// Centres the camera on the selection, close enough that it fills about a third of the
    /// view.
    void frame_selection();
    /// Frames the whole mesh as reset_camera() does, keeping the viewing angle (after a
    /// whole-mesh operation, which may shrink or grow the shape).
    /// The scene's sphere (for the near and far planes) from the mesh now; the view stays.
    void fit_depth_range();
    /// The editor's progress hook: from 0.3 s into a whole-mesh operation on, at most ten
    /// times a second, draws the 3D view as it was and a progress bar (nothing that reads the
    /// half-built document; no event handling).
    void show_progress(std::string_view verb, double fraction);
    /// Each turn of the event loop while an operation runs in the background: its result
    /// applied once it ended, else a progress frame four times a second.
    void follow_job();
    /// An interactive edit began (Editor::begin_modal): remember where the cursor and the
    /// selection's centre are. update_modal() feeds the cursor's motion since then.
    void start_modal();
    void update_modal();
    glm::dmat4 clip_of_world() const;
    /// The world point at framebuffer pixel `p` (double precision) at depth `ndc_z`.
    Vec3 world_at(glm::dvec2 p, double ndc_z) const;
    void update_camera_planes();

    /// The element under the cursor (CPU pick for meshes, nearest control point for curves).
    ElementRef pick_at_cursor();
    void update_hover();
    /// After a command: when it was a recorded change (the editor names its region), updates
    /// the GPU buffers and the picking tree around it and returns true; else false
    /// (app_picking.cpp).
    bool follow_mesh_change(const Outcome& outcome);
    /// Moves the dragged vertex or control point under the cursor, in the screen plane.
    void drag_element_to_cursor();
    /// Box and lasso select (app_region.cpp): the press, the outline drawn over the frame,
    /// the release.
    bool region_mouse_button(int button, int action, int mods);
    void draw_region();
    void finish_region(bool add, bool through);
    /// Visible, or VisibleFrontOnly where the renderer culls back faces (region_pick.h).
    Reach visible_reach() const;
    /// The brush: selects (or with Shift takes away) what lies under its circle now.
    void paint_brush();
    bool brush_mode() const { return drag_ == DragMode::BrushArmed || drag_ == DragMode::Brush; }
    float brush_radius_ = 25.0f;    ///< framebuffer pixels
    bool brush_removes_ = false;    ///< the drag began with Shift
    bool brush_through_ = false;    ///< the drag began with Alt
    glm::vec2 box_from_{0.0f};      ///< where the box's drag began, framebuffer pixels
    std::vector<glm::vec2> lasso_;  ///< the lasso's outline so far, framebuffer pixels
    /// What the view shows, kept from a region's press to its release and for later regions
    /// in the same view; dropped when the mesh changes (apply()).
    std::optional<ShownPoints> shown_;
    std::uint64_t shown_revision_ = 0;  ///< the document's revision shown_ was built from
    /// shown_, built again unless it fits the camera, image, selection kind and `reach`.
    const ShownPoints& shown_points(Reach reach);

    void draw_scene(int width, int height);
    void draw_frame();
    void write_screenshot();

    /// Cursor position in framebuffer pixels (HiDPI: window coordinates × content scale).
    glm::vec2 cursor_pixels() const;
    glm::ivec2 framebuffer_size() const;
    float aspect() const;
    /// The world point under framebuffer pixel `p` at normalised device depth `ndc_z`.
    glm::vec3 unproject(glm::vec2 p, float ndc_z) const;
    bool mesh_mode() const { return editor_.mode() != Mode::Curve; }
    /// Framebuffer pixels the info panel covers on the left (0 when hidden), and the lens
    /// shift that centres the view in the rest.
    int covered_pixels() const;
    /// Framebuffer pixels the Rewiring panel covers at the window's right edge (0: none).
    int covered_right_pixels() const;
    void keep_room_for_panels();

    GLFWwindow* window_ = nullptr;
    Editor editor_;
    Camera camera_;
    glm::vec3 scene_center_{0.0f};
    float scene_radius_ = 1.0f;

    std::unique_ptr<SceneRenderer> scene_;
    /// Features, the field and the picking tree of editor_.mesh() (overlay/display_data.h).
    DisplayData display_;
    std::uint64_t applied_revision_ = 0;  ///< the document's revision after the last apply()
    std::filesystem::path user_shader_dir_;
    bool starters_checked_ = false;
    std::vector<OverlayBatch::Label> labels_;  ///< the overlay's text, drawn with the panels

    Panels panels_;
    std::string status_;
    bool status_error_ = false;

    DragMode drag_ = DragMode::None;
    glm::dvec2 cursor_{0.0};         ///< window coordinates
    glm::dvec2 press_at_{0.0};       ///< where the left button went down
    bool cursor_moved_ = true;       ///< the hover pick is stale
    double last_cursor_time_ = 0.0;  ///< glfwGetTime() of the last cursor motion
    int redraw_frames_ = 3;          ///< frames still to draw (ImGui settles over a few)
    // Frames drawn after any input: an ImGui window that changed its content (a header opened)
    // takes two more frames to resize to it.
    static constexpr int kSettleFrames = 3;
    double last_frame_ms_ = 0.0;
    double progress_started_ = -1.0;  ///< glfwGetTime() when the running operation began
    double progress_drawn_ = 0.0;     ///< glfwGetTime() of the last progress frame
    /// While an operation runs in the background: the 3D view as last drawn, shown by the
    /// frames that only move the progress bar. view_events_ counts what can change the view
    /// (keys, buttons, drags, the wheel, resizes, applied outcomes); the still is redrawn
    /// when it moved on.
    StillFrame still_;
    std::uint64_t view_events_ = 0;
    std::uint64_t still_events_ = ~std::uint64_t{0};
    double job_drawn_ = 0.0;  ///< glfwGetTime() of the last progress frame of the operation
    double last_pick_ms_ = 0.0;
    bool quit_ = false;
    bool help_hint_ = false;       ///< the first document opened says "? for help"
    bool open_discards_ = false;   ///< the Open chooser shows with unsaved changes
    bool wireframe_shown_ = true;  ///< the wireframe setting hint_wireframe() last saw
    /// The median length on screen, in framebuffer pixels, of the mesh's edges at the
    /// orbit target's depth (from a thousand of them) (app_shading.cpp).
    double median_edge_pixels() const;
    /// After the wireframe was turned on: says when its edges are too short to show.
    void hint_wireframe();

    int press_button_ = 0;      ///< the button of the press a Pending drag started with
    bool press_shift_ = false;  ///< Shift was held: a click toggles, a drag pans
    bool press_alt_ = false;    ///< the press held Alt: a click selects an edge loop (Ctrl: ring)
    bool press_ctrl_ = false;
    bool swallow_release_ = false;     ///< the press ended an interactive edit
    glm::dvec2 modal_from_{0.0};       ///< framebuffer pixels where the interactive edit began
    glm::dvec2 modal_center_px_{0.0};  ///< the selection's centre on screen then
    double modal_depth_ = 0.0;         ///< and its normalised device depth
    Vec3 modal_center_;
    std::vector<std::string> texture_notes_;  ///< the renderer's, as last said
};

}  // namespace meshedit::viewer
