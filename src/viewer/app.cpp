#include "app.h"

#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "meshedit/files/io_error.h"
#include "meshedit/overlay/label_layout.h"
#include "meshedit/overlay/overlay.h"
#include "meshedit/render/image.h"
#include "meshedit/render/labels.h"
#include "meshedit/render/user_shaders.h"
#include "meshedit/viewer/paths.h"

namespace meshedit::viewer {

namespace {

// The key codes of keys.h are GLFW's; a mismatch here would silently rebind keys.
static_assert(static_cast<int>(Key::A) == GLFW_KEY_A && static_cast<int>(Key::F1) == GLFW_KEY_F1);
static_assert(static_cast<int>(Key::Escape) == GLFW_KEY_ESCAPE &&
              static_cast<int>(Key::KeypadAdd) == GLFW_KEY_KP_ADD &&
              static_cast<int>(Key::LeftBracket) == GLFW_KEY_LEFT_BRACKET);
static_assert(kShift == GLFW_MOD_SHIFT && kCtrl == GLFW_MOD_CONTROL && kAlt == GLFW_MOD_ALT);

constexpr float kOrbitDegreesPerPixel = 0.4f;
constexpr float kZoomPerWheelStep = 0.85f;
constexpr double kClickSlopPixels = 3.0;
constexpr double kHoverDelaySeconds = 0.03;

App& app_of(GLFWwindow* window) {
    return *static_cast<App*>(glfwGetWindowUserPointer(window));
}

// DejaVu Sans (render/labels.h: label_font()) for arrows and dashes in the panels; ImGui's
// built-in font is ASCII only and stays the fallback.
void load_ui_font(float scale) {
    static const ImWchar ranges[] = {0x0020, 0x00FF,  // Latin-1
                                     0x2010, 0x2027,  // dashes, bullets, ellipsis
                                     0x2190, 0x21FF,  // arrows
                                     0x2200, 0x22FF,  // maths (≤, ×)
                                     0};
    const std::string path = label_font().string();  // installed beside the program, or Debian's
    ImGuiIO& io = ImGui::GetIO();
    if (std::filesystem::exists(path) &&
        io.Fonts->AddFontFromFileTTF(path.c_str(), 15.0f * scale, nullptr, ranges) != nullptr) {
        return;
    }
    ImFontConfig config;
    config.SizePixels = 13.0f * scale;
    io.Fonts->AddFontDefault(&config);
}

}  // namespace

App::App(const ViewerOptions& options) {
    editor_.view().up = options.up;
    editor_.set_up_for_next_open(options.up);
    editor_.set_background(true);  // whole-mesh operations leave the window responsive
    editor_.set_progress_hook(
        [this](std::string_view verb, double fraction) { show_progress(verb, fraction); });
    glfwSetErrorCallback([](int code, const char* text) {
        std::fprintf(stderr, "meshedit: GLFW error %d: %s\n", code, text);
    });
    if (!glfwInit()) {
        throw std::runtime_error("cannot initialise GLFW (is there a display?)");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 4);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    window_ = glfwCreateWindow(options.width, options.height, "MeshEdit", nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw std::runtime_error("cannot open an OpenGL 3.3 core window");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(options.vsync ? 1 : 0);
    glfwSetWindowUserPointer(window_, this);

    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
        ++app_of(w).view_events_;
        app_of(w).on_key(key, action, mods);
    });
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned codepoint) {
        if (app_of(w).panels_.prompting()) {
            app_of(w).panels_.prompt_char(codepoint);
            app_of(w).redraw_frames_ = kSettleFrames;
        }
    });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int mods) {
        ++app_of(w).view_events_;
        app_of(w).on_mouse_button(button, action, mods);
    });
    glfwSetCursorPosCallback(window_,
                             [](GLFWwindow* w, double x, double y) { app_of(w).on_cursor(x, y); });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
        ++app_of(w).view_events_;
        app_of(w).on_scroll(dy);
    });
    glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
        app_of(w).on_drop(count, paths);
    });
    glfwSetWindowCloseCallback(window_, [](GLFWwindow* w) { app_of(w).on_close_request(); });
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) {
        App& app = app_of(w);
        app.cursor_moved_ = true;
        app.redraw_frames_ = kSettleFrames;
        ++app.view_events_;
    });
    glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) {
        app_of(w).redraw_frames_ = kSettleFrames;
        ++app_of(w).view_events_;
    });

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
    // HiDPI: the monitor's content scale (e.g. 2 on a 4K laptop panel at 200 %) sizes the
    // panels' text and spacing; the 3D view already renders at framebuffer resolution.
    float content_scale = 1.0f, unused = 1.0f;
    glfwGetWindowContentScale(window_, &content_scale, &unused);
    content_scale = std::clamp(content_scale, 1.0f, 4.0f);
    load_ui_font(content_scale);
    ImGui::StyleColorsDark();
    ImGui::GetStyle().ScaleAllSizes(content_scale);
    ImGui::GetStyle().WindowRounding = 4.0f * content_scale;
    panels_.set_scale(content_scale);
    ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 0.88f;
    ImGui_ImplGlfw_InitForOpenGL(window_, true);  // chains to the callbacks above
    ImGui_ImplOpenGL3_Init("#version 330 core");

    scene_ = std::make_unique<SceneRenderer>();
    upload_document();  // the empty document, until a file opens

    user_shader_dir_ = options.shader_dir.empty() ? default_user_shader_dir() : options.shader_dir;
    scene_->mesh().set_user_shader_dir(user_shader_dir_);
    if (!options.envmap.empty()) {
        load_environment(options.envmap);
    }
    // The student's library loads before the file, in a child first: a library that crashes
    // loading is reported and the viewer runs MeshEdit's own operations.
    const Outcome student =
        options.student.empty() ? Outcome{} : editor_.load_student(options.student);
    if (!options.file.empty()) {
        help_hint_ = true;  // the first window says where the keys are, once the file opened
        open_file(options.file);
    } else {
        set_status("drop a file on the window or press Ctrl+O to open one; ? for help", false);
    }
    if (!student.message.empty()) {
        std::printf("meshedit: %s\n", student.message.c_str());
        std::fflush(stdout);
        set_status(student.message + " — " + status_, student.refused || status_error_);
    }
    reset_camera();
}

