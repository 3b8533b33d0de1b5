// The key table: the one place keys meet commands. The help overlay and the README's keys
// table are generated from it (tests/viewer/bindings_test.cpp checks the README).

#include "meshedit/viewer/bindings.h"

#include <array>

#include "meshedit/ops/ops.h"

namespace meshedit::viewer {

namespace {

constexpr Key num(int d) {
    return static_cast<Key>(static_cast<int>(Key::Num0) + d);
}

constexpr std::string_view kShadingHelp =
    "shading mode (0 normals as colour, 1 Blinn-Phong, 2 flat grey, 3 studio, 4 matcap, "
    "5 depth, 6 hemisphere, 7 environment-map reflection, 8–9 your shaders: Ctrl+R reloads)";
constexpr std::string_view kTHelp = "decrease / increase t by 0.01";

// clang-format off
constexpr std::array kTable{
    // Edits of the mesh: verbs of the edit language (mesh and surface modes); the help is
    // the verb's own (src/ops/verbs.cpp).
    Binding{key_of('F'), kNoMods, kMeshModes, edit("flip"), "F", {}},
    Binding{key_of('S'), kNoMods, kMeshModes, edit("split"), "S", {}},
    Binding{key_of('S'), kShift, kMeshModes, edit("bisect"), "Shift+S", {}},
    Binding{key_of('C'), kNoMods, kMeshModes, edit("collapse"), "C", {}},
    Binding{Key::Delete, kNoMods, kMeshModes, {Command::Delete}, "Delete", "dissolve the selected vertices and edges, make the selected faces holes"},
    Binding{Key::Delete, kShift, kMeshModes, edit("make_boundary"), "Shift+Delete", {}},
    Binding{key_of('F'), kShift, kMeshModes, edit("fill"), "Shift+F", {}},
    Binding{key_of('J'), kNoMods, kMeshModes, edit("weld"), "J", {}},
    Binding{key_of('P'), kShift, kMeshModes, edit("poke"), "Shift+P", {}},
    Binding{key_of('X'), kNoMods, kMeshModes, interactive(Modal::Extrude), "X", "extrude the selected faces: drag up/down for height, left/right for shrink"},
    Binding{key_of('X'), kShift, kMeshModes, interactive(Modal::ExtrudeRegion), "Shift+X", "extrude the selected faces as one region: drag up/down for the height (walls around its border; shared sides stay joined)"},
    Binding{key_of('W'), kShift, kMeshModes, edit("subdivide_region"), "Shift+W", {}},
    Binding{key_of('W'), kCtrl | kShift, kMeshModes, edit("loop_region"), "Ctrl+Shift+W", {}},
    Binding{key_of('W'), kAlt | kShift, kMeshModes, edit("catmull_clark_region"), "Alt+Shift+W", {}},
    Binding{Key::Delete, kCtrl, kMeshModes, edit("dissolve_region"), "Ctrl+Delete", {}},
    Binding{key_of('I'), kShift, kMeshModes, interactive(Modal::Inset), "Shift+I", "inset the selected faces: drag for the amount"},
    Binding{key_of('I'), kAlt, kMeshModes, interactive(Modal::InsetRegion), "Alt+I", "inset the selected faces as one region: drag for the thickness (a ring of quads inside its border)"},
    Binding{key_of('B'), kCtrl, kMeshModes, interactive(Modal::Bevel), "Ctrl+B", "bevel the selected vertices or edges: drag for the amount"},
    Binding{key_of('M'), kNoMods, kMeshModes, interactive(Modal::Move), "M", "move the selection in the screen plane (X/Y/Z lock an axis)"},
    Binding{key_of('R'), kNoMods, kMeshModes, interactive(Modal::Rotate), "R", "rotate the selection about its centre (X/Y/Z: about that axis)"},
    Binding{key_of('S'), kAlt, kMeshModes, interactive(Modal::Scale), "Alt+S", "scale the selection about its centre (X/Y/Z: along that axis)"},
    Binding{key_of('T'), kCtrl, kMeshModes, edit("triangulate"), "Ctrl+T", {}},
    Binding{key_of('N'), kShift, kMeshModes, edit("flip_orientation"), "Shift+N", {}},
    Binding{key_of('L'), kNoMods, kMeshModes, edit("loop"), "L / U", {}},
    Binding{key_of('U'), kNoMods, kMeshModes, edit("loop"), "L / U", {}},
    Binding{key_of('C'), kShift, kMeshModes, edit("catmull_clark"), "Shift+C", {}},
    Binding{key_of('C'), kAlt | kShift, kMeshModes, edit("cc_step"), "Alt+Shift+C", {}},
    Binding{key_of('L'), kCtrl, kMeshModes, edit("linear"), "Ctrl+L", {}},
    Binding{key_of('L'), kAlt, kMeshModes, edit("loop_step"), "Alt+L", {}},
    Binding{key_of('D'), kNoMods, kMeshModes, edit("simplify"), "D", {}},
    Binding{key_of('D'), kAlt, kMeshModes, edit("simplify_region"), "Alt+D", {}},
    Binding{key_of('R'), kShift, kMeshModes, edit("remesh"), "Shift+R", {}},
    Binding{key_of('R'), kCtrl | kShift, kMeshModes, edit("remesh_region"), "Ctrl+Shift+R", {}},
    Binding{key_of('M'), kShift, kMeshModes, edit("smooth"), "Shift+M", {}},
    Binding{key_of('R'), kAlt | kShift, kMeshModes, edit("repair"), "Alt+Shift+R", {}},
    Binding{key_of('F'), kCtrl, kMeshModes, edit("fill_holes_fair"), "Ctrl+F", {}},
    Binding{key_of('F'), kCtrl | kShift, kMeshModes, edit("fill_fair"), "Ctrl+Shift+F", {}},
    Binding{key_of('M'), kAlt, kMeshModes, edit("fair"), "Alt+M", {}},
    Binding{key_of('M'), kCtrl | kShift, kMeshModes, edit("smooth_region"), "Ctrl+Shift+M", {}},
    // Selecting.
    Binding{key_of('A'), kCtrl, kMeshModes, {Command::SelectAll}, "Ctrl+A", "select every element of the selected kind (faces if none)"},
    Binding{key_of('A'), kAlt, kMeshModes, {Command::SelectNone}, "Alt+A", "select nothing"},
    Binding{key_of('L'), kShift, kMeshModes, {Command::SelectLoop}, "Shift+L", "select the hole beside the selected boundary edge"},
    Binding{key_of('E'), kAlt, kMeshModes, {Command::SelectEdgeLoop}, "Alt+E", "select the edge loop through the selected edge (on across valence-4 vertices; stops at poles and the border)"},
    Binding{key_of('E'), kAlt | kShift, kMeshModes, {Command::SelectEdgeRing}, "Alt+Shift+E", "select the edge ring through the selected edge (across quads to the opposite edges)"},
    Binding{key_of('L'), kCtrl | kShift, kMeshModes, {Command::SelectLinked}, "Ctrl+Shift+L", "select everything joined to the selection (its connected pieces)"},
    Binding{Key::Equal, kCtrl, kMeshModes, {Command::SelectMore}, "Ctrl+= / Ctrl+keypad +", "grow the selected faces or vertices by one ring"},
    Binding{Key::KeypadAdd, kCtrl, kMeshModes, {Command::SelectMore}, "Ctrl+= / Ctrl+keypad +", "grow the selected faces or vertices by one ring"},
    Binding{Key::Minus, kCtrl, kMeshModes, {Command::SelectLess}, "Ctrl+- / Ctrl+keypad -", "shrink the selected faces or vertices by one ring"},
    Binding{Key::KeypadSubtract, kCtrl, kMeshModes, {Command::SelectLess}, "Ctrl+- / Ctrl+keypad -", "shrink the selected faces or vertices by one ring"},
    Binding{key_of('B'), kNoMods, kMeshMode, {Command::BoxSelect}, "B", "box select: drag a rectangle with the left button; what the view shows inside it is selected in the selection's kind (faces if none; Shift adds, Alt takes what is hidden too, a right click cancels)"},
    Binding{key_of('B'), kAlt, kMeshMode, {Command::BrushSelect}, "Alt+B", "brush select: left drags paint the selection with a circle (Shift+drag takes away, the wheel sizes the circle, Esc or a right click ends it)"},
    Binding{key_of('P'), kAlt, kMeshModes, {Command::SelectPath}, "Alt+P", "select the shortest path between the two selected vertices (along edges) or faces (across edges)"},
    Binding{key_of('G'), kShift, kMeshModes, {Command::SelectTrait}, "Shift+G", "select by trait: what the info panel's Selection section names (the border, creases, vertices of valence k, faces of k corners, faces turned away from you by more than an angle)"},
    Binding{key_of('I'), kCtrl, kMeshModes, {Command::SelectInvert}, "Ctrl+I", "invert the selection: every element of its kind not selected (faces if none)"},
    Binding{Key::Period, kNoMods, kMeshModes, {Command::FrameSelection}, ". / keypad .", "frame the selection (centre the camera on it)"},
    Binding{Key::KeypadDecimal, kNoMods, kMeshModes, {Command::FrameSelection}, ". / keypad .", "frame the selection (centre the camera on it)"},
    // Navigation.
    Binding{key_of('N'), kNoMods, kMeshModes, {Command::Next}, "N", "selected halfedge → next"},
    Binding{key_of('T'), kNoMods, kMeshModes, {Command::Twin}, "T", "selected halfedge → twin"},
    Binding{key_of('H'), kNoMods, kMeshModes, {Command::ToHalfedge}, "H", "from the selection go to its halfedge"},
    Binding{key_of('V'), kNoMods, kMeshModes, {Command::ToVertex}, "V", "from the selection go to its vertex (a halfedge's source: vertex() = from)"},
    Binding{key_of('E'), kNoMods, kMeshModes, {Command::ToEdge}, "E", "from the selection go to its edge"},
    Binding{key_of('G'), kNoMods, kMeshModes, {Command::ToFace}, "G", "from the selection go to its face"},
    Binding{key_of('K'), kNoMods, kMeshModes, edit("crease"), "K", {}},
    Binding{key_of('K'), kShift, kMeshModes, edit("crease_by_angle"), "Shift+K", {}},
    Binding{key_of('W'), kAlt, kMeshModes, {Command::CycleStencil}, "Alt+W", "stencil view: hover a vertex, edge or face to see the old vertices and weights that make its new point (cycles Loop with Warren's weights, Loop's own, Catmull-Clark, off)"},
    Binding{key_of('N'), kAlt, kMeshModes, {Command::ToggleMarksNear}, "Alt+N", "a phased Loop's marks (Alt+L: targets, edge points, new and flipped edges) only within two rings of the selection, or everywhere again: for dense meshes"},
    Binding{key_of('R'), kAlt, kMeshModes, {Command::ToggleDiagram}, "Alt+R", "rewiring panel: after F, S, C or another local operation, its neighbourhood before and after, halfedges named as in its code"},
    Binding{key_of('F'), kAlt, kMeshModes, {Command::CycleField}, "Alt+F", "scalar field: colour the mesh by Gaussian or mean curvature, valence, triangle quality, dihedral angle, edge length, face area, distance from the selected vertex or the mesh's own numbers (a PLY column such as compare's deviation), with a legend (cycles them, then off)"},
    Binding{key_of('F'), kAlt | kShift, kMeshModes, {Command::CycleColormap}, "Alt+Shift+F", "the field's colour map: the field's default, viridis, magma, diverging"},
    Binding{key_of('C'), kAlt, kMeshModes, {Command::CycleSurfaceColor}, "Alt+C", "surface colour: auto, one colour, materials, vertex colours, textures, UV checker (each the file has)"},
    Binding{key_of('R'), kCtrl, kMeshModes, {Command::ReloadShaders}, "Ctrl+R", "recompile every shader from disk (modes 8 and 9 are yours: mesh8.frag, mesh9.frag in the user shader folder); on an error the old picture stays and the error names the file and line"},
    Binding{key_of('V'), kShift, kMeshModes, {Command::Validate}, "Shift+V", "check every invariant of the halfedge mesh (validate()); a broken one is selected, framed and named"},
    Binding{key_of('V'), kAlt, kMeshModes, {Command::FindProblems}, "Alt+V", "find problems: the loader's cuts, holes, degenerate faces, parts inside out, small parts, faces that pass through each other; listed in the info panel's Problems section, where a click frames each, and marked in the view (docs/rendering.md: the colours)"},
    // Display.
    Binding{key_of('Q'), kNoMods, kMeshModes, {Command::ToggleSmooth}, "Q", "toggle smooth (area-weighted vertex normals) / flat shading"},
    Binding{key_of('W'), kNoMods, kMeshModes, {Command::ToggleWireframe}, "W", "toggle wireframe overlay"},
    Binding{num(0), kNoMods, kMeshModes, {Command::Shading, 0}, "0–9", kShadingHelp},
    Binding{num(1), kNoMods, kMeshModes, {Command::Shading, 1}, "0–9", kShadingHelp},
    Binding{num(2), kNoMods, kMeshModes, {Command::Shading, 2}, "0–9", kShadingHelp},
    Binding{num(3), kNoMods, kMeshModes, {Command::Shading, 3}, "0–9", kShadingHelp},
    Binding{num(4), kNoMods, kMeshModes, {Command::Shading, 4}, "0–9", kShadingHelp},
    Binding{num(5), kNoMods, kMeshModes, {Command::Shading, 5}, "0–9", kShadingHelp},
    Binding{num(6), kNoMods, kMeshModes, {Command::Shading, 6}, "0–9", kShadingHelp},
    Binding{num(7), kNoMods, kMeshModes, {Command::Shading, 7}, "0–9", kShadingHelp},
    Binding{num(8), kNoMods, kMeshModes, {Command::Shading, 8}, "0–9", kShadingHelp},
    Binding{num(9), kNoMods, kMeshModes, {Command::Shading, 9}, "0–9", kShadingHelp},
    Binding{key_of('I'), kNoMods, kAllModes, {Command::ToggleInfo}, "I", "toggle info panel"},
    Binding{Key::Slash, kShift, kAllModes, {Command::ToggleHelp}, "? / F1", "help overlay (this list)"},
    Binding{Key::F1, kNoMods, kAllModes, {Command::ToggleHelp}, "? / F1", "help overlay (this list)"},
    // History and files.
    Binding{key_of('Z'), kCtrl, kAllModes, {Command::Undo}, "Ctrl+Z", "undo"},
    Binding{key_of('Z'), kCtrl | kShift, kAllModes, {Command::Redo}, "Ctrl+Shift+Z / Ctrl+Y", "redo"},
    Binding{key_of('Y'), kCtrl, kAllModes, {Command::Redo}, "Ctrl+Shift+Z / Ctrl+Y", "redo"},
    Binding{key_of('S'), kCtrl, kAllModes, {Command::Save}, "Ctrl+S", "save"},
    Binding{key_of('S'), kCtrl | kShift, kAllModes, {Command::SaveAs}, "Ctrl+Shift+S", "save as"},
    Binding{key_of('E'), kCtrl | kShift, kMeshMode, {Command::ExportSession}, "Ctrl+Shift+E", "export the session: every edit since the file was opened, as steps `meshedit convert IN OUT --ops @FILE` replays"},
    Binding{key_of('O'), kCtrl, kAllModes, {Command::Open}, "Ctrl+O", "open a file"},
    Binding{key_of('P'), kNoMods, kAllModes, {Command::Screenshot}, "P", "screenshot to PNG (the 3D view the panels leave free, in Pictures/MeshEdit)"},
    Binding{Key::Space, kNoMods, kAllModes, {Command::ResetCamera}, "Space", "reset the camera"},
    Binding{key_of('Y'), kNoMods, kMeshModes, {Command::CycleUp}, "Y", "up axis: +Y (as the file declares) or +Z (the CS184 course's models)"},
    Binding{key_of('O'), kNoMods, kMeshModes, {Command::ToggleTrackball}, "O", "orbit: turntable (the up axis stays up) or trackball (free rotation)"},
    Binding{Key::Escape, kNoMods, kAllModes, {Command::Escape}, "Esc", "clear the selection; with nothing selected, quit; on a student's side by side (--student), step back to the input"},
    Binding{key_of('Q'), kCtrl, kAllModes, {Command::Quit}, "Ctrl+Q", "quit"},
    // Curve mode.
    Binding{key_of('E'), kNoMods, kCurveMode, {Command::LevelDown}, "E", "show one more de Casteljau level"},
    Binding{key_of('E'), kShift, kCurveMode, {Command::LevelUp}, "Shift+E", "show one level fewer"},
    Binding{key_of('C'), kNoMods, kCurveMode, {Command::ToggleCurve}, "C", "toggle the curve"},
    Binding{Key::LeftBracket, kNoMods, kCurveMode, {Command::DecreaseT}, "[ / ]", kTHelp},
    Binding{Key::RightBracket, kNoMods, kCurveMode, {Command::IncreaseT}, "[ / ]", kTHelp},
    Binding{Key::Equal, kShift, kCurveMode, {Command::AddPoint}, "+", "add a control point"},
    Binding{Key::Equal, kNoMods, kCurveMode, {Command::AddPoint}, "+", "add a control point"},
    Binding{Key::KeypadAdd, kNoMods, kCurveMode, {Command::AddPoint}, "+", "add a control point"},
    Binding{Key::Minus, kNoMods, kCurveMode, {Command::RemovePoint}, "-", "remove a control point"},
    Binding{Key::KeypadSubtract, kNoMods, kCurveMode, {Command::RemovePoint}, "-", "remove a control point"},
    // Surface mode.
    Binding{Key::Equal, kShift, kSurfaceMode, {Command::DensityUp}, "+", "tessellation density up"},
    Binding{Key::Equal, kNoMods, kSurfaceMode, {Command::DensityUp}, "+", "tessellation density up"},
    Binding{Key::KeypadAdd, kNoMods, kSurfaceMode, {Command::DensityUp}, "+", "tessellation density up"},
    Binding{Key::Minus, kNoMods, kSurfaceMode, {Command::DensityDown}, "-", "tessellation density down"},
    Binding{Key::KeypadSubtract, kNoMods, kSurfaceMode, {Command::DensityDown}, "-", "tessellation density down"},
    Binding{key_of('B'), kNoMods, kSurfaceMode, {Command::ToggleNets}, "B", "toggle control nets"},
    Binding{key_of('U'), kShift, kSurfaceMode, {Command::PatchStep}, "Shift+U", "evaluate the patch at the selection by de Casteljau, one step a press: along u on every row, then along v, to S(u, v); then off"},
};

// The mouse as each mode handles it (App::on_mouse_button, on_cursor, on_scroll).
const std::array<HelpRow, 17> kMouseRows{{
    {"left-click", "select the element under the cursor (vertex near a corner, edge near an edge, halfedge just inside it, else face)", "mesh, surface"},
    {"Shift+left-click", "add the element under the cursor to the selection, or remove it", "mesh, surface"},
    {"left-drag off the selected vertex / right-drag", "orbit (turntable about the up axis; O: trackball)", "mesh, surface"},
    {"left-drag on the selected vertex", "move it in the screen plane (click a vertex first: a drag that starts anywhere else orbits)", "mesh, surface"},
    {"B, then left-drag", "box select: what the view shows inside the rectangle, in the selection's kind (Shift adds, Alt selects through, right-click cancels)", "mesh"},
    {"Alt+B, then left-drag", "brush select: what the view shows under the circle joins the selection (Shift+drag takes it away, the wheel sizes the circle, Esc ends)", "mesh"},
    {"Alt+left-click", "select the edge loop through the edge under the cursor (Ctrl+Alt+left-click: its ring)", "mesh"},
    {"Ctrl+right-drag", "lasso select: what the view shows inside the outline (Shift adds, Alt selects through)", "mesh"},
    {"wheel", "zoom to the cursor", "mesh, surface"},
    {"left-click", "select the control point under the cursor", "curve"},
    {"left-drag on a control point", "move it", "curve"},
    {"left-drag on empty paper", "pan", "curve"},
    {"wheel", "change t by 0.01 a step", "curve"},
    {"middle-drag / Shift+left-drag", "pan", ""},
    {"drop a file", "open it", ""},
    {"during X, Shift+X, Shift+I, Ctrl+B, M, R, Alt+S", "move the mouse to set the amount; type a number (digits . - , Backspace) to set it exactly; X/Y/Z lock an axis", "mesh, surface"},
    {"Enter / left-click, Esc / right-click", "apply the interactive edit (one undo step) / cancel it (the mesh as it was)", "mesh, surface"},
}};
// clang-format on

std::string modes_text(unsigned modes) {
    if ((modes & kAllModes) == kAllModes) {
        return "";
    }
    std::string out;
    const auto add = [&](unsigned bit, const char* name) {
        if ((modes & bit) != 0) {
            if (!out.empty()) {
                out += ", ";
            }
            out += name;
        }
    };
    add(kMeshMode, "mesh");
    add(kSurfaceMode, "surface");
    add(kCurveMode, "curve");
    return out;
}

std::string escape_cell(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        if (c == '|') {
            out += '\\';
        }
        out += c;
    }
    return out;
}

// The table with every Edit row's help taken from its verb.
std::vector<Binding> with_verb_help() {
    std::vector<Binding> out(kTable.begin(), kTable.end());
    for (Binding& b : out) {
        if (b.action.command == Command::Edit) {
            const ops::Verb* verb = ops::find_verb(b.action.verb);
            MESHEDIT_ASSERT(verb != nullptr);
            b.help = verb->key_help;
        }
    }
    return out;
}

}  // namespace

