#pragma once
// What the OpenSubdiv comparisons (opensubdiv_test.cpp: positions and creases;
// opensubdiv_fvar_test.cpp: texture coordinates) share: Far's primvar type and the matching of
// MeshEdit's vertices and faces to Far's after a level.

#include <opensubdiv/far/topologyLevel.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

#include "meshedit/core/mesh.h"

namespace meshedit::test {

// Far's primvar: three numbers (a position, a colour, a texture coordinate and a zero).
struct Point {
    double x = 0, y = 0, z = 0;
    void Clear(void* = nullptr) { x = y = z = 0; }
    void AddWithWeight(const Point& p, double w) {
        x += w * p.x;
        y += w * p.y;
        z += w * p.z;
    }
};

// A face as its vertices, from the smallest index on (the same face whatever corner it
// starts at).
using Cycle = std::vector<int>;
inline Cycle canonical(Cycle c) {
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    return c;
}

// MeshEdit's vertex indices after one level of `before` → Far's at level + 1, from the
// layout (old v, then V + e, then with face points V + E + f) and Far's parent-to-child
// queries; `vmap` and `fmap` map `before`'s vertices and faces to `parent`'s. False (with a
// failure) when an edge of `before` is not one of Far's.
inline bool next_vertex_map(const Mesh& before, const OpenSubdiv::Far::TopologyLevel& parent,
                            bool face_points, std::vector<int>& vmap, const std::vector<int>& fmap,
                            std::size_t new_vertices) {
    const std::size_t nv = before.vertices_size(), ne = before.edges_size();
    std::vector<int> next(new_vertices, -1);
    for (Vertex v : before.vertices()) {
        next[v.idx()] = parent.GetVertexChildVertex(vmap[v.idx()]);
    }
    for (Edge e : before.edges()) {
        const int osd_edge =
            parent.FindEdge(vmap[before.vertex(e, 0).idx()], vmap[before.vertex(e, 1).idx()]);
        EXPECT_GE(osd_edge, 0) << "edge " << e.idx() << " is not a Far edge";
        if (osd_edge < 0) {
            return false;
        }
        next[nv + e.idx()] = parent.GetEdgeChildVertex(osd_edge);
    }
    if (face_points) {
        for (Face f : before.faces()) {
            next[nv + ne + f.idx()] = parent.GetFaceChildVertex(fmap[f.idx()]);
        }
    }
    vmap = next;
    return true;
}

// Far's faces of `child` by their canonical cycles.
inline std::map<Cycle, int> faces_by_cycle(const OpenSubdiv::Far::TopologyLevel& child) {
    std::map<Cycle, int> out;
    for (int f = 0; f < child.GetNumFaces(); ++f) {
        const auto corners = child.GetFaceVertices(f);
        out[canonical(Cycle(corners.begin(), corners.end()))] = f;
    }
    return out;
}

}  // namespace meshedit::test
