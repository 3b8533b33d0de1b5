// COLLADA reader, part 1: file loading, text decoding, XML parsing, element paths for error
// messages, and number lists.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "collada_detail.h"

namespace meshedit::collada {
namespace {

std::string read_bytes(const std::string& file) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
        throw IoError(file, "", "is a directory, not a file");
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw IoError(file, "", std::string("cannot open file: ") + std::strerror(errno));
    }
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        throw IoError(file, "", "read error");
    }
    return bytes;
}

void append_utf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

// Converted here rather than by pugixml so that node offsets index one UTF-8 text whatever
// the file's encoding, and error lines are right for UTF-16 files too.
std::string utf16_to_utf8(const std::string& file, std::string_view bytes, bool big_endian) {
    if (bytes.size() % 2 != 0) {
        throw IoError(file, "", "truncated UTF-16 text (odd number of bytes)");
    }
    std::string out;
    out.reserve(bytes.size() / 2);
    const auto unit = [&](std::size_t i) {
        const auto a = static_cast<unsigned char>(bytes[i]);
        const auto b = static_cast<unsigned char>(bytes[i + 1]);
        return static_cast<std::uint32_t>(big_endian ? (a << 8) | b : (b << 8) | a);
    };
    for (std::size_t i = 0; i < bytes.size(); i += 2) {
        std::uint32_t cp = unit(i);
        if (cp >= 0xD800 && cp <= 0xDBFF && i + 3 < bytes.size()) {
            const std::uint32_t lo = unit(i + 2);
            if (lo >= 0xDC00 && lo <= 0xDFFF) {
                cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                i += 2;
            }
        }
        if (cp >= 0xD800 && cp <= 0xDFFF) {
            throw IoError(
                file, "",
                "invalid UTF-16 text (unpaired surrogate at byte " + std::to_string(i) + ")");
        }
        append_utf8(out, cp);
    }
    return out;
}

std::string decode(const std::string& file, std::string bytes) {
    const auto starts = [&](std::string_view prefix) {
        return std::string_view(bytes).substr(0, prefix.size()) == prefix;
    };
    if (starts("\xEF\xBB\xBF")) {
        return bytes.substr(3);
    }
    if (starts("\xFF\xFE")) {
        return utf16_to_utf8(file, std::string_view(bytes).substr(2), false);
    }
    if (starts("\xFE\xFF")) {
        return utf16_to_utf8(file, std::string_view(bytes).substr(2), true);
    }
    // UTF-16 without a byte-order mark: the first character '<' tells the byte order.
    if (starts(std::string_view("<\0", 2))) {
        return utf16_to_utf8(file, bytes, false);
    }
    if (starts(std::string_view("\0<", 2))) {
        return utf16_to_utf8(file, bytes, true);
    }
    return bytes;
}

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

std::string lowercase_first(std::string s) {
    if (!s.empty()) {
        s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
    }
    return s;
}

std::string quoted_token(std::string_view token) {
    constexpr std::size_t kMax = 24;
    std::string out(1, '"');
    out.append(token.substr(0, kMax));
    out.append(token.size() > kMax ? "…\"" : "\"");
    return out;
}

std::string element_label(pugi::xml_node node) {
    std::string label = std::string("<") + node.name();
    if (const auto id = node.attribute("id")) {
        label += std::string(" id=\"") + id.value() + "\"";
    } else if (const auto sid = node.attribute("sid")) {
        label += std::string(" sid=\"") + sid.value() + "\"";
    }
    return label + ">";
}

// Calls `token(text, index)` for each whitespace-separated token of `text`.
template <class F>
void for_each_token(const char* text, F&& token) {
    std::size_t index = 0;
    const char* p = text;
    while (*p != '\0') {
        while (is_space(*p)) {
            ++p;
        }
        if (*p == '\0') {
            break;
        }
        const char* begin = p;
        while (*p != '\0' && !is_space(*p)) {
            ++p;
        }
        token(std::string_view(begin, static_cast<std::size_t>(p - begin)), index++);
    }
}

}  // namespace

Document::Document(const std::string& path) : file_(path) {
    text_ = decode(file_, read_bytes(file_));
    if (std::all_of(text_.begin(), text_.end(), is_space)) {
        throw IoError(file_, "", "empty file");
    }
    // XML text never holds control characters; finding one means a binary file.
    const auto bad = std::find_if(text_.begin(), text_.end(), [](char c) {
        const auto u = static_cast<unsigned char>(c);
        return u < 0x20 && !is_space(c);
    });
    if (bad != text_.end()) {
        char byte[8];
        std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(*bad));
        const auto offset = bad - text_.begin();
        throw IoError(file_, "line " + std::to_string(line_of(offset)),
                      std::string("binary data (byte ") + byte + " at offset " +
                          std::to_string(offset) + "), not a COLLADA text file");
    }

    const pugi::xml_parse_result result =
        doc_.load_buffer(text_.data(), text_.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!result) {
        const std::string line = "line " + std::to_string(line_of(result.offset));
        std::size_t end = text_.size();
        while (end > 0 && is_space(text_[end - 1])) {
            --end;
        }
        if (result.status == pugi::status_no_document_element) {
            throw IoError(file_, "", "not an XML file (no root element)");
        }
        const std::string what = lowercase_first(result.description());
        if (static_cast<std::size_t>(result.offset) + 1 >= end) {
            std::string inside = " in the middle of markup";
            if (result.status == pugi::status_end_element_mismatch) {
                // pugixml keeps the partial tree: its last open element is still unclosed.
                pugi::xml_node open = doc_.document_element();
                while (open.last_child().type() == pugi::node_element) {
                    open = open.last_child();
                }
                inside = std::string(" inside <") + open.name() + ">";
            }
            throw IoError(file_, line, "truncated XML: the file ends" + inside + " (" + what + ")");
        }
        throw IoError(file_, line, "malformed XML: " + what);
    }
    const pugi::xml_node top = root();
    if (std::strcmp(top.name(), "COLLADA") != 0) {
        throw IoError(file_, where(top),
                      std::string("no <COLLADA> root element (the root is <") + top.name() +
                          ">); not a COLLADA file");
    }

    // Index every id once, walking the tree without recursion (documents may nest deeply).
    pugi::xml_node n = top;
    while (n) {
        if (const auto id = n.attribute("id"); id && *id.value() != '\0') {
            ids_.emplace(std::string_view(id.value()), n);
        }
        if (n.first_child()) {
            n = n.first_child();
            continue;
        }
        while (n && n != top && !n.next_sibling()) {
            n = n.parent();
        }
        if (!n || n == top) {
            break;
        }
        n = n.next_sibling();
    }
}

