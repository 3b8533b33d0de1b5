// Stanford PLY: the writer (the reader is in ply.cpp). Binary little-endian with double
// positions, or ASCII with shortest round-trip decimals; the file's normals, colours and UVs
// (ply_attributes.cpp), else computed float normals; polygons kept; user properties named
// "v:ply:NAME" / "f:ply:NAME" written back as NAME with their own types.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "io_util.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/normals.h"
#include "meshedit/io/ply.h"
#include "ply_attributes.h"
#include "user_properties.h"

namespace meshedit {
namespace {

template <class T>
void put(std::string& out, T value) {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof b);
    if constexpr (std::endian::native == std::endian::big) {
        std::reverse(b, b + sizeof b);
    }
    out.append(b, sizeof b);
}

const char* type_name(UserProperty::Type t) {
    static constexpr const char* kNames[] = {"char", "uchar", "short", "ushort",
                                             "int",  "uint",  "float", "double"};
    return kNames[static_cast<std::size_t>(t)];
}

std::string header_lines(const std::vector<UserProperty>& columns) {
    std::string out;
    for (const UserProperty& c : columns) {
        out += std::string("property ") + type_name(c.type) + " " + c.name + "\n";
    }
    return out;
}

/// Element `i`'s value of each column, as its type: binary, or " value" in ASCII.
void put_columns(std::string& out, const std::vector<UserProperty>& columns, std::size_t i,
                 bool ascii) {
    using Type = UserProperty::Type;
    for (const UserProperty& c : columns) {
        const double x = c.values[i];
        if (ascii) {
            out += ' ';
            if (c.type == Type::F32) {
                out += number_text(static_cast<float>(x));
            } else if (c.type == Type::F64) {
                out += number_text(x);
            } else {
                out += std::to_string(static_cast<std::int64_t>(x));
            }
            continue;
        }
        switch (c.type) {
            case Type::I8:
                put(out, static_cast<std::int8_t>(x));
                break;
            case Type::U8:
                put(out, static_cast<std::uint8_t>(x));
                break;
            case Type::I16:
                put(out, static_cast<std::int16_t>(x));
                break;
            case Type::U16:
                put(out, static_cast<std::uint16_t>(x));
                break;
            case Type::I32:
                put(out, static_cast<std::int32_t>(x));
                break;
            case Type::U32:
                put(out, static_cast<std::uint32_t>(x));
                break;
            case Type::F32:
                put(out, static_cast<float>(x));
                break;
            case Type::F64:
                put(out, x);
                break;
        }
    }
}

}  // namespace

