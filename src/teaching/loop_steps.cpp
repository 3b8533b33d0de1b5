// Loop subdivision one phase at a time (loop_steps.h), and the classic reference that runs
// the four phases in a row. Only the public mesh API, circulators and the verified local ops
// are used, so it is slow but easy to trust; the tests hold the fast path (subdivision.cpp)
// to its results.

#include "meshedit/core/loop_steps.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/loop_rules.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/validate.h"

namespace meshedit {
namespace {

bool is_sharp(const Mesh& mesh, const EdgeProperty<std::uint8_t>& crease, Edge e) {
    return loop_rules::is_sharp(mesh.is_boundary(e), crease ? crease[e] : 0);
}

// Progress is reported once per this many edges.
constexpr std::uint32_t kProgressEvery = 4096;

// 1. Positions, computed on the unchanged mesh: the target of every vertex and the point of
//    every edge.
std::size_t compute_positions(Mesh& mesh, const LoopOptions& options) {
    const EdgeProperty<std::uint8_t> crease = loop_rules::crease_property(mesh);
    auto target = mesh.property<Vertex, Vec3>(kLoopTarget);
    auto has_target = mesh.property<Vertex, std::uint8_t>(kLoopHasTarget, 0);
    auto edge_point = mesh.property<Edge, Vec3>(kLoopEdgePoint);
    const loop_rules::WeightTable weight(options.weights);
    std::size_t count = 0;
    for (Vertex v : mesh.vertices()) {
        Vec3 sum;
        Vec3 sharp_sum;
        std::size_t n = 0;
        std::size_t n_sharp = 0;
        // Clockwise from the anchor (h -> next(twin(h))), the order the fast path sums in:
        // floating-point sums depend on it, and so the targets are L's to the last bit.
        const Halfedge start = mesh.halfedge(v);
        for (Halfedge h = start; h.is_valid();) {
            const Vec3& q = mesh.position(mesh.to_vertex(h));
            sum += q;
            ++n;
            if (is_sharp(mesh, crease, Mesh::edge(h))) {
                sharp_sum += q;
                ++n_sharp;
            }
            h = mesh.next(Mesh::twin(h));
            if (h == start) {
                break;
            }
        }
        const Vec3& p = mesh.position(v);
        switch (loop_rules::classify(n_sharp)) {
            case loop_rules::VertexRule::Smooth:
                target[v] = loop_rules::smooth_vertex_point(p, sum, n, weight(n));
                break;
            case loop_rules::VertexRule::Crease:
                target[v] = loop_rules::crease_vertex_point(p, sharp_sum);
                break;
            case loop_rules::VertexRule::Corner:
                target[v] = p;
                break;
        }
        has_target[v] = 1;
        ++count;
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
    return count;
}

// 2. Split every original edge, from a snapshot (splitting appends edges). Mark the new
//    vertex and the edges crossing the old faces; both halves of the split edge inherit its
//    crease flag.
std::size_t split_edges(Mesh& mesh, loop_rules::Progress& progress) {
    EdgeProperty<std::uint8_t> crease = loop_rules::crease_property(mesh);
    auto target = mesh.get_property<Vertex, Vec3>(kLoopTarget);
    auto has_target = mesh.get_property<Vertex, std::uint8_t>(kLoopHasTarget);
    auto edge_point = mesh.get_property<Edge, Vec3>(kLoopEdgePoint);
    auto is_new_vertex = mesh.property<Vertex, std::uint8_t>(kLoopNewVertex, 0);
    auto is_new_edge = mesh.property<Edge, std::uint8_t>(kLoopNewEdge, 0);
    const auto nv = static_cast<std::uint32_t>(mesh.vertices_size());
    const auto ne = static_cast<std::uint32_t>(mesh.edges_size());
    std::vector<Edge> original;
    original.reserve(ne);
    for (Edge e : mesh.edges()) {
        original.push_back(e);
    }
    for (Edge e : original) {
        const Vertex a = mesh.from_vertex(Mesh::halfedge(e, 0));
        const Vertex b = mesh.to_vertex(Mesh::halfedge(e, 0));
        const std::uint8_t flag = crease ? crease[e] : 0;
        const OpResult<Vertex> m = split(mesh, e);
        if (!m) {
            throw std::logic_error("Loop: split refused on a triangle mesh");
        }
        // The documented index rule (vertex on edge e is V + e) relies on split appending.
        if ((*m).idx() != nv + e.idx()) {
            throw std::logic_error("Loop: split did not append the vertex");
        }
        is_new_vertex[*m] = 1;
        target[*m] = edge_point[e];
        has_target[*m] = 1;
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
    mesh.remove_property(edge_point);
    return original.size();
}

// 3. Flip each new edge joining an old and a new vertex (one per old triangle).
std::size_t flip_edges(Mesh& mesh) {
    auto is_new_vertex = mesh.get_property<Vertex, std::uint8_t>(kLoopNewVertex);
    auto is_new_edge = mesh.get_property<Edge, std::uint8_t>(kLoopNewEdge);
    auto flipped = mesh.property<Edge, std::uint8_t>(kLoopFlippedEdge, 0);
    std::size_t count = 0;
    const std::size_t n_edges = mesh.edges_size();
    for (std::uint32_t i = 0; i < n_edges; ++i) {
        const Edge e(i);
        if (!mesh.is_deleted(e) && is_new_edge[e] != 0 &&
            is_new_vertex[mesh.vertex(e, 0)] != is_new_vertex[mesh.vertex(e, 1)]) {
            if (!flip(mesh, e)) {
                throw std::logic_error("Loop: flip refused");
            }
            flipped[e] = 1;
            ++count;
        }
    }
    return count;
}

// 4. Every vertex with a target moves there; the phase properties go.
std::size_t move_vertices(Mesh& mesh) {
    auto target = mesh.get_property<Vertex, Vec3>(kLoopTarget);
    auto has_target = mesh.get_property<Vertex, std::uint8_t>(kLoopHasTarget);
    std::size_t count = 0;
    for (Vertex v : mesh.vertices()) {
        if (has_target[v] != 0) {
            mesh.position(v) = target[v];
            ++count;
        }
    }
    mesh.remove_property(target);
    mesh.remove_property(has_target);
    for (const char* flag : {kLoopNewVertex}) {
        if (auto p = mesh.get_property<Vertex, std::uint8_t>(flag)) {
            mesh.remove_property(p);
        }
    }
    for (const char* flag : {kLoopNewEdge, kLoopFlippedEdge}) {
        if (auto p = mesh.get_property<Edge, std::uint8_t>(flag)) {
            mesh.remove_property(p);
        }
    }
    return count;
}

}  // namespace

int next_loop_phase(const Mesh& mesh) {
    if (mesh.has_property<Edge>(kLoopFlippedEdge)) {
        return 4;
    }
    if (mesh.has_property<Vertex>(kLoopNewVertex)) {
        return 3;
    }
    if (mesh.has_property<Vertex>(kLoopTarget)) {
        return 2;
    }
    return 1;
}

OpStatus check_loop_step(const Mesh& mesh) {
    if (next_loop_phase(mesh) != 1) {
        return OpStatus::ok();
    }
    if (const OpStatus ok = is_loop_ok(mesh); !ok) {
        return ok;
    }
    if (!mesh.is_triangle_mesh()) {
        return OpStatus::refused(
            "cannot step Loop: the phases are shown on triangles (Ctrl+T or triangulate first)");
    }
    return OpStatus::ok();
}

LoopStepReport loop_step(Mesh& mesh, const LoopOptions& options) {
    MESHEDIT_ASSERT(check_loop_step(mesh));
    LoopStepReport report;
    report.phase = next_loop_phase(mesh);
    loop_rules::Progress progress(options.progress);
    switch (report.phase) {
        case 1:
            if (mesh.has_garbage()) {
                mesh.garbage_collection();  // the V + e rule needs dense indices
            }
            report.count = compute_positions(mesh, options);
            report.message = "Loop 1/4: computed the new position of " +
                             std::to_string(report.count) + " vertices and " +
                             std::to_string(mesh.n_edges()) + " edge points (nothing moved yet)";
            break;
        case 2:
            if (mesh.has_garbage()) {
                mesh.garbage_collection();  // a local edit since phase 1 deleted elements
            }
            report.count = split_edges(mesh, progress);
            report.message = "Loop 2/4: split " + std::to_string(report.count) + " edges";
            break;
        case 3:
            report.count = flip_edges(mesh);
            report.message = "Loop 3/4: flipped " + std::to_string(report.count) +
                             " new edges that join an old and a new vertex";
            break;
        default:
            report.count = move_vertices(mesh);
            report.message = "Loop 4/4: moved " + std::to_string(report.count) +
                             " vertices to their new positions";
            break;
    }
    MESHEDIT_ASSERT(!validate(mesh));
    return report;
}

LoopReport loop_subdivide_classic(Mesh& mesh, const LoopOptions& options) {
    LoopReport report = loop_rules::prepare(mesh);
    loop_rules::Progress progress(options.progress);
    progress(0.0);
    compute_positions(mesh, options);
    progress(0.2);
    split_edges(mesh, progress);
    progress(0.7);
    flip_edges(mesh);
    progress(0.9);
    move_vertices(mesh);
    MESHEDIT_ASSERT(!validate(mesh));
    progress(1.0);
    return report;
}

}  // namespace meshedit
