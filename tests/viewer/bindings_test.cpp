// The key table (docs/spec.md §4): every key does what its help says, in the modes it says; no two
// bindings compete for a key; every command is reachable; the README's table is generated
// from the table.

#include "meshedit/viewer/bindings.h"
#include "support/generated_text.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace meshedit::viewer {
namespace {

constexpr unsigned kShiftCtrl = kShift | kCtrl;

struct Expected {
    Key key;
    unsigned mods;
    unsigned modes;  ///< where the key must give `action`
    Action action;
};

// Written by hand from docs/spec.md §4 (keys, curve mode, surface mode), not from the table.
const std::vector<Expected>& expected_bindings() {
    static const std::vector<Expected> table = [] {
        std::vector<Expected> t{
            {key_of('F'), 0, kMeshModes, edit("flip")},
            {key_of('S'), 0, kMeshModes, edit("split")},
            {key_of('C'), 0, kMeshModes, edit("collapse")},
            {key_of('L'), 0, kMeshModes, edit("loop")},
            {key_of('U'), 0, kMeshModes, edit("loop")},
            {key_of('N'), 0, kMeshModes, {Command::Next}},
            {key_of('T'), 0, kMeshModes, {Command::Twin}},
            {key_of('H'), 0, kMeshModes, {Command::ToHalfedge}},
            {key_of('V'), 0, kMeshModes, {Command::ToVertex}},
            {key_of('E'), 0, kMeshModes, {Command::ToEdge}},
            {key_of('G'), 0, kMeshModes, {Command::ToFace}},
            {key_of('K'), 0, kMeshModes, edit("crease")},
            {key_of('K'), kShift, kMeshModes, edit("crease_by_angle")},
            {key_of('W'), kAlt, kMeshModes, {Command::CycleStencil}},
            {key_of('R'), kAlt, kMeshModes, {Command::ToggleDiagram}},
            {key_of('F'), kAlt, kMeshModes, {Command::CycleField}},
            {key_of('R'), kCtrl, kMeshModes, {Command::ReloadShaders}},
            {key_of('F'), kAlt | kShift, kMeshModes, {Command::CycleColormap}},
            {key_of('C'), kAlt, kMeshModes, {Command::CycleSurfaceColor}},
            {key_of('U'), kShift, kSurfaceMode, {Command::PatchStep}},
            {key_of('V'), kShift, kMeshModes, {Command::Validate}},
            {key_of('V'), kAlt, kMeshModes, {Command::FindProblems}},
            {key_of('N'), kAlt, kMeshModes, {Command::ToggleMarksNear}},
            {key_of('L'), kAlt, kMeshModes, edit("loop_step")},
            {key_of('C'), kAlt | kShift, kMeshModes, edit("cc_step")},
            // The local operations of polygon meshes (docs/spec.md §4).
            {key_of('S'), kShift, kMeshModes, edit("bisect")},
            {Key::Delete, 0, kMeshModes, {Command::Delete}},
            {Key::Delete, kShift, kMeshModes, edit("make_boundary")},
            {key_of('F'), kShift, kMeshModes, edit("fill")},
            {key_of('J'), 0, kMeshModes, edit("weld")},
            {key_of('P'), kShift, kMeshModes, edit("poke")},
            {key_of('X'), 0, kMeshModes, interactive(Modal::Extrude)},
            // Operations on a region of faces.
            {key_of('X'), kShift, kMeshModes, interactive(Modal::ExtrudeRegion)},
            {key_of('W'), kShift, kMeshModes, edit("subdivide_region")},
            {key_of('W'), kCtrl | kShift, kMeshModes, edit("loop_region")},
            {key_of('W'), kAlt | kShift, kMeshModes, edit("catmull_clark_region")},
            {Key::Delete, kCtrl, kMeshModes, edit("dissolve_region")},
            {key_of('G'), kShift, kMeshModes, {Command::SelectTrait}},
            {key_of('B'), kAlt, kMeshMode, {Command::BrushSelect}},
            {key_of('I'), kShift, kMeshModes, interactive(Modal::Inset)},
            {key_of('I'), kAlt, kMeshModes, interactive(Modal::InsetRegion)},
            {key_of('B'), kCtrl, kMeshModes, interactive(Modal::Bevel)},
            {key_of('M'), 0, kMeshModes, interactive(Modal::Move)},
            {key_of('R'), 0, kMeshModes, interactive(Modal::Rotate)},
            {key_of('S'), kAlt, kMeshModes, interactive(Modal::Scale)},
            {key_of('T'), kCtrl, kMeshModes, edit("triangulate")},
            {key_of('N'), kShift, kMeshModes, edit("flip_orientation")},
            {key_of('C'), kShift, kMeshModes, edit("catmull_clark")},
            {key_of('L'), kCtrl, kMeshModes, edit("linear")},
            {key_of('D'), 0, kMeshModes, edit("simplify")},
            {key_of('D'), kAlt, kMeshModes, edit("simplify_region")},
            {key_of('R'), kShift, kMeshModes, edit("remesh")},
            {key_of('R'), kCtrl | kShift, kMeshModes, edit("remesh_region")},
            {key_of('M'), kShift, kMeshModes, edit("smooth")},
            {key_of('R'), kAlt | kShift, kMeshModes, edit("repair")},
            {key_of('F'), kCtrl, kMeshModes, edit("fill_holes_fair")},
            {key_of('F'), kCtrl | kShift, kMeshModes, edit("fill_fair")},
            {key_of('M'), kAlt, kMeshModes, edit("fair")},
            {key_of('M'), kCtrl | kShift, kMeshModes, edit("smooth_region")},
            {key_of('A'), kCtrl, kMeshModes, {Command::SelectAll}},
            {key_of('A'), kAlt, kMeshModes, {Command::SelectNone}},
            {key_of('L'), kShift, kMeshModes, {Command::SelectLoop}},
            {key_of('E'), kAlt, kMeshModes, {Command::SelectEdgeLoop}},
            {key_of('E'), kAlt | kShift, kMeshModes, {Command::SelectEdgeRing}},
            {key_of('L'), kCtrl | kShift, kMeshModes, {Command::SelectLinked}},
            {Key::Equal, kCtrl, kMeshModes, {Command::SelectMore}},
            {Key::KeypadAdd, kCtrl, kMeshModes, {Command::SelectMore}},
            {Key::Minus, kCtrl, kMeshModes, {Command::SelectLess}},
            {Key::KeypadSubtract, kCtrl, kMeshModes, {Command::SelectLess}},
            {key_of('I'), kCtrl, kMeshModes, {Command::SelectInvert}},
            {key_of('B'), 0, kMeshMode, {Command::BoxSelect}},
            {key_of('P'), kAlt, kMeshModes, {Command::SelectPath}},
            {Key::Period, 0, kMeshModes, {Command::FrameSelection}},
            {Key::KeypadDecimal, 0, kMeshModes, {Command::FrameSelection}},
            {key_of('Q'), 0, kMeshModes, {Command::ToggleSmooth}},
            {key_of('W'), 0, kMeshModes, {Command::ToggleWireframe}},
            {key_of('I'), 0, kAllModes, {Command::ToggleInfo}},
            {Key::Slash, kShift, kAllModes, {Command::ToggleHelp}},
            {Key::F1, 0, kAllModes, {Command::ToggleHelp}},
            {key_of('Z'), kCtrl, kAllModes, {Command::Undo}},
            {key_of('Z'), kShiftCtrl, kAllModes, {Command::Redo}},
            {key_of('Y'), kCtrl, kAllModes, {Command::Redo}},
            {key_of('S'), kCtrl, kAllModes, {Command::Save}},
            {key_of('S'), kShiftCtrl, kAllModes, {Command::SaveAs}},
            {key_of('E'), kShiftCtrl, kMeshMode, {Command::ExportSession}},
            {key_of('O'), kCtrl, kAllModes, {Command::Open}},
            {key_of('P'), 0, kAllModes, {Command::Screenshot}},
            {Key::Space, 0, kAllModes, {Command::ResetCamera}},
            {key_of('Y'), 0, kMeshModes, {Command::CycleUp}},
            {key_of('O'), 0, kMeshModes, {Command::ToggleTrackball}},
            {Key::Escape, 0, kAllModes, {Command::Escape}},
            {key_of('Q'), kCtrl, kAllModes, {Command::Quit}},
            // Curve mode.
            {key_of('E'), 0, kCurveMode, {Command::LevelDown}},
            {key_of('E'), kShift, kCurveMode, {Command::LevelUp}},
            {key_of('C'), 0, kCurveMode, {Command::ToggleCurve}},
            {Key::LeftBracket, 0, kCurveMode, {Command::DecreaseT}},
            {Key::RightBracket, 0, kCurveMode, {Command::IncreaseT}},
            {Key::Equal, kShift, kCurveMode, {Command::AddPoint}},
            {Key::Equal, 0, kCurveMode, {Command::AddPoint}},
            {Key::KeypadAdd, 0, kCurveMode, {Command::AddPoint}},
            {Key::Minus, 0, kCurveMode, {Command::RemovePoint}},
            {Key::KeypadSubtract, 0, kCurveMode, {Command::RemovePoint}},
            // Surface mode.
            {Key::Equal, kShift, kSurfaceMode, {Command::DensityUp}},
            {Key::Equal, 0, kSurfaceMode, {Command::DensityUp}},
            {Key::KeypadAdd, 0, kSurfaceMode, {Command::DensityUp}},
            {Key::Minus, 0, kSurfaceMode, {Command::DensityDown}},
            {Key::KeypadSubtract, 0, kSurfaceMode, {Command::DensityDown}},
            {key_of('B'), 0, kSurfaceMode, {Command::ToggleNets}},
        };
        for (int d = 0; d <= 9; ++d) {
            t.push_back({key_of(static_cast<char>('0' + d)), 0, kMeshModes, {Command::Shading, d}});
        }
        return t;
    }();
    return table;
}

constexpr Mode kModes[] = {Mode::Mesh, Mode::Surface, Mode::Curve};

const char* name(Mode m) {
    return m == Mode::Mesh ? "mesh" : m == Mode::Surface ? "surface" : "curve";
}

TEST(Bindings, KeyOf) {
    EXPECT_EQ(key_of('a'), Key::A);
    EXPECT_EQ(key_of('A'), Key::A);
    EXPECT_EQ(static_cast<int>(key_of('z')), 'Z');
    EXPECT_EQ(key_of('0'), Key::Num0);
    EXPECT_EQ(static_cast<int>(key_of('7')), '7');
}

TEST(Bindings, EveryKeyOfTheSpecDoesWhatItSays) {
    for (const Expected& e : expected_bindings()) {
        for (Mode mode : kModes) {
            const std::optional<Action> got = lookup(e.key, e.mods, mode);
            SCOPED_TRACE(::testing::Message() << "key " << static_cast<int>(e.key) << " mods "
                                              << e.mods << " in " << name(mode));
            if ((e.modes & mode_bit(mode)) != 0) {
                ASSERT_TRUE(got.has_value());
                EXPECT_EQ(*got, e.action);
            } else if (got) {
                // Another binding may own the key in this mode; it must be in the list too.
                bool listed = false;
                for (const Expected& other : expected_bindings()) {
                    listed |= other.key == e.key && other.mods == e.mods &&
                              (other.modes & mode_bit(mode)) != 0 && other.action == *got;
                }
                EXPECT_TRUE(listed) << "unexpected binding";
            }
        }
    }
}

TEST(Bindings, TableHasNothingBeyondTheExpectedList) {
    for (const Binding& b : bindings()) {
        bool found = false;
        for (const Expected& e : expected_bindings()) {
            found |=
                e.key == b.key && e.mods == b.mods && e.modes == b.modes && e.action == b.action;
        }
        EXPECT_TRUE(found) << "binding " << b.label << " (" << b.help
                           << ") is not in the spec list";
    }
    EXPECT_EQ(bindings().size(), expected_bindings().size());
}

TEST(Bindings, SameKeyDiffersByMode) {
    EXPECT_EQ(lookup(key_of('E'), 0, Mode::Mesh), Action{Command::ToEdge});
    EXPECT_EQ(lookup(key_of('E'), 0, Mode::Surface), Action{Command::ToEdge});
    EXPECT_EQ(lookup(key_of('E'), 0, Mode::Curve), Action{Command::LevelDown});
    EXPECT_EQ(lookup(key_of('E'), kShift, Mode::Curve), Action{Command::LevelUp});
    EXPECT_FALSE(lookup(key_of('E'), kShift, Mode::Mesh));
    EXPECT_EQ(lookup(key_of('C'), 0, Mode::Mesh), edit("collapse"));
    EXPECT_EQ(lookup(key_of('C'), 0, Mode::Curve), Action{Command::ToggleCurve});
    EXPECT_EQ(lookup(Key::Equal, kShift, Mode::Surface), Action{Command::DensityUp});
    EXPECT_EQ(lookup(Key::Equal, kShift, Mode::Curve), Action{Command::AddPoint});
    EXPECT_FALSE(lookup(Key::Equal, kShift, Mode::Mesh));
    EXPECT_FALSE(lookup(key_of('F'), 0, Mode::Curve));
    EXPECT_EQ(lookup(key_of('B'), 0, Mode::Mesh), Action{Command::BoxSelect});
    EXPECT_EQ(lookup(key_of('B'), 0, Mode::Surface), Action{Command::ToggleNets});
}

TEST(Bindings, ModifiersAreExactAndLockBitsIgnored) {
    EXPECT_EQ(lookup(Key::Slash, kShift, Mode::Mesh), Action{Command::ToggleHelp});
    EXPECT_FALSE(lookup(Key::Slash, 0, Mode::Mesh));
    EXPECT_EQ(lookup(key_of('F'), kCtrl, Mode::Mesh), edit("fill_holes_fair"));
    EXPECT_FALSE(lookup(key_of('F'), kAlt | kCtrl, Mode::Mesh));
    EXPECT_EQ(lookup(key_of('Q'), 0, Mode::Mesh), Action{Command::ToggleSmooth});
    EXPECT_EQ(lookup(key_of('Q'), kCtrl, Mode::Mesh), Action{Command::Quit});
    EXPECT_EQ(lookup(key_of('S'), kCtrl | kShift, Mode::Mesh), Action{Command::SaveAs});
    // GLFW's Caps Lock (0x10) and Num Lock (0x20) bits, and Super (0x8), are masked off.
    EXPECT_EQ(lookup(key_of('F'), 0x10, Mode::Mesh), edit("flip"));
    EXPECT_EQ(lookup(key_of('Z'), kCtrl | 0x20, Mode::Mesh), Action{Command::Undo});
    EXPECT_EQ(lookup(key_of('F'), 0x8, Mode::Mesh), edit("flip"));
    EXPECT_FALSE(lookup(Key::Unknown, 0, Mode::Mesh));
}

TEST(Bindings, NoTwoBindingsCompete) {
    const auto table = bindings();
    for (std::size_t i = 0; i < table.size(); ++i) {
        for (std::size_t j = i + 1; j < table.size(); ++j) {
            const Binding& a = table[i];
            const Binding& b = table[j];
            EXPECT_FALSE(a.key == b.key && a.mods == b.mods && (a.modes & b.modes) != 0)
                << a.label << " (" << a.help << ") and " << b.label << " (" << b.help
                << ") share a key in some mode";
        }
    }
}

TEST(Bindings, EveryCommandIsReachable) {
    std::set<int> bound;
    for (const Binding& b : bindings()) {
        bound.insert(static_cast<int>(b.action.command));
        EXPECT_NE(b.modes & kAllModes, 0u) << b.label;
        EXPECT_EQ(b.modes & ~unsigned{kAllModes}, 0u) << b.label;
        EXPECT_FALSE(b.label.empty());
        EXPECT_FALSE(b.help.empty());
    }
    for (int c = static_cast<int>(Command::Edit); c <= static_cast<int>(Command::ToggleNets); ++c) {
        EXPECT_TRUE(bound.count(c)) << "Command " << c << " has no key";
    }
    // Every shading mode 0–9 has its digit.
    std::set<int> shading;
    for (const Binding& b : bindings()) {
        if (b.action.command == Command::Shading) {
            shading.insert(b.action.argument);
        }
    }
    EXPECT_EQ(shading, (std::set<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

TEST(Bindings, HelpRowsMergeByLabelAndHelp) {
    const std::vector<HelpRow> rows = help_rows();
    ASSERT_FALSE(rows.empty());
    const auto count = [&](const std::string& keys) {
        std::size_t n = 0;
        for (const HelpRow& r : rows) {
            n += r.keys == keys;
        }
        return n;
    };
    const auto find = [&](const std::string& keys, const std::string& modes) -> const HelpRow* {
        for (const HelpRow& r : rows) {
            if (r.keys == keys && r.modes == modes) {
                return &r;
            }
        }
        return nullptr;
    };
    EXPECT_EQ(count("0–9"), 1u);
    ASSERT_NE(find("0–9", "mesh, surface"), nullptr);
    EXPECT_NE(find("0–9", "mesh, surface")->action.find("1 Blinn-Phong"), std::string::npos);
    EXPECT_EQ(count("L / U"), 1u);
    EXPECT_EQ(count("? / F1"), 1u);
    EXPECT_EQ(count("Ctrl+Shift+Z / Ctrl+Y"), 1u);
    EXPECT_EQ(count("[ / ]"), 1u);
    // C and +/- have one row per meaning.
    EXPECT_EQ(count("C"), 2u);
    ASSERT_NE(find("C", "mesh, surface"), nullptr);
    ASSERT_NE(find("C", "curve"), nullptr);
    EXPECT_EQ(find("C", "curve")->action, "toggle the curve");
    ASSERT_NE(find("+", "curve"), nullptr);
    ASSERT_NE(find("+", "surface"), nullptr);
    ASSERT_NE(find("-", "curve"), nullptr);
    ASSERT_NE(find("-", "surface"), nullptr);
    ASSERT_NE(find("Esc", ""), nullptr);
    ASSERT_NE(find("F", "mesh, surface"), nullptr);
    EXPECT_EQ(find("F", "mesh, surface")->action, "flip the selected edge");
    // Key rows come first, then the mouse rows.
    const auto mouse = mouse_rows();
    ASSERT_EQ(mouse.size(), 17u);
    ASSERT_GE(rows.size(), mouse.size());
    for (std::size_t i = 0; i < mouse.size(); ++i) {
        EXPECT_EQ(rows[rows.size() - mouse.size() + i].keys, mouse[i].keys);
    }
    EXPECT_EQ(rows.front().keys, "F");
}

TEST(Bindings, HelpShowsOnlyWhatTheModeDoes) {
    const auto says = [](Mode mode, std::string_view word) {
        for (const HelpRow& row : help_rows(mode)) {
            if (row.keys.find(word) != std::string::npos ||
                row.action.find(word) != std::string::npos) {
                return true;
            }
        }
        return false;
    };
    // Curves are flat: no orbit, no halfedges, no flips; the wheel changes t.
    for (std::string_view word : {"orbit", "halfedge", "flip", "zoom"}) {
        EXPECT_FALSE(says(Mode::Curve, word)) << word;
        EXPECT_TRUE(says(Mode::Mesh, word)) << word;
    }
    EXPECT_TRUE(says(Mode::Curve, "change t"));
    EXPECT_FALSE(says(Mode::Mesh, "change t"));
    EXPECT_TRUE(says(Mode::Surface, "control nets"));
    EXPECT_FALSE(says(Mode::Mesh, "control nets"));
    // Every mode shows the mouse rows for all modes (pan, drop).
    for (Mode mode : {Mode::Mesh, Mode::Surface, Mode::Curve}) {
        EXPECT_TRUE(says(mode, "drop a file")) << mode_description(mode);
        EXPECT_TRUE(says(mode, "pan")) << mode_description(mode);
    }
    EXPECT_TRUE(says(Mode::Mesh, "8–9 your shaders"));
}

TEST(Bindings, LegendTakesItsColoursFromTheStyle) {
    OverlayStyle style;
    style.hovered = {0.1f, 0.2f, 0.3f, 1.0f};
    style.crease = {0.4f, 0.5f, 0.6f, 1.0f};
    const auto colour_of = [](const std::vector<LegendRow>& rows, std::string_view meaning) {
        for (const LegendRow& r : rows) {
            if (r.meaning.find(meaning) != std::string::npos) {
                return r.color;
            }
        }
        return Color{-1, -1, -1, -1};
    };
    const auto mesh = legend(Mode::Mesh, style);
    EXPECT_EQ(colour_of(mesh, "under the cursor"), style.hovered);
    EXPECT_EQ(colour_of(mesh, "selection"), style.selected);
    EXPECT_EQ(colour_of(mesh, "boundary"), style.boundary);
    EXPECT_EQ(colour_of(mesh, "crease"), style.crease);
    EXPECT_EQ(colour_of(mesh, "control nets")[0], -1.0f);
    EXPECT_EQ(colour_of(legend(Mode::Surface, style), "control nets"), style.control_net);
    const auto curve = legend(Mode::Curve, style);
    EXPECT_EQ(colour_of(curve, "control polygon"), style.levels[0]);
    EXPECT_EQ(colour_of(curve, "level 3"), style.levels[3]);
    EXPECT_EQ(colour_of(curve, "B(t)"), style.evaluated_point);
    EXPECT_EQ(colour_of(curve, "the curve"), style.curve);
    EXPECT_EQ(colour_of(curve, "boundary")[0], -1.0f);
}

TEST(Bindings, MarkdownTable) {
    const std::string md = key_table_markdown();
    EXPECT_EQ(md, key_table_markdown()) << "deterministic";
    EXPECT_EQ(md.rfind("| keys | action | modes |\n|---|---|---|\n| F | flip the selected edge | "
                       "mesh, surface |\n",
                       0),
              0u)
        << md;
    EXPECT_NE(md.find("| Esc | clear the selection; with nothing selected, quit; on a student's "
                      "side by side (--student), step back to the input | all |\n"),
              std::string::npos);
    EXPECT_NE(md.find("| wheel | zoom to the cursor | mesh, surface |\n"), std::string::npos);
    EXPECT_NE(md.find("| wheel | change t by 0.01 a step | curve |\n"), std::string::npos);
    // One line per help row plus the two header lines, each a well-formed 3-column row.
    std::istringstream in(md);
    std::string line;
    std::size_t lines = 0;
    while (std::getline(in, line)) {
        ++lines;
        EXPECT_EQ(line.front(), '|');
        EXPECT_EQ(line.back(), '|');
    }
    EXPECT_EQ(lines, help_rows().size() + 2);
}

TEST(Bindings, ReadmeKeysTableIsGenerated) {
    EXPECT_TRUE(
        test::block_is_generated(MESHEDIT_SOURCE_DIR "/README.md", "keys", key_table_markdown()));
}

}  // namespace
}  // namespace meshedit::viewer
