// Polygon soup -> halfedge mesh. The only place where input topology is diagnosed.
//
// Outline (all passes are linear except the per-vertex bucket scans, which are O(valence²)):
//   1. drop degenerate faces; check indices and positions;
//   2. pair each face halfedge u->v with the one v->u, bucketing halfedges by their smaller
//      endpoint; an edge used by more than two faces, or twice in one direction, is cut:
//      all its halfedges stay unpaired and become boundary;
//   3. group the corners around each vertex into fans (union-find over corners linked
//      through paired edges); every fan after the first gets a copy of the vertex;
//   4. assign edges in order of first appearance, add boundary twins, link boundary loops.
#include "meshedit/core/build.h"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace meshedit {
namespace {

constexpr std::uint32_t kNone = kInvalidIndex;

struct UnionFind {
    std::vector<std::uint32_t> parent;
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];  // path halving
            x = parent[x];
        }
        return x;
    }
    void unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) {
            parent[std::max(a, b)] = std::min(a, b);
        }
    }
};

bool has_repeated_corner(const std::uint32_t* c, std::size_t k) {
    for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = i + 1; j < k; ++j) {
            if (c[i] == c[j]) {
                return true;
            }
        }
    }
    return false;
}

// Face halfedges of the kept faces, in CSR order: halfedge h runs from corner[h] to
// corner[next[h]].
struct SoupHalfedges {
    std::vector<std::uint32_t> corner;
    std::vector<std::uint32_t> next;
    std::vector<std::uint32_t> prev;
    std::vector<std::uint32_t> face;
    std::vector<std::uint32_t> first;  // first halfedge of each kept face
};

void check_input(const PolygonSoup& soup) {
    const auto& off = soup.face_offsets;
    if (off.empty() || off.front() != 0 || off.back() != soup.indices.size()) {
        throw TopologyError("polygon soup: face offsets do not cover the index list");
    }
    for (std::size_t f = 0; f + 1 < off.size(); ++f) {
        if (off[f + 1] < off[f]) {
            throw TopologyError("polygon soup: face offsets decrease at face " + std::to_string(f));
        }
        for (std::uint32_t i = off[f]; i < off[f + 1]; ++i) {
            if (soup.indices[i] >= soup.positions.size()) {
                throw TopologyError("face " + std::to_string(f) + " uses vertex " +
                                    std::to_string(soup.indices[i]) + ", but there are only " +
                                    std::to_string(soup.positions.size()) + " vertices");
            }
        }
    }
    for (std::size_t v = 0; v < soup.positions.size(); ++v) {
        if (!is_finite(soup.positions[v])) {
            throw TopologyError("vertex " + std::to_string(v) + " has a non-finite coordinate");
        }
    }
}

SoupHalfedges collect_faces(const PolygonSoup& soup, BuildReport& report) {
    SoupHalfedges fh;
    fh.corner.reserve(soup.indices.size());
    fh.first.reserve(soup.n_faces());
    for (std::uint32_t f = 0; f < soup.n_faces(); ++f) {
        const std::uint32_t* c = soup.indices.data() + soup.face_offsets[f];
        const std::size_t k = soup.face_offsets[f + 1] - soup.face_offsets[f];
        if (k < 3 || has_repeated_corner(c, k)) {
            report.dropped_faces.push_back(f);
            continue;
        }
        fh.first.push_back(static_cast<std::uint32_t>(fh.corner.size()));
        fh.corner.insert(fh.corner.end(), c, c + k);
    }
    const std::size_t nh = fh.corner.size();
    fh.next.resize(nh);
    fh.prev.resize(nh);
    fh.face.resize(nh);
    for (std::uint32_t f = 0; f < fh.first.size(); ++f) {
        const std::uint32_t b = fh.first[f];
        const std::uint32_t e =
            f + 1 < fh.first.size() ? fh.first[f + 1] : static_cast<std::uint32_t>(nh);
        for (std::uint32_t h = b; h < e; ++h) {
            fh.next[h] = h + 1 < e ? h + 1 : b;
            fh.prev[h] = h > b ? h - 1 : e - 1;
            fh.face[h] = f;
        }
    }
    return fh;
}

