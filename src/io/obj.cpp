// Wavefront OBJ: a reader of our own (every number through std::from_chars, so a written file
// reads back to the same doubles; every index checked, with the line it is on) and the
// writer. Polygons stay polygons.
//
// Read: `v x y z [w | r g b [a]]` (colours kept), `vn x y z`, `vt u [v [w]]`, faces `f` with
// corners `v`, `v/vt`, `v//vn`, `v/vt/vn` and negative (relative) indices, kept per corner;
// `usemtl` (a face's material) and `mtllib` (read_obj() reads the .mtl, mtl.h); `l` and `p` are
// counted and ignored, as are `o g s` and comments. Faces with fewer than three corners are passed
// on, and build_mesh() drops and reports them as it does for every format.

#include "meshedit/io/obj.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

#include "io_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/normals.h"
#include "mtl.h"

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
        if (!colour_problem_.empty()) {
            out_.notices.push_back("vertex colours not kept: " + colour_problem_ +
                                   "; the mesh loads without them");
        } else if (!colours_.empty()) {
            out_.colors = std::move(colours_);
        }
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

    // The common extension `v x y z r g b [a]` (0–1): every vertex has a colour or none does.
    // A bad one drops them all, with one notice; `v x y z w` is a weight MeshEdit ignores.
    void read_colour(std::string_view rest) {
        const std::size_t v = out_.soup.positions.size();  // 1-based: this vertex's number
        Vec4 c{0, 0, 0, 1};
        double* channel[4] = {&c.x, &c.y, &c.z, &c.w};
        std::size_t n = 0;
        bool finite = true;
        for (std::string_view t = io_util::next_token(rest); !t.empty() && t[0] != '#';
             t = io_util::next_token(rest), ++n) {
            const std::optional<double> x = io_util::parse_double(t);
            finite = finite && x && std::isfinite(*x);
            if (n < 4) {
                *channel[n] = x ? *x : 0.0;
            }
        }
        if (!colour_problem_.empty() || n <= 1) {
            if (n <= 1 && colour_problem_.empty() && !colours_.empty()) {
                colour_problem_ = "vertex " + std::to_string(v) + " (line " +
                                  std::to_string(line_) + ") has none";
            }
            return;
        }
        const std::string where =
            "vertex " + std::to_string(v) + " (line " + std::to_string(line_) + ")";
        if (n > 4) {
            colour_problem_ = where + " has " + std::to_string(n) + " colour values";
        } else if (!finite) {
            colour_problem_ = where + " has a colour value that is not a number";
        } else if (colours_.size() + 1 != v) {
            colour_problem_ = "vertex " + std::to_string(colours_.size() + 1) + " has none";
        } else {
            colours_.push_back(c);
        }
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
            read_colour(l);
        } else if (key == "vn") {
            const Vec3 n = triple(l, "normal");
            if (!is_finite(n)) {
                fail("normal " + std::to_string(normals_.size() + 1) +
                     " is not finite (NaN or infinity)");
            }
            normals_.push_back(n);
        } else if (key == "vt") {
            Vec2 t;
            const std::string_view u = io_util::next_token(l);
            if (u.empty()) {
                fail("a texture coordinate needs at least u");
            }
            t.x = number(u);
            if (const std::string_view v = io_util::next_token(l); !v.empty()) {
                t.y = number(v);
            }
            if (!std::isfinite(t.x) || !std::isfinite(t.y)) {
                fail("texture coordinate " + std::to_string(texcoords_.size() + 1) +
                     " is not finite (NaN or infinity)");
            }
            texcoords_.push_back(t);
        } else if (key == "f") {
            read_face(l);
        } else if (key == "l" || key == "p") {
            ++points_and_lines_;
        } else if (key == "usemtl") {
            use_material(io_util::trim(l));
        } else if (key == "mtllib") {
            out_.material_libraries.emplace_back(io_util::trim(l));
        }
        // o, g, s and anything else: nothing to load.
    }

    // Faces from here on have material `name` (a name, spaces and all).
    void use_material(std::string_view name) {
        for (std::size_t i = 0; i < out_.materials.size(); ++i) {
            if (out_.materials[i].name == name) {
                material_ = static_cast<std::uint32_t>(i);
                return;
            }
        }
        if (out_.materials.empty() && face_ > 0) {
            out_.materials.push_back(Material{});  // the faces before the first usemtl: none
        }
        material_ = static_cast<std::uint32_t>(out_.materials.size());
        Material m;
        m.name = std::string(name);
        m.has_base_colour = false;  // until its .mtl says (mtl.cpp)
        m.has_opacity = false;
        out_.materials.push_back(std::move(m));
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
            if (resolved < 0 && std::string_view(what) != "vertex") {
                return kMissing;  // finish() drops the attribute and says so
            }
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
            std::int64_t t = -1;
            if (s1 != std::string_view::npos) {
                const std::string_view rest = corner.substr(s1 + 1);
                const std::size_t s2 = rest.find('/');
                if (!rest.substr(0, s2).empty()) {
                    t = index(rest.substr(0, s2), texcoords_.size(), "texture");
                    pending |= static_cast<std::size_t>(t) >= texcoords_.size();
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
            corner_texcoords_.push_back(t);
        }
        out_.soup.face_offsets.push_back(static_cast<std::uint32_t>(out_.soup.indices.size()));
        face_materials_.push_back(material_);
        if (pending) {
            pending_.push_back({face_, line_});
        }
        ++face_;
    }

    // A face naming a missing element: "face 1 refers to a normal that does not exist (the
    // file has …)".
    std::string missing_text(std::size_t face, const char* what) const {
        return "face " + std::to_string(face + 1) + " refers to a " + what +
               " that does not exist (the file has " + std::to_string(out_.soup.positions.size()) +
               " vertices, " + std::to_string(normals_.size()) + " normals and " +
               std::to_string(texcoords_.size()) + " texture coordinates)";
    }

    void finish() {
        const std::size_t nv = out_.soup.positions.size();
        // A missing vertex leaves no face to build: the file is refused. A missing normal or
        // texture coordinate drops that attribute alone; the mesh loads without it, said so.
        std::string lost_n, lost_t;
        for (const auto& [face, line] : pending_) {
            for (std::uint32_t c = out_.soup.face_offsets[face];
                 c < out_.soup.face_offsets[face + 1]; ++c) {
                if (out_.soup.indices[c] >= nv) {
                    throw IoError(file_, where_line(line), missing_text(face, "vertex"));
                }
                const std::int64_t n = corner_normals_[c];
                const std::int64_t t = corner_texcoords_[c];
                if (lost_n.empty() && n >= 0 && static_cast<std::size_t>(n) >= normals_.size()) {
                    lost_n = file_ + ": " + where_line(line) + ": " + missing_text(face, "normal");
                }
                if (lost_t.empty() && t >= 0 && static_cast<std::size_t>(t) >= texcoords_.size()) {
                    lost_t = file_ + ": " + where_line(line) + ": " +
                             missing_text(face, "texture coordinate");
                }
            }
        }
        if (!lost_n.empty()) {
            std::fill(corner_normals_.begin(), corner_normals_.end(), -1);
            out_.notices.push_back("normals not kept: " + lost_n + "; the mesh loads without them");
        }
        if (!lost_t.empty()) {
            std::fill(corner_texcoords_.begin(), corner_texcoords_.end(), -1);
            out_.notices.push_back("texture coordinates not kept: " + lost_t +
                                   "; the mesh loads without them");
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
        keep_corners();
        if (!out_.materials.empty()) {
            out_.face_materials = std::move(face_materials_);
        }
        if (points_and_lines_ > 0) {
            out_.notices.push_back("ignored " + std::to_string(points_and_lines_) +
                                   " point and line element(s); only faces are loaded");
        }
    }

    // Texture coordinates and normals per corner, when any corner names one; a corner
    // without gets (0, 0) or a zero normal, and a notice says how many.
    void keep_corners() {
        std::size_t without_t = 0;
        std::size_t without_n = 0;
        const bool any_t = std::any_of(corner_texcoords_.begin(), corner_texcoords_.end(),
                                       [](std::int64_t t) { return t >= 0; });
        const bool any_n = std::any_of(corner_normals_.begin(), corner_normals_.end(),
                                       [](std::int64_t n) { return n >= 0; });
        for (std::size_t c = 0; c < corner_texcoords_.size(); ++c) {
            if (any_t) {
                const std::int64_t t = corner_texcoords_[c];
                out_.corner_texcoords.push_back(t >= 0 ? texcoords_[static_cast<std::size_t>(t)]
                                                       : Vec2{});
                without_t += t < 0 ? 1 : 0;
            }
            if (any_n) {
                const std::int64_t n = corner_normals_[c];
                out_.corner_normals.push_back(n >= 0 ? normals_[static_cast<std::size_t>(n)]
                                                     : Vec3{});
                without_n += n < 0 ? 1 : 0;
            }
        }
        if (without_t > 0) {
            out_.notices.push_back(std::to_string(without_t) +
                                   " corner(s) without a texture coordinate got (0, 0)");
        }
        if (without_n > 0) {
            out_.notices.push_back(std::to_string(without_n) +
                                   " corner(s) without a normal got a zero normal");
        }
    }

    std::string_view text_;
    std::string file_;
    MeshSoup out_;
    std::vector<Vec3> normals_;
    std::vector<Vec2> texcoords_;
    std::vector<Vec4> colours_;                   // per vertex, while every vertex has one
    std::string colour_problem_;                  // the first reason to drop them
    std::vector<std::int64_t> corner_normals_;    // per corner: its vn, or -1
    std::vector<std::int64_t> corner_texcoords_;  // per corner: its vt, or -1
    std::vector<std::uint32_t> face_materials_;
    std::uint32_t material_ = 0;
    std::size_t points_and_lines_ = 0;
    std::size_t line_ = 0;
    std::size_t face_ = 0;
    // A relative vt or vn index before the first one: missing (finish() drops the attribute).
    static constexpr std::int64_t kMissing = std::int64_t{1} << 62;
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
    MeshSoup soup = parse_obj(text, path.string());
    mtl::read_libraries(path, soup);
    return soup;
}

namespace {

// Corner values as OBJ writes them: each distinct value once, in the order corners first use
// it, and per corner its 1-based index.
template <class T>
struct Indexed {
    std::vector<T> values;
    std::vector<std::uint32_t> corner;  // per soup corner
};

template <class T>
Indexed<T> index_corners(const Mesh& dense, HalfedgeProperty<T> prop) {
    Indexed<T> out;
    std::map<std::pair<double, double>, std::uint32_t> seen2;
    std::map<std::tuple<double, double, double>, std::uint32_t> seen3;
    for (const Face f : dense.faces()) {
        // Corner i of the soup face is the head of the halfedge before halfedge(f)'s i-th.
        const Halfedge first = dense.prev(dense.halfedge(f));
        Halfedge h = first;
        do {
            const T& v = prop[h];
            std::uint32_t i = 0;
            if constexpr (std::is_same_v<T, Vec2>) {
                i = seen2.emplace(std::pair{v.x, v.y}, out.values.size() + 1).first->second;
            } else {
                i = seen3.emplace(std::tuple{v.x, v.y, v.z}, out.values.size() + 1).first->second;
            }
            if (i == out.values.size() + 1) {
                out.values.push_back(v);
            }
            out.corner.push_back(i);
            h = dense.next(h);
        } while (h != first);
    }
    return out;
}

}  // namespace

std::string obj_text(const Mesh& mesh, const IoFlags& flags, const std::string& library) {
    std::optional<Mesh> storage;
    const Mesh& dense = io_util::compacted(mesh, storage);
    const PolygonSoup soup = to_polygon_soup(dense);
    Indexed<Vec2> texcoords;
    if (const auto uv = dense.get_property<Halfedge, Vec2>(kTexCoordProperty)) {
        texcoords = index_corners(dense, uv);
    }
    // The file's normals per corner if it had them, else area-weighted vertex normals.
    Indexed<Vec3> normals;
    if (const auto n = dense.get_property<Halfedge, Vec3>(kCornerNormalProperty)) {
        normals = index_corners(dense, n);
    } else if (flags.write_normals) {
        compute_vertex_normals(dense, normals.values);
        for (const std::uint32_t v : soup.indices) {
            normals.corner.push_back(v + 1);
        }
    }
    const auto material = dense.get_property<Face, std::uint32_t>(kMaterialProperty);
    const bool materials = material && !dense.materials().empty();

    std::string text = "# MeshEdit OBJ: " + std::to_string(soup.positions.size()) + " vertices, " +
                       std::to_string(soup.n_faces()) + " faces\n";
    if (materials && !library.empty()) {
        text += "mtllib " + library + "\n";
    }
    text.reserve(soup.positions.size() * 70 + normals.values.size() * 70 +
                 texcoords.values.size() * 50 + soup.indices.size() * 24);
    // Shortest round-trip decimals keep every double exactly.
    auto put = [&text](const char* key, const double* x, int n) {
        text += key;
        for (int i = 0; i < n; ++i) {
            text += ' ';
            append_number_text(text, x[i]);
        }
        text += '\n';
    };
    // Colours as the common `v x y z r g b` extension, alpha only when one is not 1.
    const auto colour = dense.get_property<Vertex, Vec4>(kColorProperty);
    const bool alpha = colour && std::any_of(colour.vector().begin(), colour.vector().end(),
                                             [](const Vec4& c) { return c.w != 1.0; });
    for (std::size_t v = 0; v < soup.positions.size(); ++v) {
        if (!colour) {
            put("v", &soup.positions[v].x, 3);
            continue;
        }
        const Vec3& p = soup.positions[v];
        const Vec4& c = colour[Vertex(static_cast<std::uint32_t>(v))];
        const double x[7] = {p.x, p.y, p.z, c.x, c.y, c.z, c.w};
        put("v", x, alpha ? 7 : 6);
    }
    for (const Vec2& t : texcoords.values) {
        put("vt", &t.x, 2);
    }
    for (const Vec3& n : normals.values) {
        put("vn", &n.x, 3);
    }
    std::uint32_t current = kInvalidIndex;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        if (materials) {
            const std::uint32_t m = material[Face(static_cast<std::uint32_t>(f))];
            if (m != current && m < dense.materials().size() &&
                !dense.materials()[m].name.empty()) {
                text += "usemtl " + dense.materials()[m].name + "\n";
                current = m;
            }
        }
        text += 'f';
        for (std::uint32_t c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
            text += ' ';
            text += std::to_string(soup.indices[c] + 1);
            if (!texcoords.corner.empty() || !normals.corner.empty()) {
                text += '/';
            }
            if (!texcoords.corner.empty()) {
                text += std::to_string(texcoords.corner[c]);
            }
            if (!normals.corner.empty()) {
                text += '/';
                text += std::to_string(normals.corner[c]);
            }
        }
        text += '\n';
    }
    return text;
}

void write_obj(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags) {
    // Materials go to NAME.mtl beside NAME.obj, written first so the OBJ never names a
    // library that is not there.
    std::string library;
    if (mesh.get_property<Face, std::uint32_t>(kMaterialProperty) && !mesh.materials().empty()) {
        library = path.stem().string() + ".mtl";
        const std::filesystem::path mtl_path = path.parent_path() / library;
        const std::string mtl_text = mtl::text(mesh, path.parent_path());
        write_atomically(mtl_path,
                         [&](const std::filesystem::path& tmp) { write_file(tmp, mtl_text); });
    }
    const std::string text = obj_text(mesh, flags, library);
    write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp, text); });
}

}  // namespace meshedit
