// The shader compile log as one line: Mesa's locations rewritten, lines joined, long logs cut.

#include "meshedit/overlay/shader_log.h"

#include <gtest/gtest.h>

#include <string>

namespace meshedit {
namespace {

TEST(ShaderLog, MesaLocationsBecomeLinesAndColumns) {
    EXPECT_EQ(readable_shader_log("0:36(15): error: syntax error\n0:2(1): warning: unused\n\n"),
              "line 36, column 15: error: syntax error; line 2, column 1: warning: unused");
}

TEST(ShaderLog, LookalikesAreLeftAsTheyAre) {
    EXPECT_EQ(readable_shader_log("10:3(4): x"), "10:3(4): x");  // inside a number
    EXPECT_EQ(readable_shader_log("a0:3(4): x"), "a0:3(4): x");  // inside a word
    EXPECT_EQ(readable_shader_log("0:3(4) x"), "0:3(4) x");      // no ": "
    EXPECT_EQ(readable_shader_log("0:(4): x"), "0:(4): x");      // no line
    EXPECT_EQ(readable_shader_log("0:3(): x"), "0:3(): x");      // no column
    EXPECT_EQ(readable_shader_log("0:"), "0:");
    EXPECT_EQ(readable_shader_log("x\r\ny"), "x; y");
}

TEST(ShaderLog, AnErrorLineOfThirtyThousandDigitsIsCutNotACrash) {
    // The campaign's reproducer: `#error` followed by 30,000 digits crashed the regex rewrite.
    const std::string digits(30'000, '7');
    const std::string log = "0:1(8): error: #error " + digits + "\n";
    const std::string line = readable_shader_log(log);
    EXPECT_EQ(line.rfind("line 1, column 8: error: #error 777", 0), 0u) << line.substr(0, 80);
    EXPECT_LE(line.size(), 2000u + 40u);
    EXPECT_NE(line.find("more characters)"), std::string::npos);
    // Nothing is lost without saying: the count covers exactly what was cut.
    const std::size_t note = line.find("… (");
    ASSERT_NE(note, std::string::npos);
    const std::size_t shown_digits = note - std::string("line 1, column 8: error: #error ").size();
    EXPECT_EQ(line.substr(note),
              "… (" + std::to_string(30'000 - shown_digits) + " more characters)");
}

TEST(ShaderLog, ManyLocationsAreLinear) {
    std::string log;
    for (int i = 0; i < 200'000; ++i) {
        log += "0:" + std::to_string(i) + "(1): e\n";
    }
    const std::string line = readable_shader_log(log, log.size() * 2);
    EXPECT_EQ(line.rfind("line 0, column 1: e; line 1, column 1: e", 0), 0u);
    EXPECT_NE(line.find("line 199999, column 1: e"), std::string::npos);
}

}  // namespace
}  // namespace meshedit
