// Helpers the format writers share (io_util.h).

#include "io_util.h"

#include <algorithm>
#include <charconv>

namespace meshedit::io_util {

std::string_view text_of(std::string_view bytes, const std::string& name) {
    if (bytes.substr(0, 3) == "\xEF\xBB\xBF") {
        return bytes.substr(3);
    }
    const bool utf16_bom = bytes.substr(0, 2) == "\xFF\xFE" || bytes.substr(0, 2) == "\xFE\xFF";
    const std::string_view first_line = bytes.substr(0, std::min(bytes.find('\n'), bytes.size()));
    // ASCII text in UTF-16 has a NUL beside every character (and zeros are not text at all:
    // the format's parser calls them binary data).
    const bool wide = first_line.size() >= 2 && (first_line[0] == '\0') != (first_line[1] == '\0');
    if (utf16_bom || wide) {
        throw IoError(name, "", "UTF-16 or UTF-32 text; save the file as UTF-8");
    }
    return bytes;
}

std::string_view next_token(std::string_view& line) {
    const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f'; };
    std::size_t b = 0;
    while (b < line.size() && is_space(line[b])) {
        ++b;
    }
    std::size_t e = b;
    while (e < line.size() && !is_space(line[e])) {
        ++e;
    }
    const std::string_view t = line.substr(b, e - b);
    line.remove_prefix(e);
    return t;
}

std::string_view trim(std::string_view text) {
    const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f'; };
    while (!text.empty() && is_space(text.front())) {
        text.remove_prefix(1);
    }
    while (!text.empty() && is_space(text.back())) {
        text.remove_suffix(1);
    }
    return text;
}

std::optional<double> parse_double(std::string_view token) {
    // from_chars does not take a leading '+'.
    const std::size_t skip = token.size() > 1 && token[0] == '+' ? 1 : 0;
    double x = 0.0;
    const auto [ptr, ec] = std::from_chars(token.data() + skip, token.data() + token.size(), x);
    if (ec != std::errc() || ptr != token.data() + token.size() || token.empty()) {
        return std::nullopt;
    }
    return x;
}

std::string_view next_content_line(std::string_view text, std::size_t& pos, std::size_t& line) {
    while (pos < text.size()) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        const std::string_view l = text.substr(pos, end - pos);
        pos = end + 1;
        ++line;
        std::string_view probe = l;
        if (!next_token(probe).empty()) {
            return l;
        }
    }
    return {};
}

const Mesh& compacted(const Mesh& mesh, std::optional<Mesh>& storage) {
    if (!mesh.has_garbage()) {
        return mesh;
    }
    storage.emplace(mesh);
    storage->garbage_collection();
    return *storage;
}

}  // namespace meshedit::io_util