App::~App() {
    // GL objects go while their context is current.
    glfwMakeContextCurrent(window_);
    scene_.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
}

int App::run() {
    std::string title;
    while (!quit_) {
        if (redraw_frames_ > 0) {
            glfwPollEvents();
        } else if (editor_.busy()) {
            glfwWaitEventsTimeout(0.05);  // the operation's end and progress are polled
        } else if (cursor_moved_) {
            glfwWaitEventsTimeout(kHoverDelaySeconds);
        } else {
            glfwWaitEventsTimeout(0.5);  // idle: no frames drawn, the CPU stays free
        }
        if (glfwWindowShouldClose(window_)) {
            break;
        }
        // Hover picking waits until the cursor rests a moment: the first pick after an edit
        // rebuilds the face BVH (a fifth of a second per million triangles).
        if (cursor_moved_ && drag_ == DragMode::None &&
            glfwGetTime() - last_cursor_time_ >= kHoverDelaySeconds) {
            update_hover();
        }
        if (const std::string t = editor_.title(); t != title) {
            title = t;
            glfwSetWindowTitle(window_, ("MeshEdit — " + title).c_str());
        }
        if (editor_.busy()) {
            follow_job();
        }
        if (editor_.view().render.shading >= 8 && mesh_mode()) {
            redraw_frames_ = std::max(redraw_frames_, 1);  // user shaders may animate (u_time)
        }
        if (redraw_frames_ > 0) {
            draw_frame();
            --redraw_frames_;
        }
    }
    return 0;
}

// ------------------------------------------------------------------------------ input

void App::tell_view_direction() {
    const glm::vec3 d = camera_.eye() - camera_.target;
    editor_.set_view_direction({d.x, d.y, d.z});
}

void App::on_key(int key, int action, int mods) {
    display_.settle();  // the editor may change the mesh the picking tree is built from
    redraw_frames_ = kSettleFrames;
    if (panels_.prompting()) {
        if (action != GLFW_RELEASE) {
            panels_.prompt_key(key, mods);  // every press and repeat, however slow the frames
        }
        return;
    }
    if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard) {
        return;
    }
    if (brush_mode() && (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_ENTER)) {
        drag_ = DragMode::None;  // Esc ends the brush; it does not clear the selection
        editor_.end_selection_stroke();
        set_status("brush select ended", false);
        return;
    }
    const bool was_modal = editor_.modal() != Modal::None;
    tell_view_direction();
    apply(editor_.press(static_cast<Key>(key), static_cast<unsigned>(mods)));
    if (!was_modal && editor_.modal() != Modal::None) {
        start_modal();
    }
}

