// The open and save-as prompts' paths: what they start with, what a typed text names, and Tab.

#include "meshedit/viewer/paths.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

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

}  // namespace
}  // namespace meshedit::viewer
