// Numbers as text (number_text.h).

#include "meshedit/core/number_text.h"

#include <cstdio>

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

std::string readable_number(double x) {
    if (x == 0.0) {
        return "0";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return text;
}

}  // namespace meshedit
