#pragma once
/// \file
/// The halfedge mesh: index-based, typed handles, implicit twins (2k, 2k+1), connectivity and
/// attributes in named property arrays, lazy deletion with explicit garbage collection.
/// Invariants are listed in docs/halfedge.md and checked by validate() (validate.h).

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "meshedit/core/assert.h"
#include "meshedit/core/circulators.h"
#include "meshedit/core/handles.h"
#include "meshedit/core/material.h"
#include "meshedit/core/math.h"
#include "meshedit/core/properties.h"

namespace meshedit {

template <class T>
using VertexProperty = Property<Vertex, T>;
template <class T>
using HalfedgeProperty = Property<Halfedge, T>;
template <class T>
using EdgeProperty = Property<Edge, T>;
template <class T>
using FaceProperty = Property<Face, T>;

/// Old-to-new index maps produced by Mesh::garbage_collection(); deleted elements map to an
/// invalid handle.
struct GarbageCollectionMap {
    std::vector<Vertex> vertices;
    std::vector<Halfedge> halfedges;
    std::vector<Edge> edges;
    std::vector<Face> faces;
};

/// A polygon mesh with halfedge connectivity.
///
/// Handle lifetime: handles to live elements stay valid across every operation (local ops,
/// property changes, copies and moves of the mesh) and are invalidated only by
/// garbage_collection(), which compacts the arrays and reports the old-to-new maps.
class MeshRecorder;

class Mesh {
public:
    Mesh();
    Mesh(const Mesh& other);
    Mesh(Mesh&& other) noexcept;
    Mesh& operator=(const Mesh& other);
    Mesh& operator=(Mesh&& other) noexcept;
    ~Mesh() = default;

    // ----------------------------------------------------------------- sizes and counts

    /// Live element counts (deleted elements excluded).
    std::size_t n_vertices() const { return vprops_.size() - n_deleted_vertices_; }
    std::size_t n_edges() const { return eprops_.size() - n_deleted_edges_; }
    std::size_t n_halfedges() const { return 2 * n_edges(); }
    std::size_t n_faces() const { return fprops_.size() - n_deleted_faces_; }

    /// Array sizes, deleted elements included: valid indices are `[0, *_size())`.
    std::size_t vertices_size() const { return vprops_.size(); }
    std::size_t halfedges_size() const { return 2 * eprops_.size(); }
    std::size_t edges_size() const { return eprops_.size(); }
    std::size_t faces_size() const { return fprops_.size(); }

    bool is_empty() const { return n_vertices() == 0; }
    /// True when some element is deleted and garbage_collection() would compact.
    bool has_garbage() const {
        return n_deleted_vertices_ + n_deleted_edges_ + n_deleted_faces_ > 0;
    }

    /// Bytes held by all property arrays (capacity, not size).
    std::size_t bytes() const;

    // ----------------------------------------------------------------- element creation

    /// Adds an isolated vertex at `p`. (Every call that creates elements starts with `new_`.)
    Vertex new_vertex(const Vec3& p);
    /// Adds an edge whose halfedge `2k` runs `from -> to` and `2k+1` runs `to -> from`; their
    /// next/prev/face are unset. \return halfedge `2k`.
    Halfedge new_edge(Vertex from, Vertex to);
    /// Adds a face element with no halfedge yet (callers link it).
    Face new_face();
    /// Appends `nv` vertices, `ne` edges (`2 ne` halfedges) and `nf` faces with every property
    /// at its default (positions zero, connectivity unset), one call per property array. The
    /// new indices start at the previous `*_size()`, in the order new_vertex(), new_edge()
    /// and new_face() would have given them. For local ops that create several elements.
    void new_elements(std::size_t nv, std::size_t ne, std::size_t nf);