void App::start_modal() {
    modal_from_ = cursor_pixels();
    const auto box = editor_.selection_bounds();
    modal_center_ = box ? (box->first + box->second) * 0.5 : Vec3{};
    const glm::dvec4 c =
        clip_of_world() * glm::dvec4(modal_center_.x, modal_center_.y, modal_center_.z, 1.0);
    const glm::ivec2 size = framebuffer_size();
    modal_center_px_ = {(c.x / c.w * 0.5 + 0.5) * size.x, (0.5 - c.y / c.w * 0.5) * size.y};
    modal_depth_ = c.z / c.w;
}

void App::update_modal() {
    display_.settle();  // the edit changes the mesh a picking tree may be built from
    const glm::dvec2 p(cursor_pixels());
    ModalInput in;
    in.dx = p.x - modal_from_.x;
    in.dy = modal_from_.y - p.y;
    const Vec3 from = world_at(modal_from_, modal_depth_);
    in.offset = world_at(p, modal_depth_) - from;
    in.pixel = norm(world_at(modal_from_ + glm::dvec2(1.0, 0.0), modal_depth_) - from);
    const glm::dvec2 a = modal_from_ - modal_center_px_;
    const glm::dvec2 b = p - modal_center_px_;
    in.angle = std::atan2(-b.y, b.x) - std::atan2(-a.y, a.x);
    in.scale = glm::length(b) / std::max(glm::length(a), 1.0);
    const glm::vec3 eye = camera_.eye();
    in.toward_viewer = normalize(Vec3{eye.x, eye.y, eye.z} - modal_center_);
    apply(editor_.modal_input(in));
}

void App::on_mouse_button(int button, int action, int mods) {
    display_.settle();  // the editor may change the mesh the picking tree is built from
    redraw_frames_ = kSettleFrames;
    // ImGui's WantCaptureMouse is from the last drawn frame, which may predate the pointer's
    // arrival (events come in bursts); the panels' rectangles do not move with the pointer.
    if (action == GLFW_PRESS &&
        (ImGui::GetIO().WantCaptureMouse || panels_.contains(glm::vec2(cursor_)))) {
        return;
    }
    if (editor_.modal() != Modal::None) {
        // An interactive edit: a left click applies it, a right click cancels it.
        if (action == GLFW_PRESS && button == GLFW_MOUSE_BUTTON_LEFT) {
            apply(editor_.confirm_modal());
        } else if (action == GLFW_PRESS && button == GLFW_MOUSE_BUTTON_RIGHT) {
            apply(editor_.cancel_modal());
        }
        drag_ = DragMode::None;
        swallow_release_ = true;
        return;
    }
    if (action == GLFW_RELEASE && swallow_release_) {
        swallow_release_ = false;
        return;
    }
    if (region_mouse_button(button, action, mods)) {
        return;
    }
    if (action == GLFW_PRESS) {
        press_at_ = cursor_;
        press_button_ = button;
        press_shift_ = (mods & GLFW_MOD_SHIFT) != 0;
        press_alt_ = (mods & GLFW_MOD_ALT) != 0;
        press_ctrl_ = (mods & GLFW_MOD_CONTROL) != 0;
        if (button == GLFW_MOUSE_BUTTON_MIDDLE) {
            drag_ = DragMode::Pan;
            return;
        }
        if (button == GLFW_MOUSE_BUTTON_RIGHT || press_shift_) {
            drag_ = DragMode::Pending;  // right: orbit once it moves; Shift: pan, or a click
            return;
        }
        if (button != GLFW_MOUSE_BUTTON_LEFT) {
            return;
        }
        if (press_alt_) {
            drag_ = DragMode::Pending;  // a click selects a loop; a vertex is not dragged
            return;
        }
        // Pressing on the selected vertex (or any control point) drags it; anywhere else, an
        // unselected vertex included, the press becomes a click (select) or, once it moves,
        // an orbit. (On a dense mesh the vertex radius covers the whole surface: grabbing
        // whatever vertex is under a press made every orbit a vertex drag. Blender too
        // drags only what is selected.)
        // A curve's control points are few and far apart: pressed, they drag at once.
        const ElementRef hit = pick_at_cursor();
        const ElementRef& selected = editor_.selection();
        if (hit.kind == ElementRef::Kind::Vertex && !mesh_mode()) {
            apply(editor_.select(hit));
        }
        if (hit.kind == ElementRef::Kind::Vertex && selected.kind == hit.kind &&
            selected.index == hit.index && editor_.begin_drag()) {
            drag_ = DragMode::Element;
            return;
        }
        drag_ = DragMode::Pending;
        return;
    }
    // Release.
    if (drag_ == DragMode::Element) {
        Outcome outcome = editor_.end_drag();
        outcome.changes |= kSelection;
        apply(outcome);
    } else if (drag_ == DragMode::Pending && button == GLFW_MOUSE_BUTTON_LEFT) {
        const ElementRef hit = pick_at_cursor();
        if (press_alt_ && mesh_mode()) {
            // Blender's Alt+click: the loop (Ctrl: the ring) through the edge clicked.
            apply(editor_.select(hit));
            apply(editor_.select_region(press_ctrl_ ? Command::SelectEdgeRing
                                                    : Command::SelectEdgeLoop));
            drag_ = DragMode::None;
            cursor_moved_ = true;
            return;
        }
        Outcome outcome =
            press_shift_ && mesh_mode() ? editor_.toggle_select(hit) : editor_.select(hit);
        if (outcome.message.empty()) {
            outcome.message = describe(editor_.mesh(), hit);
        }
        apply(outcome);
    }
    drag_ = DragMode::None;
    cursor_moved_ = true;
}

