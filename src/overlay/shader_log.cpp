// A GLSL compiler's log as one readable line (shader_log.h): one pass, no regex.

#include "meshedit/overlay/shader_log.h"

#include <algorithm>

namespace meshedit {
namespace {

bool is_digit(char c) {
    return c >= '0' && c <= '9';
}

// The digits of `text` from `at`; `at` moves past them.
std::string_view digits(std::string_view text, std::size_t& at) {
    const std::size_t begin = at;
    while (at < text.size() && is_digit(text[at])) {
        ++at;
    }
    return text.substr(begin, at - begin);
}

// At `at`, Mesa's location "0:L(C): " (not inside a word or a number): appends "line L,
// column C: " and moves past it. Otherwise leaves both alone.
bool rewrite_location(std::string_view log, std::size_t& at, std::string& out) {
    if (log.compare(at, 2, "0:") != 0) {
        return false;
    }
    if (at > 0) {
        const char before = log[at - 1];
        if (is_digit(before) || before == '_' || (before >= 'a' && before <= 'z') ||
            (before >= 'A' && before <= 'Z')) {
            return false;
        }
    }
    std::size_t p = at + 2;
    const std::string_view line = digits(log, p);
    if (line.empty() || p >= log.size() || log[p] != '(') {
        return false;
    }
    ++p;
    const std::string_view column = digits(log, p);
    if (column.empty() || log.compare(p, 3, "): ") != 0) {
        return false;
    }
    out += "line ";
    out += line;
    out += ", column ";
    out += column;
    out += ": ";
    at = p + 3;
    return true;
}

}  // namespace

std::string readable_shader_log(std::string_view log, std::size_t max_chars) {
    while (!log.empty() && (log.back() == '\n' || log.back() == '\r' || log.back() == ' ')) {
        log.remove_suffix(1);
    }
    std::string out;
    out.reserve(std::min(log.size(), max_chars) + 64);
    std::size_t at = 0;
    while (at < log.size() && out.size() < max_chars) {
        if (rewrite_location(log, at, out)) {
            continue;
        }
        const char c = log[at++];
        if (c == '\n') {
            out += "; ";
        } else if (c != '\r') {
            out += c;
        }
    }
    if (at < log.size()) {
        out += "… (" + std::to_string(log.size() - at) + " more characters)";
    }
    return out;
}

}  // namespace meshedit
