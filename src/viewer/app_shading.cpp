// Shading 7's environment, the user's shaders (modes 8, 9; Ctrl+R), the scalar field on
// screen (Alt+F, core/fields.h): recomputed whenever the mesh, the selection (distance's
// source) or the field's settings change, and handed to the mesh renderer as colours; the
// wireframe's hint; screenshots (P).

#include "app.h"

#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "meshedit/files/io_error.h"
#include "meshedit/render/environment.h"
#include "meshedit/render/image.h"
#include "meshedit/render/user_shaders.h"
#include "meshedit/viewer/paths.h"

namespace meshedit::viewer {

bool is_environment_image(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".hdr" || ext == ".exr" ||
           ext == ".tif" || ext == ".tiff";
}

void App::load_environment(const std::filesystem::path& path) {
    try {
        const EnvironmentImage image = read_environment(path);
        scene_->mesh().set_environment(image);
        editor_.view().render.shading = 7;
        set_status("environment: " + path.filename().string() + " (" + std::to_string(image.width) +
                       " × " + std::to_string(image.height) + "); shading 7, mirror reflection",
                   false);
        redraw_frames_ = kSettleFrames;
    } catch (const IoError& e) {
        set_status(e.what(), true);
    }
}

void App::prepare_user_shaders() {
    if (starters_checked_ || user_shader_dir_.empty()) {
        return;
    }
    starters_checked_ = true;
    try {
        const std::vector<std::filesystem::path> written =
            install_starter_shaders(user_shader_dir_);
        if (!written.empty()) {
            set_status("wrote the starter shaders mesh8.frag and mesh9.frag to " +
                           user_shader_dir_.string() + ": edit them and press Ctrl+R",
                       false);
        }
    } catch (const IoError& e) {
        set_status(e.what(), true);
    }
}

void App::reload_shaders() {
    prepare_user_shaders();
    const std::string errors = scene_->mesh().reload_shaders();
    panels_.set_shader_errors(errors);
    if (errors.empty()) {
        set_status("shaders recompiled from disk (yours from " + user_shader_dir_.string() + ")",
                   false);
    } else {
        std::fprintf(stderr, "meshedit: %s\n", errors.c_str());
        set_status(errors.substr(0, errors.find('\n')) + " — the previous shader stays", true);
    }
    redraw_frames_ = kSettleFrames;
}

RenderOptions App::frame_options() {
    RenderOptions options = editor_.view().render;
    options.time_s = static_cast<float>(glfwGetTime());
    if (const auto bounds = editor_.selection_bounds()) {
        const Vec3 c = 0.5 * (bounds->first + bounds->second);
        options.has_selection = true;
        options.selection = {static_cast<float>(c.x), static_cast<float>(c.y),
                             static_cast<float>(c.z)};
    }
    // A user shader that does not compile: its error in the panel (it draws as mode 1).
    if (options.shading >= 8 && !scene_->mesh().user_shader_error().empty()) {
        panels_.set_shader_errors(scene_->mesh().user_shader_error());
    }
    return options;
}

void App::refresh_field(bool upload) {
    const ViewState& view = editor_.view();
    FieldRequest request;
    if (view.field != nullptr && mesh_mode() && scene_->has_mesh()) {
        request.info = view.field;
    }
    if (request.info == nullptr) {
        display_.field(editor_.mesh(), request);  // clears it
        scene_->mesh().clear_field();
        return;
    }
    const Mesh& mesh = editor_.mesh();
    const ElementRef& selected = editor_.selection();
    const bool distance = view.field->name == "distance";
    request.source =
        distance && selected.kind == ElementRef::Kind::Vertex && is_live(mesh, selected)
            ? Vertex(selected.index)
            : Vertex(0);
    request.clip = view.field_clip;
    request.colormap = view.colormap;
    bool recomputed = false;
    const FieldDisplay& field = display_.field(mesh, request, &recomputed);
    if (recomputed || upload) {
        scene_->mesh().set_field(view.field->site, field.values, field.coloring);
        redraw_frames_ = kSettleFrames;
    }
}

double App::median_edge_pixels() const {
    const Mesh& mesh = editor_.mesh();
    if (mesh.n_edges() == 0) {
        return 0.0;
    }
    // A thousand edges spread over the numbering are enough for a median.
    std::vector<double> lengths;
    const std::size_t n = mesh.edges_size();
    const std::size_t step = std::max<std::size_t>(1, n / 1000);
    for (std::size_t i = 0; i < n; i += step) {
        const Edge e(static_cast<std::uint32_t>(i));
        if (!mesh.is_deleted(e)) {
            const Halfedge h = Mesh::halfedge(e, 0);
            lengths.push_back(
                norm(mesh.position(mesh.to_vertex(h)) - mesh.position(mesh.from_vertex(h))));
        }
    }
    if (lengths.empty()) {
        return 0.0;
    }
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    const double world_height =
        camera_.orthographic
            ? camera_.ortho_height
            : 2.0 * camera_.distance * std::tan(camera_.fov_y_deg * 3.14159265358979 / 360.0);
    return lengths[lengths.size() / 2] * framebuffer_size().y / world_height;
}

void App::hint_wireframe() {
    const bool shown = editor_.view().render.wireframe;
    if (shown == wireframe_shown_) {
        return;
    }
    wireframe_shown_ = shown;
    // The wire fades out where triangles are under a few pixels (mesh.frag): on a dense mesh
    // at the opening zoom, W then seems to do nothing (issue 40). Say so.
    if (shown && mesh_mode()) {
        if (const double px = median_edge_pixels(); px > 0.0 && px < 3.0) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "wireframe on — at this zoom its edges are %.1f px long and fade out "
                          "below 3 px: zoom in to see them",
                          px);
            set_status(text, false);
        }
    }
}

void App::write_screenshot() {
    // The 3D view the panels leave free (the whole window with the info panel hidden), without
    // the hover highlight (it follows the mouse, not the document), 4× MSAA like the window.
    // Its camera is the window's without the lens shift, at that part's aspect: the same
    // picture, pixel for pixel, and the same as `meshedit render` at that size after Space.
    const ElementRef hover = editor_.hover();
    editor_.set_hover({});
    rebuild_overlay();
    editor_.set_hover(hover);
    const glm::ivec2 size = framebuffer_size();
    const int width = size.x - covered_pixels();
    RenderTarget target(width, size.y, 4);
    target.bind();
    Camera free_part = camera_;
    free_part.lens_shift_x = 0.0f;
    scene_->draw(free_part, width, size.y, frame_options());
    const Image image = target.read();
    rebuild_overlay();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, size.x, size.y);
    try {
        const std::filesystem::path folder = pictures_folder();
        std::filesystem::create_directories(folder);
        const std::filesystem::path path = screenshot_path(folder, editor_.path());
        write_png(image, path);
        set_status("screenshot saved to " + path.string(), false);
        std::printf("meshedit: screenshot %s\n", path.c_str());
        std::fflush(stdout);
    } catch (const std::exception& e) {
        set_status(std::string("screenshot failed: ") + e.what(), true);
    }
}

}  // namespace meshedit::viewer
