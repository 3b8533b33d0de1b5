// COLLADA reader, part 1: file loading, text decoding, XML parsing, element paths for error
// messages, and number lists.

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <system_error>
#include <thread>

#include "collada_detail.h"
#include "meshedit/core/memory.h"
#include "meshedit/core/threads.h"
#include "meshedit/files/files.h"

namespace meshedit::collada {
namespace {

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

// XML whitespace as one compare and one bit test (number lists are scanned byte by byte).
bool is_space(char c) {
    constexpr std::uint64_t kSpaces =
        (1ull << ' ') | (1ull << '\t') | (1ull << '\n') | (1ull << '\r');
    const auto u = static_cast<unsigned char>(c);
    return u <= ' ' && ((kSpaces >> u) & 1u) != 0;
}

bool is_control(unsigned char u) {
    return u < 0x20 && u != ' ' && u != '\t' && u != '\n' && u != '\r';
}

// The offset of the first control character other than whitespace, or npos. Blocks without
// an early exit let the compiler vectorise the test; only a bad block is searched bytewise.
std::size_t first_control_byte(std::string_view text) {
    constexpr std::size_t kBlock = 64;
    std::size_t i = 0;
    for (; i + kBlock <= text.size(); i += kBlock) {
        unsigned char any = 0;  // bitwise, not ||, so that the loop vectorises
        for (std::size_t k = 0; k < kBlock; ++k) {
            const auto u = static_cast<unsigned char>(text[i + k]);
            any |= static_cast<unsigned char>((u < 0x20) & (u != '\t') & (u != '\n') & (u != '\r'));
        }
        if (any != 0) {
            break;
        }
    }
    for (; i < text.size(); ++i) {
        if (is_control(static_cast<unsigned char>(text[i]))) {
            return i;
        }
    }
    return std::string_view::npos;
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

enum class TokenError : std::uint8_t { none, bad, out_of_range };

// A stretch of a number list that one thread parses, stopping at its first bad token.
template <class T>
struct Piece {
    const char* begin = nullptr;
    const char* end = nullptr;
    std::vector<T> values;
    TokenError error = TokenError::none;
    std::string_view token;  // the bad token
};

// `scan(p, end, value)` parses the token starting at p (not whitespace) and moves p past
// what it read, which is the whole token unless it reports an error.
template <class T, class Scan>
void parse_piece(Piece<T>& piece, const Scan& scan) {
    const char* p = piece.begin;
    const char* const end = piece.end;
    for (;;) {
        while (p != end && is_space(*p)) {
            ++p;
        }
        if (p == end) {
            return;
        }
        const char* token = p;
        T value{};
        const TokenError error = scan(p, end, value);
        if (error != TokenError::none) {
            while (p != end && !is_space(*p)) {
                ++p;
            }
            piece.error = error;
            piece.token = std::string_view(token, static_cast<std::size_t>(p - token));
            return;
        }
        piece.values.push_back(value);
    }
}

// Big arrays (a million-triangle mesh has tens of MB of numbers) are cut at whitespace into
// one piece per thread (thread_count(), threads.h; at most 8) and parsed in parallel; the
// pieces are joined in order, so the values and the first bad token reported do not depend on
// the number of threads.
constexpr std::size_t kParallelBytes = std::size_t{1} << 20;

// `problem(index, token, error)` words the error for the first bad token.
template <class T, class Scan, class Problem>
std::vector<T> parse_list(const Document& doc, pugi::xml_node node, std::size_t bytes_per_value,
                          const Scan& scan, const Problem& problem) {
    const char* text = node.child_value();
    const std::size_t n = std::strlen(text);
    const std::size_t n_pieces =
        n < kParallelBytes ? 1 : std::min<std::size_t>(meshedit::thread_count(), 8);
    std::vector<Piece<T>> pieces(n_pieces);
    const char* cut = text;
    for (std::size_t k = 0; k < n_pieces; ++k) {
        pieces[k].begin = cut;
        cut = k + 1 == n_pieces ? text + n : std::max(cut, text + n * (k + 1) / n_pieces);
        while (*cut != '\0' && !is_space(*cut)) {
            ++cut;
        }
        pieces[k].end = cut;
        // The first piece reserves for all, so that the others append without reallocating.
        const std::size_t span = k == 0 ? n : static_cast<std::size_t>(cut - pieces[k].begin);
        pieces[k].values.reserve(span / bytes_per_value + 1);
        memory::advise_huge_pages(pieces[k].values.data(), pieces[k].values.capacity() * sizeof(T));
    }
    std::vector<std::exception_ptr> errors(n_pieces);  // bad_alloc must not end a thread
    const auto run = [&](std::size_t k) {
        try {
            parse_piece(pieces[k], scan);
        } catch (...) {
            errors[k] = std::current_exception();
        }
    };
    {
        std::vector<std::jthread> workers;
        workers.reserve(n_pieces);
        for (std::size_t k = 1; k < n_pieces; ++k) {
            try {
                workers.emplace_back(run, k);
            } catch (const std::system_error&) {
                run(k);  // no thread to be had: parse it here
            }
        }
        run(0);
    }  // the workers join here
    for (const std::exception_ptr& error : errors) {
        if (error) {
            std::rethrow_exception(error);
        }
    }
    std::vector<T> values = std::move(pieces[0].values);
    for (std::size_t k = 0; k < n_pieces; ++k) {
        if (k > 0) {
            values.insert(values.end(), pieces[k].values.begin(), pieces[k].values.end());
        }
        if (pieces[k].error != TokenError::none) {
            doc.fail(node, problem(values.size(), pieces[k].token, pieces[k].error));
        }
    }
    return values;
}

// Exact fast path for plain decimals such as "-1.3999684": with at most 15 digits and at
// most 22 after the point, the digits and the power of ten are exact doubles, so one
// division rounds correctly and gives the same bits as from_chars. Returns false, with p
// unchanged, for anything else.
bool scan_plain_decimal(const char*& p, const char* end, double& out) {
    static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const char* q = p;
    const bool negative = q != end && *q == '-';
    q += negative ? 1 : 0;
    std::uint64_t mantissa = 0;
    const char* digits = q;
    for (; q != end && static_cast<unsigned>(*q - '0') <= 9; ++q) {
        mantissa = 10 * mantissa + static_cast<unsigned>(*q - '0');
    }
    const auto n_int = q - digits;
    std::ptrdiff_t n_frac = 0;
    if (q != end && *q == '.') {
        const char* frac = ++q;
        for (; q != end && static_cast<unsigned>(*q - '0') <= 9; ++q) {
            mantissa = 10 * mantissa + static_cast<unsigned>(*q - '0');
        }
        n_frac = q - frac;
        if (n_frac == 0) {
            return false;
        }
    }
    // mantissa may have wrapped for long digit runs; those fail the digit count anyway.
    if (n_int == 0 || n_int + n_frac > 15 || (q != end && !is_space(*q))) {
        return false;
    }
    const double value = static_cast<double>(mantissa) / kPow10[n_frac];
    out = negative ? -value : value;
    p = q;
    return true;
}

TokenError scan_double(const char*& p, const char* end, double& value) {
    if (scan_plain_decimal(p, end, value)) {
        return TokenError::none;
    }
    const char* begin = p;
    while (p != end && !is_space(*p)) {
        ++p;
    }
    // from_chars rejects the leading '+' that xs:double allows.
    if (p - begin > 1 && *begin == '+') {
        ++begin;
    }
    const auto [stop, ec] = std::from_chars(begin, p, value);
    if (ec == std::errc::result_out_of_range) {
        return TokenError::out_of_range;
    }
    return ec != std::errc() || stop != p ? TokenError::bad : TokenError::none;
}

TokenError scan_index(const char*& p, const char* end, std::uint32_t& value) {
    constexpr std::uint64_t kMax = 0xFFFFFFFEull;
    std::uint64_t v = 0;
    const char* begin = p;
    for (; p != end && static_cast<unsigned>(*p - '0') <= 9; ++p) {
        if (v <= kMax) {  // beyond it the value is too large anyway; do not overflow
            v = 10 * v + static_cast<unsigned>(*p - '0');
        }
    }
    if (p == begin || v > kMax || (p != end && !is_space(*p))) {
        return TokenError::bad;
    }
    value = static_cast<std::uint32_t>(v);
    return TokenError::none;
}

}  // namespace

Document::Document(std::string bytes, const std::string& name) : file_(name) {
    text_ = decode(file_, std::move(bytes));
    if (std::all_of(text_.begin(), text_.end(), is_space)) {
        throw IoError(file_, "", "empty file");
    }
    // XML text never holds control characters; finding one means a binary file.
    const std::size_t offset = first_control_byte(text_);
    if (offset != std::string::npos) {
        char byte[8];
        std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned char>(text_[offset]));
        throw IoError(file_, "line " + std::to_string(line_of(static_cast<std::ptrdiff_t>(offset))),
                      std::string("binary data (byte ") + byte + " at offset " +
                          std::to_string(offset) + "), not a COLLADA text file");
    }

