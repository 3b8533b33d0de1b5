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

}  // namespace meshedit