void write_ply(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags) {
    std::optional<Mesh> storage;
    const Mesh& dense = io_util::compacted(mesh, storage);
    const PolygonSoup soup = to_polygon_soup(dense);
    bool file_normals = false;
    std::vector<UserProperty> own = ply_attributes::vertex_columns(dense, file_normals);
    const bool computed = flags.write_normals && !file_normals;
    std::vector<Vec3> normals;
    if (computed) {
        compute_vertex_normals(dense, normals);
    }
    bool uv_floats = true;
    const std::vector<Vec2> corner_uvs = ply_attributes::face_texcoords(dense, uv_floats);
    std::vector<UserProperty> vcols = user_properties::vertex_columns(dense, "v:ply:");
    std::vector<UserProperty> fcols = user_properties::face_columns(dense, "f:ply:");
    // A name the writer uses itself (a lone "nx" kept from a file without ny nz) or one that
    // is not a PLY word is left out rather than written twice or broken.
    std::erase_if(vcols, [&](const UserProperty& c) {
        return c.name == "x" || c.name == "y" || c.name == "z" ||
               (computed && (c.name == "nx" || c.name == "ny" || c.name == "nz")) ||
               std::any_of(own.begin(), own.end(),
                           [&](const UserProperty& o) { return o.name == c.name; }) ||
               c.name.find_first_of(" \t\r\n") != std::string::npos;
    });
    std::erase_if(fcols, [](const UserProperty& c) {
        return c.name == "vertex_indices" || c.name == "texcoord" ||
               c.name.find_first_of(" \t\r\n") != std::string::npos;
    });
    std::uint32_t max_corners = 0;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        max_corners = std::max(max_corners, soup.face_offsets[f + 1] - soup.face_offsets[f]);
    }
    // uchar counts are what every reader takes; polygons of more than 255 corners need uint.
    const bool wide = max_corners > 255;
    const bool uv_wide = max_corners > 127;  // two values a corner
    vcols.insert(vcols.begin(), own.begin(), own.end());
    std::string out =
        std::string("ply\nformat ") + (flags.ascii ? "ascii" : "binary_little_endian") +
        " 1.0\ncomment MeshEdit\nelement vertex " + std::to_string(soup.positions.size()) +
        "\nproperty double x\nproperty double y\nproperty double z\n";
    if (computed) {
        out += "property float nx\nproperty float ny\nproperty float nz\n";
    }
    out += header_lines(vcols);
    out += "element face " + std::to_string(soup.n_faces()) + "\nproperty list " +
           (wide ? "uint" : "uchar") + " uint vertex_indices\n" +
           (corner_uvs.empty() ? ""
                               : std::string("property list ") + (uv_wide ? "uint" : "uchar") +
                                     (uv_floats ? " float" : " double") + " texcoord\n") +
           header_lines(fcols) + "end_header\n";
    const std::size_t per_vertex = (flags.ascii ? 80 : 36) + 8 * vcols.size();
    out.reserve(out.size() + soup.positions.size() * per_vertex + soup.indices.size() * 8 +
                soup.n_faces() * (4 + 8 * fcols.size()));
    for (std::size_t v = 0; v < soup.positions.size(); ++v) {
        const Vec3& p = soup.positions[v];
        if (flags.ascii) {
            out += number_text(p.x) + ' ' + number_text(p.y) + ' ' + number_text(p.z);
            if (computed) {
                for (int c = 0; c < 3; ++c) {
                    out += ' ' + number_text(static_cast<float>(normals[v][c]));
                }
            }
            put_columns(out, vcols, v, true);
            out += '\n';
            continue;
        }
        put(out, p.x);
        put(out, p.y);
        put(out, p.z);
        if (computed) {
            for (int c = 0; c < 3; ++c) {
                put(out, static_cast<float>(normals[v][c]));
            }
        }
        put_columns(out, vcols, v, false);
    }
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const std::uint32_t n = soup.face_offsets[f + 1] - soup.face_offsets[f];
        if (flags.ascii) {
            out += std::to_string(n);
            for (std::uint32_t c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
                out += ' ' + std::to_string(soup.indices[c]);
            }
            if (!corner_uvs.empty()) {
                out += ' ' + std::to_string(2 * n);
                for (std::uint32_t c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
                    for (const double x : {corner_uvs[c].x, corner_uvs[c].y}) {
                        out +=
                            ' ' + (uv_floats ? number_text(static_cast<float>(x)) : number_text(x));
                    }
                }
            }
            put_columns(out, fcols, f, true);
            out += '\n';
            continue;
        }
        if (wide) {
            put(out, n);
        } else {
            put(out, static_cast<std::uint8_t>(n));
        }
        for (std::uint32_t c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
            put(out, soup.indices[c]);
        }
        if (!corner_uvs.empty()) {
            if (uv_wide) {
                put(out, 2 * n);
            } else {
                put(out, static_cast<std::uint8_t>(2 * n));
            }
            for (std::uint32_t c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
                for (const double x : {corner_uvs[c].x, corner_uvs[c].y}) {
                    if (uv_floats) {
                        put(out, static_cast<float>(x));
                    } else {
                        put(out, x);
                    }
                }
            }
        }
        put_columns(out, fcols, f, false);
    }
    write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp, out); });
}

}  // namespace meshedit