    /// Reserves room for that many elements in every array (no effect on sizes).
    void reserve(std::size_t n_vertices, std::size_t n_edges, std::size_t n_faces);
    /// Resizes every array; new elements hold property defaults (bulk builders use this).
    void resize(std::size_t n_vertices, std::size_t n_edges, std::size_t n_faces);
    /// Removes every element; keeps the properties (at size 0).
    void clear();
    void shrink_to_fit();

    // ----------------------------------------------------------------- connectivity

    Halfedge halfedge(Vertex v) const { return vhalfedge_[v]; }
    Halfedge halfedge(Face f) const { return fhalfedge_[f]; }
    /// Halfedge `i` (0 or 1) of edge `e`.
    static Halfedge halfedge(Edge e, unsigned i) { return Halfedge(2 * e.idx() + i); }
    static Edge edge(Halfedge h) { return Edge(h.idx() >> 1); }
    static Halfedge twin(Halfedge h) { return Halfedge(h.idx() ^ 1u); }

    Halfedge next(Halfedge h) const { return hnext_[h]; }
    Halfedge prev(Halfedge h) const { return hprev_[h]; }
    Vertex to_vertex(Halfedge h) const { return hvertex_[h]; }
    Vertex from_vertex(Halfedge h) const { return to_vertex(twin(h)); }
    Vertex vertex(Edge e, unsigned i) const { return to_vertex(halfedge(e, i)); }
    /// The face left of `h`; invalid for a boundary halfedge.
    Face face(Halfedge h) const { return hface_[h]; }
    Face face(Edge e, unsigned i) const { return face(halfedge(e, i)); }

    /// Counter-clockwise rotation around from_vertex(h): the next outgoing halfedge.
    Halfedge ccw_rotated(Halfedge h) const { return twin(prev(h)); }
    /// Clockwise rotation around from_vertex(h).
    Halfedge cw_rotated(Halfedge h) const { return next(twin(h)); }

    // Every setter tells a recorded edit (mesh_change.h) what it is about to overwrite.
    void set_halfedge(Vertex v, Halfedge h) {
        touch(v);
        vhalfedge_[v] = h;
    }
    void set_halfedge(Face f, Halfedge h) {
        touch(f);
        fhalfedge_[f] = h;
    }
    /// Sets `next(h) = n` and `prev(n) = h` together, so the two never disagree.
    void set_next(Halfedge h, Halfedge n) {
        touch(h);
        touch(n);
        hnext_[h] = n;
        hprev_[n] = h;
    }
    void set_vertex(Halfedge h, Vertex v) {
        touch(h);
        hvertex_[h] = v;
    }
    void set_face(Halfedge h, Face f) {
        touch(h);
        hface_[h] = f;
    }

    /// While an edit is recorded (MeshRecorder, mesh_change.h): the element's values, in
    /// every property of its kind, are about to change. The setters above, position() and
    /// mark_deleted() call it; code that writes a property through its handle (a crease
    /// mark) calls it first. No effect when nothing records. A halfedge touches its edge too.
    void touch(Vertex v) {
        if (recorder_ != nullptr) [[unlikely]] {
            record(0, v.idx());
        }
    }
    void touch(Halfedge h) {
        if (recorder_ != nullptr) [[unlikely]] {
            record(1, h.idx());
            record(2, h.idx() >> 1);
        }
    }
    void touch(Edge e) {
        if (recorder_ != nullptr) [[unlikely]] {
            record(2, e.idx());
        }
    }
    void touch(Face f) {
        if (recorder_ != nullptr) [[unlikely]] {
            record(3, f.idx());
        }
    }

    // ----------------------------------------------------------------- attribute carry

