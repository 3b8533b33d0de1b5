// Helpers the format writers share (io_util.h).

#include "io_util.h"

#include <cctype>
#include <filesystem>
#include <string>

#include <algorithm>
#include <charconv>

namespace meshedit::io_util {

std::string resolve_texture(std::string written, const std::filesystem::path& folder, bool uri) {
    namespace fs = std::filesystem;
    if (uri && written.rfind("file://", 0) == 0) {
        written.erase(0, 7);  // file:///C:/x keeps its slash: a path either way
    }
    std::string path;
    for (std::size_t i = 0; i < written.size(); ++i) {
        const char c = written[i];
        const auto hex = [&](std::size_t k) {
            const char x = k < written.size() ? written[k] : 'g';
            return std::isxdigit(static_cast<unsigned char>(x)) != 0;
        };
        if (uri && c == '%' && hex(i + 1) && hex(i + 2)) {
            path += static_cast<char>(std::stoi(written.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            path += c == '\\' ? '/' : c;
        }
    }
    std::error_code ec;
    const fs::path resolved = (folder / path).lexically_normal();
    if (fs::exists(resolved, ec)) {
        return fs::absolute(resolved, ec).string();
    }
    // Files written on Windows name textures as its file system finds them: "\..\x\Earth.jpg"
    // (from the drive's root, but meant beside the file) for x/earth.jpg. Tried: the path
    // from the file's folder, then the name in any case in its folder (what the writer meant).
    std::string relative = path;
    while (!relative.empty() && relative.front() == '/') {
        relative.erase(0, 1);
    }
    const fs::path beside = (folder / relative).lexically_normal();
    if (fs::exists(beside, ec)) {
        return fs::absolute(beside, ec).string();
    }
    const auto lower = [](std::string s) {
        std::transform(s.begin(), s.end(), s.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        return s;
    };
    for (const fs::path& candidate : {resolved, beside}) {
        const fs::path dir = candidate.parent_path();
        if (dir.empty() || !fs::is_directory(dir, ec)) {
            continue;
        }
        const std::string want = lower(candidate.filename().string());
        for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
            if (lower(it->path().filename().string()) == want) {
                return fs::absolute(it->path(), ec).string();
            }
        }
    }
    return path;
}

std::string texture_relative_to(const std::string& texture, const std::filesystem::path& folder) {
    namespace fs = std::filesystem;
    const fs::path file(texture);
    if (!file.is_absolute()) {
        return file.generic_string();
    }
    std::error_code ec;
    const fs::path relative =
        fs::relative(file, fs::absolute(folder.empty() ? fs::path(".") : folder, ec), ec);
    return (ec || relative.empty() ? file : relative).generic_string();
}

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