void App::on_cursor(double x, double y) {
    const glm::dvec2 previous = cursor_;
    cursor_ = {x, y};
    cursor_moved_ = true;
    last_cursor_time_ = glfwGetTime();
    const glm::vec2 delta(cursor_ - previous);
    if (editor_.modal() != Modal::None) {
        update_modal();
        return;
    }
    switch (drag_) {
        case DragMode::None:
            return;  // hover is updated once per frame in run()
        case DragMode::Pending:
            if (glm::length(cursor_ - press_at_) < kClickSlopPixels) {
                return;
            }
            if (!mesh_mode() || (press_shift_ && press_button_ == GLFW_MOUSE_BUTTON_LEFT)) {
                drag_ = DragMode::Pan;  // curves are 2D: dragging empty paper pans
                return;
            }
            drag_ = DragMode::Orbit;
            [[fallthrough]];
        case DragMode::Orbit:
            camera_.orbit(delta.x * kOrbitDegreesPerPixel, delta.y * kOrbitDegreesPerPixel);
            break;
        case DragMode::Pan: {
            // One window pixel moves the target by the world size of a pixel at its depth.
            int w = 0, h = 0;
            glfwGetWindowSize(window_, &w, &h);
            const float world_height =
                camera_.orthographic
                    ? camera_.ortho_height
                    : 2.0f * camera_.distance * std::tan(glm::radians(camera_.fov_y_deg) / 2.0f);
            const float per_pixel = world_height / static_cast<float>(std::max(h, 1));
            const glm::mat4 view = camera_.view();
            const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
            const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
            camera_.target += (-delta.x * right + delta.y * up) * per_pixel;
            update_camera_planes();
            break;
        }
        case DragMode::Element:
            drag_element_to_cursor();
            break;
        case DragMode::BoxArmed:
        case DragMode::Box:
        case DragMode::BrushArmed:
            break;  // the box and the circle follow the cursor when the frame is drawn
        case DragMode::Brush:
            paint_brush();
            break;
        case DragMode::Lasso:
            if (lasso_.empty() || glm::length(cursor_pixels() - lasso_.back()) >= 3.0f) {
                lasso_.push_back(cursor_pixels());
            }
            break;
    }
    redraw_frames_ = kSettleFrames;
    ++view_events_;
}

void App::on_scroll(double dy) {
    redraw_frames_ = kSettleFrames;
    if (ImGui::GetIO().WantCaptureMouse || panels_.contains(glm::vec2(cursor_))) {
        return;
    }
    if (brush_mode()) {  // the wheel sizes the brush, as in Blender
        brush_radius_ =
            std::clamp(brush_radius_ * (1.0f + 0.1f * static_cast<float>(dy)), 4.0f, 400.0f);
        return;
    }
    if (!mesh_mode()) {
        apply(editor_.set_t(editor_.view().t + 0.01 * dy));
        return;
    }
    // Zoom to the cursor: the point under it on the plane through the target stays put.
    const glm::vec2 p = cursor_pixels();
    const glm::vec3 eye = camera_.eye();
    const glm::vec3 forward = glm::normalize(camera_.target - eye);
    const glm::vec3 ray = glm::normalize(unproject(p, 1.0f) - eye);
    const float along = glm::dot(camera_.target - eye, forward) / glm::dot(ray, forward);
    const glm::vec3 under_cursor = eye + ray * along;
    const float factor = std::pow(kZoomPerWheelStep, static_cast<float>(dy));
    camera_.distance =
        std::clamp(camera_.distance * factor, 1e-4f * scene_radius_, 1e3f * scene_radius_);
    camera_.target += (under_cursor - camera_.target) * (1.0f - factor);
    update_camera_planes();
}

