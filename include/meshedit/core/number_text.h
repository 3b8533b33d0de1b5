#pragma once
/// \file
/// Numbers as text, the one way every writer and message spells a double: the shortest decimal
/// text that reads back as exactly the same double (std::to_chars), so files round-trip bit for
/// bit and the edit language's amounts parse back to what was written.

#include <string>

namespace meshedit {

/// "0.1", "1e+200", "-0", "nan", "inf", "-inf".
std::string number_text(double x);
/// number_text() appended to `out` without a temporary (writers of big files).
void append_number_text(std::string& out, double x);
/// Six significant digits, what a person reads in a report ("0.0173205", "1.2e+06"); "0"
/// for both zeros. Exact text is number_text()'s.
std::string readable_number(double x);

}  // namespace meshedit