std::span<const Binding> bindings() {
    static const std::vector<Binding> table = with_verb_help();
    return table;
}

std::optional<Action> lookup(Key key, unsigned mods, Mode mode) {
    const unsigned wanted = mods & (kShift | kCtrl | kAlt);
    const unsigned bit = mode_bit(mode);
    for (const Binding& b : bindings()) {
        if (b.key == key && b.mods == wanted && (b.modes & bit) != 0) {
            return b.action;
        }
    }
    return std::nullopt;
}

std::span<const HelpRow> mouse_rows() {
    return kMouseRows;
}

std::vector<HelpRow> help_rows() {
    // Merge bindings that share label and help (in first-occurrence order); their modes
    // are united.
    struct Merged {
        std::string_view label;
        std::string_view help;
        unsigned modes;
    };
    std::vector<Merged> merged;
    for (const Binding& b : bindings()) {
        bool found = false;
        for (Merged& m : merged) {
            if (m.label == b.label && m.help == b.help) {
                m.modes |= b.modes;
                found = true;
                break;
            }
        }
        if (!found) {
            merged.push_back({b.label, b.help, b.modes});
        }
    }
    std::vector<HelpRow> rows;
    rows.reserve(merged.size() + kMouseRows.size());
    for (const Merged& m : merged) {
        rows.push_back({std::string(m.label), std::string(m.help), modes_text(m.modes)});
    }
    rows.insert(rows.end(), kMouseRows.begin(), kMouseRows.end());
    return rows;
}