void App::on_drop(int count, const char** paths) {
    display_.settle();  // the editor may change the mesh the picking tree is built from
    if (count > 0) {
        open_file(paths[0]);
        if (count > 1) {
            set_status(status_ + " (" + std::to_string(count - 1) + " more dropped files ignored)",
                       status_error_);
        }
    }
}

void App::on_close_request() {
    // The window's close button follows the same rule as Ctrl+Q.
    glfwSetWindowShouldClose(window_, GLFW_FALSE);
    apply(editor_.run({Command::Quit}));
}

// --------------------------------------------------------------------------- commands

void App::set_status(std::string message, bool error) {
    status_ = std::move(message);
    status_error_ = error;
    if (error) {
        std::fprintf(stderr, "meshedit: %s\n", status_.c_str());
    }
    redraw_frames_ = kSettleFrames;
}

void App::open_file(const std::filesystem::path& path, bool discard_confirmed) {
    if (is_environment_image(path)) {
        load_environment(path);  // Ctrl+O or a drop: an image is an environment, not a document
        return;
    }
    try {
        apply(editor_.open(path, discard_confirmed));  // uploads, reframes, rebuilds the overlay
    } catch (const std::exception& e) {
        set_status(editor_.open_failure(path, e), true);
    }
}

void App::apply(const Outcome& outcome) {
    redraw_frames_ = kSettleFrames;
    progress_started_ = -1.0;  // the next operation's progress starts afresh
    if (!outcome.message.empty()) {
        set_status(outcome.message, outcome.refused);
    }
    if ((outcome.changes & kDisplay) != 0) {
        hint_wireframe();
    }
    if (help_hint_ && !outcome.refused && (outcome.changes & kDocument) != 0) {
        set_status(status_ + "; ? for help", false);
        help_hint_ = false;
    }
    const unsigned c = outcome.changes;
    const bool mesh_changed = (c & (kTopology | kGeometry | kDocument)) != 0;
    if (mesh_changed) {
        shown_.reset();  // what the view showed of the old mesh
    }
    if (!follow_mesh_change(outcome)) {  // not a recorded change: upload, rebuild the tree lazily
        DisplayData::Change change;
        change.mesh = mesh_changed;
        change.features = (c & kDisplay) != 0;
        display_.follow(editor_.mesh(), change);
        if (c & (kTopology | kDocument)) {
            upload_document();
            if (!editor_.busy()) {
                display_.prebuild(editor_.mesh(), editor_.document().revision);
            }
        } else if (c & kGeometry) {
            scene_->mesh().update_geometry(editor_.mesh());
            cursor_moved_ = true;
        }
    }
    if (c & (kTopology | kGeometry | kDocument | kDisplay | kSelection)) {
        refresh_field((c & (kTopology | kDocument)) != 0);
    }
    if ((c & kDisplay) && !camera_.orthographic && camera_.trackball != editor_.view().trackball) {
        camera_.set_trackball(editor_.view().trackball);
    }
    if (c & (kTopology | kGeometry | kSelection | kDisplay | kCurve | kDocument)) {
        // Feature edges walk every edge: display_ redoes them only when the mesh or a
        // crease changed, not when the selection or hover moves.
        rebuild_overlay();
    }
    if (c & kResetCamera) {
        reset_camera();
    }
    if (c & kBoxSelect) {
        drag_ = DragMode::BoxArmed;
        if (mesh_mode() && scene_->has_mesh()) {
            shown_points(visible_reach());  // while the pointer goes to the first corner
        }
    }
    if (c & kBrushSelect) {
        drag_ = DragMode::BrushArmed;
    }
    if (c & kFrameSelection) {
        frame_selection();
    }
    // The depth range follows a whole-mesh change (an operation, or undoing one); the undo of
    // a local edit (a recorded region) moves a few vertices and skips the pass over all.
    const bool whole = (c & kSceneBounds) != 0 || ((c & kDocument) != 0 && !outcome.region);
    if (whole && (c & kResetCamera) == 0) {
        fit_depth_range();
    }
    if ((c & kDisplay) && editor_.view().render.shading >= 8) {
        prepare_user_shaders();
    }
    if (c & kReloadShaders) {
        reload_shaders();
    }
    if (c & kScreenshot) {
        write_screenshot();
    }
    if (c & kAskSavePath) {
        panels_.ask_path(ChooserPurpose::SaveAs, editor_.path(), editor_.mode());
    }
    if (c & kAskSessionPath) {
        std::filesystem::path session = editor_.path();
        panels_.ask_path(ChooserPurpose::ExportSession,
                         session.empty() ? session : session.replace_extension(kSessionExtension),
                         editor_.mode());
    }
    if (c & kAskOpenPath) {
        // Told once, in the chooser, before the choice (a second Ctrl+O and the path typed
        // again, as the refusal asked, was where a new user gave up).
        open_discards_ = editor_.dirty();
        const std::string name = editor_.path().empty() ? std::string("the untitled document")
                                                        : editor_.path().filename().string();
        panels_.ask_path(ChooserPurpose::Open, editor_.path(), editor_.mode(),
                         open_discards_ ? "Unsaved changes to " + name +
                                              ": Open discards them (Cancel, then Ctrl+S, to "
                                              "keep them)."
                                        : std::string());
    }
    applied_revision_ = editor_.document().revision;
    if (c & kQuit) {
        quit_ = true;
    }
}

