// STL: a reader of our own and the writer.
//
// Read: binary when the size is exactly 84 + 50 · (the count at byte 80), whatever the header
// says (many binary exporters start it with "solid"); otherwise ASCII if the bytes are text,
// else a binary file whose count disagrees with its size, which is refused. Corners are welded
// by the bit pattern of their position (−0 taken as +0), so a file written by write_stl()
// reads back with the same vertices in the same order.

#include "meshedit/io/stl.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io_util.h"
#include "meshedit/core/hash.h"
#include "meshedit/core/mesh.h"

namespace meshedit {
namespace {

constexpr std::size_t kHeader = 84;
constexpr std::size_t kRecord = 50;

// Collects triangles, welding corners and checking stored normals against the winding. The
// weld is an open-addressing table of vertex numbers keyed by position (NaN is refused before
// and −0 made +0, so == on the coordinates is equality of their bits).
class Welder {
public:
    explicit Welder(std::size_t triangles) {
        out_.soup.indices.reserve(triangles * 3);
        out_.soup.face_offsets.reserve(triangles + 1);
        std::size_t capacity = 64;
        while (capacity < triangles) {  // half a vertex per triangle when closed; grow() if more
            capacity *= 2;
        }
        slots_.assign(capacity * 4, kEmpty);
    }

    void add(const Vec3& normal, const Vec3 (&corners)[3]) {
        for (const Vec3& c : corners) {
            const Vec3 p(c.x + 0.0, c.y + 0.0, c.z + 0.0);  // −0 → +0: one vertex
            out_.soup.indices.push_back(vertex_of(p));
        }
        out_.soup.face_offsets.push_back(static_cast<std::uint32_t>(out_.soup.indices.size()));
        const Vec3 winding = cross(corners[1] - corners[0], corners[2] - corners[0]);
        opposite_ += dot(winding, normal) < 0.0 ? 1 : 0;
    }

    MeshSoup finish() {
        const std::size_t faces = out_.soup.n_faces();
        const std::size_t welded = out_.soup.indices.size() - out_.soup.positions.size();
        if (welded > 0) {
            out_.notices.push_back("welded " + std::to_string(welded) +
                                   " vertices by exact position");
        }
        if (opposite_ > 0) {
            out_.notices.push_back(std::to_string(opposite_) + " of " + std::to_string(faces) +
                                   " facets have a stored normal opposite to their winding "
                                   "(the winding is kept)");
        }
        return std::move(out_);
    }

private:
    static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;

    std::uint32_t vertex_of(const Vec3& p) {
        std::vector<Vec3>& positions = out_.soup.positions;
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t i = position_hash(p) & mask;; i = (i + 1) & mask) {
            if (slots_[i] == kEmpty) {
                slots_[i] = static_cast<std::uint32_t>(positions.size());
                positions.push_back(p);
                if (positions.size() * 2 > slots_.size()) {
                    grow();
                }
                return static_cast<std::uint32_t>(positions.size() - 1);
            }
            if (positions[slots_[i]] == p) {
                return slots_[i];
            }
        }
    }

    void grow() {
        slots_.assign(slots_.size() * 2, kEmpty);
        const std::size_t mask = slots_.size() - 1;
        for (std::uint32_t v = 0; v < out_.soup.positions.size(); ++v) {
            std::size_t i = position_hash(out_.soup.positions[v]) & mask;
            while (slots_[i] != kEmpty) {
                i = (i + 1) & mask;
            }
            slots_[i] = v;
        }
    }