    /// Attribute carry (docs/halfedge.md, "What every operation carries"): element `to`, made
    /// or rewritten by an operation, takes in every attribute — each property but connectivity
    /// and positions — the value its Carry rule derives from `from`: a copy of one element, or a
    /// blend with the weights the operation used for the position. An operation states this
    /// once for every element it makes; a recorded edit that makes an element without it fails
    /// the recorder's self-check. It tells the recorder, like every setter.
    template <class H>
    void carry(H to, H from) {
        if (carries_nothing<H>()) [[likely]] {
            return;  // no attribute and nobody recording: a flip pays two compares
        }
        const std::uint32_t i = from.idx();
        const double w = 1.0;
        derive(to, &i, &w, 1);
    }
    /// A blend: `{{a, 0.5}, {b, 0.5}}`. The weights sum to 1.
    template <class H>
    void carry(H to, std::initializer_list<std::pair<H, double>> from);
    /// The same with `n` sources in arrays (a poke's centre blends a whole face).
    template <class H>
    void carry(H to, const H* from, const double* weight, std::size_t n);
    /// A whole-mesh rewiring that moves what elements mean (flip_orientation: a halfedge's
    /// corner becomes another's): element i of every attribute takes element `source[i]`'s
    /// value. Not recorded (a whole-array write). No cost without attributes.
    template <class H>
    void permute_attributes(const std::vector<std::uint32_t>& source);
    /// Element `h`'s values in every attribute of its kind, as bytes (empty without
    /// attributes): what an operation that rewrites `h` in place keeps, to derive from it
    /// again at another amount (bevel_positions()).
    template <class H>
    std::vector<std::byte> attribute_values(H h) const;
    /// Puts back values attribute_values() took of `h` (while the same attributes exist).
    /// Tells the recorder, like every setter.
    template <class H>
    void set_attribute_values(H h, const std::vector<std::byte>& values);
    /// An element nothing old describes (an edge across a face): the properties' defaults.
    template <class H>
    void carry_default(H to) {
        if (!carries_nothing<H>()) {
            derive(to, nullptr, nullptr, 0);
        }
    }

    // ----------------------------------------------------------------- queries

    bool is_boundary(Halfedge h) const { return !face(h).is_valid(); }
    bool is_boundary(Edge e) const {
        return is_boundary(halfedge(e, 0)) || is_boundary(halfedge(e, 1));
    }
    /// True for a vertex on a boundary loop, and for an isolated vertex. O(1): a boundary
    /// vertex's outgoing halfedge is a boundary halfedge (invariant).
    bool is_boundary(Vertex v) const {
        const Halfedge h = halfedge(v);
        return !h.is_valid() || is_boundary(h);
    }
    /// True for a face with at least one boundary edge.
    bool is_boundary(Face f) const;
    bool is_isolated(Vertex v) const { return !halfedge(v).is_valid(); }

    /// Number of edges at `v`.
    std::size_t valence(Vertex v) const;
    /// Number of sides of `f`.
    std::size_t valence(Face f) const;
    bool is_triangle(Face f) const { return next(next(next(halfedge(f)))) == halfedge(f); }
    /// True when every live face is a triangle. O(F).
    bool is_triangle_mesh() const;

    /// The halfedge `a -> b`, or invalid if there is none. O(valence(a)).
    Halfedge find_halfedge(Vertex a, Vertex b) const;
    /// The edge joining `a` and `b`, or invalid.
    Edge find_edge(Vertex a, Vertex b) const;

    bool is_valid(Vertex v) const { return v.idx() < vertices_size(); }
    bool is_valid(Halfedge h) const { return h.idx() < halfedges_size(); }
    bool is_valid(Edge e) const { return e.idx() < edges_size(); }
    bool is_valid(Face f) const { return f.idx() < faces_size(); }

    // ----------------------------------------------------------------- deletion

    bool is_deleted(Vertex v) const { return vdeleted_[v] != 0; }
    bool is_deleted(Halfedge h) const { return is_deleted(edge(h)); }
    bool is_deleted(Edge e) const { return edeleted_[e] != 0; }
    bool is_deleted(Face f) const { return fdeleted_[f] != 0; }

