// The open and save-as prompts' paths (what they start with, what a typed text names, Tab)
// and where screenshots go.

#include "meshedit/viewer/paths.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "support/scratch_dir.h"

namespace meshedit::viewer {
namespace {

namespace fs = std::filesystem;

TEST(PromptPaths, StartIsTheFolderWithASeparatorOrTheFile) {
    const fs::path here = fs::current_path();
    EXPECT_EQ(prompt_start("models/dae/teapot.dae", false), (here / "models/dae/").string());
    EXPECT_EQ(prompt_start("models/dae/teapot.dae", true),
              (here / "models/dae/teapot.dae").string());
    EXPECT_EQ(prompt_start("", false), here.string() + "/");
    EXPECT_EQ(prompt_start("a/../b/./c.obj", true), (here / "b/c.obj").string());
    // Typing a name after the start lands in the folder (once, it landed in "daeteapot.dae").
    EXPECT_EQ(resolve_prompt_path(prompt_start("models/dae/x.dae", false) + "teapot.dae", "/"),
              here / "models/dae/teapot.dae");
}

TEST(PromptPaths, RelativeHomeAndDotsResolve) {
    EXPECT_EQ(resolve_prompt_path("teapot.dae", "/data/models"),
              fs::path("/data/models/teapot.dae"));
    EXPECT_EQ(resolve_prompt_path("a/../b/../c.obj", "/data"), fs::path("/data/c.obj"));
    EXPECT_EQ(resolve_prompt_path("/abs/./x.obj", "/data"), fs::path("/abs/x.obj"));
    // An absolute path typed after the prefilled folder replaces it (a lost Ctrl+A).
    EXPECT_EQ(resolve_prompt_path("/data/models//tmp/w/ico.dae", "/data/models"),
              fs::path("/tmp/w/ico.dae"));
    EXPECT_EQ(resolve_prompt_path(prompt_start("/data/models/x.dae", false) + "/tmp/ico.dae",
                                  "/data/models"),
              fs::path("/tmp/ico.dae"));
    const char* home = std::getenv("HOME");
    ASSERT_NE(home, nullptr);
    EXPECT_EQ(resolve_prompt_path("~/m.dae", "/data"), fs::path(home) / "m.dae");
    EXPECT_EQ(resolve_prompt_path("~user/m.dae", "/data"), fs::path("/data/~user/m.dae"));
}

TEST(PromptPaths, TabCompletesNamesAndFolders) {
    test::ScratchDir dir;
    fs::create_directories(dir / "models");
    for (const char* name : {"teapot.dae", "teacup.dae", "torus.obj", ".hidden.dae"}) {
        std::ofstream(dir / "models" / name) << "x";
    }
    const std::string base = dir.path().string() + "/";
    // One folder: completed with its separator.
    Completion c = complete_path(base + "mo", "/");
    EXPECT_EQ(c.text, base + "models/");
    EXPECT_EQ(c.candidates, std::vector<std::string>{"models/"});
    // Several names: their shared prefix, and the names to show.
    c = complete_path(base + "models/te", "/");
    EXPECT_EQ(c.text, base + "models/tea");
    EXPECT_EQ(c.candidates, (std::vector<std::string>{"teacup.dae", "teapot.dae"}));
    c = complete_path(base + "models/teap", "/");
    EXPECT_EQ(c.text, base + "models/teapot.dae");
    // Relative to the prompt's folder; hidden names only for a leading dot.
    c = complete_path("models/", dir.path());
    EXPECT_EQ(c.candidates.size(), 3u);
    c = complete_path("models/.h", dir.path());
    EXPECT_EQ(c.text, "models/.hidden.dae");
    // Nothing matches: the text stays.
    c = complete_path(base + "models/zz", "/");
    EXPECT_EQ(c.text, base + "models/zz");
    EXPECT_TRUE(c.candidates.empty());
}

// Sets environment variables for one test and puts the old values back.
class ScopedEnvironment {
public:
    void set(const char* name, const std::string& value) {
        remember(name);
        ::setenv(name, value.c_str(), 1);
    }
    void unset(const char* name) {
        remember(name);
        ::unsetenv(name);
    }
    ~ScopedEnvironment() {
        for (const auto& [name, value] : saved_) {
            if (value) {
                ::setenv(name.c_str(), value->c_str(), 1);
            } else {
                ::unsetenv(name.c_str());
            }
        }
    }

private:
    void remember(const char* name) {
        const char* old = std::getenv(name);
        saved_.emplace_back(name, old ? std::optional<std::string>(old) : std::nullopt);
    }
    std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

TEST(Screenshots, GoToTheUsersPicturesFolder) {
    test::ScratchDir home;
    ScopedEnvironment env;
    env.set("HOME", home.path().string());
    env.unset("XDG_PICTURES_DIR");
    env.unset("XDG_CONFIG_HOME");
    EXPECT_EQ(pictures_folder(), home / "Pictures" / "MeshEdit");

    // A desktop's user-dirs.dirs names it (here in another language).
    fs::create_directories(home / ".config");
    std::ofstream(home / ".config" / "user-dirs.dirs")
        << "# written by xdg-user-dirs-update\nXDG_DESKTOP_DIR=\"$HOME/Desktop\"\n"
           "XDG_PICTURES_DIR=\"$HOME/Bilder\"\n";
    EXPECT_EQ(pictures_folder(), home / "Bilder" / "MeshEdit");
    env.set("XDG_CONFIG_HOME", (home / "elsewhere").string());
    EXPECT_EQ(pictures_folder(), home / "Pictures" / "MeshEdit");
    env.set("XDG_PICTURES_DIR", "/srv/shots");
    EXPECT_EQ(pictures_folder(), fs::path("/srv/shots/MeshEdit"));
    env.unset("XDG_PICTURES_DIR");
    env.unset("HOME");
    EXPECT_EQ(pictures_folder(), fs::temp_directory_path() / "MeshEdit");
}

TEST(Screenshots, AreNamedAfterTheDocumentAndNeverOverwrite) {
    test::ScratchDir dir;
    EXPECT_EQ(screenshot_path(dir.path(), "/models/cow.dae"), dir / "meshedit-cow-1.png");
    std::ofstream(dir / "meshedit-cow-1.png") << "x";
    std::ofstream(dir / "meshedit-cow-2.png") << "x";
    EXPECT_EQ(screenshot_path(dir.path(), "/models/cow.dae"), dir / "meshedit-cow-3.png");
    EXPECT_EQ(screenshot_path(dir.path(), ""), dir / "meshedit-1.png");
}

}  // namespace
}  // namespace meshedit::viewer
