// The file chooser of Open, Save as and Export session without a window: the typed path
// field, the keys queued between two frames, and the listing with its filter.

#include "meshedit/viewer/file_chooser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "support/scratch_dir.h"

namespace meshedit::viewer {
namespace {

namespace fs = std::filesystem;

void type(FileChooser& chooser, const std::string& text) {
    for (const char c : text) {
        chooser.push(FieldKey{FieldKey::Char, static_cast<char32_t>(c), false});
    }
}

void press(FileChooser& chooser, FieldKey::Kind kind, int times = 1) {
    for (int i = 0; i < times; ++i) {
        chooser.push(FieldKey{kind, 0, false});
    }
}

void touch(const fs::path& path) {
    std::ofstream(path) << "x";
}

// A folder with two subfolders, a hidden one, and files of several kinds.
struct Tree {
    test::ScratchDir dir;
    Tree() {
        fs::create_directories(dir / "models");
        fs::create_directories(dir / "Zeta");
        fs::create_directories(dir / ".cache");
        for (const char* name : {"b.obj", "A.dae", "notes.txt", "c.PLY", "s.ops", ".hidden.obj"}) {
            touch(dir / name);
        }
        touch(dir / "models" / "inner.off");
    }
    std::vector<std::string> names(const FileChooser& chooser) const {
        std::vector<std::string> out;
        for (const ChooserEntry& e : chooser.entries()) {
            out.push_back(e.folder ? e.name + "/" : e.name);
        }
        return out;
    }
};

FileChooser save_chooser(const fs::path& folder, const std::string& name = "cube.dae") {
    FileChooser chooser;
    chooser.start(ChooserPurpose::SaveAs, folder, name,
                  chooser_extensions(ChooserPurpose::SaveAs, Mode::Mesh));
    return chooser;
}

TEST(FileChooser, StartsWithTheNameSelectedSoTypingReplacesIt) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path());
    EXPECT_EQ(chooser.field(), "cube.dae");
    EXPECT_EQ(chooser.selection_begin(), 0u);
    EXPECT_EQ(chooser.selection_end(), 8u);
    type(chooser, "new.obj");
    EXPECT_EQ(chooser.process(), FileChooser::Result::None);
    EXPECT_EQ(chooser.field(), "new.obj");
    EXPECT_EQ(chooser.resolved(), tree.dir / "new.obj");
}

TEST(FileChooser, TypedAbsolutePathReplacesTheField) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path());
    type(chooser, "/tmp/x.obj");
    chooser.process();
    EXPECT_EQ(chooser.field(), "/tmp/x.obj");
    EXPECT_EQ(chooser.resolved(), fs::path("/tmp/x.obj"));

    // Typed after a folder the field holds (Tab completed "models/"): '/' right after a '/'
    // starts afresh — never "<folder>//<path>".
    press(chooser, FieldKey::SelectAll);
    type(chooser, "models/");
    type(chooser, "/tmp/y.obj");
    chooser.process();
    EXPECT_EQ(chooser.field(), "/tmp/y.obj");
    EXPECT_EQ(chooser.resolved(), fs::path("/tmp/y.obj"));
}

TEST(FileChooser, RelativePathIsInTheListedFolder) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path());
    type(chooser, "models/../models/out.ply");
    chooser.process();
    EXPECT_EQ(chooser.resolved(), tree.dir / "models" / "out.ply");
    chooser.push(FieldKey{FieldKey::Enter});
    EXPECT_EQ(chooser.process(), FileChooser::Result::Chosen);
    EXPECT_EQ(chooser.chosen(), tree.dir / "models" / "out.ply");
}

TEST(FileChooser, TildeIsTheHomeFolder) {
    const char* home = std::getenv("HOME");
    ASSERT_NE(home, nullptr);
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path());
    type(chooser, "~/x.obj");
    chooser.process();
    EXPECT_EQ(chooser.resolved(), (fs::path(home) / "x.obj").lexically_normal());
    // '~' right after a '/' starts afresh too.
    press(chooser, FieldKey::SelectAll);
    type(chooser, "models/~/y.obj");
    chooser.process();
    EXPECT_EQ(chooser.field(), "~/y.obj");
}