void App::upload_document() {
    scene_->mesh().set_normal_split(editor_.view().normals);
    scene_->upload(mesh_mode() ? &editor_.mesh() : nullptr);
    // A texture that cannot be shown is said once, when the textures are (re)loaded.
    const std::vector<std::string>& notes = scene_->mesh().texture_notes();
    if (notes != texture_notes_) {
        texture_notes_ = notes;
        if (!notes.empty()) {
            set_status(notes.front() +
                           (notes.size() > 1
                                ? " (and " + std::to_string(notes.size() - 1) + " more textures)"
                                : ""),
                       false);
        }
    }
    editor_.set_hover({});
    cursor_moved_ = true;  // the caller rebuilds the overlay
}

void App::rebuild_overlay() {
    const ViewState& view = editor_.view();
    SceneContent scene;
    const Document& doc = editor_.document();
    if (mesh_mode()) {
        scene.mesh = &doc.mesh;
        scene.patches = doc.patches;
        scene.show_nets = view.show_nets;
        scene.steps = editor_.mode() == Mode::Surface ? view.patch_step : -1;
        scene.steps_patch = view.patch;
        scene.steps_u = view.patch_u;
        scene.steps_v = view.patch_v;
        scene.uv_seams = view.render.color == SurfaceColor::Checker;
        scene.material_borders = view.render.color == SurfaceColor::Material;
    } else {
        scene.curve = &doc.curve;
        scene.t = view.t;
        scene.level = view.level;
        scene.show_curve = view.show_curve;
    }
    scene.selected = editor_.selection();
    scene.also_selected = editor_.also_selected();
    scene.hovered = editor_.hover();
    if (mesh_mode()) {
        scene.stencil = view.stencil;
        scene.marks_near_selection = view.marks_near_selection;
        scene.problems = editor_.problems();  // null unless found for this revision
    }
    // Surfaces (tessellated patches) show their nets, not the tessellation's features.
    const bool features = editor_.mode() == Mode::Mesh;
    OverlayBatch batch = display_.overlay(scene, features, features);
    if (const StudentComparison* comparison = editor_.student_comparison()) {
        add_comparison_marks(editor_.mesh(), *comparison, batch);
    }
    labels_ = std::move(batch.labels);
    scene_->overlay().upload(batch);
    redraw_frames_ = kSettleFrames;
}

// ----------------------------------------------------------------------------- camera

// ---------------------------------------------------------------------------- dragging

