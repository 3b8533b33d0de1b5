// The editor: files, the command dispatcher, display toggles, undo/redo, quitting, selection
// and dragging. Mesh operations, navigation, curve and surface commands are in
// editor_ops.cpp.

#include "meshedit/viewer/editor.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "meshedit/io/io.h"

namespace meshedit::viewer {

namespace {

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::string file_name(const std::filesystem::path& path) {
    return path.empty() ? std::string("untitled") : path.filename().string();
}

std::string counts(const Mesh& mesh) {
    return "V " + std::to_string(mesh.n_vertices()) + " E " + std::to_string(mesh.n_edges()) +
           " F " + std::to_string(mesh.n_faces());
}

/// True if some binding makes `command` available in `mode`.
bool available(Command command, Mode mode) {
    const unsigned bit = mode_bit(mode);
    return std::any_of(bindings().begin(), bindings().end(), [&](const Binding& b) {
        return b.action.command == command && (b.modes & bit) != 0;
    });
}

const char* mode_name(Mode mode) {
    switch (mode) {
        case Mode::Mesh:
            return "mesh";
        case Mode::Surface:
            return "surface";
        case Mode::Curve:
            return "curve";
    }
    return "";
}

/// Multi-line summaries as one status line.
std::string one_line(std::string text) {
    while (!text.empty() && text.back() == '\n') {
        text.pop_back();
    }
    for (std::size_t i = text.find('\n'); i != std::string::npos; i = text.find('\n', i)) {
        text.replace(i, 1, "; ");
    }
    return text;
}

Outcome refused(std::string message) {
    return {kNothing, std::move(message), true};
}

}  // namespace

Editor::Editor(HistoryLimits limits) : history_(limits) {}

// ------------------------------------------------------------------------------- files

Outcome Editor::open(const std::filesystem::path& path) {
    // Everything is read into a local document first: an IoError leaves the editor as it was.
    const std::string ext = lower_extension(path);
    Document doc;
    std::string details;
    if (ext == ".bez") {
        doc.mode = Mode::Surface;
        doc.patches = read_bez(path);
        doc.density = 8;
        TessellationOptions options;
        options.density = doc.density;
        doc.mesh = tessellate(doc.patches, options);
        details = std::to_string(doc.patches.size()) + " patches, " + counts(doc.mesh);
    } else if (ext == ".bzc") {
        doc.mode = Mode::Curve;
        doc.curve = read_bzc(path);
        details = std::to_string(doc.curve.control_points.size()) + " control points";
    } else {
        // read_mesh() names unknown extensions itself.
        LoadedMesh loaded = read_mesh(path);
        doc.mode = Mode::Mesh;
        doc.mesh = std::move(loaded.mesh);
        details = counts(doc.mesh);
        if (loaded.repairs.repaired()) {
            details += "; repaired: " + one_line(loaded.repairs.summary());
        }
        for (const std::string& notice : loaded.notices) {
            details += "; " + notice;
        }
    }
    const Mode mode = doc.mode;
    set_document(std::move(doc), path);
    if (mode == Mode::Surface) {
        pristine_revisions_.insert(doc_.revision);
    }
    return {kDocument | kTopology | kGeometry | kSelection | kDisplay | kCurve | kResetCamera,
            "opened " + file_name(path) + ": " + details};
}

void Editor::set_document(Document document, std::filesystem::path path) {
    doc_ = std::move(document);
    doc_.revision = next_revision_++;
    doc_.selection = {};
    saved_revision_ = doc_.revision;
    history_.clear();
    pristine_revisions_.clear();
    hover_ = {};
    path_ = std::move(path);
    view_.level = 0;
    view_.t = 0.5;
    dragging_ = false;
    drag_moved_ = false;
    quit_armed_ = false;
}

Outcome Editor::save() {
    if (path_.empty()) {
        return refused("no file name: use Ctrl+Shift+S");
    }
    const std::string ext = lower_extension(path_);
    if (doc_.mode == Mode::Curve && ext != ".bzc") {
        return refused("a curve is saved as .bzc: use Ctrl+Shift+S");
    }
    if (doc_.mode == Mode::Surface && ext == ".bez") {
        return refused(
            "a .bez file holds patches, not the edited mesh: save as .dae, .obj or .gltf "
            "(Ctrl+Shift+S)");
    }
    if (doc_.mode != Mode::Curve && !is_mesh_extension(ext)) {
        return refused("cannot save a mesh as '" + ext +
                       "': use Ctrl+Shift+S with .dae, .gltf, .glb or .obj");
    }
    return write_to(path_);
}

Outcome Editor::save_as(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    if (doc_.mode == Mode::Curve && ext != ".bzc") {
        return refused("a curve is saved as .bzc, not '" + ext + "'");
    }
    if (doc_.mode != Mode::Curve && !is_mesh_extension(ext)) {
        return refused("a mesh is saved as .dae, .gltf, .glb or .obj, not '" + ext + "'");
    }
    Outcome outcome = write_to(path);
    if (!outcome.refused) {
        path_ = path;
    }
    return outcome;
}

Outcome Editor::write_to(const std::filesystem::path& path) {
    Outcome outcome;
    try {
        if (doc_.mode == Mode::Curve) {
            write_bzc(doc_.curve, path);
        } else {
            // Collect first, so the file numbers elements as the info panel showed them.
            if (doc_.mesh.has_garbage()) {
                compact();
                outcome.changes |= kTopology | kSelection;
            }
            write_mesh(doc_.mesh, path);  // atomic: temporary file + rename
        }
    } catch (const IoError& e) {
        outcome.message = e.what();
        outcome.refused = true;
        return outcome;
    }
    saved_revision_ = doc_.revision;
    quit_armed_ = false;
    outcome.changes |= kDisplay;  // the title loses its '*'
    outcome.message = "saved " + file_name(path);
    return outcome;
}

std::string Editor::title() const {
    std::string out = file_name(path_) + " — ";
    if (doc_.mode == Mode::Curve) {
        out += "curve, " + std::to_string(doc_.curve.control_points.size()) + " points";
    } else {
        out += counts(doc_.mesh);
    }
    if (dirty()) {
        out += " *";
    }
    return out;
}

// ---------------------------------------------------------------------------- commands

Outcome Editor::press(Key key, unsigned mods) {
    const std::optional<Action> action = lookup(key, mods, doc_.mode);
    if (!action) {
        return {};
    }
    return run(*action);
}

Outcome Editor::run(Action action) {
    const Command c = action.command;
    if (c != Command::Escape && c != Command::Quit) {
        quit_armed_ = false;
    }
    if (!available(c, doc_.mode)) {
        return refused(std::string("not available in ") + mode_name(doc_.mode) + " mode");
    }
    switch (c) {
        case Command::Flip:
        case Command::Split:
        case Command::Collapse:
        case Command::Loop:
        case Command::ToggleCrease:
            return run_mesh_op(c);
        case Command::Next:
        case Command::Twin:
        case Command::ToHalfedge:
        case Command::ToVertex:
        case Command::ToEdge:
        case Command::ToFace:
            return run_navigation(c);
        case Command::ToggleSmooth:
        case Command::ToggleWireframe:
        case Command::Shading:
        case Command::ToggleInfo:
        case Command::ToggleHelp:
        case Command::ResetCamera:
        case Command::Screenshot:
            return run_display(action);
        case Command::Undo:
            return undo();
        case Command::Redo:
            return redo();
        case Command::Save:
            return save();
        case Command::SaveAs:
            return {kAskSavePath, ""};
        case Command::Open:
            return {kAskOpenPath, ""};
        case Command::Escape:
            if (!doc_.selection.is_none()) {
                doc_.selection = {};
                return {kSelection, "selection cleared"};
            }
            return quit(true);
        case Command::Quit:
            return quit(false);
        case Command::LevelDown:
        case Command::LevelUp:
        case Command::ToggleCurve:
        case Command::DecreaseT:
        case Command::IncreaseT:
        case Command::AddPoint:
        case Command::RemovePoint:
            return run_curve(action);
        case Command::DensityUp:
        case Command::DensityDown:
        case Command::ToggleNets:
            return run_surface(c);
    }
    return {};
}

Outcome Editor::run_display(Action action) {
    RenderOptions& r = view_.render;
    switch (action.command) {
        case Command::ToggleSmooth:
            r.smooth = !r.smooth;
            return {kDisplay,
                    r.smooth ? "smooth shading (area-weighted vertex normals)" : "flat shading"};
        case Command::ToggleWireframe:
            r.wireframe = !r.wireframe;
            return {kDisplay, r.wireframe ? "wireframe on" : "wireframe off"};
        case Command::Shading: {
            const int n = action.argument;
            if (n < 0 || n >= static_cast<int>(kShadingModes.size())) {
                return refused("no shading mode " + std::to_string(n));
            }
            r.shading = n;
            return {kDisplay, "shading " + std::to_string(n) + ": " +
                                  std::string(kShadingModes[static_cast<std::size_t>(n)].name)};
        }
        case Command::ToggleInfo:
            view_.show_info = !view_.show_info;
            return {kDisplay, ""};
        case Command::ToggleHelp:
            view_.show_help = !view_.show_help;
            return {kDisplay, ""};
        case Command::ResetCamera:
            return {kResetCamera, ""};
        case Command::Screenshot:
            return {kScreenshot, ""};
        default:
            break;
    }
    return {};
}

// ------------------------------------------------------------------------------ history

void Editor::begin_edit() {
    commit_edit(doc_);
}

void Editor::commit_edit(Document before) {
    history_.push(std::move(before));
    doc_.revision = next_revision_++;
    quit_armed_ = false;
}

Outcome Editor::undo() {
    end_drag();
    if (!history_.undo(doc_)) {
        return refused("nothing to undo");
    }
    hover_ = {};
    if (doc_.mode == Mode::Curve) {
        view_.level = std::min(view_.level, doc_.curve.degree());
    }
    return {kDocument | kTopology | kSelection | kCurve | kDisplay,
            "undo (" + std::to_string(history_.undo_steps()) + " left)"};
}

Outcome Editor::redo() {
    end_drag();
    if (!history_.redo(doc_)) {
        return refused("nothing to redo");
    }
    hover_ = {};
    if (doc_.mode == Mode::Curve) {
        view_.level = std::min(view_.level, doc_.curve.degree());
    }
    return {kDocument | kTopology | kSelection | kCurve | kDisplay,
            "redo (" + std::to_string(history_.redo_steps()) + " left)"};
}

Outcome Editor::quit(bool from_escape) {
    (void)from_escape;
    if (!dirty() || quit_armed_) {
        return {kQuit, ""};
    }
    quit_armed_ = true;
    return refused(
        "unsaved changes: press Esc or Ctrl+Q again to quit without saving, or Ctrl+S to save");
}

// ---------------------------------------------------------------------- selection, drag

Outcome Editor::select(ElementRef element) {
    bool ok = false;
    if (doc_.mode == Mode::Curve) {
        ok = element.kind == ElementRef::Kind::Vertex &&
             element.index < doc_.curve.control_points.size();
    } else {
        ok = is_live(doc_.mesh, element);
    }
    doc_.selection = ok ? element : ElementRef{};
    if (doc_.mode == Mode::Curve) {
        return {kSelection, ok ? "control point " + std::to_string(element.index)
                               : std::string("nothing selected")};
    }
    return {kSelection, describe(doc_.mesh, doc_.selection)};
}

bool Editor::begin_drag() {
    const ElementRef& s = doc_.selection;
    if (s.kind != ElementRef::Kind::Vertex) {
        return false;
    }
    const bool ok = doc_.mode == Mode::Curve ? s.index < doc_.curve.control_points.size()
                                             : is_live(doc_.mesh, s);
    if (!ok) {
        return false;
    }
    // The snapshot is taken on the first real move (the document cannot change before
    // it), so a click without a move costs no copy and leaves no undo step.
    dragging_ = true;
    drag_moved_ = false;
    drag_index_ = s.index;
    return true;
}

Outcome Editor::drag_to(const Vec3& position) {
    if (!dragging_) {
        return {};
    }
    const ElementRef& s = doc_.selection;
    if (s.kind != ElementRef::Kind::Vertex || s.index != drag_index_) {
        return {};  // the selection changed under the drag
    }
    if (!is_finite(position)) {
        return refused("cannot move to a non-finite position");
    }
    Vec3* target = nullptr;
    Vec3 wanted = position;
    if (doc_.mode == Mode::Curve) {
        if (drag_index_ >= doc_.curve.control_points.size()) {
            return {};
        }
        target = &doc_.curve.control_points[drag_index_];
        wanted.z = target->z;  // curves are 2D: keep z
    } else {
        if (!is_live(doc_.mesh, s)) {
            return {};
        }
        target = &doc_.mesh.position(Vertex(drag_index_));
    }
    if (*target == wanted) {
        return {};
    }
    if (!drag_moved_) {
        begin_edit();  // invalidates nothing: doc_ is copied, not moved
        drag_moved_ = true;
        target = doc_.mode == Mode::Curve ? &doc_.curve.control_points[drag_index_]
                                          : &doc_.mesh.position(Vertex(drag_index_));
    }
    *target = wanted;
    return {doc_.mode == Mode::Curve ? unsigned{kCurve} : unsigned{kGeometry}, ""};
}

void Editor::end_drag() {
    dragging_ = false;
    drag_moved_ = false;
}

Outcome Editor::set_t(double t) {
    if (doc_.mode != Mode::Curve) {
        return refused("t belongs to curves");
    }
    if (!std::isfinite(t)) {
        return refused("t must be a number");
    }
    view_.t = std::clamp(t, 0.0, 1.0);
    char buf[32];
    std::snprintf(buf, sizeof buf, "t = %.2f", view_.t);
    return {kDisplay, buf};
}

}  // namespace meshedit::viewer
