// Loop subdivision, classic reference (the shape shared by pmp, geometry-central and OpenMesh
// LoopT): compute every new position first, then split every original edge, flip each new
// edge that joins an old and a new vertex, and commit the positions. It uses only the public
// mesh API, circulators and the verified local ops, so it is slow but easy to trust; the
// tests hold the fast path (subdivision.cpp) to its results.

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "loop_rules.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/validate.h"

namespace meshedit {
namespace {

bool is_sharp(const Mesh& mesh, const EdgeProperty<std::uint8_t>& crease, Edge e) {
    return loop_rules::is_sharp(mesh.is_boundary(e), crease ? crease[e] : 0);
}

// Progress is reported once per this many edges.
constexpr std::uint32_t kProgressEvery = 4096;

}  // namespace

LoopReport loop_subdivide_classic(Mesh& mesh, const LoopOptions& options) {
    LoopReport report = loop_rules::prepare(mesh);
    loop_rules::Progress progress(options.progress);
    progress(0.0);

    const auto nv = static_cast<std::uint32_t>(mesh.vertices_size());
    const auto ne = static_cast<std::uint32_t>(mesh.edges_size());
    EdgeProperty<std::uint8_t> crease = loop_rules::crease_property(mesh);

    // 1. Positions, computed on the unchanged mesh. `point` ends up holding the final
    //    position of every vertex, old and new.
    ScopedProperty<Vertex, Vec3> point(mesh, "v:loop_point");
    ScopedProperty<Edge, Vec3> edge_point(mesh, "e:loop_point");
    const loop_rules::WeightTable weight(options.weights);
    for (Vertex v : mesh.vertices()) {
        Vec3 sum;
        Vec3 sharp_sum;
        std::size_t n = 0;
        std::size_t n_sharp = 0;
        for (Halfedge h : mesh.halfedges(v)) {
            const Vec3& q = mesh.position(mesh.to_vertex(h));
            sum += q;
            ++n;
            if (is_sharp(mesh, crease, Mesh::edge(h))) {
                sharp_sum += q;
                ++n_sharp;
            }
        }
        const Vec3& p = mesh.position(v);
        switch (loop_rules::classify(n_sharp)) {
            case loop_rules::VertexRule::Smooth:
                point[v] = loop_rules::smooth_vertex_point(p, sum, n, weight(n));
                break;
            case loop_rules::VertexRule::Crease:
                point[v] = loop_rules::crease_vertex_point(p, sharp_sum);
                break;
            case loop_rules::VertexRule::Corner:
                point[v] = p;
                break;
        }
    }
    for (Edge e : mesh.edges()) {
        const Halfedge h0 = Mesh::halfedge(e, 0);
        const Halfedge h1 = Mesh::halfedge(e, 1);
        const Vec3& a = mesh.position(mesh.to_vertex(h1));
        const Vec3& b = mesh.position(mesh.to_vertex(h0));
        if (is_sharp(mesh, crease, e)) {
            edge_point[e] = loop_rules::sharp_edge_point(a, b);
        } else {
            const Vec3& c = mesh.position(mesh.to_vertex(mesh.next(h0)));
            const Vec3& d = mesh.position(mesh.to_vertex(mesh.next(h1)));
            edge_point[e] = loop_rules::smooth_edge_point(a, b, c, d);
        }
    }
    progress(0.2);

    // 2. Split every original edge, from a snapshot (splitting appends edges). Mark the new
    //    vertex and the edges crossing the old faces; both halves of the split edge inherit
    //    its crease flag.
    std::vector<Edge> original;
    original.reserve(ne);
    for (Edge e : mesh.edges()) {
        original.push_back(e);
    }
    ScopedProperty<Vertex, std::uint8_t> is_new_vertex(mesh, "v:loop_new", 0);
    ScopedProperty<Edge, std::uint8_t> is_new_edge(mesh, "e:loop_new", 0);
    for (Edge e : original) {
        const Vertex a = mesh.from_vertex(Mesh::halfedge(e, 0));
        const Vertex b = mesh.to_vertex(Mesh::halfedge(e, 0));
        const std::uint8_t flag = crease ? crease[e] : 0;
        const OpResult<Vertex> m = split(mesh, e);
        if (!m) {
            throw std::logic_error("loop_subdivide_classic: split refused on a triangle mesh");
        }
        // The documented index rule (vertex on edge e is V + e) relies on split appending.
        if ((*m).idx() != nv + e.idx()) {
            throw std::logic_error("loop_subdivide_classic: split did not append the vertex");
        }
        is_new_vertex[*m] = 1;
        point[*m] = edge_point[e];
        for (Halfedge h : mesh.halfedges(*m)) {
            const Vertex w = mesh.to_vertex(h);
            if (w == a || w == b) {
                if (crease) {
                    crease[Mesh::edge(h)] = flag;
                }
            } else {
                is_new_edge[Mesh::edge(h)] = 1;
            }
        }
        if (e.idx() % kProgressEvery == 0) {
            progress(0.2 + 0.5 * e.idx() / ne);
        }
    }
    progress(0.7);

    // 3. Flip each new edge joining an old and a new vertex (one per old triangle).
    const std::size_t n_edges = mesh.edges_size();
    for (std::uint32_t i = 0; i < n_edges; ++i) {
        const Edge e(i);
        if (is_new_edge[e] != 0 &&
            is_new_vertex[mesh.vertex(e, 0)] != is_new_vertex[mesh.vertex(e, 1)]) {
            if (!flip(mesh, e)) {
                throw std::logic_error("loop_subdivide_classic: flip refused");
            }
        }
    }
    progress(0.9);

    // 4. Commit the positions.
    mesh.position_vector() = point.vector();
    MESHEDIT_ASSERT(!validate(mesh));
    progress(1.0);
    return report;
}

}  // namespace meshedit
