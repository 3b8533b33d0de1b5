// OFF's colours and texture coordinates (off_attributes.h). Geomview's vertex line is
// `x y z [nx ny nz] [r g b a] [s t]`; a face line may end with a colour. Files write colours
// as 0–1 decimals or as 0–255 integers, without saying which: integers with a value above 1
// are read as 0–255 (MeshLab's and CGAL's convention), everything else as 0–1. The writer
// writes integers only when every colour is exactly k/255, so reading it back gives the same
// doubles.

#include "off_attributes.h"

#include <cmath>
#include <limits>

#include "io_util.h"
#include "meshedit/core/attributes.h"

namespace meshedit::off_attributes {
namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

std::vector<std::string_view> tokens_of(std::string_view rest) {
    std::vector<std::string_view> out;
    for (std::string_view t = io_util::next_token(rest); !t.empty();
         t = io_util::next_token(rest)) {
        out.push_back(t);
    }
    return out;
}

std::string at(const std::string& what, std::size_t line) {
    return what + " (line " + std::to_string(line) + ")";
}

// Corner values held by the halfedge arriving at each vertex, as one value per vertex, or
// empty when two corners of a vertex differ (a seam OFF cannot hold).
template <class T>
std::vector<T> per_vertex(const Mesh& mesh, const char* name) {
    const auto corner = mesh.get_property<Halfedge, T>(name);
    if (!corner) {
        return {};
    }
    std::vector<std::uint8_t> seen(mesh.vertices_size(), 0);
    std::vector<T> value(mesh.vertices_size(), T{});
    for (const Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h)) {
            continue;
        }
        const std::uint32_t v = mesh.to_vertex(h).idx();
        if (seen[v] != 0 && !(value[v] == corner[h])) {
            return {};
        }
        seen[v] = 1;
        value[v] = corner[h];
    }
    return value;
}

bool all_bytes(const std::vector<Vec4>& colours) {
    for (const Vec4& x : colours) {
        for (const double c : {x.x, x.y, x.z, x.w}) {
            const double k = std::nearbyint(c * 255.0);
            if (!(k >= 0 && k <= 255 && k / 255.0 == c)) {
                return false;
            }
        }
    }
    return true;
}

void put_colour(std::string& out, const Vec4& x, bool whole) {
    for (const double c : {x.x, x.y, x.z, x.w}) {
        out += ' ';
        out += whole ? std::to_string(static_cast<int>(std::nearbyint(c * 255.0))) : number_text(c);
    }
}

}  // namespace

void Reader::Colours::add(const std::vector<std::string_view>& tokens, const std::string& where) {
    if (!problem.empty()) {
        return;
    }
    if (tokens.size() != 3 && tokens.size() != 4) {
        problem =
            where + " has " + std::to_string(tokens.size()) + " colour values (3 or 4 expected)";
        return;
    }
    double rgba[4] = {0, 0, 0, kNone};
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const std::optional<double> x = io_util::parse_double(tokens[i]);
        if (!x || !std::isfinite(*x)) {
            problem = where + " has a colour value that is not a number ('" +
                      std::string(tokens[i].substr(0, 24)) + "')";
            return;
        }
        rgba[i] = *x;
        whole = whole && tokens[i].find_first_of(".eE") == std::string_view::npos;
    }
    values.insert(values.end(), rgba, rgba + 4);
}

std::vector<Vec4> Reader::Colours::scaled() const {
    bool above_one = false;
    for (const double x : values) {
        above_one = above_one || x > 1.0;
    }
    const double scale = whole && above_one ? 255.0 : 1.0;
    std::vector<Vec4> out(values.size() / 4);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double* c = &values[4 * i];
        out[i] = {c[0] / scale, c[1] / scale, c[2] / scale, std::isnan(c[3]) ? 1.0 : c[3] / scale};
    }
    return out;
}