    /// Tombstones an element. Low level: the caller has already unlinked it; local ops use
    /// these. Marking twice is harmless.
    void mark_deleted(Vertex v);
    void mark_deleted(Edge e);
    void mark_deleted(Face f);

    /// Removes tombstoned elements and compacts every property array, keeping the relative
    /// order of live elements. Invalidates all handles; `map`, if given, receives the
    /// old-to-new index maps.
    void garbage_collection(GarbageCollectionMap* map = nullptr);

    // ----------------------------------------------------------------- geometry

    const Vec3& position(Vertex v) const { return vpoint_[v]; }
    Vec3& position(Vertex v) {
        touch(v);
        return vpoint_[v];
    }
    /// Whole-array access: not allowed while an edit is recorded (its writes would be
    /// unseen; MeshRecorder::finish() then throws).
    VertexProperty<Vec3> positions() {
        untracked();
        return vpoint_;
    }
    const memory::Array<Vec3>& position_vector() const { return vpoint_.vector(); }
    memory::Array<Vec3>& position_vector() {
        untracked();
        return vpoint_.vector();
    }
    BoundingBox bounds() const;

    // ----------------------------------------------------------------- ranges

    /// Live elements in index order; e.g. `for (Vertex v : mesh.vertices())`.
    ElementRange<Vertex> vertices() const { return {this, vertices_size()}; }
    ElementRange<Halfedge> halfedges() const { return {this, halfedges_size()}; }
    ElementRange<Edge> edges() const { return {this, edges_size()}; }
    ElementRange<Face> faces() const { return {this, faces_size()}; }

    /// Outgoing halfedges of `v`, counter-clockwise from halfedge(v).
    CirculatorRange<VertexOutgoingHalfedges> halfedges(Vertex v) const {
        return {this, halfedge(v)};
    }
    /// Neighbours of `v` (the one-ring), counter-clockwise.
    CirculatorRange<VertexOneRing> vertices(Vertex v) const { return {this, halfedge(v)}; }
    /// Faces around `v` (boundary gaps skipped).
    CirculatorRange<VertexFaces> faces(Vertex v) const { return {this, halfedge(v)}; }
    /// Edges around `v`.
    CirculatorRange<VertexEdges> edges(Vertex v) const { return {this, halfedge(v)}; }
    /// Halfedges of `f` in order (`next` direction).
    CirculatorRange<FaceHalfedges> halfedges(Face f) const { return {this, halfedge(f)}; }
    /// Corners of `f` in order.
    CirculatorRange<FaceVertices> vertices(Face f) const { return {this, halfedge(f)}; }
    /// Halfedges of the loop through `h` (a face or a boundary loop).
    CirculatorRange<FaceHalfedges> loop(Halfedge h) const { return {this, h}; }

    // ----------------------------------------------------------------- properties

    /// Adds a property named `name` on elements of kind `H` (Vertex, Halfedge, Edge, Face).
    /// \throws std::logic_error if the name is taken.
    /// Its Carry rule is its type's default (properties.h) unless attributes.h names another.
    template <class H, class T>
    Property<H, T> add_property(std::string name, T default_value = T()) {
        auto* array = container<H>().template add<T>(std::move(name), default_value);
        well_known_carry(*array);
        return Property<H, T>(array);
    }
    /// \return the property, or a null Property (false in `if`) if it does not exist with `T`.
    template <class H, class T>
    Property<H, T> get_property(std::string_view name) const {
        return Property<H, T>(container<H>().template get<T>(name));
    }
    /// \return the property, adding it if missing.
    template <class H, class T>
    Property<H, T> property(std::string_view name, T default_value = T()) {
        if (auto existing = get_property<H, T>(name)) {
            return existing;
        }
        return add_property<H, T>(std::string(name), default_value);
    }
    /// How the property `name` follows operations (Mesh::carry()); false if there is none.
    template <class H>
    bool set_carry(std::string_view name, Carry rule) {
        return container<H>().set_carry(name, rule);
    }
    template <class H>
    bool has_property(std::string_view name) const {
        return container<H>().exists(name);
    }
    /// Removes a user property; connectivity properties cannot be removed.
    template <class H, class T>
    void remove_property(Property<H, T>& p) {
        MESHEDIT_ASSERT(!is_connectivity(p.array()));
        removing(p.array());
        container<H>().remove(p.array());
        p = Property<H, T>();
    }
    template <class H>
    std::vector<std::string> property_names() const {
        return container<H>().names();
    }

