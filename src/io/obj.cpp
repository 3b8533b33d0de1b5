// Wavefront OBJ: a reader of our own (every number through std::from_chars, so a written file
// reads back to the same doubles; every index checked, with the line it is on) and the
// writer. Polygons stay polygons.
//
// Read: `v x y z [w | r g b]`, `vn x y z`, `vt …` (counted, for index checks), faces `f` with
// corners `v`, `v/vt`, `v//vn`, `v/vt/vn` and negative (relative) indices; `l` and `p` are
// counted and ignored, as are `o g s usemtl mtllib` and comments. Faces with fewer than three
// corners are passed on, and build_mesh() drops and reports them as it does for every format.

#include "meshedit/io/obj.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>
#include <string_view>

#include "io_util.h"
#include "meshedit/core/normals.h"

namespace meshedit {
namespace {

std::string where_line(std::size_t line) {
    return "line " + std::to_string(line);
}

class ObjReader {
public:
    ObjReader(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

    MeshSoup read() {
        std::size_t pos = 0;
        while (pos < text_.size()) {
            std::size_t end = text_.find('\n', pos);
            if (end == std::string_view::npos) {
                end = text_.size();
            }
            ++line_;
            read_line(text_.substr(pos, end - pos));
            pos = end + 1;
        }
        finish();
        return std::move(out_);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const {
        throw IoError(file_, where_line(line_), problem);
    }

    double number(std::string_view t) const {
        const std::optional<double> x = io_util::parse_double(t);
        if (!x) {
            fail("expected a number, found '" + std::string(t.substr(0, 24)) + "'");
        }
        return *x;
    }

    Vec3 triple(std::string_view& rest, const char* what) const {
        Vec3 p;
        for (int i = 0; i < 3; ++i) {
            const std::string_view t = io_util::next_token(rest);
            if (t.empty()) {
                fail(std::string("a ") + what + " needs three coordinates");
            }
            p[i] = number(t);
        }
        return p;
    }

    void read_line(std::string_view l) {
        if (l.find('\0') != std::string_view::npos) {
            fail("binary data (a NUL byte): not an OBJ text file");
        }
        const std::string_view key = io_util::next_token(l);
        if (key.empty() || key[0] == '#') {
            return;
        }
        if (key == "v") {
            const Vec3 p = triple(l, "vertex");
            if (!is_finite(p)) {
                fail("vertex " + std::to_string(out_.soup.positions.size() + 1) +
                     " is not finite (NaN or infinity)");
            }
            out_.soup.positions.push_back(p);
        } else if (key == "vn") {
            const Vec3 n = triple(l, "normal");
            if (!is_finite(n)) {
                fail("normal " + std::to_string(normals_.size() + 1) +
                     " is not finite (NaN or infinity)");
            }
            normals_.push_back(n);
        } else if (key == "vt") {
            ++n_texcoords_;
        } else if (key == "f") {
            read_face(l);
        } else if (key == "l" || key == "p") {
            ++points_and_lines_;
        }
        // o, g, s, usemtl, mtllib and anything else: nothing to load.
    }

    // A 1-based, possibly negative OBJ index into `count` elements so far → 0-based. Absolute
    // indices are checked against the final count in finish() (some files name vertices
    // before they define them).
    std::int64_t index(std::string_view t, std::size_t count, const char* what) const {
        std::int64_t i = 0;
        const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), i);
        if (ec == std::errc::result_out_of_range) {
            fail("face " + std::to_string(face_ + 1) + ": " + what + " index " + std::string(t) +
                 " is out of range");
        }
        if (ec != std::errc() || ptr != t.data() + t.size()) {
            fail("face " + std::to_string(face_ + 1) + ": bad " + what + " index '" +
                 std::string(t.substr(0, 24)) + "'");
        }
        if (i == 0) {
            fail("face " + std::to_string(face_ + 1) + " uses " + what +
                 " index 0; OBJ indices start at 1");
        }
        if (i < 0) {
            const std::int64_t resolved = static_cast<std::int64_t>(count) + i;
            if (resolved < 0) {
                fail("face " + std::to_string(face_ + 1) + " refers to a " + what +
                     " that does not exist (relative index " + std::string(t) + ", " +
                     std::to_string(count) + " so far)");
            }
            return resolved;
        }
        return i - 1;
    }

