#pragma once
/// \file
/// Helpers for the formats tests: a scratch folder per test, file contents, data paths.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "meshedit/core/build.h"
#include "meshedit/files/io_error.h"
#include "support/fixtures.h"
#include "support/scratch_dir.h"

namespace meshedit::test {

inline std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void spit(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

/// `x` rounded to float. Through a volatile: GCC 12 at -O3 (its SLP vectorizer) was seen to
/// drop the rounding of `Vec3(float(p.x), float(p.y), float(p.z))` inlined into EXPECT_EQ.
inline double to_float(double x) {
    volatile float f = static_cast<float>(x);
    return f;
}

/// A file of tests/io/data.
inline std::filesystem::path data_file(const std::string& name) {
    return std::filesystem::path(MESHEDIT_TEST_DATA) / name;
}

/// A file of the repository's sample folders (bez/, dae/).
inline std::filesystem::path sample_file(const std::string& relative) {
    return std::filesystem::path(MESHEDIT_TEST_DATA).parent_path().parent_path().parent_path() /
           relative;
}

/// Runs `f`, expects an IoError, and returns its what() (empty, and a failure, otherwise).
template <class F>
std::string io_error_of(F&& f) {
    try {
        f();
    } catch (const IoError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected IoError, got another exception: " << e.what();
        return {};
    }
    ADD_FAILURE() << "expected IoError, nothing was thrown";
    return {};
}

/// `text` contains `part`; the message shows both (gmock's HasSubstr without gmock).
inline ::testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

}  // namespace meshedit::test

#define EXPECT_CONTAINS(text, part) EXPECT_TRUE(::meshedit::test::contains((text), (part)))