std::vector<HelpRow> help_rows(Mode mode) {
    const std::string_view word = mode == Mode::Mesh      ? "mesh"
                                  : mode == Mode::Surface ? "surface"
                                                          : "curve";
    std::vector<HelpRow> rows;
    for (HelpRow& row : help_rows()) {
        if (row.modes.empty() || row.modes.find(word) != std::string::npos) {
            rows.push_back(std::move(row));
        }
    }
    return rows;
}

std::vector<LegendRow> legend(Mode mode, const OverlayStyle& style) {
    std::vector<LegendRow> rows;
    if (mode == Mode::Curve) {
        const std::size_t n = style.levels.size();
        for (std::size_t k = 0; k < n; ++k) {
            rows.push_back({style.levels[k], k == 0 ? "level 0, the control polygon (level " +
                                                          std::to_string(n) +
                                                          " and on reuse these colours in turn)"
                                                    : "de Casteljau level " + std::to_string(k)});
        }
        rows.push_back({style.curve, "the curve (C shows or hides it)"});
        rows.push_back({style.evaluated_point, "the point B(t) on the curve"});
        rows.push_back({style.hovered, "the control point under the cursor"});
        rows.push_back({style.selected, "the selected control point"});
        return rows;
    }
    rows.push_back({style.hovered, "the element under the cursor"});
    rows.push_back({style.selected, "the selection (a halfedge: an arrow inside its face)"});
    rows.push_back({style.boundary, "boundary edges"});
    rows.push_back({style.crease, "crease edges (K)"});
    if (mode == Mode::Surface) {
        rows.push_back({style.control_net, "control nets (B)"});
    }
    return rows;
}

std::string key_table_markdown() {
    std::string out = "| keys | action | modes |\n|---|---|---|\n";
    for (const HelpRow& row : help_rows()) {
        out += "| " + escape_cell(row.keys) + " | " + escape_cell(row.action) + " | " +
               (row.modes.empty() ? std::string("all") : escape_cell(row.modes)) + " |\n";
    }
    return out;
}

}  // namespace meshedit::viewer
