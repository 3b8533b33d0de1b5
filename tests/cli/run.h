#pragma once
/// \file
/// Running the real `meshedit` executable from tests: fork/exec with stdout and stderr
/// captured, a time limit, and per-test temporary folders.

#include <filesystem>
#include <string>
#include <vector>

namespace meshedit::test {

/// What one run of a program did.
struct RunResult {
    int exit_code = -1;      ///< exit status, or -1 if it did not exit normally
    int signal = 0;          ///< the signal that ended it (0 if none)
    bool timed_out = false;  ///< killed after the time limit
    std::string out;         ///< stdout
    std::string err;         ///< stderr
};

/// Runs `program` with `args`, stdin from /dev/null, killing it (SIGKILL) after
/// `timeout_seconds`; with `memory_limit_bytes`, the process's address space is limited to
/// that (an allocation beyond it fails as it would on a machine that small).
RunResult run_program(const std::string& program, const std::vector<std::string>& args,
                      double timeout_seconds = 20.0, std::size_t memory_limit_bytes = 0);

/// run_program() on the built meshedit (MESHEDIT_EXE).
RunResult run_meshedit(const std::vector<std::string>& args, double timeout_seconds = 20.0,
                       std::size_t memory_limit_bytes = 0);

/// The repository root (MESHEDIT_SOURCE_DIR), e.g. for dae/ and bez/.
std::filesystem::path repo_root();
/// tests/cli/data.
std::filesystem::path data_dir();

/// A fresh empty folder, removed with everything in it when the object goes away.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
    /// Names of the entries in the folder, sorted.
    std::vector<std::string> entries() const;

private:
    std::filesystem::path path_;
};

/// The lines of `text` without their newlines.
std::vector<std::string> split_lines(const std::string& text);

}  // namespace meshedit::test