TEST(FileChooser, CtrlAThenTypingReplacesEverything) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path());
    press(chooser, FieldKey::End);  // nothing selected, the cursor after the name
    type(chooser, "x");
    chooser.process();
    EXPECT_EQ(chooser.field(), "cube.daex");
    press(chooser, FieldKey::SelectAll);
    type(chooser, "other.off");
    chooser.process();
    EXPECT_EQ(chooser.field(), "other.off");
    EXPECT_EQ(chooser.cursor(), 9u);
}

// ImGui 1.86 saw one Backspace a frame: on a slow document, five presses erased one and
// "bunny_l2.off" + "bunny_300k.off" became "bunny_l2.ofbunny_300k.off". Every queued key
// counts, however many arrive between two frames.
TEST(FileChooser, EveryBackspaceQueuedInOneFrameCounts) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path(), "bunny_l2.off");
    press(chooser, FieldKey::End);
    press(chooser, FieldKey::Backspace, 5);
    type(chooser, "3.off");
    chooser.process();
    EXPECT_EQ(chooser.field(), "bunny_l3.off");
    // Delete, Right, Home and a word back.
    press(chooser, FieldKey::Home);
    press(chooser, FieldKey::Delete, 6);
    press(chooser, FieldKey::Right, 2);
    type(chooser, "/");
    press(chooser, FieldKey::End);
    press(chooser, FieldKey::DeleteWord);
    type(chooser, "a.off");
    chooser.process();
    EXPECT_EQ(chooser.field(), "l3/a.off");
}

TEST(FileChooser, BackspaceErasesAWholeCharacter) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path(), "");
    chooser.push(FieldKey{FieldKey::Char, U'é', false});
    chooser.push(FieldKey{FieldKey::Char, U'→', false});
    chooser.process();
    EXPECT_EQ(chooser.field(), "é→");
    press(chooser, FieldKey::Backspace);
    chooser.process();
    EXPECT_EQ(chooser.field(), "é");
}

TEST(FileChooser, ListsFoldersFirstThenFilesOfThePurpose) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path());
    EXPECT_EQ(tree.names(chooser),
              (std::vector<std::string>{"../", "models/", "Zeta/", "A.dae", "b.obj", "c.PLY"}));
    chooser.set_show_all(true);
    EXPECT_EQ(tree.names(chooser),
              (std::vector<std::string>{"../", ".cache/", "models/", "Zeta/", ".hidden.obj",
                                        "A.dae", "b.obj", "c.PLY", "notes.txt", "s.ops"}));

    FileChooser session;
    session.start(ChooserPurpose::ExportSession, tree.dir.path(), "cube.ops",
                  chooser_extensions(ChooserPurpose::ExportSession, Mode::Mesh));
    EXPECT_EQ(tree.names(session), (std::vector<std::string>{"../", "models/", "Zeta/", "s.ops"}));
}

TEST(FileChooser, ExtensionsComeFromTheFormatTables) {
    const std::vector<std::string> open = chooser_extensions(ChooserPurpose::Open, Mode::Mesh);
    for (const char* ext : {".dae", ".obj", ".ply", ".stl", ".glb", ".bez", ".bzc"}) {
        EXPECT_NE(std::find(open.begin(), open.end(), ext), open.end()) << ext;
    }
    const std::vector<std::string> mesh = chooser_extensions(ChooserPurpose::SaveAs, Mode::Mesh);
    EXPECT_EQ(std::find(mesh.begin(), mesh.end(), ".bzc"), mesh.end());
    EXPECT_NE(std::find(mesh.begin(), mesh.end(), ".off"), mesh.end());
    EXPECT_EQ(chooser_extensions(ChooserPurpose::SaveAs, Mode::Curve),
              std::vector<std::string>{".bzc"});
}

