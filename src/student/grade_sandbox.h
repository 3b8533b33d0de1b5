#pragma once
/// \file
/// Running one grading case in a forked child, so that a crash, an exception or an endless
/// loop in student code is reported with its case and never takes the grader down.

#include <functional>
#include <string>

namespace meshedit::cli::grade {

/// How one case went.
struct Outcome {
    bool pass = false;
    /// Why not: the check's message, "crashed (SIGSEGV)", "timed out after 5 s (an endless
    /// loop?)", "threw std::logic_error: …".
    std::string message;
};

/// Runs `check` in a child process (its stdout goes to stderr, so the report stays clean) and
/// waits at most `seconds`. `check` returns "" for a pass, else what is wrong.
Outcome run_isolated(const std::function<std::string()>& check, double seconds);

}  // namespace meshedit::cli::grade
