// Wavefront OBJ through tinyobjloader (the double-precision build, so a written file reads
// back to the same doubles). Polygons are kept: triangulate = false.

#include "meshedit/io/obj.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "io_util.h"
#include "meshedit/core/normals.h"

namespace meshedit {
namespace {

/// The 1-based line of the `which`-th (0-based) line starting with `keyword` ("v", "f"):
/// tinyobjloader does not keep line numbers, so errors found after parsing look them up.
int line_of(std::string_view text, std::string_view keyword, std::size_t which) {
    int line = 1;
    std::size_t seen = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) {
            end = text.size();
        }
        std::string_view l = text.substr(pos, end - pos);
        const std::size_t first = l.find_first_not_of(" \t");
        if (first != std::string_view::npos) {
            l.remove_prefix(first);
            if (l.substr(0, keyword.size()) == keyword && l.size() > keyword.size() &&
                (l[keyword.size()] == ' ' || l[keyword.size()] == '\t')) {
                if (seen++ == which) {
                    return line;
                }
            }
        }
        ++line;
        pos = end + 1;
    }
    return 0;
}

std::string where_line(int line) {
    return line > 0 ? "line " + std::to_string(line) : std::string();
}

/// The first three numbers of every line starting with `keyword` ("v", "vn"), parsed with
/// std::from_chars. tinyobjloader's own number parser is off by an ulp now and then, and a
/// file MeshEdit writes must read back to the same doubles. Returns false (and leaves the
/// loader's values in charge) on anything unusual; throws on a non-number or a non-finite one.
bool parse_triples(std::string_view text, std::string_view keyword, const std::string& file,
                   std::vector<Vec3>& out) {
    out.clear();
    int line = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        ++line;
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) {
            end = text.size();
        }
        std::string_view l = text.substr(pos, end - pos);
        pos = end + 1;
        const std::size_t first = l.find_first_not_of(" \t");
        if (first == std::string_view::npos) {
            continue;
        }
        l.remove_prefix(first);
        if (l.substr(0, keyword.size()) != keyword || l.size() == keyword.size() ||
            (l[keyword.size()] != ' ' && l[keyword.size()] != '\t')) {
            continue;
        }
        l.remove_prefix(keyword.size());
        Vec3 p;
        for (int i = 0; i < 3; ++i) {
            const std::size_t b = l.find_first_not_of(" \t\r");
            if (b == std::string_view::npos) {
                return false;  // short line: let tinyobjloader's defaults stand
            }
            l.remove_prefix(b);
            const std::size_t e = std::min(l.find_first_of(" \t\r"), l.size());
            const std::string_view token = l.substr(0, e);
            // from_chars does not take the leading '+' some exporters write.
            const std::size_t skip = token.size() > 1 && token[0] == '+' ? 1 : 0;
            const auto [ptr, ec] =
                std::from_chars(token.data() + skip, token.data() + token.size(), p[i]);
            if (ec != std::errc() || ptr != token.data() + token.size()) {
                throw IoError(
                    file, where_line(line),
                    "expected a number, found '" + std::string(token.substr(0, 24)) + "'");
            }
            if (!std::isfinite(p[i])) {
                throw IoError(file, where_line(line),
                              std::string(keyword == "v" ? "vertex " : "normal ") +
                                  std::to_string(out.size() + 1) +
                                  " is not finite (NaN or infinity)");
            }
            l.remove_prefix(e);
        }
        out.push_back(p);
    }
    return true;
}

/// tinyobjloader's messages end in blank lines and sometimes carry a "line N" of their own.
std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) {
        s.pop_back();
    }
    for (char& c : s) {
        if (c == '\n') {
            c = ' ';
        }
    }
    return s;
}

}  // namespace

