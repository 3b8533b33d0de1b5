// User properties: a file's values without a meaning in MeshEdit, kept as typed mesh properties.

#include "user_properties.h"

#include <cstdint>
#include <map>
#include <tuple>

namespace meshedit::user_properties {
namespace {

using Type = UserProperty::Type;

/// Calls f(T{}) with the C++ type of `type`.
template <class F>
void with_type(Type type, F&& f) {
    switch (type) {
        case Type::I8:
            return f(std::int8_t{});
        case Type::U8:
            return f(std::uint8_t{});
        case Type::I16:
            return f(std::int16_t{});
        case Type::U16:
            return f(std::uint16_t{});
        case Type::I32:
            return f(std::int32_t{});
        case Type::U32:
            return f(std::uint32_t{});
        case Type::F32:
            return f(float{});
        case Type::F64:
            return f(double{});
    }
}

/// Colours and texture coordinates blend through edits whatever their type (an edge's
/// midpoint gets the average colour); other integers are labels (the heaviest source).
bool blends(std::string_view name) {
    const std::string_view base = name.substr(name.rfind(':') + 1);
    for (const char* c : {"red", "green", "blue", "alpha", "diffuse_red", "diffuse_green",
                          "diffuse_blue", "diffuse_alpha", "s", "t", "u", "v", "texture_u",
                          "texture_v", "texture_s", "texture_t"}) {
        if (base == c) {
            return true;
        }
    }
    return false;
}

/// `source[e]` is the soup element of mesh element e.
template <class H>
void add(const std::vector<UserProperty>& props, const std::vector<std::size_t>& source,
         Mesh& mesh) {
    for (const UserProperty& up : props) {
        if (mesh.has_property<H>(up.name)) {
            continue;
        }
        with_type(up.type, [&](auto zero) {
            using T = decltype(zero);
            auto prop = mesh.add_property<H, T>(up.name, T{});
            if (blends(up.name)) {
                mesh.template set_carry<H>(up.name, Carry::Blend);  // a uchar colour too
            }
            for (std::size_t e = 0; e < source.size(); ++e) {
                if (source[e] < up.values.size()) {
                    prop[H(static_cast<std::uint32_t>(e))] = static_cast<T>(up.values[source[e]]);
                }
            }
        });
    }
}

template <class H>
std::vector<UserProperty> columns(const Mesh& mesh, std::string_view prefix, std::size_t n) {
    std::vector<UserProperty> out;
    for (const std::string& name : mesh.property_names<H>()) {
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) {
            continue;
        }
        for (int t = 0; t <= static_cast<int>(Type::F64); ++t) {
            bool found = false;
            with_type(static_cast<Type>(t), [&](auto zero) {
                using T = decltype(zero);
                if (const auto prop = mesh.get_property<H, T>(name)) {
                    UserProperty up{name.substr(prefix.size()), static_cast<Type>(t), {}};
                    up.values.resize(n);
                    for (std::size_t e = 0; e < n; ++e) {
                        up.values[e] = static_cast<double>(prop[H(static_cast<std::uint32_t>(e))]);
                    }
                    out.push_back(std::move(up));
                    found = true;
                }
            });
            if (found) {
                break;
            }
        }
    }
    return out;
}

}  // namespace

void attach(const MeshSoup& soup, const BuildReport& report, Mesh& mesh) {
    if (soup.vertex_properties.empty() && soup.face_properties.empty()) {
        return;
    }
    const std::size_t n_in = soup.soup.positions.size();
    if (!soup.vertex_properties.empty()) {
        // Copies of split vertices come after the input vertices, at the same position.
        std::map<std::tuple<double, double, double>, std::size_t> split_at;
        for (const std::uint32_t v : report.split_vertices) {
            const Vec3& p = soup.soup.positions[v];
            split_at.emplace(std::make_tuple(p.x, p.y, p.z), v);
        }
        std::vector<std::size_t> source(mesh.n_vertices());
        for (std::size_t v = 0; v < source.size(); ++v) {
            source[v] = v;
            if (v >= n_in) {
                const Vec3 p = mesh.position(Vertex(static_cast<std::uint32_t>(v)));
                const auto found = split_at.find(std::make_tuple(p.x, p.y, p.z));
                source[v] = found != split_at.end() ? found->second : SIZE_MAX;
            }
        }
        add<Vertex>(soup.vertex_properties, source, mesh);
    }
    if (!soup.face_properties.empty()) {
        std::vector<bool> dropped(soup.soup.n_faces(), false);
        for (const std::uint32_t f : report.dropped_faces) {
            if (f < dropped.size()) {
                dropped[f] = true;
            }
        }
        std::vector<std::size_t> source;
        source.reserve(mesh.n_faces());
        for (std::size_t f = 0; f < dropped.size(); ++f) {
            if (!dropped[f]) {
                source.push_back(f);
            }
        }
        source.resize(mesh.n_faces(), SIZE_MAX);
        add<Face>(soup.face_properties, source, mesh);
    }
}

std::vector<UserProperty> vertex_columns(const Mesh& mesh, std::string_view prefix) {
    return columns<Vertex>(mesh, prefix, mesh.n_vertices());
}

std::vector<UserProperty> face_columns(const Mesh& mesh, std::string_view prefix) {
    return columns<Face>(mesh, prefix, mesh.n_faces());
}

}  // namespace meshedit::user_properties