    std::vector<std::uint32_t> slots_;
    std::size_t opposite_ = 0;
    MeshSoup out_;
};

float float_at(const char* p) {
    std::uint32_t u;
    std::memcpy(&u, p, 4);
    if constexpr (std::endian::native == std::endian::big) {
        u = __builtin_bswap32(u);
    }
    return std::bit_cast<float>(u);
}

std::uint32_t uint_at(const char* p) {
    std::uint32_t u;
    std::memcpy(&u, p, 4);
    if constexpr (std::endian::native == std::endian::big) {
        u = __builtin_bswap32(u);
    }
    return u;
}

MeshSoup parse_binary(std::string_view bytes, const std::string& name) {
    const std::size_t n = uint_at(bytes.data() + 80);
    Welder welder(n);
    const char* p = bytes.data() + kHeader;
    for (std::size_t t = 0; t < n; ++t, p += kRecord) {
        const Vec3 normal(float_at(p), float_at(p + 4), float_at(p + 8));
        Vec3 corners[3];
        for (int c = 0; c < 3; ++c) {
            const char* q = p + 12 + 12 * c;
            corners[c] = Vec3(float_at(q), float_at(q + 4), float_at(q + 8));
            if (!is_finite(corners[c])) {
                throw IoError(name, "triangle " + std::to_string(t),
                              "corner " + std::to_string(c) + " is not finite (NaN or infinity)");
            }
        }
        welder.add(normal, corners);
    }
    return welder.finish();
}

class AsciiReader {
public:
    AsciiReader(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

    MeshSoup read() {
        // An ASCII triangle takes well over 100 bytes: reserve for no more than that.
        Welder welder(text_.size() / 100);
        std::size_t solids = 0;
        for (std::string_view l = next_line(); !l.empty(); l = next_line()) {
            std::string_view rest = l;
            if (io_util::next_token(rest) != "solid") {
                fail(solids == 0 ? "not an STL file: it should start with 'solid'"
                                 : "expected 'solid' or the end of the file, found '" +
                                       std::string(l.substr(0, 32)) + "'");
            }
            ++solids;
            const std::size_t solid_line = line_;
            for (;;) {
                std::string_view f = next_line();
                if (f.empty()) {
                    fail("the file ends inside the solid that starts on line " +
                         std::to_string(solid_line) + " (no 'endsolid')");
                }
                std::string_view words = f;
                const std::string_view key = io_util::next_token(words);
                if (key == "endsolid") {
                    break;
                }
                if (key != "facet" || io_util::next_token(words) != "normal") {
                    fail("expected 'facet normal' or 'endsolid', found '" +
                         std::string(f.substr(0, 32)) + "'");
                }
                const Vec3 normal = triple(words, "the facet normal");
                expect("outer", "loop");
                Vec3 corners[3];
                for (int c = 0; c < 3; ++c) {
                    std::string_view v = next_line();
                    if (v.empty()) {
                        fail("the file ends inside a facet");
                    }
                    if (io_util::next_token(v) != "vertex") {
                        fail("expected 'vertex' (a facet has three corners)");
                    }
                    corners[c] = triple(v, "a vertex");
                    // STL's coordinates are floats (binary stores nothing else): text is read
                    // as the floats it means, so ASCII and binary copies of a file agree.
                    for (int i = 0; i < 3; ++i) {
                        const float single = static_cast<float>(corners[c][i]);
                        rounded_ = rounded_ || static_cast<double>(single) != corners[c][i];
                        corners[c][i] = single;
                    }
                    if (!is_finite(corners[c])) {
                        fail("a vertex is not finite (NaN or infinity)");
                    }
                }
                expect("endloop", {});
                expect("endfacet", {});
                welder.add(normal, corners);
            }
        }
        if (solids == 0) {
            fail("empty file: no STL solid");
        }
        MeshSoup out = welder.finish();
        if (rounded_) {
            out.notices.push_back("coordinates rounded to 32-bit floats (STL stores floats)");
        }
        return out;
    }

private:
    [[noreturn]] void fail(const std::string& problem) const {
        throw IoError(file_, line_ == 0 ? "" : "line " + std::to_string(line_), problem);
    }

    std::string_view next_line() { return io_util::next_content_line(text_, pos_, line_); }

    void expect(std::string_view first, std::string_view second) {
        std::string_view l = next_line();
        const std::string want =
            std::string(first) + (second.empty() ? "" : " ") + std::string(second);
        if (l.empty()) {
            fail("the file ends inside a facet, before '" + want + "'");
        }
        std::string_view rest = l;
        if (io_util::next_token(rest) != first ||
            (!second.empty() && io_util::next_token(rest) != second)) {
            fail("expected '" + want + "', found '" + std::string(l.substr(0, 32)) + "'");
        }
    }

    Vec3 triple(std::string_view& l, const char* what) const {
        Vec3 v;
        for (int i = 0; i < 3; ++i) {
            const std::string_view t = io_util::next_token(l);
            const std::optional<double> x = io_util::parse_double(t);
            if (!x) {
                fail(std::string(what) + ": expected three numbers, found '" +
                     std::string(t.substr(0, 24)) + "'");
            }
            v[i] = *x;
        }
        return v;
    }

    std::string_view text_;
    std::string file_;
    std::size_t pos_ = 0;
    std::size_t line_ = 0;
    bool rounded_ = false;
};

// Text: no control bytes other than tab, newline, CR and FF in the first 4 KiB.
bool looks_like_text(std::string_view bytes) {
    const std::string_view head = bytes.substr(0, 4096);
    for (const char c : head) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 && u != '\t' && u != '\n' && u != '\r' && u != '\f') {
            return false;
        }
    }
    return true;
}

