#pragma once
/// \file
/// Element ranges and one generic circulator. A circulator walks halfedges with a `step`
/// function and presents each as a value (a halfedge, vertex, edge or face); the traits below
/// are the only per-orbit code. Used through Mesh::vertices(v), Mesh::halfedges(f), etc.
///
/// Mutation rule: a range reads the mesh as it goes. Code that changes the connectivity it
/// walks must first copy the handles into a vector (docs/halfedge.md, "Iteration rule").

#include <cstddef>
#include <iterator>

#include "meshedit/core/handles.h"

namespace meshedit {

class Mesh;

/// Live elements of one kind, in index order, skipping deleted ones.
template <class H>
class ElementRange {
public:
    class Iterator {
    public:
        using iterator_category = std::forward_iterator_tag;
        using value_type = H;
        using difference_type = std::ptrdiff_t;
        using pointer = const H*;
        using reference = H;

        Iterator(const Mesh* mesh, std::size_t idx, std::size_t end)
            : mesh_(mesh), idx_(idx), end_(end) {
            skip_deleted();
        }
        H operator*() const { return H(static_cast<std::uint32_t>(idx_)); }
        Iterator& operator++() {
            ++idx_;
            skip_deleted();
            return *this;
        }
        bool operator==(const Iterator& o) const { return idx_ == o.idx_; }
        bool operator!=(const Iterator& o) const { return idx_ != o.idx_; }

    private:
        void skip_deleted();  // defined in mesh.h, where Mesh is complete
        const Mesh* mesh_;
        std::size_t idx_;
        std::size_t end_;
    };

    ElementRange(const Mesh* mesh, std::size_t size) : mesh_(mesh), size_(size) {}
    Iterator begin() const { return {mesh_, 0, size_}; }
    Iterator end() const { return {mesh_, size_, size_}; }

private:
    const Mesh* mesh_;
    std::size_t size_;
};

/// Walks the orbit of `start` under `Traits::step` until it returns to `start`, yielding
/// `Traits::value(h)`; halfedges for which `Traits::skip(h)` holds are passed over.
template <class Traits>
class CirculatorRange {
public:
    using Value = typename Traits::Value;

    class Iterator {
    public:
        using iterator_category = std::forward_iterator_tag;
        using value_type = Value;
        using difference_type = std::ptrdiff_t;
        using pointer = const Value*;
        using reference = Value;

        Iterator(const Mesh* mesh, Halfedge h, bool done) : mesh_(mesh), h_(h), start_(h) {
            done_ = done || !h.is_valid();
            if (!done_ && Traits::skip(*mesh_, h_)) {
                ++*this;
            }
        }
        Value operator*() const { return Traits::value(*mesh_, h_); }
        Halfedge halfedge() const { return h_; }
        Iterator& operator++() {
            do {
                h_ = Traits::step(*mesh_, h_);
                done_ = (h_ == start_);
            } while (!done_ && Traits::skip(*mesh_, h_));
            return *this;
        }
        bool operator==(const Iterator& o) const { return done_ == o.done_ && h_ == o.h_; }
        bool operator!=(const Iterator& o) const { return !(*this == o); }

    private:
        const Mesh* mesh_;
        Halfedge h_;
        Halfedge start_;
        bool done_ = false;
    };

    CirculatorRange(const Mesh* mesh, Halfedge start) : mesh_(mesh), start_(start) {}
    Iterator begin() const { return {mesh_, start_, false}; }
    Iterator end() const { return {mesh_, start_, true}; }

private:
    const Mesh* mesh_;
    Halfedge start_;
};

// Orbit traits; defined at the end of mesh.h, where Mesh is complete.
struct VertexOutgoingHalfedges {
    using Value = Halfedge;
    static Halfedge step(const Mesh& m, Halfedge h);
    static bool skip(const Mesh&, Halfedge) { return false; }
    static Halfedge value(const Mesh&, Halfedge h) { return h; }
};
struct VertexOneRing : VertexOutgoingHalfedges {
    using Value = Vertex;
    static Vertex value(const Mesh& m, Halfedge h);
};
struct VertexEdges : VertexOutgoingHalfedges {
    using Value = Edge;
    static Edge value(const Mesh& m, Halfedge h);
};
struct VertexFaces : VertexOutgoingHalfedges {
    using Value = Face;
    static bool skip(const Mesh& m, Halfedge h);
    static Face value(const Mesh& m, Halfedge h);
};
struct FaceHalfedges {
    using Value = Halfedge;
    static Halfedge step(const Mesh& m, Halfedge h);
    static bool skip(const Mesh&, Halfedge) { return false; }
    static Halfedge value(const Mesh&, Halfedge h) { return h; }
};
struct FaceVertices : FaceHalfedges {
    using Value = Vertex;
    static Vertex value(const Mesh& m, Halfedge h);
};

}  // namespace meshedit