void Reader::read_vertex(std::string_view rest, std::size_t v, std::size_t line) {
    if (!vertex_colours && !texcoords) {
        return;
    }
    std::vector<std::string_view> t = tokens_of(rest);
    const std::string where = at("vertex " + std::to_string(v), line);
    if (texcoords) {
        std::optional<double> s, u;
        if (t.size() >= 2) {
            s = io_util::parse_double(t[t.size() - 2]);
            u = io_util::parse_double(t[t.size() - 1]);
        }
        if (uv_problem_.empty() && !(s && u && std::isfinite(*s) && std::isfinite(*u))) {
            uv_problem_ = where + " has no two numbers for its texture coordinates";
        }
        uv_.push_back(s && u ? Vec2{*s, *u} : Vec2{});
        t.resize(t.size() >= 2 ? t.size() - 2 : 0);
    }
    if (vertex_colours) {
        vertex_.add(t, where);
    }
}

void Reader::read_face(std::string_view rest, std::size_t f, std::size_t line) {
    ++faces_;
    const std::vector<std::string_view> t = tokens_of(rest);
    if (t.empty()) {
        if (face_.problem.empty() && !face_.values.empty()) {
            face_.problem = at("face " + std::to_string(f), line) + " has none";
        }
        return;
    }
    if (t.size() == 1) {
        ++colour_map_faces_;  // an index into Geomview's colour map, which no file carries
        return;
    }
    if (face_.problem.empty() && face_.values.size() / 4 != f) {
        face_.problem = "face " + std::to_string(f - 1) + " (before line " + std::to_string(line) +
                        ") has none";
    }
    face_.add(t, at("face " + std::to_string(f), line));
}

void Reader::finish(MeshSoup& soup) {
    if (vertex_colours) {
        if (vertex_.problem.empty()) {
            soup.colors = vertex_.scaled();
        } else {
            soup.notices.push_back("vertex colours not kept: " + vertex_.problem +
                                   "; the mesh loads without them");
        }
    }
    if (texcoords) {
        if (uv_problem_.empty()) {
            const std::vector<std::uint32_t>& idx = soup.soup.indices;
            soup.corner_texcoords.resize(idx.size());
            for (std::size_t c = 0; c < idx.size(); ++c) {
                soup.corner_texcoords[c] = uv_[idx[c]];
            }
        } else {
            soup.notices.push_back("texture coordinates not kept: " + uv_problem_ +
                                   "; the mesh loads without them");
        }
    }
    if (!face_.values.empty() || !face_.problem.empty()) {
        if (face_.problem.empty() && face_.values.size() / 4 == faces_) {
            soup.face_colors = face_.scaled();
        } else {
            soup.notices.push_back(
                "face colours not kept: " +
                (face_.problem.empty() ? "the last face has none" : face_.problem) +
                "; the mesh loads without them");
        }
    }
    if (colour_map_faces_ > 0) {
        soup.notices.push_back("ignored the colour map indices of " +
                               std::to_string(colour_map_faces_) +
                               " face(s) (an OFF file carries no colour map)");
    }
}

Columns::Columns(const Mesh& mesh) {
    normals_ = per_vertex<Vec3>(mesh, kCornerNormalProperty);
    uvs_ = per_vertex<Vec2>(mesh, kTexCoordProperty);
    if (const auto c = mesh.get_property<Vertex, Vec4>(kColorProperty)) {
        colours_.assign(c.vector().begin(), c.vector().end());
        whole_colours_ = all_bytes(colours_);
    }
    if (const auto c = mesh.get_property<Face, Vec4>(kFaceColorProperty)) {
        face_colours_.assign(c.vector().begin(), c.vector().end());
        whole_face_colours_ = all_bytes(face_colours_);
    }
}

std::string Columns::keyword() const {
    return std::string(uvs_.empty() ? "" : "ST") + (colours_.empty() ? "" : "C") +
           (normals_.empty() ? "" : "N") + "OFF";
}

void Columns::put_vertex(std::string& out, std::size_t v) const {
    if (!normals_.empty()) {
        for (int k = 0; k < 3; ++k) {
            out += ' ' + number_text(normals_[v][k]);
        }
    }
    if (!colours_.empty()) {
        put_colour(out, colours_[v], whole_colours_);
    }
    if (!uvs_.empty()) {
        out += ' ' + number_text(uvs_[v].x) + ' ' + number_text(uvs_[v].y);
    }
}

void Columns::put_face(std::string& out, std::size_t f) const {
    if (!face_colours_.empty()) {
        put_colour(out, face_colours_[f], whole_face_colours_);
    }
}

}  // namespace meshedit::off_attributes
