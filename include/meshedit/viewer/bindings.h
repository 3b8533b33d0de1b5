#pragma once
/// \file
/// The one table that binds keys to commands. The window dispatches through it, the help
/// overlay lists it, and the README's keys table is generated from it (a test checks the
/// README against key_table_markdown()). Adding a key is adding a row here.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "meshedit/overlay/overlay.h"
#include "meshedit/viewer/document.h"
#include "meshedit/viewer/keys.h"

namespace meshedit::viewer {

/// A set of modes a binding is active in.
enum ModeMask : unsigned {
    kMeshMode = 1u << 0,
    kSurfaceMode = 1u << 1,
    kCurveMode = 1u << 2,
    kMeshModes = kMeshMode | kSurfaceMode,
    kAllModes = kMeshMode | kSurfaceMode | kCurveMode,
};

constexpr ModeMask mode_bit(Mode mode) {
    return mode == Mode::Mesh ? kMeshMode : mode == Mode::Surface ? kSurfaceMode : kCurveMode;
}

/// The interactive edits: a key starts one, the mouse (or typed numbers) sets its amount
/// live, and it ends confirmed (one undo step) or cancelled (the document as it was, bit for
/// bit). Editor::begin_modal().
enum class Modal { None, Extrude, Inset, Bevel, ExtrudeRegion, InsetRegion, Move, Rotate, Scale };

/// Everything a key can ask for.
enum class Command {
    /// An edit of the mesh: the verb of the edit language (meshedit/ops/ops.h) named by
    /// Action::verb, applied to the selection (edge verbs) or the whole mesh.
    Edit,
    /// An interactive edit; argument: the Modal, as an int.
    Interactive,
    /// Dissolves the selected vertices and edges, makes the selected faces holes.
    Delete,
    // Selecting.
    SelectAll,
    SelectNone,
    SelectLoop,      ///< the hole beside the selected boundary edge
    SelectEdgeLoop,  ///< the edge loop through the selected edge (selection/selection.h)
    SelectEdgeRing,  ///< the edge ring through the selected edge
    SelectLinked,    ///< every face (or vertex, edge) reachable from the selection
    SelectMore,      ///< grow the selected faces or vertices by one ring
    SelectLess,      ///< shrink them by one ring
    SelectInvert,    ///< every live element of the selected kind not selected
    SelectPath,      ///< the shortest path between the two selected vertices or faces
    SelectTrait,     ///< every element with the trait the info panel sets (ToolSettings::trait)
    BoxSelect,       ///< the next left drag draws a box that selects (the window's part)
    BrushSelect,     ///< left drags paint the selection with a circle until Esc (the window's)
    FrameSelection,  ///< the camera centres on the selection
    // Moving the selection through the connectivity.
    Next,
    Twin,
    ToHalfedge,
    ToVertex,
    ToEdge,
    ToFace,
    // Display.
    ToggleSmooth,
    ToggleWireframe,
    Shading,  ///< argument: the mode number 0–9
    ToggleInfo,
    ToggleHelp,
    ResetCamera,
    CycleUp,          ///< which world axis is up: +Y, +Z
    ToggleTrackball,  ///< turntable or trackball orbit
    CycleStencil,     ///< stencil view: off, Loop (Warren), Loop (Loop's), Catmull-Clark
    ToggleDiagram,    ///< the rewiring panel
    ToggleMarksNear,  ///< a phased Loop's marks near the selection only, or everywhere
    CycleField,       ///< the scalar field shown: off, then each of core/fields.h
    ReloadShaders,    ///< recompile every shader from disk (user shaders: modes 8, 9)
    CycleColormap,    ///< the field's colour map: default, viridis, magma, diverging
    CycleSurfaceColor,
    PatchStep,  ///< Surface mode: de Casteljau on the patch at the selection, one step more  ///<
                ///< where the surface colour comes from (overlay/shading.h)
    Screenshot,
    // History and files.
    Undo,
    Redo,
    Save,
    SaveAs,
    ExportSession,  ///< write the session's steps for `meshedit convert --ops @FILE`
    Validate,       ///< run validate(); on failure select and frame the culprit
    FindProblems,   ///< list what is wrong (repair/problems.h) in the Problems panel
    Open,
    Escape,  ///< clears the selection; with nothing selected, quits
    Quit,
    // Curve mode.
    LevelDown,  ///< one more de Casteljau level shown
    LevelUp,
    ToggleCurve,
    DecreaseT,
    IncreaseT,
    AddPoint,
    RemovePoint,
    // Surface mode.
    DensityUp,
    DensityDown,
    ToggleNets,
};

/// A command with its argument: Shading's mode number, or Edit's verb.
struct Action {
    Command command;
    int argument = 0;
    std::string_view verb = {};
    friend bool operator==(const Action&, const Action&) = default;
};

/// The action that runs the edit-language verb `verb` ("flip").
constexpr Action edit(std::string_view verb) {
    return {Command::Edit, 0, verb};
}
/// The action that starts an interactive edit.
constexpr Action interactive(Modal kind) {
    return {Command::Interactive, static_cast<int>(kind), {}};
}

struct Binding {
    Key key;
    unsigned mods;   ///< exact Shift/Ctrl/Alt combination (Mods bits)
    unsigned modes;  ///< ModeMask
    Action action;
    /// How the help and README write the key(s); bindings that share `label` and `help`
    /// form one row ("0–9", "L / U").
    std::string_view label;
    std::string_view help;
};

/// Every key binding, in help order. An Edit binding's help is its verb's key_help.
std::span<const Binding> bindings();

/// The action bound to `key` with exactly `mods` (Shift/Ctrl/Alt; other bits ignored) in
/// `mode`, if any.
std::optional<Action> lookup(Key key, unsigned mods, Mode mode);

/// One row of the help overlay / README table.
struct HelpRow {
    std::string keys;
    std::string action;
    std::string modes;  ///< "" for all modes, else e.g. "curve" or "mesh, surface"
};

/// Key rows (bindings merged by label and help, in table order) followed by the mouse rows.
std::vector<HelpRow> help_rows();

/// The rows that apply in `mode` (its own and those of every mode): what the help shows.
std::vector<HelpRow> help_rows(Mode mode);

/// The mouse actions (not dispatched through the key table, listed for the help).
std::span<const HelpRow> mouse_rows();

/// One colour the viewer draws with and what it means.
struct LegendRow {
    Color color;
    std::string meaning;
};

/// The colours of `mode`'s overlays (taken from `style`, so the legend cannot drift).
std::vector<LegendRow> legend(Mode mode, const OverlayStyle& style);

/// The README's keys-and-mouse table: a Markdown table of help_rows().
std::string key_table_markdown();

}  // namespace meshedit::viewer