    // Where the text ends, before an in-place parse may overwrite the last bytes.
    std::size_t end = text_.size();
    while (end > 0 && is_space(text_[end - 1])) {
        --end;
    }
    // pugixml parses in place rather than from a second copy of a file that is mostly number
    // text; it overwrites some bytes (newlines among them), so the line numbers of error
    // messages come from newline offsets recorded first. A file with very many lines would
    // make that table bigger than the copy it saves: it is parsed from a copy instead.
    constexpr std::size_t kMinBytesPerLine = 8;
    in_place_ = true;
    for (std::size_t i = text_.find('\n'); i != std::string::npos; i = text_.find('\n', i + 1)) {
        if (newlines_.size() >= text_.size() / kMinBytesPerLine) {
            in_place_ = false;
            newlines_ = {};
            break;
        }
        newlines_.push_back(i);
    }
    if (in_place_) {
        // load_buffer's copy ends in a NUL that pugixml parses as the last character; the
        // same NUL here keeps the errors at the end of a truncated file the same.
        text_.push_back('\0');
    }
    const pugi::xml_parse_result result =
        in_place_ ? doc_.load_buffer_inplace(text_.data(), text_.size(), pugi::parse_default,
                                             pugi::encoding_utf8)
                  : doc_.load_buffer(text_.data(), text_.size(), pugi::parse_default,
                                     pugi::encoding_utf8);
    if (!result) {
        const std::string line = "line " + std::to_string(line_of(result.offset));
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
    if (in_place_) {
        return 1 +
               static_cast<std::size_t>(std::lower_bound(newlines_.begin(), newlines_.end(), end) -
                                        newlines_.begin());
    }
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

// A number written with a decimal comma ("-7,589569", as some exporters write them in their
// locale): the comma read as a point; a token with both, or two commas, is not a number.
TokenError scan_comma_double(const char*& p, const char* end, double& value) {
    const char* begin = p;
    const char* stop = begin;
    while (stop != end && !is_space(*stop)) {
        ++stop;
    }
    char token[64];
    const std::size_t n = static_cast<std::size_t>(stop - begin);
    if (n >= sizeof token || std::count(begin, stop, ',') > 1 ||
        (std::find(begin, stop, ',') != stop && std::find(begin, stop, '.') != stop)) {
        return scan_double(p, end, value);  // as it is: its own error names it
    }
    std::replace_copy(begin, stop, token, ',', '.');
    const char* q = token;
    const TokenError error = scan_double(q, token + n, value);
    p = stop;
    return error;
}

std::vector<double> parse_doubles(const Document& doc, pugi::xml_node node) {
    const auto problem = [](std::size_t index, std::string_view token, TokenError error) {
        return "number " + std::to_string(index) + " " + quoted_token(token) +
               (error == TokenError::out_of_range ? " is out of range" : " is not a number");
    };
    try {
        return parse_list<double>(
            doc, node, 8,
            [](const char*& p, const char* end, double& v) { return scan_double(p, end, v); },
            problem);
    } catch (const IoError&) {
        // A comma in a list of numbers is never a separator in COLLADA (whitespace is): read
        // again with decimal commas (a clean list never pays for this).
        if (std::strchr(node.child_value(), ',') == nullptr) {
            throw;
        }
    }
    std::vector<double> values = parse_list<double>(
        doc, node, 8,
        [](const char*& p, const char* end, double& v) { return scan_comma_double(p, end, v); },
        problem);
    doc.note_decimal_commas();
    return values;
}

std::vector<std::uint32_t> parse_indices(const Document& doc, pugi::xml_node node) {
    return parse_list<std::uint32_t>(
        doc, node, 4,
        [](const char*& p, const char* end, std::uint32_t& v) { return scan_index(p, end, v); },
        [](std::size_t index, std::string_view token, TokenError) {
            return "value " + std::to_string(index) + " " + quoted_token(token) +
                   " is not an index (a non-negative integer below 2^32 - 1)";
        });
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
