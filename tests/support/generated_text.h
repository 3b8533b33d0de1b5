#pragma once
/// \file
/// Text that a document carries as a copy of generated output (the README's keys table,
/// docs/cli.md's table of `--ops` verbs), between the lines `<!-- NAME:begin -->` and
/// `<!-- NAME:end -->`. A test compares the block with what the code generates now.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace meshedit::test {

/// Passes when the block `name` of the file at `path` equals `expected`; the failure
/// message says what to paste there.
inline ::testing::AssertionResult block_is_generated(const std::string& path,
                                                     const std::string& name,
                                                     const std::string& expected) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return ::testing::AssertionFailure() << "cannot read " << path;
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    const std::string begin = "<!-- " + name + ":begin -->\n";
    const std::string end = "<!-- " + name + ":end -->";
    const std::size_t b = text.find(begin);
    const std::size_t e = text.find(end);
    if (b == std::string::npos || e == std::string::npos || e < b) {
        return ::testing::AssertionFailure()
               << path << " lacks the lines " << begin << "and " << end;
    }
    if (text.substr(b + begin.size(), e - b - begin.size()) != expected) {
        return ::testing::AssertionFailure()
               << path << " is out of date with the code. Replace the lines between " << begin
               << "and " << end << " with:\n"
               << expected;
    }
    return ::testing::AssertionSuccess();
}

}  // namespace meshedit::test
