// What the attributes of two isomorphic meshes differ in (compare.h): each attribute's values
// on A's elements against those on B's matched elements.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/compare.h"

namespace meshedit {
namespace {

double largest_gap(const Vec2& x, const Vec2& y) {
    return std::max(std::abs(x.x - y.x), std::abs(x.y - y.y));
}
double largest_gap(const Vec3& x, const Vec3& y) {
    return std::max({std::abs(x.x - y.x), std::abs(x.y - y.y), std::abs(x.z - y.z)});
}
double largest_gap(const Vec4& x, const Vec4& y) {
    return std::max(
        {std::abs(x.x - y.x), std::abs(x.y - y.y), std::abs(x.z - y.z), std::abs(x.w - y.w)});
}

ElementRef ref_of(Halfedge h) {
    return ElementRef::halfedge(h);
}
ElementRef ref_of(Vertex v) {
    return ElementRef::vertex(v);
}
ElementRef ref_of(Face f) {
    return ElementRef::face(f);
}

// One attribute on elements H: A's live elements against B's at `to` (the match's map).
template <class H, class T>
AttributeDifference compare_one(const Mesh& a, const Mesh& b, const char* property,
                                std::string name, const std::vector<std::uint32_t>& to) {
    AttributeDifference d;
    d.name = std::move(name);
    d.elements = std::is_same_v<H, Halfedge> ? "corners"
                 : std::is_same_v<H, Vertex> ? "vertices"
                                             : "faces";
    const auto pa = a.get_property<H, T>(property);
    const auto pb = b.get_property<H, T>(property);
    d.in_a = static_cast<bool>(pa);
    d.in_b = static_cast<bool>(pb);
    if (!pa || !pb) {
        return d;
    }
    const auto compare = [&](H x) {
        if (x.idx() >= to.size() || to[x.idx()] == kInvalidIndex) {
            return;
        }
        ++d.compared;
        const T& va = pa[x];
        const T& vb = pb[H(to[x.idx()])];
        if (!(va == vb)) {
            d.max = std::max(d.max, largest_gap(va, vb));
            if (d.differing++ == 0) {
                d.first_a = ref_of(x);
            }
        }
    };
    if constexpr (std::is_same_v<H, Halfedge>) {
        for (const Face f : a.faces()) {
            for (const Halfedge h : a.halfedges(f)) {
                compare(h);
            }
        }
    } else if constexpr (std::is_same_v<H, Vertex>) {
        for (const Vertex v : a.vertices()) {
            compare(v);
        }
    } else {
        for (const Face f : a.faces()) {
            compare(f);
        }
    }
    return d;
}

// Face materials: the Material each face names, not its index (a renumbered table is equal).
AttributeDifference compare_materials(const Mesh& a, const Mesh& b,
                                      const std::vector<std::uint32_t>& to) {
    AttributeDifference d;
    d.name = "materials";
    const auto ma = a.get_property<Face, std::uint32_t>(kMaterialProperty);
    const auto mb = b.get_property<Face, std::uint32_t>(kMaterialProperty);
    d.in_a = ma && !a.materials().empty();
    d.in_b = mb && !b.materials().empty();
    if (!d.in_a || !d.in_b) {
        return d;
    }
    const auto material_of = [](const Mesh& mesh, std::uint32_t index) {
        return index < mesh.materials().size() ? &mesh.materials()[index] : nullptr;
    };
    for (const Face f : a.faces()) {
        if (to[f.idx()] == kInvalidIndex) {
            continue;
        }
        ++d.compared;
        const Material* x = material_of(a, ma[f]);
        const Material* y = material_of(b, mb[Face(to[f.idx()])]);
        const bool same = x == nullptr || y == nullptr
                              ? x == y
                              : x->name == y->name && x->base_colour == y->base_colour &&
                                    x->opacity == y->opacity &&
                                    x->base_colour_texture == y->base_colour_texture &&
                                    x->base_colour_texcoord == y->base_colour_texcoord;
        if (!same && d.differing++ == 0) {
            d.first_a = ElementRef::face(f);
        }
    }
    return d;
}

}  // namespace

std::vector<AttributeDifference> compare_attributes(const Mesh& a, const Mesh& b,
                                                    const TopologyMatch& match) {
    std::vector<AttributeDifference> out;
    if (!match.isomorphic) {
        return out;
    }
    std::vector<AttributeDifference> all = {
        compare_one<Halfedge, Vec2>(a, b, kTexCoordProperty, "texture coordinates", match.halfedge),
        compare_one<Halfedge, Vec2>(a, b, kTexCoord1Property, "second texture coordinate set",
                                    match.halfedge),
        compare_one<Halfedge, Vec3>(a, b, kCornerNormalProperty, "corner normals", match.halfedge),
        compare_one<Vertex, Vec4>(a, b, kColorProperty, "vertex colours", match.vertex),
        compare_one<Face, Vec4>(a, b, kFaceColorProperty, "face colours", match.face),
        compare_materials(a, b, match.face),
    };
    for (AttributeDifference& d : all) {
        if (d.in_a || d.in_b) {
            out.push_back(std::move(d));
        }
    }
    return out;
}

}  // namespace meshedit
