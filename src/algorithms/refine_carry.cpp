// The attribute carry of whole-mesh refinement (refine_carry.h).

#include "refine_carry.h"

#include <array>
#include <memory>
#include <string_view>
#include <typeinfo>
#include <utility>
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

// A blending vertex attribute through the refinement itself: three channels per run.
void refine_channels(const Mesh& base, const BasePropertyArray& old, BasePropertyArray& out,
                     const std::function<void(Mesh&)>& refine) {
    std::vector<double> values;
    for (std::size_t c = 0; c < old.channels(); c += 3) {
        Mesh m = base;
        auto& p = m.position_vector();
        for (std::size_t j = 0; j < 3; ++j) {
            if (c + j < old.channels()) {
                old.get_channel(c + j, values);
                for (std::size_t v = 0; v < p.size(); ++v) {
                    p[v][static_cast<int>(j)] = values[v];
                }
            } else {
                for (Vec3& x : p) {
                    x[static_cast<int>(j)] = 0.0;
                }
            }
        }
        refine(m);
        const auto& q = m.position_vector();
        for (std::size_t j = 0; j < 3 && c + j < old.channels(); ++j) {
            values.resize(q.size());
            for (std::size_t v = 0; v < q.size(); ++v) {
                values[v] = q[v][static_cast<int>(j)];
            }
            out.set_channel(c + j, values);
        }
    }
}

// The old face's halfedge arriving at `v`, or invalid.
Halfedge corner_at(const std::vector<Halfedge>& corners, const Mesh& base, Vertex v) {
    for (const Halfedge h : corners) {
        if (base.to_vertex(h) == v) {
            return h;
        }
    }
    return Halfedge();
}

// A texture coordinate or corner normal array, refined as face-varying values: true if done.
bool refine_corner_values(const Mesh& base, const Mesh& refined, FaceVaryingRules rules,
                          const BasePropertyArray& old, BasePropertyArray& out) {
    if (old.name() == kTexCoordProperty && old.type() == typeid(Vec2)) {
        refine_face_varying<Vec2>(base, refined, rules,
                                  static_cast<const PropertyArray<Vec2>&>(old).vector(),
                                  static_cast<PropertyArray<Vec2>&>(out).vector());
        return true;
    }
    if (old.name() == kCornerNormalProperty && old.type() == typeid(Vec3)) {
        // A corner normal's seams are hard edges: they stay where they are, and smoothing
        // a normal field by a parametrization's rules means nothing; linear keeps both.
        rules.uv = UvInterpolation::All;
        refine_face_varying<Vec3>(base, refined, rules,
                                  static_cast<const PropertyArray<Vec3>&>(old).vector(),
                                  static_cast<PropertyArray<Vec3>&>(out).vector());
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
                     const std::function<void(Mesh&)>& refine) {
    const Layout layout = rules.scheme == Scheme::Loop ? Layout::Loop : Layout::Quad;
    // The arrays stay the same objects (a user's Property handles stay valid): the old
    // values are copied aside, the refinement sizes the arrays, then they are derived.
    const std::array<std::vector<BasePropertyArray*>, 4> now = attributes(mesh);
    std::array<Arrays, 4> old;
    for (int k = 0; k < 4; ++k) {
        for (BasePropertyArray* a : now[k]) {
            old[k].push_back(a->clone());
        }
    }
    Mesh base = mesh;
    const std::array<std::vector<BasePropertyArray*>, 4> copies = attributes(base);
    for (int k = 0; k < 4; ++k) {
        for (const BasePropertyArray* a : copies[k]) {
            MeshArrays::container(base, k).remove(a);
        }
    }
    const std::size_t nv = base.vertices_size();
    const std::size_t ne = base.edges_size();
    refine(mesh);

    // Parents of the new faces, and the old faces' corners.
    std::vector<std::uint32_t> parent(mesh.faces_size());
    std::vector<std::vector<Halfedge>> corners(base.faces_size());
    for (const Face f : base.faces()) {
        for (const Halfedge h : base.halfedges(f)) {
            corners[f.idx()].push_back(h);
        }
    }
    for (std::uint32_t f = 0, c = 0; f < base.faces_size(); ++f) {
        const std::size_t parts = layout == Layout::Loop ? 4 : corners[f].size();
        for (std::size_t i = 0; i < parts && c < parent.size(); ++i) {
            parent[c++] = f;
        }
    }
    std::vector<std::uint32_t> from;
    std::vector<double> weight;
    const auto all_corners = [&](auto pick, std::uint32_t f) {
        from.clear();
        weight.clear();
        for (const Halfedge h : corners[f]) {
            from.push_back(pick(h));
            weight.push_back(1.0 / static_cast<double>(corners[f].size()));
        }
    };

    for (std::size_t i = 0; i < old[0].size(); ++i) {
        const BasePropertyArray* a = old[0][i].get();
        BasePropertyArray* out = now[0][i];  // old vertices keep their values
        if (a->carry() == Carry::Blend && a->channels() > 0) {
            refine_channels(base, *a, *out, refine);
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
        for (std::uint32_t c = 0; c < mesh.faces_size(); ++c) {
            out->derive_from(*a, c, &parent[c], &one, 1);
        }
    }
    for (std::size_t i = 0; i < old[1].size(); ++i) {
        const BasePropertyArray* a = old[1][i].get();
        BasePropertyArray* out = now[1][i];
        if (refine_corner_values(base, mesh, rules, *a, *out)) {
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
                        corner_at(corners[p], base, old_vertex ? Vertex(head) : base.vertex(e, 0)),
                        corner_at(corners[p], base, old_vertex ? Vertex(head) : base.vertex(e, 1))};
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
