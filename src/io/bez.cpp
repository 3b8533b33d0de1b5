// .bez (Bezier patches) and .bzc (Bezier curve) files, docs/spec.md §2: readers that accept
// more than the course's files use (comments, free layout), writers that emit exactly that.
//
// Both are free-form streams of numbers: any whitespace separates them, line breaks carry no
// meaning, and `#` starts a comment that runs to the end of the line. A .bez file is a patch
// count P followed by P × 48 numbers (16 control points x y z per patch, row-major
// cp[row][col]); a .bzc file is a point count N ≥ 2 followed by N pairs x y. Because layout
// is free, a patch with a missing number is only noticed where the file ends, so errors name
// the patch whose numbers ran out.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "io_util.h"
#include "meshedit/io/io.h"

namespace meshedit {
namespace {

constexpr int kPatchNumbers = 48;
/// Counts above this are rejected before any parsing: no real file comes near it, and a
/// corrupt count must not turn into a huge allocation or a long loop.
constexpr std::uint64_t kMaxCount = 100'000'000;

/// The token as it should appear in a message: at most 24 characters, control and non-ASCII
/// bytes escaped (binary garbage must not garble a terminal).
std::string quoted(std::string_view token) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out = "'";
    for (std::size_t i = 0; i < token.size() && i < 24; ++i) {
        const auto c = static_cast<unsigned char>(token[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    if (token.size() > 24) {
        out += "...";
    }
    return out + "'";
}

/// Splits the text into whitespace-separated tokens, skipping `#` comments and counting
/// lines for messages.
class Scanner {
public:
    explicit Scanner(std::string_view text) : text_(text) {}

    /// The next token, or false at the end of the text.
    bool next(std::string_view& token) {
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (c == '\n') {
                ++line_;
                ++pos_;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f') {
                ++pos_;
            } else if (c == '#') {
                while (pos_ < text_.size() && text_[pos_] != '\n') {
                    ++pos_;
                }
            } else {
                break;
            }
        }
        if (pos_ >= text_.size()) {
            return false;
        }
        const std::size_t start = pos_;
        while (pos_ < text_.size() && !is_separator(text_[pos_])) {
            ++pos_;
        }
        token = text_.substr(start, pos_ - start);
        token_line_ = line_;
        return true;
    }

    /// The place of the token just read, for messages about it.
    std::string where() const { return "line " + std::to_string(token_line_); }
    /// The place where the data ran out: the line of the last token (trailing comments and
    /// blank lines do not count), or nothing for a file without any.
    std::string end_where() const {
        return token_line_ > 0 ? "line " + std::to_string(token_line_) : std::string();
    }
    std::size_t remaining() const { return text_.size() - pos_; }

private:
    static bool is_separator(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f' ||
               c == '#';
    }

    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int token_line_ = 0;
};

/// Parses `token` as a finite double. \throws IoError naming the file, the line and the token.
double parse_number(std::string_view token, const std::string& file, const Scanner& scanner) {
    std::string_view digits = token;
    // from_chars does not take the leading '+' people write ("+0.5").
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') {
        digits.remove_prefix(1);
    }
    double value = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) {
        throw IoError(file, scanner.where(), "number " + quoted(token) + " is out of range");
    }
    if (ec != std::errc() || end != digits.data() + digits.size()) {
        throw IoError(file, scanner.where(), "expected a number, found " + quoted(token));
    }
    if (!std::isfinite(value)) {
        throw IoError(file, scanner.where(),
                      "expected a finite number, found " + quoted(token) + " (NaN or infinity)");
    }
    return value;
}

/// Parses the leading count of a file. `what` is "patches" or "points".
std::uint64_t parse_count(std::string_view token, const char* what, const std::string& file,
                          const Scanner& scanner) {
    std::uint64_t count = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), count);
    if (ec == std::errc() && end == token.data() + token.size()) {
        if (count > kMaxCount) {
            throw IoError(file, scanner.where(),
                          "the number of " + std::string(what) + ", " + std::string(token) +
                              ", is absurd (at most " + std::to_string(kMaxCount) + ")");
        }
        return count;
    }
    if (ec == std::errc::result_out_of_range) {
        throw IoError(file, scanner.where(),
                      "the number of " + std::string(what) + ", " + quoted(token) +
                          ", is absurd (at most " + std::to_string(kMaxCount) + ")");
    }
    if (!token.empty() && token[0] == '-') {
        throw IoError(
            file, scanner.where(),
            "the number of " + std::string(what) + " must not be negative, found " + quoted(token));
    }
    throw IoError(file, scanner.where(),
                  "expected the number of " + std::string(what) + " (a whole number), found " +
                      quoted(token));
}

std::string plural(std::uint64_t n, const char* singular, const char* plural_form) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural_form);
}

}  // namespace

std::vector<BezierPatch> read_bez(const std::filesystem::path& path) {
    return parse_bez(read_file(path), path.string());
}