// mate[h] = the opposite face halfedge, or kNone for an unpaired (boundary or cut) one.
std::vector<std::uint32_t> pair_halfedges(const SoupHalfedges& fh, std::size_t n_vertices,
                                          BuildReport& report) {
    const std::size_t nh = fh.corner.size();
    auto from = [&](std::uint32_t h) { return fh.corner[h]; };
    auto to = [&](std::uint32_t h) { return fh.corner[fh.next[h]]; };

    // Bucket halfedges by their smaller endpoint (counting sort).
    std::vector<std::uint32_t> start(n_vertices + 1, 0);
    for (std::uint32_t h = 0; h < nh; ++h) {
        ++start[std::min(from(h), to(h)) + 1];
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::uint32_t> bucket(nh);
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t h = 0; h < nh; ++h) {
        bucket[fill[std::min(from(h), to(h))]++] = h;
    }

    std::vector<std::uint32_t> mate(nh, kNone);
    std::vector<std::uint8_t> seen(nh, 0);
    for (std::uint32_t a = 0; a < n_vertices; ++a) {
        for (std::uint32_t i = start[a]; i < start[a + 1]; ++i) {
            const std::uint32_t h = bucket[i];
            if (seen[h]) {
                continue;
            }
            // All halfedges of the bucket joining the same two vertices as h.
            const std::uint32_t b = from(h) == a ? to(h) : from(h);
            std::uint32_t count = 0, forward = 0, backward = 0;
            std::uint32_t h_fwd = kNone, h_bwd = kNone;
            for (std::uint32_t j = i; j < start[a + 1]; ++j) {
                const std::uint32_t g = bucket[j];
                if (from(g) == b || to(g) == b) {
                    seen[g] = 1;
                    ++count;
                    if (from(g) == from(h)) {
                        ++forward;
                        h_fwd = g;
                    } else {
                        ++backward;
                        h_bwd = g;
                    }
                }
            }
            if (forward == 1 && backward == 1) {
                mate[h_fwd] = h_bwd;
                mate[h_bwd] = h_fwd;
            } else if (count > 1) {
                report.nonmanifold_edges.emplace_back(a, b);
            }
        }
    }
    return mate;
}

}  // namespace

Mesh build_mesh(const PolygonSoup& soup, BuildReport* report_out) {
    check_input(soup);
    BuildReport report;
    const std::size_t nv_in = soup.positions.size();
    const SoupHalfedges fh = collect_faces(soup, report);
    const std::vector<std::uint32_t> mate = pair_halfedges(fh, nv_in, report);
    const auto nh = static_cast<std::uint32_t>(fh.corner.size());
    const auto nf = static_cast<std::uint32_t>(fh.first.size());

    // Corners: corner h is where halfedge h arrives (at corner[next[h]]). Corners around a
    // vertex are linked through paired edges; each linked group is one fan.
    UnionFind fans(nh);
    for (std::uint32_t h = 0; h < nh; ++h) {
        const std::uint32_t m = mate[fh.next[h]];
        if (m != kNone) {
            fans.unite(h, m);
        }
    }
    std::vector<std::uint32_t> fan_vertex(nh, kNone);
    std::vector<std::uint8_t> used(nv_in, 0);
    std::vector<Vec3> extra_positions;
    for (std::uint32_t h = 0; h < nh; ++h) {
        const std::uint32_t root = fans.find(h);
        if (fan_vertex[root] != kNone) {
            continue;
        }
        const std::uint32_t v = fh.corner[fh.next[h]];
        if (!used[v]) {
            used[v] = 1;
            fan_vertex[root] = v;
        } else {
            if (used[v] == 1) {
                report.split_vertices.push_back(v);
                used[v] = 2;
            }
            fan_vertex[root] = static_cast<std::uint32_t>(nv_in + extra_positions.size());
            extra_positions.push_back(soup.positions[v]);
        }
    }
    std::sort(report.split_vertices.begin(), report.split_vertices.end());
    report.added_vertices = extra_positions.size();
    report.isolated_vertices =
        static_cast<std::size_t>(std::count(used.begin(), used.end(), std::uint8_t{0}));
    auto arrival = [&](std::uint32_t h) { return Vertex(fan_vertex[fans.find(h)]); };

    // Edges in order of first appearance: a paired edge is (h, mate); an unpaired one is
    // (h, boundary twin).
    std::vector<std::uint32_t> mesh_halfedge(nh, kNone);
    std::uint32_t n_edges = 0;
    for (std::uint32_t h = 0; h < nh; ++h) {
        if (mesh_halfedge[h] != kNone) {
            continue;
        }
        mesh_halfedge[h] = 2 * n_edges;
        if (mate[h] != kNone) {
            mesh_halfedge[mate[h]] = 2 * n_edges + 1;
        }
        ++n_edges;
    }

    Mesh mesh;
    mesh.resize(nv_in + extra_positions.size(), n_edges, nf);
    std::copy(soup.positions.begin(), soup.positions.end(), mesh.position_vector().begin());
    std::copy(extra_positions.begin(), extra_positions.end(),
              mesh.position_vector().begin() + static_cast<std::ptrdiff_t>(nv_in));

    std::vector<Halfedge> out_boundary(mesh.vertices_size());
    for (std::uint32_t h = 0; h < nh; ++h) {
        const Halfedge mh(mesh_halfedge[h]);
        const Vertex v = arrival(h);
        mesh.set_vertex(mh, v);
        mesh.set_face(mh, Face(fh.face[h]));
        mesh.set_next(mh, Halfedge(mesh_halfedge[fh.next[h]]));
        if (!mesh.halfedge(v).is_valid()) {
            mesh.set_halfedge(v, Halfedge(mesh_halfedge[fh.next[h]]));
        }
        if (mate[h] == kNone) {
            // Boundary twin: runs from v back to where h starts; v's outgoing boundary.
            const Halfedge b = Mesh::twin(mh);
            mesh.set_vertex(b, arrival(fh.prev[h]));
            mesh.set_face(b, Face());
            out_boundary[v.idx()] = b;
        }
    }
    for (std::uint32_t f = 0; f < nf; ++f) {
        mesh.set_halfedge(Face(f), Halfedge(mesh_halfedge[fh.first[f]]));
    }
    // Boundary loops: each vertex has at most one outgoing boundary halfedge (one fan).
    for (std::uint32_t h = 0; h < nh; ++h) {
        if (mate[h] == kNone) {
            const Halfedge b = Mesh::twin(Halfedge(mesh_halfedge[h]));
            mesh.set_next(b, out_boundary[mesh.to_vertex(b).idx()]);
        }
    }
    for (std::uint32_t v = 0; v < out_boundary.size(); ++v) {
        if (out_boundary[v].is_valid()) {
            mesh.set_halfedge(Vertex(v), out_boundary[v]);  // boundary-anchor rule
        }
    }
    if (report_out != nullptr) {
        *report_out = std::move(report);
    }
    return mesh;
}

