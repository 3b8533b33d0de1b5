// `--threads N` and MESHEDIT_THREADS on `meshedit` and `meshedit render`: a good count is used
// and gives the same file as any other; a bad one stops the program with exit 2 and one line
// naming the option or the variable.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "run.h"

namespace meshedit::test {
namespace {

std::string contents(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Sets a variable for the programs this test starts, and removes it afterwards.
struct ScopedEnv {
    explicit ScopedEnv(const char* value) { ::setenv("MESHEDIT_THREADS", value, 1); }
    ~ScopedEnv() { ::unsetenv("MESHEDIT_THREADS"); }
};

void expect_refused(const RunResult& r, const std::string& program, const std::string& source) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    const auto lines = split_lines(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_EQ(lines[0].rfind(program + ": ", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find(source), std::string::npos) << lines[0];
    EXPECT_NE(lines[0].find("not a thread count"), std::string::npos) << lines[0];
    EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(CliThreads, AnyCountGivesTheSameFile) {
    TempDir tmp;
    const std::string torus = (repo_root() / "dae/torus.dae").string();
    std::vector<std::string> outputs;
    for (const char* n : {"1", "0", "3"}) {
        const std::string out = (tmp / (std::string("out") + n + ".obj")).string();
        // Before and after the command name alike.
        const RunResult before = run_meshedit({"--threads", n, "subdivide", torus, out, "-n", "2"});
        ASSERT_EQ(before.exit_code, 0) << before.err;
        outputs.push_back(contents(out));
        const RunResult after = run_meshedit({"subdivide", torus, out, "-n", "2", "--threads", n});
        ASSERT_EQ(after.exit_code, 0) << after.err;
        EXPECT_EQ(contents(out), outputs.back());
    }
    EXPECT_EQ(outputs[1], outputs[0]);
    EXPECT_EQ(outputs[2], outputs[0]);
}

TEST(CliThreads, BadFlagValuesExitTwoNamingTheFlag) {
    const std::string cube = (repo_root() / "dae/cube.dae").string();
    for (const char* bad : {"-1", "two", "4.5", "100000", ""}) {
        SCOPED_TRACE(bad);
        expect_refused(run_meshedit({"info", cube, "--threads", bad}), "meshedit", "--threads");
    }
}

TEST(CliThreads, BadVariableExitsTwoNamingItUnlessTheFlagIsGiven) {
    const std::string cube = (repo_root() / "dae/cube.dae").string();
    for (const char* bad : {"-2", "lots", "100000"}) {
        SCOPED_TRACE(bad);
        const ScopedEnv env(bad);
        expect_refused(run_meshedit({"info", cube}), "meshedit", "MESHEDIT_THREADS");
        const RunResult flag = run_meshedit({"info", cube, "--threads", "2"});
        EXPECT_EQ(flag.exit_code, 0) << flag.err;
    }
    const ScopedEnv good("1");
    const RunResult r = run_meshedit({"info", cube});
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

#ifdef MESHEDIT_HAS_RENDER
TEST(CliThreads, RenderTakesTheFlagAndTheVariable) {
    TempDir tmp;
    const std::string cube = (repo_root() / "dae/cube.dae").string();
    const std::string png = (tmp / "out.png").string();
    expect_refused(run_meshedit({"render", cube, "-o", png, "--threads", "-1"}), "meshedit",
                   "--threads");
    const ScopedEnv env("many");
    expect_refused(run_meshedit({"render", cube, "-o", png}), "meshedit", "MESHEDIT_THREADS");
    EXPECT_TRUE(tmp.entries().empty());
}
#endif

}  // namespace
}  // namespace meshedit::test
