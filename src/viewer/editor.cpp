// The editor's dispatcher, display toggles, undo/redo, quitting, and the edit funnel every
// change of the document goes through. Files, mesh edits, curve and surface commands and the
// selection are in the other editor_*.cpp files (editor.h lists them).

#include "meshedit/viewer/editor.h"

#include "meshedit/core/attributes.h"

#include <algorithm>
#include <exception>
#include <new>
#include <stdexcept>
#include <utility>

#include "meshedit/core/attributes.h"
#include "meshedit/ops/ops.h"
#include "meshedit/viewer/paths.h"

namespace meshedit::viewer {

namespace {

/// True if some binding makes `command` available in `mode`.
bool available(Command command, Mode mode) {
    const unsigned bit = mode_bit(mode);
    return std::any_of(bindings().begin(), bindings().end(), [&](const Binding& b) {
        return b.action.command == command && (b.modes & bit) != 0;
    });
}

/// Commands that only change how the document is shown (run_display()).
bool display_command(Command c) {
    switch (c) {
        case Command::ToggleSmooth:
        case Command::ToggleWireframe:
        case Command::Shading:
        case Command::ToggleInfo:
        case Command::ToggleHelp:
        case Command::ResetCamera:
        case Command::CycleUp:
        case Command::ToggleTrackball:
        case Command::CycleStencil:
        case Command::ToggleDiagram:
        case Command::ToggleMarksNear:
        case Command::CycleField:
        case Command::ReloadShaders:
        case Command::CycleColormap:
        case Command::CycleSurfaceColor:
        case Command::Screenshot:
            return true;
        default:
            return false;
    }
}

}  // namespace

// ---------------------------------------------------------------------------- commands

Outcome Editor::press(Key key, unsigned mods) {
    if (std::optional<Outcome> taken = modal_key(key, mods)) {
        return *taken;
    }
    const std::optional<Action> action = lookup(key, mods, doc_.mode);
    if (!action) {
        return {};
    }
    return run(*action);
}

Outcome Editor::run(Action action) {
    const Command c = action.command;
    if (busy()) {
        // While an operation runs, the view is the user's; the document is the operation's.
        if (c == Command::Escape) {
            return cancel_job();
        }
        if (c == Command::Quit) {
            cancel_job();
            wait_job();
            return quit();
        }
        if (c != Command::FrameSelection && !display_command(c)) {
            return *refuse_if_busy();
        }
    }
    end_drag();  // a key during a drag ends it (its transaction commits) before it runs
    if (modal_.kind != Modal::None) {
        // A key the interactive edit does not take (modal_key) applies it first, as in
        // Blender.
        if (Outcome confirmed = confirm_modal(); confirmed.refused) {
            return confirmed;
        }
    }
    if (c != Command::Escape && c != Command::Quit) {
        ledger_.quit_armed = false;
    }
    if (c != Command::Open) {
        ledger_.replace_armed = false;
    }
    if (c != Command::Save && c != Command::SaveAs) {
        lossy_armed_.clear();
    }
    if (!available(c, doc_.mode)) {
        return refused(std::string("not available in ") + kind_name(doc_.mode) + " mode");
    }
    if (display_command(c)) {
        return run_display(action);
    }
    switch (c) {
        case Command::Edit:
            return edit_mesh(action.verb);
        case Command::Interactive:
            return begin_modal(static_cast<Modal>(action.argument));
        case Command::Delete:
        case Command::SelectAll:
        case Command::SelectNone:
        case Command::SelectLoop:
        case Command::SelectEdgeLoop:
        case Command::SelectEdgeRing:
        case Command::SelectLinked:
        case Command::SelectMore:
        case Command::SelectLess:
        case Command::SelectInvert:
        case Command::SelectPath:
        case Command::SelectTrait:
        case Command::BoxSelect:
        case Command::BrushSelect:
        case Command::FrameSelection:
        case Command::Validate:
            return run_selection(c);
        case Command::FindProblems:
            return find_problems();
        case Command::Next:
        case Command::Twin:
        case Command::ToHalfedge:
        case Command::ToVertex:
        case Command::ToEdge:
        case Command::ToFace:
            return run_navigation(c);
        case Command::Undo:
            return undo();
        case Command::Redo:
            return redo();
        case Command::Save:
            return save();
        case Command::SaveAs:
            return {kAskSavePath, ""};
        case Command::ExportSession:
            return {kAskSessionPath, ""};
        case Command::Open:
            return {kAskOpenPath, ""};
        case Command::Escape:
            if (student_comparison() != nullptr) {
                Outcome back = undo();
                back.message =
                    "back to your input (the side by side is undone; Ctrl+Shift+Z "
                    "shows it again)";
                return back;
            }
            if (!doc_.selection.is_none() || !doc_.also_selected.empty()) {
                return select_none();
            }
            return quit();
        case Command::Quit:
            return quit();
        case Command::LevelDown:
            if (student_) {
                const int last = static_cast<int>(doc_.curve.control_points.size()) - 1;
                const int level = view_.level < 0 ? last : std::min(view_.level, last);
                if (level < last) {
                    if (std::optional<Outcome> wrong = check_student_step(level)) {
                        return *wrong;
                    }
                }
            }
            return run_curve(action);
        case Command::LevelUp:
        case Command::ToggleCurve:
        case Command::DecreaseT:
        case Command::IncreaseT:
        case Command::AddPoint:
        case Command::RemovePoint:
            return run_curve(action);
        case Command::DensityUp:
        case Command::DensityDown: {
            Outcome out = run_surface(c);
            if (student_ && !out.refused) {
                out.message += check_student_patches();
            }
            return out;
        }
        case Command::ToggleNets:
        case Command::PatchStep:
            return run_surface(c);
        default:
            break;  // display commands, above
    }
    return {};
}

Outcome Editor::run_display(Action action) {
    RenderOptions& r = view_.render;
    switch (action.command) {
        case Command::ToggleSmooth: {
            r.smooth = !r.smooth;
            if (r.smooth && student_ && doc_.mode != Mode::Curve && !student_comparison()) {
                return check_student_normals();
            }
            return {kDisplay,
                    r.smooth ? "smooth shading (area-weighted vertex normals)" : "flat shading"};
        }
        case Command::ToggleWireframe:
            r.wireframe = !r.wireframe;
            return {kDisplay, r.wireframe ? "wireframe on" : "wireframe off"};
        case Command::Shading: {
            const int n = action.argument;
            if (n < 0 || n >= static_cast<int>(kShadingModes.size())) {
                return refused("no shading mode " + std::to_string(n));
            }
            r.shading = n;
            const ShadingMode& m = kShadingModes[static_cast<std::size_t>(n)];
            const bool alias = m.number >= 8;  // the user's: say where the file is
            return {kDisplay, "shading " + std::to_string(n) + ": " +
                                  std::string(alias ? m.description : m.name)};
        }
        case Command::ToggleInfo:
            view_.show_info = !view_.show_info;
            return {kDisplay, ""};
        case Command::ToggleHelp:
            view_.show_help = !view_.show_help;
            return {kDisplay, ""};
        case Command::ResetCamera:
            return {kResetCamera, ""};
        case Command::CycleUp:
            view_.up = view_.up == UpAxis::Y ? UpAxis::Z : UpAxis::Y;
            remember_up(session_source_hash_, view_.up == UpAxis::Z ? 'z' : 'y');
            return {kResetCamera | kDisplay, view_.up == UpAxis::Y
                                                 ? "up axis +Y, as the file declares"
                                                 : "up axis +Z (the CS184 course's models are "
                                                   "Z-up whatever they declare)"};
        case Command::ToggleTrackball:
            view_.trackball = !view_.trackball;
            return {kDisplay, view_.trackball ? "orbit: trackball (free rotation)"
                                              : "orbit: turntable (the up axis stays up)"};
        case Command::CycleStencil:
            return cycle_stencil();
        case Command::CycleField:
            return cycle_field();
        case Command::ReloadShaders:
            return {kReloadShaders, ""};
        case Command::CycleSurfaceColor:
            return cycle_surface_color();
        case Command::CycleColormap: {
            std::optional<ColorMap>& map = view_.colormap;
            map = !map                        ? std::optional(ColorMap::Viridis)
                  : *map == ColorMap::Viridis ? std::optional(ColorMap::Magma)
                  : *map == ColorMap::Magma   ? std::optional(ColorMap::Diverging)
                                              : std::nullopt;
            return {kDisplay, "colour map: " + (map ? std::string(colormap_name(*map))
                                                    : std::string("the field's default"))};
        }
        case Command::ToggleDiagram:
            view_.show_diagram = !view_.show_diagram;
            return {kDisplay, view_.show_diagram
                                  ? "rewiring panel on (shows after F, S, C and the other local "
                                    "operations)"
                                  : "rewiring panel off"};
        case Command::ToggleMarksNear:
            view_.marks_near_selection = !view_.marks_near_selection;
            return {kDisplay, view_.marks_near_selection
                                  ? "Loop's marks near the selection only (two rings; all of "
                                    "them when nothing is selected)"
                                  : "Loop's marks everywhere"};
        case Command::Screenshot:
            return {kScreenshot, ""};
        default:
            break;
    }
    return {};
}

// --------------------------------------------------------------------- the edit funnel

namespace {

// The rewiring diagram of a one-step local edit, read from its recorded change (no copy of the
// mesh, so at any size).
std::optional<OpDiagram> rewiring_of(Mesh& mesh, const MeshChange& change, const ops::Step& step) {
    try {
        return op_diagram(mesh, change, step.verb->name, step.verb->names,
                          [&](const Mesh& before) { return ops::named_element(before, step); });
    } catch (const std::exception&) {
        // A step that ran names a live element; whatever goes wrong in drawing its diagram
        // must not take the edit, which is done, down with it.
        return std::nullopt;
    }
}

}  // namespace

Outcome Editor::edit(const std::function<OpStatus()>& check,
                     const std::function<Edited(Document&)>& apply, bool local) {
    if (const OpStatus status = check(); !status) {
        return refused(status.text());
    }
    const bool recorded = local && doc_.mode != Mode::Curve;
    diagram_.reset();
    Transaction transaction(ledger_, doc_,
                            recorded ? Transaction::Kind::Recorded : Transaction::Kind::Snapshot);
    Edited edited;
    try {
        edited = apply(doc_);
    } catch (const std::bad_alloc&) {
        transaction.roll_back();
        return refused("not enough memory: nothing changed");
    } catch (const std::exception& e) {
        transaction.roll_back();
        return refused(e.what());
    }
    settle(edited);
    if (!recorded && compact()) {
        edited.steps.emplace_back("compact");
    }
    // The diagram only when its panel is shown: it costs what the edit touched, not the mesh.
    const ops::Step* step = edited.step;
    const bool drawn =
        recorded && view_.show_diagram && step != nullptr && ops::draws_diagram(*step);
    Outcome out = transaction.commit(
        edited.changes, std::move(edited.message), std::move(edited.steps),
        drawn ? [&](const MeshChange& change) { diagram_ = rewiring_of(doc_.mesh, change, *step); }
              : std::function<void(const MeshChange&)>());
    if (out.message.find(" — cannot be undone: ") != std::string::npos) {
        diagram_.reset();
    }
    return out;
}

void Editor::settle(Edited& edited) {
    if (edited.select) {
        doc_.selection = *edited.select;
        doc_.also_selected.clear();
    }
    if ((edited.changes & kTopology) != 0) {
        hover_ = {};
    }
}

// ------------------------------------------------------------------------------ history

Outcome Editor::undo() {
    return step_history(false);
}

Outcome Editor::redo() {
    return step_history(true);
}

Outcome Editor::step_history(bool forward) {
    end_drag();
    // An interactive edit under way is cancelled first; where its preview was must be
    // redrawn too.
    const bool was_modal = modal_.kind != Modal::None;
    std::optional<MeshChange::Region> cancelled = cancel_modal().region;
    diagram_.reset();
    std::optional<std::optional<MeshChange::Region>> moved = ledger_.step(doc_, forward);
    if (!moved) {
        Outcome out = refused(forward ? "nothing to redo" : "nothing to undo");
        out.changes = was_modal ? kTopology | kSelection : kNothing;
        out.region = std::move(cancelled);
        return out;
    }
    Outcome out{kDocument | kTopology | kSelection | kCurve | kDisplay,
                std::string(forward ? "redo (" : "undo (") +
                    std::to_string(forward ? history().redo_steps() : history().undo_steps()) +
                    " left)",
                false, std::move(*moved)};  // none after a snapshot: the window redraws it all
    if (out.region && cancelled) {
        out.region->add(*cancelled);
    }
    hover_ = {};
    if (doc_.mode == Mode::Curve) {
        view_.level = std::min(view_.level, doc_.curve.degree());
    }
    return out;
}

Outcome Editor::quit() {
    if (!dirty() || ledger_.quit_armed) {
        return {kQuit, ""};
    }
    ledger_.quit_armed = true;
    return refused(
        "unsaved changes: press Esc or Ctrl+Q again to quit without saving, or Ctrl+S to save");
}

Outcome Editor::cycle_stencil() {
    std::optional<StencilScheme>& stencil = view_.stencil;
    if (!stencil) {
        stencil = StencilScheme::LoopWarren;
    } else if (*stencil == StencilScheme::LoopWarren) {
        stencil = StencilScheme::LoopOriginal;
    } else if (*stencil == StencilScheme::LoopOriginal) {
        stencil = StencilScheme::CatmullClark;
    } else {
        stencil.reset();
        return {kDisplay | kSelection, "stencil view off"};
    }
    return {kDisplay | kSelection,
            std::string("stencil view: ") + scheme_name(*stencil) + " — hover a vertex, an edge" +
                (*stencil == StencilScheme::CatmullClark ? " or a face" : "") +
                " (Alt+W: next scheme)"};
}

Outcome Editor::cycle_field() {
    // The computed fields, then the mesh's own numbers (a PLY column such as compare's
    // deviation), then off.
    const std::vector<const FieldInfo*> all = mesh_fields(mesh());
    const auto at = std::find(all.begin(), all.end(), view_.field);
    if (view_.field == nullptr || at == all.end()) {
        view_.field = all.front();
    } else if (at + 1 == all.end()) {
        view_.field = nullptr;
        return {kDisplay, "field off"};
    } else {
        view_.field = *(at + 1);
    }
    std::string message = "field: " + std::string(view_.field->title);
    if (view_.field->name == "distance") {
        message += " from the selected vertex (vertex 0 when none)";
    }
    return {kDisplay, message + " (Alt+F: next)"};
}

Outcome Editor::cycle_surface_color() {
    // The choices this mesh has data for, in the table's order, Auto first.
    const Mesh& m = mesh();
    const bool uv = m.has_property<Halfedge>(kTexCoordProperty);
    const bool texture =
        std::any_of(m.materials().begin(), m.materials().end(),
                    [](const Material& x) { return !x.base_colour_texture.empty(); });
    const bool has[] = {
        true,
        true,
        m.has_property<Face>(kMaterialProperty) && !m.materials().empty(),
        m.has_property<Vertex>(kColorProperty) || m.has_property<Face>(kFaceColorProperty),
        uv && texture,
        uv};
    std::size_t i = static_cast<std::size_t>(view_.render.color);
    do {
        i = (i + 1) % kSurfaceColors.size();
    } while (!has[i]);
    const SurfaceColorMode& mode = kSurfaceColors[i];
    view_.render.color = mode.color;
    return {kDisplay, "surface colour: " + std::string(mode.name) + " — " +
                          std::string(mode.description) + " (Alt+C: next)"};
}

ElementRef Editor::stencil_element() const {
    if (!view_.stencil || mode() == Mode::Curve) {
        return {};
    }
    return hover_.is_none() ? selection() : hover_;
}

}  // namespace meshedit::viewer
