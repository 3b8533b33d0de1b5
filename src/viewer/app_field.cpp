// Shading 7's environment, and the scalar field on screen (Alt+F, core/fields.h): recomputed
// whenever the mesh, the selection (distance's source) or the field's settings change, and handed
// to the mesh renderer as colours.

#include "app.h"

#include <cctype>
#include <string>

#include "meshedit/files/io_error.h"
#include "meshedit/render/environment.h"

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

void App::refresh_field() {
    const ViewState& view = editor_.view();
    if (view.field == nullptr || !mesh_mode() || !scene_->has_mesh()) {
        field_ = {};
        scene_->mesh().clear_field();
        return;
    }
    const Mesh& mesh = editor_.mesh();
    FieldOptions options;
    const ElementRef& selected = editor_.selection();
    options.source = selected.kind == ElementRef::Kind::Vertex && is_live(mesh, selected)
                         ? Vertex(selected.index)
                         : Vertex(0);
    field_.info = view.field;
    field_.source = options.source;
    field_.values = compute_field(mesh, *view.field, options);
    field_.stats = field_stats(field_.values);
    field_.coloring = default_coloring(*view.field, field_.values, view.field_clip);
    if (view.colormap) {
        field_.coloring.map = *view.colormap;
    }
    scene_->mesh().set_field(view.field->site, field_.values, field_.coloring);
    redraw_frames_ = kSettleFrames;
}

}  // namespace meshedit::viewer