pugi::xml_node Document::find_id(std::string_view id) const {
    const auto it = ids_.find(id);
    return it == ids_.end() ? pugi::xml_node() : it->second;
}

pugi::xml_node Document::resolve(std::string_view url, pugi::xml_node at) const {
    if (url.empty()) {
        fail(at, "missing URL");
    }
    if (url.front() != '#') {
        fail(at, "external reference " + quoted_token(url) + " is not supported");
    }
    const pugi::xml_node target = find_id(url.substr(1));
    if (!target) {
        fail(at, "unknown URL " + quoted_token(url) + " (no element has that id)");
    }
    return target;
}

std::size_t Document::line_of(std::ptrdiff_t offset) const {
    const auto end = static_cast<std::size_t>(
        std::clamp<std::ptrdiff_t>(offset, 0, static_cast<std::ptrdiff_t>(text_.size())));
    return 1 + static_cast<std::size_t>(std::count(text_.begin(), text_.begin() + end, '\n'));
}

std::string Document::where(pugi::xml_node node) const {
    // The path runs up to the nearest element a reader can find by id, e.g.
    // <geometry id="box">/<mesh>/<triangles>/<p>.
    std::vector<pugi::xml_node> chain;
    for (pugi::xml_node n = node; n && n.type() == pugi::node_element; n = n.parent()) {
        chain.push_back(n);
        const std::string_view name = n.name();
        const pugi::xml_node parent = n.parent();
        if (name == "geometry" || name == "node" || name == "visual_scene" ||
            name == "controller" || !parent || parent == root() ||
            parent.type() != pugi::node_element) {
            break;
        }
    }
    std::string path;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        if (!path.empty()) {
            path += '/';
        }
        path += element_label(*it);
    }
    const std::ptrdiff_t offset = node.offset_debug();
    if (offset < 0) {
        return path;
    }
    return "line " + std::to_string(line_of(offset)) + ", " + path;
}

void Document::fail(pugi::xml_node node, const std::string& problem) const {
    throw IoError(file_, where(node), problem);
}

std::vector<double> parse_doubles(const Document& doc, pugi::xml_node node) {
    const char* text = node.child_value();
    std::vector<double> values;
    values.reserve(std::strlen(text) / 8 + 1);
    for_each_token(text, [&](std::string_view token, std::size_t index) {
        std::string_view digits = token;
        // from_chars rejects the leading '+' that xs:double allows.
        if (digits.size() > 1 && digits.front() == '+') {
            digits.remove_prefix(1);
        }
        double value = 0.0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (ec == std::errc::result_out_of_range) {
            doc.fail(node, "number " + std::to_string(index) + " " + quoted_token(token) +
                               " is out of range");
        }
        if (ec != std::errc() || end != digits.data() + digits.size()) {
            doc.fail(node, "number " + std::to_string(index) + " " + quoted_token(token) +
                               " is not a number");
        }
        values.push_back(value);
    });
    return values;
}

std::vector<std::uint32_t> parse_indices(const Document& doc, pugi::xml_node node) {
    const char* text = node.child_value();
    std::vector<std::uint32_t> values;
    values.reserve(std::strlen(text) / 4 + 1);
    for_each_token(text, [&](std::string_view token, std::size_t index) {
        std::uint64_t value = 0;
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (ec != std::errc() || end != token.data() + token.size() || value > 0xFFFFFFFEull) {
            doc.fail(node, "value " + std::to_string(index) + " " + quoted_token(token) +
                               " is not an index (a non-negative integer below 2^32 - 1)");
        }
        values.push_back(static_cast<std::uint32_t>(value));
    });
    return values;
}

std::uint64_t count_attribute(const Document& doc, pugi::xml_node node, const char* name,
                              std::uint64_t fallback) {
    const pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) {
        return fallback;
    }
    std::string_view text = attribute.value();
    while (!text.empty() && is_space(text.front())) {
        text.remove_prefix(1);
    }
    while (!text.empty() && is_space(text.back())) {
        text.remove_suffix(1);
    }
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
        doc.fail(node, std::string(name) + "=" + quoted_token(attribute.value()) +
                           " is not a non-negative integer");
    }
    return value;
}

}  // namespace meshedit::collada
