#pragma once
// Private to meshedit_core: the typed door to a mesh's own arrays, for the algorithms that
// read or rebuild connectivity array by array (Loop's fast path, vertex normals) and for
// cache hints in the local operations. Mesh names this struct its friend (as pmp's
// SurfaceMesh befriends its own readers); nothing outside the core can reach it, and a typo
// in an array's name does not compile, where a property looked up by string would fail at
// run time.

#include <cstdint>

#include "meshedit/core/mesh.h"

namespace meshedit {

struct MeshArrays {
    /// Where each kind's attributes start in its container (Mesh::kFirstAttribute).
    static constexpr const std::size_t* kFirstAttribute = Mesh::kFirstAttribute;
    static PropertyContainer& container(Mesh& m, int kind) {
        PropertyContainer* c[] = {&m.vprops_, &m.hprops_, &m.eprops_, &m.fprops_};
        return *c[kind];
    }

    static memory::Array<Halfedge>& next(Mesh& m) {
        m.untracked();
        return m.hnext_.vector();
    }
    static memory::Array<Halfedge>& prev(Mesh& m) {
        m.untracked();
        return m.hprev_.vector();
    }
    static memory::Array<Vertex>& to_vertex(Mesh& m) {
        m.untracked();
        return m.hvertex_.vector();
    }
    static memory::Array<Face>& face(Mesh& m) {
        m.untracked();
        return m.hface_.vector();
    }
    static memory::Array<Halfedge>& vertex_halfedge(Mesh& m) {
        m.untracked();
        return m.vhalfedge_.vector();
    }
    static memory::Array<Halfedge>& face_halfedge(Mesh& m) {
        m.untracked();
        return m.fhalfedge_.vector();
    }
    static memory::Array<std::uint8_t>& edge_deleted(Mesh& m) {
        m.untracked();
        return m.edeleted_.vector();
    }
    static memory::Array<std::uint8_t>& face_deleted(Mesh& m) {
        m.untracked();
        return m.fdeleted_.vector();
    }

    static const memory::Array<Halfedge>& next(const Mesh& m) { return m.hnext_.vector(); }
    static const memory::Array<Halfedge>& prev(const Mesh& m) { return m.hprev_.vector(); }
    static const memory::Array<Halfedge>& vertex_halfedge(const Mesh& m) {
        return m.vhalfedge_.vector();
    }
    static const memory::Array<Vertex>& to_vertex(const Mesh& m) { return m.hvertex_.vector(); }
    static const memory::Array<Halfedge>& face_halfedge(const Mesh& m) {
        return m.fhalfedge_.vector();
    }
    static const memory::Array<std::uint8_t>& face_deleted(const Mesh& m) {
        return m.fdeleted_.vector();
    }

    // ------------------------------------------------------------------ cache hints

    /// Which of a halfedge's links prefetch() asks for (or-ed together).
    enum Links : unsigned { kNext = 1, kPrev = 2, kVertex = 4, kFace = 8, kAllLinks = 15 };

    /// Asks for the cache lines a local op is about to read or write: a halfedge's links, a
    /// vertex's anchor (and position), a face's anchor. On a large mesh each is a cache miss;
    /// asked for together, as soon as the handles are known, the misses overlap instead of
    /// queueing behind one another. No effect on the mesh.
    static void prefetch(const Mesh& m, Halfedge h, unsigned links = kAllLinks) {
        if ((links & kNext) != 0) {
            hint(&m.hnext_[h]);
        }
        if ((links & kPrev) != 0) {
            hint(&m.hprev_[h]);
        }
        if ((links & kVertex) != 0) {
            hint(&m.hvertex_[h]);
        }
        if ((links & kFace) != 0) {
            hint(&m.hface_[h]);
        }
    }
    static void prefetch(const Mesh& m, Vertex v, bool with_position = false) {
        hint(&m.vhalfedge_[v]);
        if (with_position) {
            hint(&m.vpoint_[v]);
        }
    }
    static void prefetch(const Mesh& m, Face f) { hint(&m.fhalfedge_[f]); }

private:
    static void hint([[maybe_unused]] const void* p) {
#if defined(__GNUC__)
        __builtin_prefetch(p, 1);
#endif
    }
};

}  // namespace meshedit
