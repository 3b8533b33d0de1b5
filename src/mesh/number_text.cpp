// Numbers as text (number_text.h).

#include "meshedit/core/number_text.h"

#include <charconv>
#include <system_error>

namespace meshedit {

void append_number_text(std::string& out, double x) {
    char buffer[32];  // the longest shortest double ("-2.2250738585072014e-308") is 24
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
    out.append(buffer, ec == std::errc() ? end : buffer);
}

std::string number_text(double x) {
    std::string out;
    append_number_text(out, x);
    return out;
}

}  // namespace meshedit