MeshSoup read_obj(const std::filesystem::path& path) {
    const std::string file = path.string();
    // Read the text ourselves: one error path for missing files, and the text is needed for
    // line numbers anyway. Materials are not used; parsing from a string skips `mtllib`.
    const std::string text = read_file(path);

    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, "", config)) {
        throw IoError(file, "", trimmed(reader.Error().empty() ? "cannot parse" : reader.Error()));
    }

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    std::vector<Vec3> exact_positions, exact_normals;
    const bool have_exact_positions = parse_triples(text, "v", file, exact_positions) &&
                                      exact_positions.size() * 3 == attrib.vertices.size();
    const bool have_exact_normals = parse_triples(text, "vn", file, exact_normals) &&
                                    exact_normals.size() * 3 == attrib.normals.size();
    MeshSoup out;
    PolygonSoup& soup = out.soup;
    const std::size_t n_vertices = attrib.vertices.size() / 3;
    soup.positions.reserve(n_vertices);
    for (std::size_t i = 0; i < n_vertices; ++i) {
        const Vec3 p = have_exact_positions
                           ? exact_positions[i]
                           : Vec3(attrib.vertices[3 * i], attrib.vertices[3 * i + 1],
                                  attrib.vertices[3 * i + 2]);
        if (!is_finite(p)) {
            throw IoError(file, where_line(line_of(text, "v", i)),
                          "vertex " + std::to_string(i + 1) + " is not finite (NaN or infinity)");
        }
        soup.positions.push_back(p);
    }

    // Per-vertex normals exist when every corner of a vertex names the same `vn`.
    const std::size_t n_normals = attrib.normals.size() / 3;
    std::vector<int> normal_of(n_vertices, -1);
    bool per_vertex_normals = n_normals > 0;

    std::size_t face = 0;
    std::size_t points_and_lines = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        points_and_lines += shape.lines.num_line_vertices.size() + shape.points.indices.size();
        std::size_t corner = 0;
        for (const unsigned char valence : shape.mesh.num_face_vertices) {
            if (corner + valence > shape.mesh.indices.size()) {
                break;  // inconsistent counts: reported below
            }
            for (std::size_t k = 0; k < valence; ++k) {
                const tinyobj::index_t idx = shape.mesh.indices[corner + k];
                // Negative (relative) indices are already resolved; one that points before
                // the first vertex comes out negative.
                if (idx.vertex_index < 0 ||
                    static_cast<std::size_t>(idx.vertex_index) >= n_vertices) {
                    throw IoError(file, where_line(line_of(text, "f", face)),
                                  "face " + std::to_string(face + 1) +
                                      " refers to a vertex that does not exist (the file has " +
                                      std::to_string(n_vertices) + " vertices)");
                }
                const auto v = static_cast<std::uint32_t>(idx.vertex_index);
                soup.indices.push_back(v);
                if (per_vertex_normals) {
                    const int n = idx.normal_index;
                    if (n < 0 || static_cast<std::size_t>(n) >= n_normals ||
                        (normal_of[v] >= 0 && normal_of[v] != n)) {
                        per_vertex_normals = false;
                    } else {
                        normal_of[v] = n;
                    }
                }
            }
            corner += valence;
            soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.indices.size()));
            ++face;
        }
        // tinyobjloader counts corners in an unsigned char: a face with more than 255 corners
        // wraps around and the counts stop adding up. Refuse rather than load wrong faces.
        if (corner != shape.mesh.indices.size()) {
            throw IoError(file, "",
                          "a face has more than 255 corners, which the OBJ loader cannot read");
        }
    }

    if (per_vertex_normals) {
        out.normals.resize(n_vertices);
        for (std::size_t v = 0; v < n_vertices; ++v) {
            if (const int n = normal_of[v]; n >= 0) {
                out.normals[v] = have_exact_normals
                                     ? exact_normals[static_cast<std::size_t>(n)]
                                     : Vec3(attrib.normals[3 * n], attrib.normals[3 * n + 1],
                                            attrib.normals[3 * n + 2]);
            }
        }
    }
    if (points_and_lines > 0) {
        out.notices.push_back("ignored " + std::to_string(points_and_lines) +
                              " point and line element(s); only faces are loaded");
    }
    return out;
}

void write_obj(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags) {
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
    // Shortest round-trip decimals keep every double exactly (tinyobjloader_double).
    auto put3 = [&text](const char* key, const Vec3& p) {
        text += key;
        for (int i = 0; i < 3; ++i) {
            text += ' ';
            text += io_util::format_double(p[i]);
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
    write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp, text); });
}

}  // namespace meshedit
