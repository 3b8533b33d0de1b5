// Every COLLADA file of Debian's assimp-testmodels package through `meshedit check`: each
// loads and validates (exit 0), or fails with exit 2 and one line naming the file. Never a
// crash (a signal) or a hang (killed after 5 s).

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "run.h"

namespace meshedit::test {
namespace {

// Where `dpkg -L assimp-testmodels` puts the models on Debian 12.
const char* const kCorpusRoots[] = {"/usr/share/assimp/models", "/usr/share/assimp-testmodels"};

std::vector<std::filesystem::path> corpus_files() {
    std::vector<std::filesystem::path> files;
    for (const char* root : kCorpusRoots) {
        std::error_code ec;
        if (!std::filesystem::is_directory(root, ec)) {
            continue;
        }
        for (const auto& entry : std::filesystem::recursive_directory_iterator(root, ec)) {
            std::string ext = entry.path().extension().string();
            std::transform(ext.begin(), ext.end(), ext.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            if (ext == ".dae" && entry.is_regular_file()) {
                files.push_back(entry.path());
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(CliCorpus, AssimpColladaModelsLoadOrFailCleanly) {
    const std::vector<std::filesystem::path> files = corpus_files();
    if (files.empty()) {
        GTEST_SKIP() << "assimp-testmodels is not installed";
    }
    int loaded = 0;
    int refused = 0;
    for (const auto& file : files) {
        SCOPED_TRACE(file.string());
        const RunResult r = run_meshedit({"check", file.string()}, 5.0);
        ASSERT_FALSE(r.timed_out) << "hang: killed after 5 s";
        ASSERT_EQ(r.signal, 0) << "crash: signal " << r.signal << "\n" << r.err;
        if (r.exit_code == 0) {
            ++loaded;
            EXPECT_NE(r.out.find(": OK ("), std::string::npos) << r.out;
            continue;
        }
        ++refused;
        EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
        const auto lines = split_lines(r.err);
        ASSERT_EQ(lines.size(), 1u) << r.err;
        EXPECT_EQ(lines[0].rfind("meshedit: " + file.string() + ": ", 0), 0u) << lines[0];
        EXPECT_EQ(lines[0].find("internal error"), std::string::npos) << lines[0];
    }
    RecordProperty("loaded", loaded);
    RecordProperty("refused", refused);
    std::printf("[ corpus   ] %d COLLADA files: %d load and validate, %d refused cleanly\n",
                loaded + refused, loaded, refused);
    EXPECT_GT(loaded, 0);
}

}  // namespace
}  // namespace meshedit::test
