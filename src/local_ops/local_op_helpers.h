#pragma once
// Private to meshedit_core: small steps several local operations share.

#include "meshedit/core/mesh.h"

namespace meshedit {

/// Every halfedge that arrives at `from` arrives at `to` instead (one walk around `from`,
/// reading only next and prev, so it may run before any relinking). The first step of a
/// merge of two vertices (collapse, weld).
inline void redirect_arrivals(Mesh& mesh, Vertex from, Vertex to) {
    const Halfedge start = mesh.halfedge(from);
    Halfedge h = start;
    do {
        mesh.set_vertex(Mesh::twin(h), to);
        h = mesh.ccw_rotated(h);
    } while (h != start);
}

}  // namespace meshedit