    /// The materials a face's kMaterialProperty names (attributes.h), in index order.
    const std::vector<Material>& materials() const { return materials_; }
    std::vector<Material>& materials() { return materials_; }

private:
    template <class H>
    PropertyContainer& container() {
        return const_cast<PropertyContainer&>(std::as_const(*this).container<H>());
    }
    template <class H>
    const PropertyContainer& container() const {
        if constexpr (std::is_same_v<H, Vertex>) {
            return vprops_;
        } else if constexpr (std::is_same_v<H, Halfedge>) {
            return hprops_;
        } else if constexpr (std::is_same_v<H, Edge>) {
            return eprops_;
        } else {
            static_assert(std::is_same_v<H, Face>, "H must be Vertex, Halfedge, Edge or Face");
            return fprops_;
        }
    }
    bool is_connectivity(const BasePropertyArray* array) const;
    /// Gives a property attributes.h lists its rule (the crease flag: Carry::Any).
    static void well_known_carry(BasePropertyArray& array);
    friend class MeshRecorder;
    friend class MeshChange;
    friend bool bitwise_equal(const Mesh& a, const Mesh& b, std::string* why);
    /// Out of line, so the setters stay small: `kind` 0 vertex, 1 halfedge, 2 edge, 3 face.
    void record(int kind, std::uint32_t index);
    /// Tells the recorder's self-check that `index` of `kind` was derived (mesh_change.cpp).
    void carried(int kind, std::uint32_t index);
    /// Where each kind's attributes start in its container (0 vertex … 3 face): the
    /// positions and connectivity add_connectivity() makes come first, and carry() leaves
    /// them to the operation.
    static constexpr std::size_t kFirstAttribute[4] = {3, 4, 1, 2};
    /// True when carry() has nothing to do: no attribute of kind H and no recording.
    template <class H>
    bool carries_nothing() const {
        return recorder_ == nullptr &&
               container<H>().n_properties() == kFirstAttribute[kind_of<H>()];
    }
    /// The recorder's number of an element kind: 0 vertex, 1 halfedge, 2 edge, 3 face.
    template <class H>
    static constexpr int kind_of() {
        return std::is_same_v<H, Vertex>     ? 0
               : std::is_same_v<H, Halfedge> ? 1
               : std::is_same_v<H, Edge>     ? 2
                                             : 3;
    }
    /// carry()'s body: derives `to` in every attribute of its kind and tells the recorder.
    template <class H>
    void derive(H to, const std::uint32_t* from, const double* weight, std::size_t n);
    /// A write the recorder cannot see is coming (whole arrays, renumbering, replacement).
    void untracked() {
        if (recorder_ != nullptr) [[unlikely]] {
            record(-1, 0);
        }
    }
    /// Moves `other`'s arrays here and leaves `other` a valid empty mesh.
    void take_from(Mesh& other) noexcept;
    /// Resets every container to the connectivity properties only, at size 0.
    void add_connectivity();
    void bind_connectivity();
    /// A recorded edit may remove only properties it added itself (scratch data).
    void removing(const BasePropertyArray* array);
    void count_deleted();

    PropertyContainer vprops_;
    PropertyContainer hprops_;
    PropertyContainer eprops_;
    PropertyContainer fprops_;

