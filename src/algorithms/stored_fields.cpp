// Stored fields (fields.h): the scalar vertex and face properties a mesh carries, shown,
// summed up and rendered like the computed fields. `meshedit compare --field OUT.ply` writes
// the deviation as a PLY vertex column; reading it back gives "v:ply:deviation", which the
// viewer's Alt+F, `meshedit render --field deviation` and `info --stats` then show.

#include <cstdint>
#include <deque>
#include <limits>
#include <mutex>
#include <string>

#include "meshedit/core/attributes.h"
#include "meshedit/core/fields.h"
#include "stored_fields.h"

namespace meshedit {
namespace {

// Calls f(T{}) for each element type a stored field may have.
template <class F>
void for_each_scalar_type(F&& f) {
    f(double{});
    f(float{});
    f(std::int8_t{});
    f(std::uint8_t{});
    f(std::int16_t{});
    f(std::uint16_t{});
    f(std::int32_t{});
    f(std::uint32_t{});
}

template <class H>
bool is_scalar(const Mesh& mesh, const std::string& name) {
    bool found = false;
    for_each_scalar_type([&](auto zero) {
        using T = decltype(zero);
        found = found || static_cast<bool>(mesh.get_property<H, T>(name));
    });
    return found;
}

// The mesh's own arrays, the material index and what the teaching phases leave between them
// (the Carry::None rows of attributes.h) are drawn their own way, never as a field.
bool is_own_attribute(std::string_view name) {
    if (name == "v:deleted" || name == "f:deleted" || name == kMaterialProperty) {
        return true;
    }
    for (const auto& [rule_name, rule] : kCarryRules) {
        if (rule_name == name && rule == Carry::None) {
            return true;
        }
    }
    return false;
}

std::string field_name_of(std::string_view property) {
    std::string_view name = property.substr(2);  // "v:" or "f:"
    if (name.starts_with("ply:") && name.size() > 4) {
        const std::string_view bare = name.substr(4);
        if (find_field(bare) == nullptr) {
            name = bare;
        }
    } else if (find_field(name) != nullptr) {
        return "user:" + std::string(name);
    }
    return std::string(name);
}

// The FieldInfo of every stored field seen so far. A deque: entries never move, so the
// pointers the viewer keeps stay valid; there is one per property name, a few per file.
struct Registry {
    std::mutex mutex;
    std::deque<std::string> strings;
    std::deque<FieldInfo> infos;

    const FieldInfo* get(const std::string& property, FieldSite site) {
        std::lock_guard lock(mutex);
        for (const FieldInfo& info : infos) {
            if (info.property == property && info.site == site) {
                return &info;
            }
        }
        const std::string& prop = strings.emplace_back(property);
        const std::string& name = strings.emplace_back(field_name_of(property));
        const std::string& description = strings.emplace_back(
            "the " + std::string(site == FieldSite::Vertex ? "vertex" : "face") + " property '" +
            property + "' the mesh carries (from its file or a program)");
        infos.push_back({name, name, "", site, false, description, prop});
        return &infos.back();
    }
};

Registry& registry() {
    static Registry r;
    return r;
}

template <class H>
void add_stored(const Mesh& mesh, FieldSite site, std::vector<const FieldInfo*>& out) {
    for (const std::string& name : mesh.template property_names<H>()) {
        if (name.size() > 2 && !is_own_attribute(name) && is_scalar<H>(mesh, name)) {
            out.push_back(registry().get(name, site));
        }
    }
}

template <class H>
std::vector<double> read_stored(const Mesh& mesh, const std::string& name, std::size_t n) {
    std::vector<double> out(n, std::numeric_limits<double>::quiet_NaN());
    bool done = false;
    for_each_scalar_type([&](auto zero) {
        using T = decltype(zero);
        const auto prop = mesh.get_property<H, T>(name);
        if (done || !prop) {
            return;
        }
        for (std::size_t i = 0; i < n; ++i) {
            const H h(static_cast<std::uint32_t>(i));
            if (!mesh.is_deleted(h)) {
                out[i] = static_cast<double>(prop[h]);
            }
        }
        done = true;
    });
    return out;
}

}  // namespace

std::vector<const FieldInfo*> stored_fields(const Mesh& mesh) {
    std::vector<const FieldInfo*> out;
    add_stored<Vertex>(mesh, FieldSite::Vertex, out);
    add_stored<Face>(mesh, FieldSite::Face, out);
    return out;
}

std::vector<const FieldInfo*> mesh_fields(const Mesh& mesh) {
    std::vector<const FieldInfo*> out;
    for (const FieldInfo& info : field_infos()) {
        out.push_back(&info);
    }
    for (const FieldInfo* info : stored_fields(mesh)) {
        out.push_back(info);
    }
    return out;
}

const FieldInfo* find_field(const Mesh& mesh, std::string_view name) {
    for (const FieldInfo* info : mesh_fields(mesh)) {
        if (info->name == name) {
            return info;
        }
    }
    return nullptr;
}

std::string field_names(const Mesh& mesh, std::string_view separator) {
    std::string out;
    for (const FieldInfo* info : mesh_fields(mesh)) {
        out += (out.empty() ? "" : std::string(separator)) + std::string(info->name);
    }
    return out;
}

std::vector<double> stored_field_values(const Mesh& mesh, const FieldInfo& info) {
    const std::string name(info.property);
    return info.site == FieldSite::Vertex ? read_stored<Vertex>(mesh, name, mesh.vertices_size())
                                          : read_stored<Face>(mesh, name, mesh.faces_size());
}

}  // namespace meshedit
