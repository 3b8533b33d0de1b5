// The attribute carry of whole-mesh refinement (refine_carry.h).

#include "refine_carry.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <typeinfo>
#include <utility>
#include <variant>
#include <vector>

#include "mesh/mesh_arrays.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/properties.h"

namespace meshedit::refine {
namespace {

using Arrays = std::vector<std::unique_ptr<BasePropertyArray>>;

bool carried_here(int kind, const BasePropertyArray& a) {
    return !(kind == 2 && a.name() == std::string_view(kCreaseProperty));
}

// The attributes of `mesh` (not the crease flags), in their order, per kind.
std::array<std::vector<BasePropertyArray*>, 4> attributes(Mesh& mesh) {
    std::array<std::vector<BasePropertyArray*>, 4> out;
    for (int k = 0; k < 4; ++k) {
        PropertyContainer& c = MeshArrays::container(mesh, k);
        for (std::size_t i = MeshArrays::kFirstAttribute[k]; i < c.n_properties(); ++i) {
            if (carried_here(k, c.array(i))) {
                out[k].push_back(&c.array(i));
            }
        }
    }
    return out;
}

// Resets `a` to `n` elements at the default.
void reset(BasePropertyArray& a, std::size_t n) {
    a.resize(0);
    a.resize(n);
}

// The groups of three channels of a blending vertex attribute (the last padded with 0).
void add_groups(const BasePropertyArray& old, std::size_t nv, ChannelGroups& groups) {
    const std::byte* raw = old.channel_doubles();  // one copy for all channels
    const std::size_t size = old.element_bytes();
    std::vector<double> values;
    for (std::size_t c = 0; c < old.channels(); c += 3) {
        memory::Array<Vec3>& in = groups.in.emplace_back();
        in.assign(nv, Vec3{});
        const std::size_t n = std::min<std::size_t>(3, old.channels() - c);
        if (raw != nullptr) {
            for (std::size_t v = 0; v < nv; ++v) {
                std::memcpy(&in[v], raw + v * size + 8 * c, 8 * n);
            }
            continue;
        }
        for (std::size_t j = 0; j < n; ++j) {
            old.get_channel(c + j, values);
            for (std::size_t v = 0; v < nv; ++v) {
                in[v][static_cast<int>(j)] = values[v];
            }
        }
    }
}

// Writes the refined groups from `first` on into `out`'s channels.
void take_groups(const ChannelGroups& groups, std::size_t first, BasePropertyArray& out) {
    std::byte* raw = out.channel_doubles();
    const std::size_t size = out.element_bytes();
    std::vector<double> values;
    for (std::size_t c = 0, g = first; c < out.channels(); c += 3, ++g) {
        const memory::Array<Vec3>& refined = groups.out[g];
        const std::size_t n = std::min<std::size_t>(3, out.channels() - c);
        if (raw != nullptr) {
            for (std::size_t v = 0; v < refined.size(); ++v) {
                std::memcpy(raw + v * size + 8 * c, &refined[v], 8 * n);
            }
            continue;
        }
        for (std::size_t j = 0; j < n; ++j) {
            values.resize(refined.size());
            for (std::size_t v = 0; v < refined.size(); ++v) {
                values[v] = refined[v][static_cast<int>(j)];
            }
            out.set_channel(c + j, values);
        }
    }
}

// The old face's halfedge arriving at `v`, or invalid.
Halfedge corner_at(std::span<const Halfedge> corners, const Mesh& base, Vertex v) {
    for (const Halfedge h : corners) {
        if (base.to_vertex(h) == v) {
            return h;
        }
    }
    return Halfedge();
}

// Whether `a` is one of the texture coordinate sets (kTexCoordSets).
bool is_texcoord_set(const BasePropertyArray& a) {
    for (const char* name : kTexCoordSets) {
        if (a.name() == name && a.type() == typeid(Vec2)) {
            return true;
        }
    }
    return false;
}

// A texture coordinate set or corner normal array's values for the next level, made from
// the old level before the refinement replaces it (empty for any other corner array).
using Prepared = std::variant<std::monostate, FaceVaryingLevel<Vec2>, FaceVaryingLevel<Vec3>>;

Prepared prepare_corner_values(const Mesh& base, FaceVaryingRules rules,
                               const BasePropertyArray& old) {
    if (is_texcoord_set(old)) {
        return prepare_face_varying<Vec2>(base, rules,
                                          static_cast<const PropertyArray<Vec2>&>(old).vector());
    }
    if (old.name() == kCornerNormalProperty && old.type() == typeid(Vec3)) {
        // A corner normal's seams are hard edges: they stay where they are, and smoothing
        // a normal field by a parametrization's rules means nothing; linear keeps both.
        rules.uv = UvInterpolation::All;
        return prepare_face_varying<Vec3>(base, rules,
                                          static_cast<const PropertyArray<Vec3>&>(old).vector());
    }
    return std::monostate{};
}

// Writes what prepare_corner_values() made: true if there was anything.
bool write_corner_values(const Prepared& prepared, std::size_t halfedges, BasePropertyArray& out) {
    if (const auto* uv = std::get_if<FaceVaryingLevel<Vec2>>(&prepared)) {
        write_face_varying(*uv, halfedges, static_cast<PropertyArray<Vec2>&>(out).vector());
        return true;
    }
    if (const auto* normal = std::get_if<FaceVaryingLevel<Vec3>>(&prepared)) {
        write_face_varying(*normal, halfedges, static_cast<PropertyArray<Vec3>&>(out).vector());
        return true;
    }
    return false;
}

}  // namespace

bool has_attributes(const Mesh& mesh) {
    Mesh& m = const_cast<Mesh&>(mesh);  // read only: container() has no const overload
    for (int k = 0; k < 4; ++k) {
        const PropertyContainer& c = MeshArrays::container(m, k);
        for (std::size_t i = MeshArrays::kFirstAttribute[k]; i < c.n_properties(); ++i) {
            if (carried_here(k, c.array(i))) {
                return true;
            }
        }
    }
    return false;
}

void refine_carrying(Mesh& mesh, const FaceVaryingRules& rules,
                     const std::function<void(Mesh&, ChannelGroups&)>& refine) {
    const Layout layout = rules.scheme == Scheme::Loop ? Layout::Loop : Layout::Quad;
    // The arrays stay the same objects (a user's Property handles stay valid): the old
    // values are set aside, the refinement sizes the arrays, then they are derived. Vertex
    // arrays are copied (old vertices keep their values in place); the others are taken
    // without a copy, so the old connectivity below is copied without them too.
    const std::array<std::vector<BasePropertyArray*>, 4> now = attributes(mesh);
    std::array<Arrays, 4> old;
    for (int k = 0; k < 4; ++k) {
        for (BasePropertyArray* a : now[k]) {
            old[k].push_back(k == 0 ? a->clone() : a->take_values());
        }
    }
    const std::size_t nv = mesh.vertices_size();
    const std::size_t ne = mesh.edges_size();
    const std::size_t nf = mesh.faces_size();
    // Texture coordinates and corner normals: the next level's values, from this one.
    std::vector<Prepared> prepared;
    // The old connectivity, copied only for attributes that read it after the refinement:
    // vertex attributes that do not blend and corner attributes that are not face-varying.
    std::optional<Mesh> kept;
    // The old faces' corners (face f's are corner_list[corner_start[f] .. [f + 1])) and the
    // parents of the new faces, where something reads them.
    std::vector<std::uint32_t> corner_start;
    std::vector<Halfedge> corner_list;
    std::vector<std::uint32_t> parent;
    // The blending vertex attributes go through the refinement with the positions.
    ChannelGroups groups;
    std::vector<std::size_t> first_group(old[0].size(), 0);
    try {
        for (const auto& a : old[1]) {
            prepared.push_back(prepare_corner_values(mesh, rules, *a));
        }
        bool needs_base = false;
        for (const auto& a : old[0]) {
            needs_base = needs_base || !(a->carry() == Carry::Blend && a->channels() > 0);
        }
        for (const Prepared& p : prepared) {
            needs_base = needs_base || std::holds_alternative<std::monostate>(p);
        }
        if (needs_base) {
            kept.emplace(mesh);
            const std::array<std::vector<BasePropertyArray*>, 4> copies = attributes(*kept);
            for (int k = 0; k < 4; ++k) {
                for (const BasePropertyArray* a : copies[k]) {
                    MeshArrays::container(*kept, k).remove(a);
                }
            }
        }
        if (needs_base || (!old[3].empty() && layout == Layout::Quad)) {
            corner_start.assign(nf + 1, 0);
            for (std::uint32_t f = 0; f < nf; ++f) {
                corner_start[f] = static_cast<std::uint32_t>(corner_list.size());
                if (!mesh.is_deleted(Face(f))) {
                    for (const Halfedge h : mesh.halfedges(Face(f))) {
                        corner_list.push_back(h);
                    }
                }
            }
            corner_start[nf] = static_cast<std::uint32_t>(corner_list.size());
        }
        if (!old[3].empty() || needs_base) {
            if (layout == Layout::Loop) {
                parent.resize(4 * nf);
                for (std::uint32_t c = 0; c < parent.size(); ++c) {
                    parent[c] = c / 4;  // face 4f + i is a part of old face f
                }
            } else {
                parent.resize(corner_list.size());
                for (std::uint32_t f = 0; f < nf; ++f) {
                    std::fill(parent.begin() + corner_start[f],
                              parent.begin() + corner_start[f + 1],
                              f);  // one quad per corner
                }
            }
        }
        for (std::size_t i = 0; i < old[0].size(); ++i) {
            if (old[0][i]->carry() == Carry::Blend && old[0][i]->channels() > 0) {
                first_group[i] = groups.in.size();
                add_groups(*old[0][i], nv, groups);
            }
        }
        refine(mesh, groups);
    } catch (...) {
        // Refused before it changed the mesh (no memory, a result too big to index): the
        // mesh gets its values back. Failed part way: the refinement cleared the mesh.
        if (mesh.edges_size() == ne && mesh.faces_size() == nf) {
            for (int k = 1; k < 4; ++k) {
                for (std::size_t i = 0; i < now[k].size(); ++i) {
                    now[k][i]->swap_values(*old[k][i]);
                }
            }
        }
        throw;
    }
    const Mesh& base = kept ? *kept : mesh;  // without a copy, only face-varying values read it
    const auto corners_of = [&](std::uint32_t f) {
        return std::span<const Halfedge>(corner_list.data() + corner_start[f],
                                         corner_start[f + 1] - corner_start[f]);
    };
    groups.in.clear();

    std::vector<std::uint32_t> from;
    std::vector<double> weight;
    const auto all_corners = [&](auto pick, std::uint32_t f) {
        from.clear();
        weight.clear();
        const std::span<const Halfedge> around = corners_of(f);
        for (const Halfedge h : around) {
            from.push_back(pick(h));
            weight.push_back(1.0 / static_cast<double>(around.size()));
        }
    };

    for (std::size_t i = 0; i < old[0].size(); ++i) {
        const BasePropertyArray* a = old[0][i].get();
        BasePropertyArray* out = now[0][i];  // old vertices keep their values
        if (a->carry() == Carry::Blend && a->channels() > 0) {
            take_groups(groups, first_group[i], *out);
        } else {
            for (std::uint32_t e = 0; e < ne; ++e) {
                const std::uint32_t ends[2] = {base.vertex(Edge(e), 0).idx(),
                                               base.vertex(Edge(e), 1).idx()};
                const double half[2] = {0.5, 0.5};
                out->derive_from(*a, nv + e, ends, half, 2);
            }
            for (std::uint32_t f = 0; layout == Layout::Quad && f < base.faces_size(); ++f) {
                all_corners([&](Halfedge h) { return base.to_vertex(h).idx(); }, f);
                out->derive_from(*a, nv + ne + f, from.data(), weight.data(), from.size());
            }
        }
    }
    for (std::size_t i = 0; i < old[2].size(); ++i) {
        const BasePropertyArray* a = old[2][i].get();
        BasePropertyArray* out = now[2][i];
        reset(*out, mesh.edges_size());
        const double one = 1.0;
        for (std::uint32_t g = 0; g < 2 * ne && g < mesh.edges_size(); ++g) {
            const std::uint32_t half_of = g / 2;
            out->derive_from(*a, g, &half_of, &one, 1);
        }
    }
    for (std::size_t i = 0; i < old[3].size(); ++i) {
        const BasePropertyArray* a = old[3][i].get();
        BasePropertyArray* out = now[3][i];
        reset(*out, mesh.faces_size());
        const double one = 1.0;
        for (std::uint32_t c = 0; c < mesh.faces_size() && c < parent.size(); ++c) {
            out->derive_from(*a, c, &parent[c], &one, 1);
        }
    }
    for (std::size_t i = 0; i < old[1].size(); ++i) {
        const BasePropertyArray* a = old[1][i].get();
        BasePropertyArray* out = now[1][i];
        if (write_corner_values(prepared[i], mesh.halfedges_size(), *out)) {
            continue;
        }
        reset(*out, mesh.halfedges_size());
        for (const Face c : mesh.faces()) {
            const std::uint32_t p = parent[c.idx()];
            for (const Halfedge h : mesh.halfedges(c)) {
                const std::uint32_t head = mesh.to_vertex(h).idx();
                if (head < nv + ne) {
                    // An old vertex's corner, or an edge point's between the edge's ends.
                    const bool old_vertex = head < nv;
                    const Edge e(old_vertex ? 0 : head - static_cast<std::uint32_t>(nv));
                    const Halfedge ends[2] = {
                        corner_at(corners_of(p), base,
                                  old_vertex ? Vertex(head) : base.vertex(e, 0)),
                        corner_at(corners_of(p), base,
                                  old_vertex ? Vertex(head) : base.vertex(e, 1))};
                    if (ends[0].is_valid() && ends[1].is_valid()) {
                        const std::uint32_t src[2] = {ends[0].idx(), ends[1].idx()};
                        const double half[2] = {0.5, 0.5};
                        out->derive_from(*a, h.idx(), src, half, old_vertex ? 1 : 2);
                    }
                } else {
                    all_corners([](Halfedge x) { return x.idx(); }, p);
                    out->derive_from(*a, h.idx(), from.data(), weight.data(), from.size());
                }
            }
        }
    }
}

}  // namespace meshedit::refine