    // Cached views of the connectivity properties (rebound after copy or move). Core
    // algorithms reach the arrays through MeshArrays (src/mesh/mesh_arrays.h), never by name.
    friend struct MeshArrays;
    VertexProperty<Vec3> vpoint_;
    VertexProperty<Halfedge> vhalfedge_;
    VertexProperty<std::uint8_t> vdeleted_;
    HalfedgeProperty<Halfedge> hnext_;
    HalfedgeProperty<Halfedge> hprev_;
    HalfedgeProperty<Vertex> hvertex_;
    HalfedgeProperty<Face> hface_;
    EdgeProperty<std::uint8_t> edeleted_;
    FaceProperty<Halfedge> fhalfedge_;
    FaceProperty<std::uint8_t> fdeleted_;

    std::size_t n_deleted_vertices_ = 0;
    std::size_t n_deleted_edges_ = 0;
    std::size_t n_deleted_faces_ = 0;
    std::vector<Material> materials_;
    MeshRecorder* recorder_ = nullptr;  ///< the edit being recorded; never copied or moved
};

/// RAII temporary property for algorithm scratch data: removed when the scope ends, also
/// when an exception leaves it.
template <class H, class T>
class ScopedProperty {
public:
    ScopedProperty(Mesh& mesh, std::string name, T default_value = T())
        : mesh_(mesh), prop_(mesh.add_property<H, T>(std::move(name), default_value)) {}
    ~ScopedProperty() { mesh_.remove_property(prop_); }
    ScopedProperty(const ScopedProperty&) = delete;
    ScopedProperty& operator=(const ScopedProperty&) = delete;

    T& operator[](H h) { return prop_[h]; }
    const T& operator[](H h) const { return prop_[h]; }
    memory::Array<T>& vector() { return prop_.vector(); }
    Property<H, T>& get() { return prop_; }

private:
    Mesh& mesh_;
    Property<H, T> prop_;
};

template <class H>
void Mesh::carry(H to, std::initializer_list<std::pair<H, double>> from) {
    if (carries_nothing<H>()) {
        return;
    }
    std::uint32_t index[8];
    double weight[8];
    MESHEDIT_ASSERT(from.size() <= 8);
    std::size_t n = 0;
    for (const auto& [h, w] : from) {
        index[n] = h.idx();
        weight[n++] = w;
    }
    derive(to, index, weight, n);
}

template <class H>
void Mesh::carry(H to, const H* from, const double* weight, std::size_t n) {
    if (carries_nothing<H>()) {
        return;
    }
    std::uint32_t small[16];
    std::vector<std::uint32_t> large(n > 16 ? n : 0);
    std::uint32_t* index = n > 16 ? large.data() : small;
    for (std::size_t i = 0; i < n; ++i) {
        index[i] = from[i].idx();
    }
    derive(to, index, weight, n);
}

// ----------------------------------------------------------------- range internals

template <class H>
void ElementRange<H>::Iterator::skip_deleted() {
    while (idx_ < end_ && mesh_->is_deleted(H(static_cast<std::uint32_t>(idx_)))) {
        ++idx_;
    }
}

// ----------------------------------------------------------------- circulator traits

inline Halfedge VertexOutgoingHalfedges::step(const Mesh& m, Halfedge h) {
    return m.ccw_rotated(h);
}
inline Vertex VertexOneRing::value(const Mesh& m, Halfedge h) {
    return m.to_vertex(h);
}
inline Edge VertexEdges::value(const Mesh&, Halfedge h) {
    return Mesh::edge(h);
}
inline bool VertexFaces::skip(const Mesh& m, Halfedge h) {
    return m.is_boundary(h);
}
inline Face VertexFaces::value(const Mesh& m, Halfedge h) {
    return m.face(h);
}
inline Halfedge FaceHalfedges::step(const Mesh& m, Halfedge h) {
    return m.next(h);
}
inline Vertex FaceVertices::value(const Mesh& m, Halfedge h) {
    return m.to_vertex(h);
}

}  // namespace meshedit