TEST(FileChooser, NavigatesByClickEnterAndDotDot) {
    Tree tree;
    FileChooser chooser;
    chooser.start(ChooserPurpose::Open, tree.dir.path(), "",
                  chooser_extensions(ChooserPurpose::Open, Mode::Mesh));
    chooser.click(1);  // models/
    EXPECT_EQ(chooser.folder(), tree.dir / "models");
    EXPECT_EQ(tree.names(chooser), (std::vector<std::string>{"../", "inner.off"}));
    chooser.click(0);  // ..
    EXPECT_EQ(chooser.folder(), tree.dir.path());

    // Down, Down (models/) and Enter list it; a file's name and Enter choose it.
    press(chooser, FieldKey::Down, 2);
    EXPECT_EQ(chooser.process(), FileChooser::Result::None);
    EXPECT_EQ(chooser.field(), "models/");
    press(chooser, FieldKey::Enter);
    type(chooser, "inner.off");
    press(chooser, FieldKey::Enter);
    EXPECT_EQ(chooser.process(), FileChooser::Result::Chosen);
    EXPECT_EQ(chooser.chosen(), tree.dir / "models" / "inner.off");

    // A click on a file puts its name in the field.
    chooser.go_to(tree.dir.path());
    chooser.click(4);
    EXPECT_EQ(chooser.field(), "b.obj");
    EXPECT_EQ(chooser.highlighted(), 4);
}

TEST(FileChooser, RefusesAFolderAsASaveTargetAndListsIt) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path());
    type(chooser, "models");
    press(chooser, FieldKey::Enter);
    EXPECT_EQ(chooser.process(), FileChooser::Result::None);
    EXPECT_TRUE(chooser.message_is_error());
    EXPECT_EQ(chooser.message(),
              "'models' is a folder, not a file: it is listed now; type a name for the file");
    EXPECT_EQ(chooser.folder(), tree.dir / "models");
    EXPECT_EQ(chooser.field(), "cube.dae") << "the suggested name comes back";
    // Enter again saves the suggested name there.
    press(chooser, FieldKey::Enter);
    EXPECT_EQ(chooser.process(), FileChooser::Result::Chosen);
    EXPECT_EQ(chooser.chosen(), tree.dir / "models" / "cube.dae");
}

TEST(FileChooser, RefusesMissingFilesAndFolders) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path());
    type(chooser, "nowhere/x.obj");
    press(chooser, FieldKey::Enter);
    EXPECT_EQ(chooser.process(), FileChooser::Result::None);
    EXPECT_EQ(chooser.message(), "no folder " + (tree.dir / "nowhere").string() + " to save in");

    FileChooser open;
    open.start(ChooserPurpose::Open, tree.dir.path(), "",
               chooser_extensions(ChooserPurpose::Open, Mode::Mesh));
    press(open, FieldKey::Enter);
    EXPECT_EQ(open.process(), FileChooser::Result::None);
    EXPECT_EQ(open.message(), "type a file's name or pick one");
    type(open, "missing.obj");
    press(open, FieldKey::Enter);
    EXPECT_EQ(open.process(), FileChooser::Result::None);
    EXPECT_EQ(open.message(), "no file missing.obj in " + tree.dir.path().string());
}

TEST(FileChooser, EscapeCancelsAndDropsTheKeysAfterIt) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path());
    press(chooser, FieldKey::Escape);
    type(chooser, "zzz");
    EXPECT_EQ(chooser.process(), FileChooser::Result::Cancelled);
    EXPECT_EQ(chooser.field(), "cube.dae");
}

TEST(FileChooser, TabCompletesInTheListedFolder) {
    Tree tree;
    FileChooser chooser = save_chooser(tree.dir.path());
    type(chooser, "mo");
    press(chooser, FieldKey::Tab);
    chooser.process();
    EXPECT_EQ(chooser.field(), "models/");
}

}  // namespace
}  // namespace meshedit::viewer
