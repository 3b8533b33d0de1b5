// Region selection (selection.h): loops, rings, floods, traits, conversions, paths.

#include "meshedit/selection/selection.h"

#include <bit>
#include <cmath>
#include <functional>
#include <queue>
#include <utility>

#include "meshedit/core/attributes.h"
#include "meshedit/core/normals.h"

namespace meshedit {

template <class H>
std::size_t ElementSet<H>::count() const {
    std::size_t n = 0;
    for (const std::uint64_t w : words_) {
        n += static_cast<std::size_t>(std::popcount(w));
    }
    return n;
}

template <class H>
std::vector<H> ElementSet<H>::elements() const {
    std::vector<H> out;
    out.reserve(count());
    for (std::size_t i = 0; i < words_.size(); ++i) {
        for (std::uint64_t w = words_[i]; w != 0; w &= w - 1) {
            out.push_back(H(static_cast<std::uint32_t>(64 * i + std::countr_zero(w))));
        }
    }
    return out;
}

template class ElementSet<Vertex>;
template class ElementSet<Edge>;
template class ElementSet<Face>;

namespace {

// ------------------------------------------------------------ loops and rings

// The halfedge that goes on from `h` (arriving at v = to_vertex(h)) along the loop, or none.
// Interior v of valence 4: its outgoing halfedges o0..o3 counter-clockwise with o0 = twin(h);
// the loop goes on along o2. A boundary h (or twin) at a border vertex of valence 3 goes on
// along the next boundary halfedge.
//
//            o1                        border:   x <--- v <--- (h)
//            ^                                          |
//   twin(h)  |   o2 (next)                              o (into the faces)
//   <------- v ------->
//            |
//            o3
Halfedge loop_next(const Mesh& mesh, Halfedge h) {
    const Vertex v = mesh.to_vertex(h);
    if (mesh.is_boundary(Mesh::edge(h))) {
        if (!mesh.is_boundary(v) || mesh.valence(v) != 3) {
            return Halfedge();
        }
        // Walk on along the border in h's direction: the boundary halfedge side of h's edge.
        const Halfedge b = mesh.is_boundary(h) ? h : Mesh::twin(h);
        const bool along = b == h;
        const Halfedge next = along ? mesh.next(b) : Mesh::twin(mesh.prev(b));
        return next;
    }
    if (mesh.is_boundary(v) || mesh.valence(v) != 4) {
        return Halfedge();
    }
    return mesh.ccw_rotated(mesh.ccw_rotated(Mesh::twin(h)));
}

// The halfedge across the quad left of `h` from it (the ring's next), or none.
Halfedge ring_next(const Mesh& mesh, Halfedge h) {
    const Face f = mesh.face(h);
    if (!f.is_valid() || mesh.valence(f) != 4) {
        return Halfedge();
    }
    return Mesh::twin(mesh.next(mesh.next(h)));
}

// Walks from e one way, and if that does not come back to e, the other. Each step is a
// one-to-one map of halfedges (it can be walked back), so a walk meets no edge twice before
// it meets e; the step bound only guards that argument.
template <class Next>
std::vector<Edge> walk_both_ways(const Mesh& mesh, Edge e, const Next& next) {
    MESHEDIT_ASSERT(mesh.is_valid(e) && !mesh.is_deleted(e));
    std::vector<Edge> out{e};
    const auto walk = [&](Halfedge h) {
        for (Halfedge x = next(mesh, h); x.is_valid() && out.size() <= mesh.edges_size();
             x = next(mesh, x)) {
            if (Mesh::edge(x) == e) {
                return true;  // closed
            }
            out.push_back(Mesh::edge(x));
        }
        return false;
    };
    if (!walk(Mesh::halfedge(e, 0))) {
        walk(Mesh::halfedge(e, 1));
    }
    return out;
}

}  // namespace

std::vector<Edge> edge_loop(const Mesh& mesh, Edge e) {
    return walk_both_ways(mesh, e, loop_next);
}

std::vector<Edge> edge_ring(const Mesh& mesh, Edge e) {
    return walk_both_ways(mesh, e, ring_next);
}

// ------------------------------------------------------------ regions

namespace {

bool is_seam(const Mesh& mesh, Edge e) {
    const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    if (!uv || mesh.is_boundary(e)) {
        return false;
    }
    const Halfedge h = Mesh::halfedge(e, 0);
    const Halfedge t = Mesh::halfedge(e, 1);
    // The corners of the two faces at each end: uv[h] and uv[prev(t)] at to_vertex(h).
    return uv[h] != uv[mesh.prev(t)] || uv[t] != uv[mesh.prev(h)];
}

}  // namespace

FaceSet linked_faces(const Mesh& mesh, const FaceSet& seeds, const LinkedOptions& options) {
    FaceSet out(mesh.faces_size());
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    const bool creases = options.stop_at_creases && crease;
    const bool seams = options.stop_at_seams && mesh.has_property<Halfedge>(kTexCoordProperty);
    // Breadth first, the queue a plain array read from the front: faces are visited in
    // waves, which on a mesh stored in scan order keeps the reads close together.
    std::vector<Face> queue;
    for (const Face f : seeds.elements()) {
        if (f.idx() < mesh.faces_size() && !mesh.is_deleted(f) && !out.contains(f)) {
            out.insert(f);
            queue.push_back(f);
        }
    }
    for (std::size_t next = 0; next < queue.size(); ++next) {
        const Halfedge start = mesh.halfedge(queue[next]);
        Halfedge h = start;
        do {
            const Face g = mesh.face(Mesh::twin(h));
            if (g.is_valid() && !out.contains(g)) {
                const Edge e = Mesh::edge(h);
                if (!(creases && crease[e] != 0) && !(seams && is_seam(mesh, e))) {
                    out.insert(g);
                    queue.push_back(g);
                }
            }
            h = mesh.next(h);
        } while (h != start);
    }
    return out;
}

FaceSet grow(const Mesh& mesh, const FaceSet& faces) {
    FaceSet out = faces;
    for (const Face f : faces.elements()) {
        for (const Halfedge h : mesh.halfedges(f)) {
            for (const Halfedge o : mesh.halfedges(mesh.to_vertex(h))) {
                if (const Face g = mesh.face(o); g.is_valid()) {
                    out.insert(g);
                }
            }
        }
    }
    return out;
}

FaceSet shrink(const Mesh& mesh, const FaceSet& faces) {
    FaceSet out = faces;
    for (const Face f : faces.elements()) {
        bool inner = true;
        for (const Halfedge h : mesh.halfedges(f)) {
            for (const Halfedge o : mesh.halfedges(mesh.to_vertex(h))) {
                const Face g = mesh.face(o);
                inner = inner && g.is_valid() && faces.contains(g);
            }
        }
        if (!inner) {
            out.erase(f);
        }
    }
    return out;
}

VertexSet grow(const Mesh& mesh, const VertexSet& vertices) {
    VertexSet out = vertices;
    for (const Vertex v : vertices.elements()) {
        if (!mesh.is_isolated(v)) {
            for (const Halfedge o : mesh.halfedges(v)) {
                out.insert(mesh.to_vertex(o));
            }
        }
    }
    return out;
}

VertexSet shrink(const Mesh& mesh, const VertexSet& vertices) {
    VertexSet out = vertices;
    for (const Vertex v : vertices.elements()) {
        bool inner = !mesh.is_boundary(v);
        if (!mesh.is_isolated(v)) {
            for (const Halfedge o : mesh.halfedges(v)) {
                inner = inner && vertices.contains(mesh.to_vertex(o));
            }
        }
        if (!inner) {
            out.erase(v);
        }
    }
    return out;
}

template <class H>
ElementSet<H> invert(const Mesh& mesh, const ElementSet<H>& set) {
    ElementSet<H> out(set.size());
    for (std::uint32_t i = 0; i < set.size(); ++i) {
        if (!mesh.is_deleted(H(i)) && !set.contains(H(i))) {
            out.insert(H(i));
        }
    }
    return out;
}
template VertexSet invert(const Mesh&, const VertexSet&);
template EdgeSet invert(const Mesh&, const EdgeSet&);
template FaceSet invert(const Mesh&, const FaceSet&);

// ------------------------------------------------------------ by trait

EdgeSet edges_with(const Mesh& mesh, const TraitQuery& query) {
    EdgeSet out(mesh.edges_size());
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    for (const Edge e : mesh.edges()) {
        const bool has = query.trait == Trait::Boundary ? mesh.is_boundary(e)
                         : query.trait == Trait::Crease ? crease && crease[e] != 0
                                                        : false;
        if (has) {
            out.insert(e);
        }
    }
    return out;
}

VertexSet vertices_with(const Mesh& mesh, const TraitQuery& query) {
    if (query.trait == Trait::Crease) {
        return vertices_of_edges(mesh, edges_with(mesh, query));
    }
    if (query.trait == Trait::Degree || query.trait == Trait::FacingAway) {
        return vertices_of_faces(mesh, faces_with(mesh, query));
    }
    VertexSet out(mesh.vertices_size());
    for (const Vertex v : mesh.vertices()) {
        const bool has =
            query.trait == Trait::Boundary ? mesh.is_boundary(v) : mesh.valence(v) == query.k;
        if (has) {
            out.insert(v);
        }
    }
    return out;
}

FaceSet faces_with(const Mesh& mesh, const TraitQuery& query) {
    FaceSet out(mesh.faces_size());
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    const double cos_limit = std::cos(query.angle_deg * 3.14159265358979323846 / 180.0);
    const Vec3 d = normalize(query.direction);
    for (const Face f : mesh.faces()) {
        bool has = false;
        switch (query.trait) {
            case Trait::Boundary:
            case Trait::Crease:
                for (const Halfedge h : mesh.halfedges(f)) {
                    const Edge e = Mesh::edge(h);
                    has = has || (query.trait == Trait::Boundary ? mesh.is_boundary(e)
                                                                 : crease && crease[e] != 0);
                }
                break;
            case Trait::Degree:
                has = mesh.valence(f) == query.k;
                break;
            case Trait::FacingAway: {
                const Vec3 n = face_normal(mesh, f);
                has = sqrnorm(n) > 0.0 && dot(n, d) < cos_limit;
                break;
            }
            case Trait::Valence:
                for (const Halfedge h : mesh.halfedges(f)) {
                    has = has || mesh.valence(mesh.to_vertex(h)) == query.k;
                }
                break;
        }
        if (has) {
            out.insert(f);
        }
    }
    return out;
}

// ------------------------------------------------------------ between modes

EdgeSet edges_of_vertices(const Mesh& mesh, const VertexSet& vertices) {
    EdgeSet out(mesh.edges_size());
    for (const Edge e : mesh.edges()) {
        if (vertices.contains(mesh.vertex(e, 0)) && vertices.contains(mesh.vertex(e, 1))) {
            out.insert(e);
        }
    }
    return out;
}

FaceSet faces_of_vertices(const Mesh& mesh, const VertexSet& vertices) {
    FaceSet out(mesh.faces_size());
    for (const Face f : mesh.faces()) {
        bool all = true;
        for (const Halfedge h : mesh.halfedges(f)) {
            all = all && vertices.contains(mesh.to_vertex(h));
        }
        if (all) {
            out.insert(f);
        }
    }
    return out;
}

VertexSet vertices_of_faces(const Mesh& mesh, const FaceSet& faces) {
    VertexSet out(mesh.vertices_size());
    for (const Face f : faces.elements()) {
        for (const Halfedge h : mesh.halfedges(f)) {
            out.insert(mesh.to_vertex(h));
        }
    }
    return out;
}

VertexSet vertices_of_edges(const Mesh& mesh, const EdgeSet& edges) {
    VertexSet out(mesh.vertices_size());
    for (const Edge e : edges.elements()) {
        out.insert(mesh.vertex(e, 0));
        out.insert(mesh.vertex(e, 1));
    }
    return out;
}

// ------------------------------------------------------------ shortest paths

namespace {

// Dijkstra over `n` nodes from `from` to `to`; `neighbours(i, visit)` calls visit(j, length)
// for each neighbour. Ties between equal distances go to the lower index.
template <class Neighbours>
std::optional<std::vector<std::uint32_t>> dijkstra(std::size_t n, std::uint32_t from,
                                                   std::uint32_t to, const Neighbours& neighbours) {
    constexpr auto kNone = static_cast<std::uint32_t>(-1);
    std::vector<double> distance(n, INFINITY);
    std::vector<std::uint32_t> parent(n, kNone);
    using Entry = std::pair<double, std::uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    distance[from] = 0.0;
    queue.push({0.0, from});
    while (!queue.empty()) {
        const auto [d, i] = queue.top();
        queue.pop();
        if (d > distance[i]) {
            continue;
        }
        if (i == to) {
            break;
        }
        neighbours(i, [&](std::uint32_t j, double length) {
            const double through = d + length;
            if (through < distance[j] || (through == distance[j] && i < parent[j])) {
                distance[j] = through;
                parent[j] = i;
                queue.push({through, j});
            }
        });
    }
    if (from != to && parent[to] == kNone) {
        return std::nullopt;
    }
    std::vector<std::uint32_t> path;
    for (std::uint32_t i = to; i != from; i = parent[i]) {
        path.push_back(i);
    }
    path.push_back(from);
    return std::vector<std::uint32_t>(path.rbegin(), path.rend());
}

}  // namespace

std::optional<std::vector<Vertex>> shortest_vertex_path(const Mesh& mesh, Vertex a, Vertex b) {
    MESHEDIT_ASSERT(!mesh.is_deleted(a) && !mesh.is_deleted(b));
    const auto path =
        dijkstra(mesh.vertices_size(), a.idx(), b.idx(), [&](std::uint32_t i, const auto& visit) {
            const Vertex v(i);
            if (mesh.is_isolated(v)) {
                return;
            }
            for (const Halfedge o : mesh.halfedges(v)) {
                const Vertex w = mesh.to_vertex(o);
                visit(w.idx(), norm(mesh.position(w) - mesh.position(v)));
            }
        });
    if (!path) {
        return std::nullopt;
    }
    std::vector<Vertex> out;
    for (const std::uint32_t i : *path) {
        out.emplace_back(i);
    }
    return out;
}

std::optional<std::vector<Face>> shortest_face_path(const Mesh& mesh, Face f, Face g) {
    MESHEDIT_ASSERT(!mesh.is_deleted(f) && !mesh.is_deleted(g));
    const auto path =
        dijkstra(mesh.faces_size(), f.idx(), g.idx(), [&](std::uint32_t i, const auto& visit) {
            const Face x(i);
            const Vec3 c = face_centroid(mesh, x);
            for (const Halfedge h : mesh.halfedges(x)) {
                if (const Face y = mesh.face(Mesh::twin(h)); y.is_valid()) {
                    visit(y.idx(), norm(face_centroid(mesh, y) - c));
                }
            }
        });
    if (!path) {
        return std::nullopt;
    }
    std::vector<Face> out;
    for (const std::uint32_t i : *path) {
        out.emplace_back(i);
    }
    return out;
}

}  // namespace meshedit