std::vector<BezierPatch> parse_bez(std::string_view bytes, const std::string& file) {
    Scanner scanner(io_util::text_of(bytes, file));
    std::string_view token;
    if (!scanner.next(token)) {
        throw IoError(file, scanner.end_where(),
                      "no data; expected the number of patches, then 48 numbers per patch");
    }
    const std::uint64_t n_patches = parse_count(token, "patches", file, scanner);
    if (n_patches == 0) {
        throw IoError(file, scanner.where(), "the file declares 0 patches");
    }

    std::vector<BezierPatch> patches;
    // Trust the count only as far as the text can back it: a number takes at least two
    // bytes (a digit and a separator), so a patch takes at least 96.
    patches.reserve(std::min<std::uint64_t>(n_patches, scanner.remaining() / 96 + 1));
    for (std::uint64_t p = 0; p < n_patches; ++p) {
        BezierPatch patch;  // 4 × 4, the only size .bez stores
        patch.control_points.resize(16);
        for (int k = 0; k < kPatchNumbers; ++k) {
            if (!scanner.next(token)) {
                std::string problem = "patch " + std::to_string(p + 1) + " has " +
                                      plural(static_cast<std::uint64_t>(k), "number", "numbers") +
                                      ", expected 48";
                if (n_patches > 1) {
                    problem += " (the file declares " + plural(n_patches, "patch", "patches") +
                               " and ends here)";
                }
                throw IoError(file, scanner.end_where(), problem);
            }
            patch.control_points[static_cast<std::size_t>(k / 3)][k % 3] =
                parse_number(token, file, scanner);
        }
        patches.push_back(std::move(patch));
    }
    if (scanner.next(token)) {
        throw IoError(file, scanner.where(),
                      "unexpected " + quoted(token) + " after the last of the " +
                          plural(n_patches, "patch", "patches") + " the file declares");
    }
    return patches;
}

BezierCurve read_bzc(const std::filesystem::path& path) {
    return parse_bzc(read_file(path), path.string());
}

BezierCurve parse_bzc(std::string_view bytes, const std::string& file) {
    Scanner scanner(io_util::text_of(bytes, file));
    std::string_view token;
    if (!scanner.next(token)) {
        throw IoError(file, scanner.end_where(),
                      "no data; expected the number of points, then x y per point");
    }
    const std::uint64_t n_points = parse_count(token, "points", file, scanner);
    if (n_points < 2) {
        throw IoError(file, scanner.where(),
                      "a curve needs at least 2 points, the file has " + std::to_string(n_points));
    }

    BezierCurve curve;
    curve.control_points.reserve(std::min<std::uint64_t>(n_points, scanner.remaining() / 4 + 1));
    for (std::uint64_t i = 0; i < n_points; ++i) {
        double xy[2];
        for (int k = 0; k < 2; ++k) {
            if (!scanner.next(token)) {
                throw IoError(file, scanner.end_where(),
                              "point " + std::to_string(i + 1) + " has " +
                                  plural(static_cast<std::uint64_t>(k), "number", "numbers") +
                                  ", expected 2 (the file declares " +
                                  plural(n_points, "point", "points") + " and ends here)");
            }
            xy[k] = parse_number(token, file, scanner);
        }
        curve.control_points.emplace_back(xy[0], xy[1], 0.0);
    }
    if (scanner.next(token)) {
        throw IoError(file, scanner.where(),
                      "unexpected " + quoted(token) + " after the last of the " +
                          plural(n_points, "point", "points") + " the file declares");
    }
    return curve;
}

// Both writers follow the CS184 course's grammar, which its skeleton reads with fscanf: the
// count ("%d"), then the numbers ("%lf"); no comments, which fscanf cannot skip. Numbers in
// the shortest form that reads back as the same double.
namespace {

std::string coordinates(const std::string& file, const std::string& what, const Vec3& p, int n) {
    std::string line;
    for (int k = 0; k < n; ++k) {
        if (!std::isfinite(p[k])) {
            throw IoError(file, "", what + " is not finite");
        }
        if (k > 0) {
            line += ' ';
        }
        line += number_text(p[k]);
    }
    return line + "\n";
}

}  // namespace

void write_bzc(const BezierCurve& curve, const std::filesystem::path& path) {
    const std::string file = path.string();
    const std::size_t n = curve.control_points.size();
    if (n < 2) {
        throw IoError(file, "",
                      "a curve needs at least 2 points, this one has " + std::to_string(n));
    }
    std::string text = std::to_string(n) + "\n";
    for (std::size_t i = 0; i < n; ++i) {
        // z is not stored: curves live in the z = 0 plane.
        text += coordinates(file, "point " + std::to_string(i + 1), curve.control_points[i], 2);
    }
    write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp, text); });
}

void write_bez(const std::vector<BezierPatch>& patches, const std::filesystem::path& path) {
    const std::string file = path.string();
    if (patches.empty()) {
        throw IoError(file, "", "no patches to write");
    }
    std::string text = std::to_string(patches.size()) + "\n";
    for (std::size_t p = 0; p < patches.size(); ++p) {
        const BezierPatch& patch = patches[p];
        const std::string name = "patch " + std::to_string(p + 1);
        if (patch.rows != 4 || patch.cols != 4 || patch.control_points.size() != 16) {
            throw IoError(file, "",
                          name + " is " + std::to_string(patch.rows) + " × " +
                              std::to_string(patch.cols) + "; a .bez file holds 4 × 4 patches");
        }
        for (std::size_t k = 0; k < 16; ++k) {  // row-major cp[row][col], one point a line
            text += coordinates(file, name + ", point " + std::to_string(k + 1),
                                patch.control_points[k], 3);
        }
    }
    write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp, text); });
}

}  // namespace meshedit
