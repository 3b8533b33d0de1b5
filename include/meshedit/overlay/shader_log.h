#pragma once
/// \file
/// A GLSL compiler's log as one readable line for the one-line error convention. GL-free, so
/// that it is tested and fuzzed without a context: a user shader's log is hostile input (a
/// `#error` line of 30,000 digits took the old regex rewrite into a stack overflow).

#include <cstddef>
#include <string>
#include <string_view>

namespace meshedit {

/// Mesa's "0:36(15): error: …" becomes "line 36, column 15: error: …"; lines are joined with
/// "; ", trailing blanks dropped, carriage returns removed; past `max_chars` characters the
/// rest is cut and counted ("… (12345 more characters)"). Linear in the log's length.
std::string readable_shader_log(std::string_view log, std::size_t max_chars = 2000);

}  // namespace meshedit
