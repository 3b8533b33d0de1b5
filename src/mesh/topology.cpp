#include "meshedit/core/topology.h"

#include <numeric>
#include <vector>

namespace meshedit {

std::size_t count_boundary_loops(const Mesh& mesh) {
    std::vector<std::uint8_t> visited(mesh.halfedges_size(), 0);
    std::size_t loops = 0;
    for (Halfedge h : mesh.halfedges()) {
        if (!mesh.is_boundary(h) || visited[h.idx()]) {
            continue;
        }
        ++loops;
        for (Halfedge g : mesh.loop(h)) {
            visited[g.idx()] = 1;
        }
    }
    return loops;
}

bool is_closed(const Mesh& mesh) {
    for (Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h)) {
            return false;
        }
    }
    return true;
}

std::vector<std::uint32_t> component_roots(const Mesh& mesh) {
    std::vector<std::uint32_t> parent(mesh.vertices_size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t x) {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        return x;
    };
    for (Edge e : mesh.edges()) {
        const std::uint32_t a = find(mesh.vertex(e, 0).idx());
        const std::uint32_t b = find(mesh.vertex(e, 1).idx());
        if (a != b) {
            parent[std::max(a, b)] = std::min(a, b);
        }
    }
    for (std::uint32_t i = 0; i < parent.size(); ++i) {
        parent[i] = find(i);
    }
    return parent;
}

std::size_t count_components(const Mesh& mesh) {
    const auto roots = component_roots(mesh);
    std::size_t n = 0;
    for (Vertex v : mesh.vertices()) {
        n += roots[v.idx()] == v.idx();
    }
    return n;
}

long euler_characteristic(const Mesh& mesh) {
    return static_cast<long>(mesh.n_vertices()) - static_cast<long>(mesh.n_edges()) +
           static_cast<long>(mesh.n_faces());
}

MeshStats compute_stats(const Mesh& mesh) {
    MeshStats s;
    s.vertices = mesh.n_vertices();
    s.edges = mesh.n_edges();
    s.faces = mesh.n_faces();
    s.boundary_loops = count_boundary_loops(mesh);
    s.components = count_components(mesh);
    s.euler_characteristic = euler_characteristic(mesh);
    // χ = Σ_c (2 − 2g_c − b_c) over surface components; isolated vertices (χ = 1 each) are
    // points, not surfaces, so they are left out of the genus.
    long isolated = 0;
    for (Vertex v : mesh.vertices()) {
        isolated += mesh.is_isolated(v);
    }
    const long surfaces = static_cast<long>(s.components) - isolated;
    const long chi = s.euler_characteristic - isolated;
    s.genus = (2 * surfaces - static_cast<long>(s.boundary_loops) - chi) / 2;
    return s;
}

}  // namespace meshedit