void App::drag_element_to_cursor() {
    display_.settle();  // the edit changes the mesh a picking tree may be built from
    const ElementRef& s = editor_.selection();
    Vec3 position;
    if (mesh_mode()) {
        position = editor_.mesh().position(Vertex(s.index));
    } else {
        position = editor_.document().curve.control_points[s.index];
    }
    // Keep the point's depth; move it to where the cursor is in the screen plane. In double
    // precision, so no float rounding reaches the document (or the saved file).
    const glm::dmat4 clip_of_world =
        glm::dmat4(camera_.projection(aspect())) * glm::dmat4(camera_.view());
    const glm::dvec4 c = clip_of_world * glm::dvec4(position.x, position.y, position.z, 1.0);
    const glm::ivec2 size = framebuffer_size();
    const glm::dvec2 p = glm::dvec2(cursor_pixels());
    const glm::dvec4 ndc(2.0 * p.x / size.x - 1.0, 1.0 - 2.0 * p.y / size.y, c.z / c.w, 1.0);
    const glm::dvec4 world = glm::inverse(clip_of_world) * ndc;
    const double pixel =
        camera_.orthographic ? static_cast<double>(camera_.ortho_height) / size.y : 0.0;
    apply(editor_.drag_to(Vec3{world.x / world.w, world.y / world.w, world.z / world.w}, pixel));
}

// ---------------------------------------------------------------------------- drawing

void App::draw_scene(int width, int height) {
    scene_->draw(camera_, width, height, frame_options());
}

void App::draw_frame() {
    const auto start = std::chrono::steady_clock::now();
    keep_room_for_panels();  // follows the info panel (I) and window resizes
    const glm::ivec2 size = framebuffer_size();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, size.x, size.y);
    // While an operation runs, a frame that only moves the progress bar shows the still.
    const bool busy = editor_.busy();
    const bool still = busy && view_events_ == still_events_ && still_.holds(size.x, size.y);
    if (still) {
        glClear(GL_COLOR_BUFFER_BIT);
    } else {
        draw_scene(size.x, size.y);
        if (busy) {
            still_.capture(size.x, size.y);
            still_events_ = view_events_;
        }
    }

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (still) {
        still_.draw_behind_panels();
    }
    FrameStats stats;
    stats.frame_ms = last_frame_ms_;
    stats.pick_ms = last_pick_ms_;
    stats.width = size.x;
    stats.height = size.y;
    stats.triangles = scene_->has_mesh() ? scene_->mesh().triangle_count() : 0;
    int window_w = 1, window_h = 1;
    glfwGetWindowSize(window_, &window_w, &window_h);
    if (!labels_.empty() && mesh_mode() && scene_->has_mesh() && !editor_.busy()) {
        // Which labels the surface hides depends on the camera: every frame (tens of rays).
        std::vector<OverlayBatch::Label> labels = labels_;
        const glm::vec3 eye = camera_.eye();
        hide_labels_behind(labels, Vec3(eye.x, eye.y, eye.z), editor_.mesh(),
                           display_.picking_tree(editor_.mesh(), editor_.document().revision));
        draw_labels(labels, camera_, window_w, window_h);
    } else {
        draw_labels(labels_, camera_, window_w, window_h);
    }
    draw_region();
    const PanelRequests requests =
        panels_.draw(editor_, stats, status_, status_error_, display_.field());
    display_.settle();  // what the panels ask for may change the mesh
    if (const auto job = editor_.job_progress()) {
        panels_.draw_progress(job->verb, job->fraction, job->seconds);
    }
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(window_);
    last_frame_ms_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

    if (requests.save_as) {
        apply(editor_.save_as(*requests.save_as));
    }
    if (requests.open) {
        open_file(*requests.open, open_discards_);
    }
    if (requests.export_session) {
        apply(editor_.export_session(*requests.export_session));
    }
    if (requests.normals_changed && scene_->has_mesh()) {
        scene_->mesh().set_normal_split(editor_.view().normals);
        scene_->mesh().update_geometry(editor_.mesh());
    }
    if (requests.field_changed) {
        refresh_field();
    }
    if (requests.view_changed) {
        redraw_frames_ = std::max(redraw_frames_, 1);
    }
    if (requests.action) {
        tell_view_direction();
        apply(editor_.run(*requests.action));
    }
    if (requests.select) {
        apply(editor_.select(*requests.select));
        if (requests.frame) {
            apply(editor_.run(Action{Command::FrameSelection}));
        }
    }
    if (requests.hover && (requests.hover->kind != editor_.hover().kind ||
                           requests.hover->index != editor_.hover().index)) {
        editor_.set_hover(*requests.hover);
        rebuild_overlay();
    }
}

}  // namespace meshedit::viewer
