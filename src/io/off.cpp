// Object File Format: a reader of our own and the writer.
//
// Read: an optional header keyword OFF, with Geomview's prefixes for what each vertex line
// also carries (ST texture coordinates, C colour, N normal: STCNOFF, COFF, NOFF …; the header
// may share its line with the counts), then `nv nf ne`, nv vertex lines `x y z [nx ny nz] …`
// and nf face lines `n i0 … i(n−1) [colour]`. '#' starts a comment anywhere. Kept: positions,
// NOFF normals, COFF vertex colours and STOFF texture coordinates (off_attributes.cpp), face
// colours, polygons. Binary OFF and the 4D/nD variants are refused by name.
//
// Counts come from the file, so they may lie: nothing is reserved beyond what the file's bytes
// can hold, and a file that ends early says after how many vertices or faces.

#include "meshedit/io/off.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "io_util.h"
#include "meshedit/core/mesh.h"
#include "off_attributes.h"

namespace meshedit {
namespace {

class OffReader {
public:
    OffReader(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

    MeshSoup read() {
        std::string_view l = next_line();
        if (l.empty()) {
            fail("empty file: no OFF header");
        }
        if (read_header(l)) {
            std::string_view probe = l;
            if (io_util::next_token(probe).empty()) {
                l = next_line();  // the counts on a line of their own
            }
        }
        if (l.empty()) {
            fail("the file ends after its header, before the vertex and face counts");
        }
        nv_ = count(io_util::next_token(l), "vertex");
        nf_ = count(io_util::next_token(l), "face");
        // The edge count may follow; nothing needs it.
        // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 8: never reserve for
        // more lines than the file can hold, whatever the counts say.
        out_.soup.positions.reserve(std::min(nv_, text_.size() / 6));
        out_.soup.face_offsets.reserve(std::min(nf_, text_.size() / 8) + 1);
        for (std::size_t v = 0; v < nv_; ++v) {
            read_vertex(v);
        }
        for (std::size_t f = 0; f < nf_; ++f) {
            read_face(f);
        }
        for (std::string_view rest = next_line(); !rest.empty(); rest = next_line()) {
            ++extra_lines_;
        }
        colours_.finish(out_);
        if (extra_lines_ > 0) {
            out_.notices.push_back("ignored " + std::to_string(extra_lines_) +
                                   " line(s) after the last of the " + std::to_string(nf_) +
                                   " faces the header announced");
        }
        return std::move(out_);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const {
        throw IoError(file_, line_ == 0 ? "" : "line " + std::to_string(line_), problem);
    }

    // The next line with content, comments removed; empty at the end of the file.
    std::string_view next_line() {
        while (pos_ < text_.size()) {
            std::size_t end = text_.find('\n', pos_);
            if (end == std::string_view::npos) {
                end = text_.size();
            }
            std::string_view l = text_.substr(pos_, end - pos_);
            pos_ = end + 1;
            ++line_;
            if (l.find('\0') != std::string_view::npos) {
                fail("binary data (a NUL byte): not an ASCII OFF file");
            }
            l = l.substr(0, l.find('#'));
            std::string_view probe = l;
            if (!io_util::next_token(probe).empty()) {
                return l;
            }
        }
        return {};
    }

    // Reads the keyword off `l` if it starts with one (true); a file may also start with its
    // counts (false).
    bool read_header(std::string_view& l) {
        std::string_view rest = l;
        const std::string_view key = io_util::next_token(rest);
        if (whole(key)) {
            return false;
        }
        if (key.size() < 3 || key.substr(key.size() - 3) != "OFF") {
            fail("not an OFF file: it should start with the keyword OFF, found '" +
                 std::string(key.substr(0, 24)) + "'");
        }
        // Geomview's prefixes, in their order: ST (texture coordinates), C (colour),
        // N (normal), 4 or n (more than three dimensions).
        std::string_view prefix = key.substr(0, key.size() - 3);
        for (const std::string_view p : {"ST", "C", "N"}) {
            if (prefix.substr(0, p.size()) == p) {
                normals_ = normals_ || p == "N";
                extras_ = extras_ || p != "N";
                colours_.vertex_colours = colours_.vertex_colours || p == "C";
                colours_.texcoords = colours_.texcoords || p == "ST";
                prefix.remove_prefix(p.size());
            }
        }
        if (!prefix.empty() && (prefix[0] == '4' || prefix[0] == 'n')) {
            fail("'" + std::string(key) + "' holds points of " + (prefix[0] == '4' ? "four" : "n") +
                 " dimensions; MeshEdit reads 3D OFF");
        }
        if (!prefix.empty()) {
            fail("unknown OFF keyword '" + std::string(key.substr(0, 24)) + "'");
        }
        std::string_view after = rest;
        if (io_util::next_token(after) == "BINARY") {
            fail("binary OFF is not read; save the file as ASCII OFF");
        }
        l = rest;
        return true;
    }

    // A count or index: a whole number below kInvalidIndex, else nullopt.
    static std::optional<std::size_t> whole(std::string_view t) {
        std::uint64_t x = 0;
        const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
        if (t.empty() || ec != std::errc() || ptr != t.data() + t.size() || x >= kInvalidIndex) {
            return std::nullopt;
        }
        return static_cast<std::size_t>(x);
    }

    std::size_t count(std::string_view t, const char* what) const {
        if (t.empty()) {
            fail(std::string("the header ends before the ") + what + " count");
        }
        const std::optional<std::size_t> x = whole(t);
        if (!x) {
            fail(std::string("the ") + what +
                 " count should be a whole number below 4,294,967,295, found '" +
                 std::string(t.substr(0, 24)) + "'");
        }
        return *x;
    }

    double number(std::string_view t, const std::string& what) const {
        if (t.empty()) {
            fail(what + ": the line ends too early");
        }
        const std::optional<double> x = io_util::parse_double(t);
        if (!x) {
            fail(what + ": expected a number, found '" + std::string(t.substr(0, 24)) + "'");
        }
        return *x;
    }

    // The line of record `i` of the `total` the header announced; the end of the file there
    // is an error that says how far it got.
    std::string_view record_line(std::size_t i, std::size_t total, const char* kinds) {
        const std::string_view l = next_line();
        if (l.empty()) {
            fail("the file ends after " + std::to_string(i) + " of the " + std::to_string(total) +
                 " " + kinds + " the header announced");
        }
        return l;
    }

    // Whether `l` reads as a face line ("3 0 1 2": a corner count k of at least 3, then k
    // whole numbers), where a vertex line of a file without colours or texture coordinates
    // was due: the header announced more vertices than the file has, and taking a face as a
    // vertex would silently lose it.
    static bool reads_as_face(std::string_view l, std::size_t vertex_numbers) {
        const std::optional<std::size_t> k = whole(io_util::next_token(l));
        if (!k || *k < 3 || *k + 1 <= vertex_numbers) {
            return false;
        }
        for (std::size_t i = 0; i < *k; ++i) {
            if (!whole(io_util::next_token(l))) {
                return false;
            }
        }
        return true;
    }

    void read_vertex(std::size_t v) {
        std::string_view l = record_line(v, nv_, "vertices");
        if (!extras_ && reads_as_face(l, normals_ ? 6 : 3)) {
            fail("vertex " + std::to_string(v) + " reads as a face line ('" +
                 std::string(io_util::next_token(l)) + " …'): the header announces " +
                 std::to_string(nv_) + " vertices, more than the file has");
        }
        const std::string what = "vertex " + std::to_string(v);
        Vec3 p;
        for (int i = 0; i < 3; ++i) {
            p[i] = number(io_util::next_token(l), what);
        }
        if (!is_finite(p)) {
            fail(what + " is not finite (NaN or infinity)");
        }
        out_.soup.positions.push_back(p);
        if (normals_) {
            Vec3 n;
            for (int i = 0; i < 3; ++i) {
                n[i] = number(io_util::next_token(l), what + "'s normal");
            }
            out_.normals.push_back(is_finite(n) ? n : Vec3());
        }
        // Colour and texture coordinates (C, ST) follow, in that order.
        colours_.read_vertex(l, v, line_);
    }

    void read_face(std::size_t f) {
        std::string_view l = record_line(f, nf_, "faces");
        const std::string what = "face " + std::to_string(f);
        const std::string_view n_text = io_util::next_token(l);
        const std::optional<std::size_t> corners = whole(n_text);
        if (!corners) {
            fail(what + " should start with its number of corners, found '" +
                 std::string(n_text.substr(0, 24)) + "'");
        }
        for (std::size_t c = 0; c < *corners; ++c) {
            const std::string_view t = io_util::next_token(l);
            if (t.empty()) {
                fail(what + " has " + std::to_string(*corners) + " corners but its line lists " +
                     std::to_string(c) + " vertex indices");
            }
            const std::optional<std::size_t> i = whole(t);
            if (!i && !t.empty() && t[0] != '-' &&
                std::isdigit(static_cast<unsigned char>(t[0])) == 0) {
                fail(what + ": bad vertex index '" + std::string(t.substr(0, 24)) + "'");
            }
            if (!i || *i >= nv_) {
                fail(what + " refers to vertex " + std::string(t.substr(0, 24)) +
                     ", but the file has " + std::to_string(nv_) + " vertices (0 to " +
                     std::to_string(nv_ == 0 ? 0 : nv_ - 1) + ")");
            }
            out_.soup.indices.push_back(static_cast<std::uint32_t>(*i));
        }
        colours_.read_face(l, f, line_);
        // Faces with fewer than three corners go on: build_mesh() drops and reports them.
        out_.soup.face_offsets.push_back(static_cast<std::uint32_t>(out_.soup.indices.size()));
    }

    std::string_view text_;
    std::string file_;
    std::size_t pos_ = 0;
    std::size_t line_ = 0;
    bool normals_ = false;
    bool extras_ = false;  // C or ST: colours or texture coordinates follow a vertex
    std::size_t nv_ = 0;
    std::size_t nf_ = 0;
    std::size_t extra_lines_ = 0;
    off_attributes::Reader colours_;
    MeshSoup out_;
};

}  // namespace

MeshSoup parse_off(std::string_view bytes, const std::string& name) {
    return OffReader(io_util::text_of(bytes, name), name).read();
}

MeshSoup read_off(const std::filesystem::path& path) {
    const std::string text = read_file(path);
    return parse_off(text, path.string());
}

void write_off(const Mesh& mesh, const std::filesystem::path& path) {
    std::optional<Mesh> storage;
    const Mesh& dense = io_util::compacted(mesh, storage);
    const PolygonSoup soup = to_polygon_soup(dense);
    const off_attributes::Columns extra(dense);
    std::string text = extra.keyword() + "\n" + std::to_string(soup.positions.size()) + ' ' +
                       std::to_string(soup.n_faces()) + ' ' + std::to_string(dense.n_edges()) +
                       '\n';
    text.reserve(soup.positions.size() * 70 + soup.indices.size() * 10);
    for (std::size_t v = 0; v < soup.positions.size(); ++v) {
        const Vec3& p = soup.positions[v];
        text += number_text(p.x) + ' ' + number_text(p.y) + ' ' + number_text(p.z);
        extra.put_vertex(text, v);
        text += '\n';
    }
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        text += std::to_string(soup.face_offsets[f + 1] - soup.face_offsets[f]);
        for (std::uint32_t c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
            text += ' ';
            text += std::to_string(soup.indices[c]);
        }
        extra.put_face(text, f);
        text += '\n';
    }
    write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp, text); });
}

}  // namespace meshedit