PolygonSoup to_polygon_soup(const Mesh& mesh) {
    PolygonSoup soup;
    soup.positions = mesh.position_vector();
    soup.indices.reserve(3 * mesh.n_faces());
    soup.face_offsets.reserve(mesh.n_faces() + 1);
    for (Face f : mesh.faces()) {
        // Start at from_vertex(halfedge(f)) so that build_mesh() reproduces the mesh exactly.
        for (Halfedge h : mesh.halfedges(f)) {
            soup.indices.push_back(mesh.from_vertex(h).idx());
        }
        soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.indices.size()));
    }
    return soup;
}

namespace {

template <class List>
std::string list_some(const List& items, std::size_t limit = 8) {
    std::ostringstream s;
    for (std::size_t i = 0; i < items.size() && i < limit; ++i) {
        s << (i ? ", " : "") << items[i];
    }
    if (items.size() > limit) {
        s << ", …";
    }
    return s.str();
}

}  // namespace

std::string BuildReport::summary() const {
    auto count = [](std::size_t n, const char* one, const char* many) {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    std::ostringstream s;
    if (!dropped_faces.empty()) {
        s << "dropped " << count(dropped_faces.size(), "degenerate face", "degenerate faces")
          << " (fewer than 3 corners or a repeated corner): " << list_some(dropped_faces) << "\n";
    }
    if (!nonmanifold_edges.empty()) {
        std::vector<std::string> names;
        for (const auto& [a, b] : nonmanifold_edges) {
            names.push_back(std::to_string(a) + "-" + std::to_string(b));
        }
        s << "cut "
          << count(nonmanifold_edges.size(), "non-manifold or inconsistently oriented edge",
                   "non-manifold or inconsistently oriented edges")
          << " into boundaries: " << list_some(names) << "\n";
    }
    if (!split_vertices.empty()) {
        s << "split "
          << count(split_vertices.size(), "non-manifold vertex", "non-manifold vertices") << " ("
          << list_some(split_vertices) << ") by adding " << count(added_vertices, "copy", "copies")
          << "\n";
    }
    return s.str();
}

}  // namespace meshedit
