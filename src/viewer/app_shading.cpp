// Shading 7's environment, the user's shaders (modes 8, 9; Ctrl+R), and the scalar field on
// screen (Alt+F, core/fields.h): recomputed
// whenever the mesh, the selection (distance's source) or the field's settings change, and handed
// to the mesh renderer as colours.

#include "app.h"

#include <cctype>
#include <cstdio>
#include <vector>

#include <GLFW/glfw3.h>
#include <string>

#include "meshedit/files/io_error.h"
#include "meshedit/render/environment.h"
#include "meshedit/render/user_shaders.h"

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

}  // namespace meshedit::viewer