// ASCII STL starts with "solid" (after a UTF-8 byte-order mark, which some editors add).
bool starts_solid(std::string_view bytes) {
    if (bytes.substr(0, 3) == "\xEF\xBB\xBF") {
        bytes.remove_prefix(3);
    }
    return bytes.substr(0, 5) == "solid";
}

void put_float(std::string& out, float x) {
    std::uint32_t u = std::bit_cast<std::uint32_t>(x);
    if constexpr (std::endian::native == std::endian::big) {
        u = __builtin_bswap32(u);
    }
    out.append(reinterpret_cast<const char*>(&u), 4);
}

}  // namespace

MeshSoup parse_stl(std::string_view bytes, const std::string& name) {
    if (bytes.size() >= kHeader) {
        const std::uint64_t n = uint_at(bytes.data() + 80);
        if (kHeader + kRecord * n == bytes.size()) {
            return parse_binary(bytes, name);
        }
        if (!starts_solid(bytes) || !looks_like_text(bytes)) {
            throw IoError(name, "",
                          "binary STL whose header announces " + std::to_string(n) +
                              " triangles (84 + 50 × " + std::to_string(n) + " = " +
                              std::to_string(kHeader + kRecord * n) + " bytes), but the file is " +
                              std::to_string(bytes.size()) + " bytes");
        }
    } else if (!looks_like_text(bytes) || !starts_solid(bytes)) {
        throw IoError(name, "",
                      bytes.empty() ? "empty file: no STL data"
                                    : "too short for binary STL (" + std::to_string(bytes.size()) +
                                          " bytes; a binary STL has at least 84) and not "
                                          "ASCII STL");
    }
    return AsciiReader(io_util::text_of(bytes, name), name).read();
}

MeshSoup read_stl(const std::filesystem::path& path) {
    const std::string bytes = read_file(path);
    return parse_stl(bytes, path.string());
}

void write_stl(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags) {
    std::optional<Mesh> storage;
    const Mesh& dense = io_util::compacted(mesh, storage);
    const PolygonSoup soup = to_polygon_soup(dense);
    std::size_t triangles = 0;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        triangles += soup.face_offsets[f + 1] - soup.face_offsets[f] - 2;
    }
    if (triangles >= 0xFFFFFFFFu) {
        throw IoError(path.string(), "", "more triangles than binary STL can count");
    }
    std::string out;
    if (flags.ascii) {
        out = "solid meshedit\n";
        out.reserve(triangles * 260);
    } else {
        // Not "solid …": some readers take any file starting so for ASCII.
        std::string header = "MeshEdit binary STL";
        header.resize(80, ' ');
        out = header;
        out.reserve(kHeader + kRecord * triangles);
        const auto n = static_cast<std::uint32_t>(triangles);
        std::uint32_t le = n;
        if constexpr (std::endian::native == std::endian::big) {
            le = __builtin_bswap32(le);
        }
        out.append(reinterpret_cast<const char*>(&le), 4);
    }
    // ASCII is written as the exact decimal of each float, so both kinds read back the same.
    const auto text = [](float x) { return number_text(x); };
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const std::uint32_t first = soup.face_offsets[f];
        for (std::uint32_t c = first + 1; c + 1 < soup.face_offsets[f + 1]; ++c) {
            // Corners and normal in float, as the file stores them: a file read and written
            // again gives the same bytes.
            float corners[3][3];
            const std::uint32_t at[3] = {soup.indices[first], soup.indices[c], soup.indices[c + 1]};
            for (int k = 0; k < 3; ++k) {
                for (int i = 0; i < 3; ++i) {
                    corners[k][i] = static_cast<float>(soup.positions[at[k]][i]);
                }
            }
            float e1[3], e2[3];
            for (int i = 0; i < 3; ++i) {
                e1[i] = corners[1][i] - corners[0][i];
                e2[i] = corners[2][i] - corners[0][i];
            }
            float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                          e1[0] * e2[1] - e1[1] * e2[0]};
            const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (float& x : n) {
                x = len > 0.0f ? x / len : 0.0f;
            }
            if (flags.ascii) {
                out += "facet normal " + text(n[0]) + ' ' + text(n[1]) + ' ' + text(n[2]) +
                       "\nouter loop\n";
                for (const auto& p : corners) {
                    out += "vertex " + text(p[0]) + ' ' + text(p[1]) + ' ' + text(p[2]) + '\n';
                }
                out += "endloop\nendfacet\n";
                continue;
            }
            for (const float x : n) {
                put_float(out, x);
            }
            for (const auto& p : corners) {
                for (const float x : p) {
                    put_float(out, x);
                }
            }
            out.append(2, '\0');
        }
    }
    if (flags.ascii) {
        out += "endsolid meshedit\n";
    }
    write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp, out); });
}

}  // namespace meshedit
