// Bad input through the command line: exit status 2, one line "meshedit: <file>: …" naming
// the file and the problem, and no output file (nor a temporary one) left behind.

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "run.h"

namespace meshedit::test {
namespace {

struct BadInput {
    const char* file;     // in tests/cli/data
    const char* out;      // output name (its extension picks the writer)
    const char* problem;  // a phrase the message must contain (case-sensitive)
};

const BadInput kBadInputs[] = {
    {"empty.dae", "out.dae", "empty"},
    {"truncated.dae", "out.dae", "truncated"},
    {"garbage.dae", "out.dae", "binary"},
    {"missing_p.dae", "out.dae", "missing <p>"},
    {"index_out_of_range.dae", "out.dae", "out of range"},
    {"nan.dae", "out.dae", "NaN"},
    {"inf.dae", "out.dae", "infinity"},
    {"hole.dae", "out.dae", "<ph>"},
    {"short_patch.bez", "out.dae", "47 numbers"},
    {"one_point.bzc", "out.bzc", "at least 2 points"},
    {"unknown.xyz", "out.dae", "unknown extension"},
    {"does_not_exist.dae", "out.dae", "no such file"},
};

// Checks the error contract for one run whose output was to go into `out_dir`.
void expect_bad_input(const RunResult& r, const std::string& file, const std::string& problem,
                      const TempDir& out_dir) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.signal, 0);
    const auto lines = split_lines(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_EQ(lines[0].rfind("meshedit: ", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find(file), std::string::npos) << "file not named: " << lines[0];
    EXPECT_NE(lines[0].find(problem), std::string::npos) << "problem not named: " << lines[0];
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_TRUE(out_dir.entries().empty()) << "left behind: " << out_dir.entries().front();
}

TEST(CliErrors, BadInputFilesExitTwoNamingFileAndProblem) {
    for (const BadInput& bad : kBadInputs) {
        SCOPED_TRACE(bad.file);
        TempDir tmp;
        const RunResult r =
            run_meshedit({"convert", (data_dir() / bad.file).string(), (tmp / bad.out).string()});
        expect_bad_input(r, bad.file, bad.problem, tmp);
    }
}

TEST(CliErrors, InfoAndCheckReportTheSameWay) {
    for (const char* command : {"info", "check"}) {
        for (const BadInput& bad : kBadInputs) {
            if (std::string(bad.file).ends_with(".bzc") && std::string(command) == "info") {
                continue;  // info on a curve is covered below
            }
            SCOPED_TRACE(std::string(command) + " " + bad.file);
            TempDir tmp;
            const RunResult r = run_meshedit({command, (data_dir() / bad.file).string()});
            expect_bad_input(r, bad.file, bad.problem, tmp);
        }
    }
    TempDir tmp;
    expect_bad_input(run_meshedit({"info", (data_dir() / "one_point.bzc").string()}),
                     "one_point.bzc", "at least 2 points", tmp);
    expect_bad_input(run_meshedit({"eval", (data_dir() / "one_point.bzc").string(), "--t", "0.5"}),
                     "one_point.bzc", "at least 2 points", tmp);
    expect_bad_input(
        run_meshedit({"eval", (data_dir() / "short_patch.bez").string(), "--uv", "0.5,0.5"}),
        "short_patch.bez", "47 numbers", tmp);
}

TEST(CliErrors, UnknownOutputExtension) {
    TempDir tmp;
    const RunResult r =
        run_meshedit({"convert", (data_dir() / "ok.dae").string(), (tmp / "out.xyz").string()});
    expect_bad_input(r, "out.xyz", "unknown extension", tmp);
}

TEST(CliErrors, UnwritableOutputFolder) {
    // Tests may run as root, for whom permissions do not stop a write: a "folder" that is a
    // regular file does.
    TempDir tmp;
    { std::ofstream(tmp / "not_a_folder") << "x"; }
    for (const char* name : {"out.dae", "out.gltf", "out.glb", "out.obj"}) {
        const auto out = tmp / "not_a_folder" / name;
        const RunResult r =
            run_meshedit({"convert", (data_dir() / "ok.dae").string(), out.string()});
        EXPECT_EQ(r.exit_code, 2) << r.err;
        const auto lines = split_lines(r.err);
        ASSERT_EQ(lines.size(), 1u) << r.err;
        EXPECT_NE(lines[0].find(out.string()), std::string::npos) << lines[0];
        EXPECT_NE(lines[0].find("not a folder"), std::string::npos) << lines[0];
    }
    EXPECT_EQ(tmp.entries(), std::vector<std::string>{"not_a_folder"});
    // A missing folder is just as unwritable.
    const RunResult r = run_meshedit(
        {"convert", (data_dir() / "ok.dae").string(), (tmp / "missing" / "out.dae").string()});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
    EXPECT_EQ(tmp.entries(), std::vector<std::string>{"not_a_folder"});
}

TEST(CliErrors, FailedConvertKeepsAnExistingTarget) {
    TempDir tmp;
    { std::ofstream(tmp / "out.dae") << "precious"; }
    const RunResult r =
        run_meshedit({"convert", (data_dir() / "nan.dae").string(), (tmp / "out.dae").string()});
    EXPECT_EQ(r.exit_code, 2);
    std::ifstream in(tmp / "out.dae");
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(content, "precious");
    EXPECT_EQ(tmp.entries(), std::vector<std::string>{"out.dae"});
}

TEST(CliErrors, GoodInputForComparison) {
    TempDir tmp;
    const RunResult r =
        run_meshedit({"convert", (data_dir() / "ok.dae").string(), (tmp / "ok.obj").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(tmp.entries(), std::vector<std::string>{"ok.obj"});
}

}  // namespace
}  // namespace meshedit::test