    void read_face(std::string_view l) {
        bool pending = false;  // an absolute index beyond what is defined so far
        for (std::string_view corner = io_util::next_token(l); !corner.empty();
             corner = io_util::next_token(l)) {
            const std::size_t s1 = corner.find('/');
            const std::int64_t v =
                index(corner.substr(0, s1), out_.soup.positions.size(), "vertex");
            std::int64_t n = -1;
            if (s1 != std::string_view::npos) {
                const std::string_view rest = corner.substr(s1 + 1);
                const std::size_t s2 = rest.find('/');
                if (!rest.substr(0, s2).empty()) {
                    const std::int64_t t = index(rest.substr(0, s2), n_texcoords_, "texture");
                    pending |= static_cast<std::size_t>(t) >= n_texcoords_;
                }
                if (s2 != std::string_view::npos && !rest.substr(s2 + 1).empty()) {
                    n = index(rest.substr(s2 + 1), normals_.size(), "normal");
                    pending |= static_cast<std::size_t>(n) >= normals_.size();
                }
            }
            if (v > std::int64_t{kInvalidIndex} - 1) {
                fail("face " + std::to_string(face_ + 1) + ": vertex index " +
                     std::to_string(v + 1) + " is out of range");
            }
            pending |= static_cast<std::size_t>(v) >= out_.soup.positions.size();
            out_.soup.indices.push_back(static_cast<std::uint32_t>(v));
            corner_normals_.push_back(n);
        }
        out_.soup.face_offsets.push_back(static_cast<std::uint32_t>(out_.soup.indices.size()));
        if (pending) {
            pending_.push_back({face_, line_});
        }
        ++face_;
    }

    void finish() {
        const std::size_t nv = out_.soup.positions.size();
        for (const auto& [face, line] : pending_) {
            for (std::uint32_t c = out_.soup.face_offsets[face];
                 c < out_.soup.face_offsets[face + 1]; ++c) {
                const std::int64_t n = corner_normals_[c];
                if (out_.soup.indices[c] >= nv ||
                    (n >= 0 && static_cast<std::size_t>(n) >= normals_.size())) {
                    throw IoError(file_, where_line(line),
                                  "face " + std::to_string(face + 1) + " refers to a " +
                                      (out_.soup.indices[c] >= nv ? "vertex" : "normal") +
                                      " that does not exist (the file has " + std::to_string(nv) +
                                      " vertices and " + std::to_string(normals_.size()) +
                                      " normals)");
                }
            }
        }
        // Per-vertex normals exist when every corner of a vertex names the same `vn`.
        std::vector<std::int64_t> normal_of(nv, -1);
        bool per_vertex = !normals_.empty();
        for (std::size_t c = 0; c < out_.soup.indices.size() && per_vertex; ++c) {
            const std::int64_t n = corner_normals_[c];
            std::int64_t& mine = normal_of[out_.soup.indices[c]];
            per_vertex = n >= 0 && (mine < 0 || mine == n);
            mine = n;
        }
        if (per_vertex) {
            out_.normals.resize(nv);
            for (std::size_t v = 0; v < nv; ++v) {
                if (normal_of[v] >= 0) {
                    out_.normals[v] = normals_[static_cast<std::size_t>(normal_of[v])];
                }
            }
        }
        if (points_and_lines_ > 0) {
            out_.notices.push_back("ignored " + std::to_string(points_and_lines_) +
                                   " point and line element(s); only faces are loaded");
        }
    }

    std::string_view text_;
    std::string file_;
    MeshSoup out_;
    std::vector<Vec3> normals_;
    std::vector<std::int64_t> corner_normals_;  // per corner: its vn, or -1
    std::size_t n_texcoords_ = 0;
    std::size_t points_and_lines_ = 0;
    std::size_t line_ = 0;
    std::size_t face_ = 0;
    struct Pending {
        std::size_t face;
        std::size_t line;
    };
    std::vector<Pending> pending_;
};

}  // namespace

MeshSoup parse_obj(std::string_view bytes, const std::string& name) {
    return ObjReader(io_util::text_of(bytes, name), name).read();
}

MeshSoup read_obj(const std::filesystem::path& path) {
    const std::string text = read_file(path);
    return parse_obj(text, path.string());
}

std::string obj_text(const Mesh& mesh, const IoFlags& flags) {
    std::optional<Mesh> storage;
    const Mesh& dense = io_util::compacted(mesh, storage);
    const PolygonSoup soup = to_polygon_soup(dense);
    std::vector<Vec3> normals;
    if (flags.write_normals) {
        compute_vertex_normals(dense, normals);
    }

    std::string text = "# MeshEdit OBJ: " + std::to_string(soup.positions.size()) + " vertices, " +
                       std::to_string(soup.n_faces()) + " faces\n";
    text.reserve(soup.positions.size() * (flags.write_normals ? 140 : 70) +
                 soup.indices.size() * 14);
    // Shortest round-trip decimals keep every double exactly.
    auto put3 = [&text](const char* key, const Vec3& p) {
        text += key;
        for (int i = 0; i < 3; ++i) {
            text += ' ';
            text += number_text(p[i]);
        }
        text += '\n';
    };
    for (const Vec3& p : soup.positions) {
        put3("v", p);
    }
    for (const Vec3& n : normals) {
        put3("vn", n);
    }
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        text += 'f';
        for (std::uint32_t c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
            const std::string i = std::to_string(soup.indices[c] + 1);
            text += ' ';
            text += i;
            if (flags.write_normals) {
                text += "//";
                text += i;
            }
        }
        text += '\n';
    }
    return text;
}

void write_obj(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags) {
    const std::string text = obj_text(mesh, flags);
    write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp, text); });
}

}  // namespace meshedit
