// PLY's vertex colours, texture coordinates and normals as MeshEdit's own attributes
// (ply_attributes.h). The reader keeps them first as the user properties every PLY scalar
// becomes; here they move to kColorProperty and kTexCoordProperty, so that edits and the
// other formats see them. Writing picks the narrowest type that holds every value exactly.

#include "ply_attributes.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "io_util.h"
#include "meshedit/core/attributes.h"

namespace meshedit::ply_attributes {
namespace {

using Type = UserProperty::Type;

// The user property `name` ("v:ply:red") of `props`, or nullptr.
UserProperty* find(std::vector<UserProperty>& props, const std::string& name) {
    for (UserProperty& p : props) {
        if (p.name == name) {
            return &p;
        }
    }
    return nullptr;
}

void remove(std::vector<UserProperty>& props, const std::vector<const UserProperty*>& gone) {
    std::erase_if(props, [&](const UserProperty& p) {
        return std::find(gone.begin(), gone.end(), &p) != gone.end();
    });
}

// What a stored value is divided by to give a colour channel in 0–1; 0 for a type that is
// not a colour (a signed integer: no common reader writes one).
double colour_scale(Type t) {
    switch (t) {
        case Type::U8:
            return 255.0;
        case Type::U16:
            return 65535.0;
        case Type::F32:
        case Type::F64:
            return 1.0;
        default:
            return 0.0;
    }
}

// The first vertex (or element) whose value in any of `props` is NaN or infinite, or -1.
long first_not_finite(const std::vector<const UserProperty*>& props, std::string& which) {
    const std::size_t n = props.empty() ? 0 : props[0]->values.size();
    for (std::size_t i = 0; i < n; ++i) {
        for (const UserProperty* p : props) {
            if (!std::isfinite(p->values[i])) {
                which = p->name.substr(6);  // without "v:ply:"
                return static_cast<long>(i);
            }
        }
    }
    return -1;
}

void take_colours(MeshSoup& soup) {
    auto& props = soup.vertex_properties;
    for (const char* prefix : {"v:ply:", "v:ply:diffuse_"}) {
        const std::string p = prefix;
        UserProperty* r = find(props, p + "red");
        UserProperty* g = find(props, p + "green");
        UserProperty* b = find(props, p + "blue");
        UserProperty* a = find(props, p + "alpha");
        if (r == nullptr || g == nullptr || b == nullptr) {
            continue;
        }
        std::vector<const UserProperty*> channels = {r, g, b};
        if (a != nullptr) {
            channels.push_back(a);
        }
        if (std::any_of(channels.begin(), channels.end(),
                        [](const UserProperty* c) { return colour_scale(c->type) == 0.0; })) {
            continue;  // signed integers: left as PLY properties, written back as they were
        }
        std::string which;
        const long bad = first_not_finite(channels, which);
        if (bad >= 0) {
            soup.notices.push_back("vertex colours not kept: vertex " + std::to_string(bad) +
                                   "'s " + which +
                                   " is not a number; the mesh loads without colours");
        } else {
            const std::size_t n = r->values.size();
            soup.colors.resize(n);
            for (std::size_t v = 0; v < n; ++v) {
                soup.colors[v] = {r->values[v] / colour_scale(r->type),
                                  g->values[v] / colour_scale(g->type),
                                  b->values[v] / colour_scale(b->type),
                                  a != nullptr ? a->values[v] / colour_scale(a->type) : 1.0};
            }
        }
        remove(props, channels);
        return;
    }
}

void take_vertex_texcoords(MeshSoup& soup) {
    auto& props = soup.vertex_properties;
    for (const auto& [su, sv] :
         {std::pair{"s", "t"}, std::pair{"u", "v"}, std::pair{"texture_u", "texture_v"},
          std::pair{"texture_s", "texture_t"}}) {
        UserProperty* u = find(props, std::string("v:ply:") + su);
        UserProperty* v = find(props, std::string("v:ply:") + sv);
        if (u == nullptr || v == nullptr) {
            continue;
        }
        std::string which;
        const long bad = first_not_finite({u, v}, which);
        if (bad >= 0) {
            soup.notices.push_back("texture coordinates not kept: vertex " + std::to_string(bad) +
                                   "'s " + which + " is not a number; the mesh loads without them");
        } else if (soup.corner_texcoords.empty()) {
            const std::vector<std::uint32_t>& idx = soup.soup.indices;
            soup.corner_texcoords.resize(idx.size());
            for (std::size_t c = 0; c < idx.size(); ++c) {
                soup.corner_texcoords[c] = {u->values[idx[c]], v->values[idx[c]]};
            }
        }
        remove(props, {u, v});
        return;
    }
}

void take_face_texcoords(MeshSoup& soup, const FaceTexcoords& uvs) {
    const PolygonSoup& s = soup.soup;
    if (uvs.face.empty() || s.n_faces() == 0) {
        return;
    }
    std::vector<Vec2> corner(s.indices.size());
    std::size_t at = 0;
    for (std::size_t k = 0; k < uvs.face.size(); ++k) {
        const std::uint32_t f = uvs.face[k];
        const std::uint32_t corners = s.face_offsets[f + 1] - s.face_offsets[f];
        const std::string where =
            "face " + std::to_string(f) +
            (k < uvs.line.size() ? " (line " + std::to_string(uvs.line[k]) + ")" : "");
        std::string problem;
        if (uvs.count[k] != 2 * corners) {
            problem = where + " has " + std::to_string(uvs.count[k]) + " texcoord values for " +
                      std::to_string(corners) + " corners";
        }
        for (std::uint32_t c = 0; c < corners && problem.empty(); ++c) {
            const double u = uvs.values[at + 2 * c];
            const double v = uvs.values[at + 2 * c + 1];
            if (!std::isfinite(u) || !std::isfinite(v)) {
                problem = where + " has a texcoord value that is not a number";
            }
            corner[s.face_offsets[f] + c] = {u, v};
        }
        if (!problem.empty()) {
            soup.notices.push_back("per-corner texture coordinates (face.texcoord) not kept: " +
                                   problem + "; the mesh loads without them");
            return;
        }
        at += uvs.count[k];
    }
    soup.corner_texcoords = std::move(corner);  // over a vertex pair's, which they refine
}

bool float_exact(double x) {
    return static_cast<double>(static_cast<float>(x)) == x;
}

UserProperty column(const char* name, Type type, std::vector<double> values) {
    return {name, type, std::move(values)};
}

}  // namespace

void take(MeshSoup& soup, const FaceTexcoords& uvs) {
    take_colours(soup);
    take_vertex_texcoords(soup);
    take_face_texcoords(soup, uvs);
}

std::vector<UserProperty> vertex_columns(const Mesh& mesh, bool& file_normals) {
    std::vector<UserProperty> out;
    const std::size_t n = mesh.vertices_size();
    file_normals = false;
    if (const auto normal = mesh.get_property<Halfedge, Vec3>(kCornerNormalProperty)) {
        std::vector<Vec3> value;
        if (io_util::per_vertex(mesh, normal, value)) {
            std::vector<double> c[3];
            bool floats = true;
            for (const Vec3& x : value) {
                for (int k = 0; k < 3; ++k) {
                    c[k].push_back(x[k]);
                    floats = floats && float_exact(x[k]);
                }
            }
            const Type t = floats ? Type::F32 : Type::F64;
            out.push_back(column("nx", t, std::move(c[0])));
            out.push_back(column("ny", t, std::move(c[1])));
            out.push_back(column("nz", t, std::move(c[2])));
            file_normals = true;
        }
    }
    if (const auto color = mesh.get_property<Vertex, Vec4>(kColorProperty)) {
        bool bytes = true, floats = true, alpha = false;
        for (std::size_t v = 0; v < n; ++v) {
            const Vec4& x = color[Vertex(static_cast<std::uint32_t>(v))];
            for (const double c : {x.x, x.y, x.z, x.w}) {
                const double k = std::nearbyint(c * 255.0);
                bytes = bytes && k >= 0 && k <= 255 && k / 255.0 == c;
                floats = floats && float_exact(c);
            }
            alpha = alpha || x.w != 1.0;
        }
        const Type t = bytes ? Type::U8 : floats ? Type::F32 : Type::F64;
        const double scale = bytes ? 255.0 : 1.0;
        std::vector<double> c[4];
        for (std::size_t v = 0; v < n; ++v) {
            const Vec4& x = color[Vertex(static_cast<std::uint32_t>(v))];
            const double channel[4] = {x.x, x.y, x.z, x.w};
            for (int k = 0; k < 4; ++k) {
                c[k].push_back(bytes ? std::nearbyint(channel[k] * scale) : channel[k]);
            }
        }
        out.push_back(column("red", t, std::move(c[0])));
        out.push_back(column("green", t, std::move(c[1])));
        out.push_back(column("blue", t, std::move(c[2])));
        if (alpha) {
            out.push_back(column("alpha", t, std::move(c[3])));
        }
    }
    if (const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty)) {
        std::vector<Vec2> value;
        if (io_util::per_vertex(mesh, uv, value)) {
            std::vector<double> s, t;
            bool floats = true;
            for (const Vec2& x : value) {
                s.push_back(x.x);
                t.push_back(x.y);
                floats = floats && float_exact(x.x) && float_exact(x.y);
            }
            out.push_back(column("s", floats ? Type::F32 : Type::F64, std::move(s)));
            out.push_back(column("t", floats ? Type::F32 : Type::F64, std::move(t)));
        }
    }
    return out;
}

std::vector<Vec2> face_texcoords(const Mesh& mesh, bool& exact_in_float) {
    std::vector<Vec2> out;
    exact_in_float = true;
    const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    std::vector<Vec2> value;
    if (!uv || io_util::per_vertex(mesh, uv, value)) {
        return out;
    }
    for (const Face f : mesh.faces()) {
        for (const Halfedge h : mesh.halfedges(f)) {
            // The corner at from_vertex(h), where to_polygon_soup() starts, is held by the
            // halfedge arriving there.
            const Vec2 x = uv[mesh.prev(h)];
            out.push_back(x);
            exact_in_float = exact_in_float && float_exact(x.x) && float_exact(x.y);
        }
    }
    return out;
}

}  // namespace meshedit::ply_attributes
