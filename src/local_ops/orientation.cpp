/// \file
/// Reversing the orientation of every face and boundary loop.

#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/mesh_arrays.h"
#include "meshedit/core/local_ops.h"

namespace meshedit {

// Each loop h0 -> h1 -> h2 -> h0 becomes h0 -> h2 -> h1 -> h0 with every halfedge turned
// round: `next` and `prev` swap, and h's head becomes its old tail (its twin's head). A
// halfedge keeps its face, so every face and boundary loop keeps its halfedges.
//
//          a                            a
//        /   ^  h1                    ^   \  h1
//    h2 v  f  \                   h2 /  f  v
//      b --h0--> c                  b <--h0-- c
//
//   f = (b, c, a): h0 b->c, h1 c->a, h2 a->b    f = (c, b, a): h0 c->b, h2 b->a, h1 a->c
//
// A vertex's anchor h leaves it; afterwards h arrives at it, and the halfedge that arrived
// just before h in h's loop (the old prev(h)) leaves it. On a boundary vertex h is a boundary
// halfedge and so is the old prev(h): the anchor stays on the boundary.
void flip_orientation(Mesh& mesh) {
    // Carry: h's head becomes its old tail, so h becomes its face's corner there, which
    // the old prev(h) was.
    {
        const auto& old_prev = MeshArrays::prev(mesh);
        std::vector<std::uint32_t> source(old_prev.size());
        for (std::size_t h = 0; h < source.size(); ++h) {
            source[h] = old_prev[h].is_valid() ? old_prev[h].idx() : static_cast<std::uint32_t>(h);
        }
        mesh.permute_attributes<Halfedge>(source);
    }
    auto& next = MeshArrays::next(mesh);
    auto& prev = MeshArrays::prev(mesh);
    auto& head = MeshArrays::to_vertex(mesh);
    auto& anchor = MeshArrays::vertex_halfedge(mesh);
    for (std::size_t v = 0; v < anchor.size(); ++v) {
        if (anchor[v].is_valid() && !mesh.is_deleted(Vertex(static_cast<std::uint32_t>(v)))) {
            anchor[v] = prev[anchor[v].idx()];
        }
    }
    // Twins 2k and 2k+1 swap their heads.
    for (std::size_t k = 0; k + 1 < head.size(); k += 2) {
        std::swap(head[k], head[k + 1]);
    }
    next.swap(prev);
}

}  // namespace meshedit
