// Loop subdivision, fast path: the refined mesh is written directly into exactly sized arrays.
//
// Index layout of the result (V, E, F = old counts after garbage collection and
// triangulation; V' = V + E, E' = 2E + 3F, F' = 4F):
//
//   vertices   [0, V)        the old vertices, same indices
//              V + e         the new vertex m_e on old edge e
//   edges      [0, 2E)       new edge g is the half of old edge g/2 at the tail of old halfedge
//                            g: its halfedge 2g runs from_vertex(g) -> m, 2g+1 runs back.
//                            So old halfedge h becomes first(h) = 2h then
//                            second(h) = 2·twin(h) + 1 (m -> to_vertex(h)).
//              2E + 3f + i   the inner edge of old face f cutting off corner i; its halfedge
//                            2(2E+3f+i) lies in the corner triangle, +1 in the centre one
//   faces      4f + i        corner triangle i (i = 0, 1, 2) of old face f
//              4f + 3        centre triangle of old face f
//
// For old face f with halfedges h0 = halfedge(f), h1 = next(h0), h2 = next(h1), corner i is
// c_i = to_vertex(h_i) and m_i is the new vertex on h_i:
//
//                 c_i
//               /     ^
//    first(h_i+1)      second(h_i)        corner face 4f+i (counter-clockwise):
//             v          \                  second(h_i) -> first(h_i+1) -> 2I_i
//         m_i+1 --------> m_i
//                 2I_i                     2I_i runs m_i+1 -> m_i; its twin 2I_i+1 runs
//                                          m_i -> m_i+1 around the centre face 4f+3
//
// Passes: one over the old edges (edge points, neighbour sums, sharp counts), one over the
// old vertices (vertex points), one over the old halfedges (appending new halfedges 2h and
// 2h+1), one over the old faces (appending the inner halfedges and the faces), one over the
// vertices (anchors). Every new element is written once; halfedge and face arrays are
// appended in index order. No allocation happens per element, and no hashing: every new
// index is a formula of old indices.
//
// Why it equals loop_subdivide_classic(): splitting edge e there appends vertex V + e (edges
// are split in index order), and after the flips each old triangle (c0, c1, c2) is replaced
// by exactly the four triangles (c_i, m_i+1, m_i) and (m0, m1, m2) written here; Loop
// connectivity has no other choice. Positions go through the same rules (loop_rules.h) from
// the same old mesh. The tests compare both on several meshes.

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "loop_rules.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/validate.h"

namespace meshedit {
namespace {

using loop_rules::Progress;

// Elements per progress report: large enough that the callback costs nothing.
constexpr std::size_t kChunk = std::size_t{1} << 16;

// Runs body(begin, end) over [0, n), in chunks when progress is wanted, reporting a fraction
// that goes from `lo` to `hi`.
template <class Body>
void chunked(std::size_t n, Progress& progress, double lo, double hi, Body&& body) {
    if (!progress.enabled()) {
        body(std::size_t{0}, n);
        return;
    }
    for (std::size_t begin = 0; begin < n; begin += kChunk) {
        const std::size_t end = std::min(n, begin + kChunk);
        body(begin, end);
        progress(lo + (hi - lo) * static_cast<double>(end) / static_cast<double>(n));
    }
    progress(hi);
}

// Moves the contents out of a property array, leaving it empty (and unallocated).
template <class T>
std::vector<T> take(std::vector<T>& v) {
    std::vector<T> out;
    out.swap(v);
    return out;
}

template <class H, class T>
std::vector<T>& array(Mesh& mesh, const char* name) {
    return mesh.get_property<H, T>(name).vector();
}

constexpr std::uint32_t u32(std::size_t i) {
    return static_cast<std::uint32_t>(i);
}

// The old mesh's connectivity, moved out of the mesh before the new arrays are allocated.
struct OldMesh {
    std::vector<Halfedge> next;
    std::vector<Halfedge> prev;
    std::vector<Vertex> to;
    std::vector<Face> face;
    std::vector<Halfedge> face_halfedge;
    std::vector<Halfedge> vertex_halfedge;
    std::vector<std::uint8_t> crease;  // empty when the mesh has no crease flags

    bool is_sharp(std::size_t e) const {
        const bool boundary = !face[2 * e].is_valid() || !face[2 * e + 1].is_valid();
        return loop_rules::is_sharp(boundary, crease.empty() ? 0 : crease[e]);
    }
};

// New positions: [0, V) the moved old vertices, [V, V + E) the edge points. One pass over
// the edges computes the edge points and accumulates neighbour sums, valences and sharp-edge
// counts; one pass over the vertices applies the vertex rules.
std::vector<Vec3> loop_positions(const OldMesh& old, const std::vector<Vec3>& p,
                                 LoopWeights weights, Progress& progress) {
    const std::size_t nv = p.size();
    const std::size_t ne = old.to.size() / 2;
    std::vector<Vec3> out(nv + ne);  // [0, V) first holds the neighbour sums
    std::vector<std::uint32_t> valence(nv, 0);
    std::vector<std::uint8_t> n_sharp(nv, 0);  // saturates at 3 (a corner)

    chunked(ne, progress, 0.0, 0.25, [&](std::size_t begin, std::size_t end) {
        for (std::size_t e = begin; e < end; ++e) {
            const std::uint32_t a = old.to[2 * e + 1].idx();
            const std::uint32_t b = old.to[2 * e].idx();
            out[a] += p[b];
            out[b] += p[a];
            ++valence[a];
            ++valence[b];
            if (old.is_sharp(e)) {
                n_sharp[a] = static_cast<std::uint8_t>(n_sharp[a] + (n_sharp[a] < 3));
                n_sharp[b] = static_cast<std::uint8_t>(n_sharp[b] + (n_sharp[b] < 3));
                out[nv + e] = loop_rules::sharp_edge_point(p[a], p[b]);
            } else {
                const Vertex c = old.to[old.next[2 * e].idx()];
                const Vertex d = old.to[old.next[2 * e + 1].idx()];
                out[nv + e] = loop_rules::smooth_edge_point(p[a], p[b], p[c.idx()], p[d.idx()]);
            }
        }
    });

    const loop_rules::WeightTable u(weights);
    chunked(nv, progress, 0.25, 0.4, [&](std::size_t begin, std::size_t end) {
        for (std::size_t v = begin; v < end; ++v) {
            switch (loop_rules::classify(n_sharp[v])) {
                case loop_rules::VertexRule::Smooth:
                    out[v] =
                        loop_rules::smooth_vertex_point(p[v], out[v], valence[v], u(valence[v]));
                    break;
                case loop_rules::VertexRule::Crease: {
                    // Rare (boundary and crease curves): find the two sharp edges by walking
                    // the old one-ring clockwise, h -> next(twin(h)).
                    Vec3 sharp_sum;
                    const Halfedge start = old.vertex_halfedge[v];
                    Halfedge h = start;
                    do {
                        if (old.is_sharp(h.idx() >> 1)) {
                            sharp_sum += p[old.to[h.idx()].idx()];
                        }
                        h = old.next[h.idx() ^ 1u];
                    } while (h != start);
                    out[v] = loop_rules::crease_vertex_point(p[v], sharp_sum);
                    break;
                }
                case loop_rules::VertexRule::Corner:
                    out[v] = p[v];
                    break;
            }
        }
    });
    return out;
}

// Emits the connectivity of the refined mesh. Every halfedge and face array is appended in
// index order (push_back into an exactly reserved vector), so each element is written once,
// sequentially, with no default-initialisation pass before it.
//
// Halfedges [0, 4E) come from one pass over the old halfedges h: 2h = first(h) and
// 2h+1 = second(twin(h)). Halfedges [4E, 4E + 6F) and all faces come from one pass over the
// old faces. Only the vertex anchors are written by index afterwards.
void loop_connectivity(Mesh& mesh, const OldMesh& old, std::size_t nv, Progress& progress) {
    const std::size_t nh = old.to.size();
    const std::size_t ne = nh / 2;
    const std::size_t nf = old.face_halfedge.size();
    const std::size_t new_nh = 2 * (2 * ne + 3 * nf);

    std::vector<Halfedge>& next = array<Halfedge, Halfedge>(mesh, "h:next");
    std::vector<Halfedge>& prev = array<Halfedge, Halfedge>(mesh, "h:prev");
    std::vector<Vertex>& to = array<Halfedge, Vertex>(mesh, "h:vertex");
    std::vector<Face>& face = array<Halfedge, Face>(mesh, "h:face");
    std::vector<Halfedge>& face_halfedge = array<Face, Halfedge>(mesh, "f:halfedge");
    next.reserve(new_nh);
    prev.reserve(new_nh);
    to.reserve(new_nh);
    face.reserve(new_nh);
    face_halfedge.reserve(4 * nf);

    // Position (0, 1, 2) of interior old halfedge h in its face, counted from halfedge(f).
    auto corner = [&](std::size_t h) -> std::uint32_t {
        const Halfedge h0 = old.face_halfedge[old.face[h].idx()];
        return h0.idx() == h ? 0 : (old.next[h0.idx()].idx() == h ? 1 : 2);
    };
    // Halfedge 2I_i of old face f (the inner edge cutting off corner i, corner side).
    auto inner = [&](std::size_t f, std::uint32_t i) {
        return Halfedge(u32(2 * (2 * ne + 3 * f + i)));
    };
    // first(h) = 2h, second(h) = 2·twin(h) + 1.
    auto first = [](std::size_t h) { return Halfedge(u32(2 * h)); };
    auto second = [](std::size_t h) { return Halfedge(u32(2 * (h ^ 1) + 1)); };

    chunked(nh, progress, 0.4, 0.7, [&](std::size_t begin, std::size_t end) {
        for (std::size_t h = begin; h < end; ++h) {
            const std::size_t t = h ^ 1;
            // 2h = first(h), from(h) -> m. Interior h = h_j of face f: side b of corner
            // i = j - 1, between second(h_i) and 2I_i. Boundary: between second(prev(h)) and
            // second(h). Either way prev is second(prev(h)).
            const Face f = old.face[h];
            prev.push_back(second(old.prev[h].idx()));
            if (f.is_valid()) {
                const std::uint32_t i = (corner(h) + 2) % 3;
                next.push_back(inner(f.idx(), i));
                face.push_back(Face(4 * f.idx() + i));
            } else {
                next.push_back(second(h));
                face.push_back(Face());
            }
            to.push_back(Vertex(u32(nv + h / 2)));

            // 2h+1 = second(t), m -> to(t). Interior t = h_k of face g: side a of corner k,
            // between 2I_k and first(h_k+1). Boundary: between first(t) and
            // first(next(t)). Either way next is first(next(t)).
            const Face g = old.face[t];
            next.push_back(first(old.next[t].idx()));
            if (g.is_valid()) {
                const std::uint32_t k = corner(t);
                prev.push_back(inner(g.idx(), k));
                face.push_back(Face(4 * g.idx() + k));
            } else {
                prev.push_back(first(t));
                face.push_back(Face());
            }
            to.push_back(old.to[t]);
        }
    });

    chunked(nf, progress, 0.7, 0.95, [&](std::size_t begin, std::size_t end) {
        for (std::size_t f = begin; f < end; ++f) {
            std::uint32_t hs[3];
            hs[0] = old.face_halfedge[f].idx();
            hs[1] = old.next[hs[0]].idx();
            hs[2] = old.next[hs[1]].idx();
            for (std::uint32_t i = 0; i < 3; ++i) {
                const std::uint32_t j = i == 2 ? 0 : i + 1;  // i + 1 and i - 1, mod 3
                const std::uint32_t l = i == 0 ? 2 : i - 1;
                // 2I_i: m_j -> m_i in corner face 4f+i, between first(h_j) and second(h_i).
                next.push_back(second(hs[i]));
                prev.push_back(first(hs[j]));
                to.push_back(Vertex(u32(nv + hs[i] / 2)));
                face.push_back(Face(u32(4 * f + i)));
                // 2I_i + 1: m_i -> m_j around the centre face 4f+3.
                next.push_back(Halfedge(inner(f, j).idx() + 1));
                prev.push_back(Halfedge(inner(f, l).idx() + 1));
                to.push_back(Vertex(u32(nv + hs[j] / 2)));
                face.push_back(Face(u32(4 * f + 3)));
            }
            // Faces 4f+i are anchored at first(h_i+1), the centre at 2I_0 + 1.
            face_halfedge.push_back(first(hs[1]));
            face_halfedge.push_back(first(hs[2]));
            face_halfedge.push_back(first(hs[0]));
            face_halfedge.push_back(Halfedge(inner(f, 0).idx() + 1));
        }
    });

    // Both children of a crease edge stay creases; inner edges are not creases.
    if (!old.crease.empty()) {
        std::vector<std::uint8_t>& crease = array<Edge, std::uint8_t>(mesh, kCreaseProperty);
        crease.reserve(2 * ne + 3 * nf);
        for (std::size_t g = 0; g < nh; ++g) {
            crease.push_back(old.crease[g / 2]);
        }
        crease.resize(2 * ne + 3 * nf, 0);
    }

    // Vertex anchors, keeping the boundary-anchor rule: an old vertex's first(h) is on the
    // boundary iff h was; m_e leaves along second() of e's boundary halfedge, if any.
    std::vector<Halfedge>& vertex_halfedge = array<Vertex, Halfedge>(mesh, "v:halfedge");
    for (std::size_t v = 0; v < nv; ++v) {
        const Halfedge h = old.vertex_halfedge[v];
        vertex_halfedge[v] = h.is_valid() ? first(h.idx()) : Halfedge();
    }
    for (std::size_t e = 0; e < ne; ++e) {
        const bool h1_boundary = !old.face[2 * e + 1].is_valid();
        vertex_halfedge[nv + e] = second(h1_boundary ? 2 * e + 1 : 2 * e);
    }
}

}  // namespace

LoopReport loop_subdivide(Mesh& mesh, const LoopOptions& options) {
    LoopReport report = loop_rules::prepare(mesh);
    Progress progress(options.progress);
    progress(0.0);

    const std::size_t nv = mesh.vertices_size();
    const std::size_t ne = mesh.edges_size();
    const std::size_t nf = mesh.faces_size();
    const std::size_t new_nv = nv + ne;
    const std::size_t new_ne = 2 * ne + 3 * nf;
    const std::size_t new_nf = 4 * nf;
    if (2 * new_ne >= kInvalidIndex || new_nv >= kInvalidIndex) {
        throw std::length_error("loop_subdivide: the result would exceed 2^32 - 1 elements");
    }

    try {
        // Move the old connectivity out of the mesh (the arrays are left empty).
        OldMesh old;
        old.next = take(array<Halfedge, Halfedge>(mesh, "h:next"));
        old.prev = take(array<Halfedge, Halfedge>(mesh, "h:prev"));
        old.to = take(array<Halfedge, Vertex>(mesh, "h:vertex"));
        old.face = take(array<Halfedge, Face>(mesh, "h:face"));
        old.face_halfedge = take(array<Face, Halfedge>(mesh, "f:halfedge"));
        old.vertex_halfedge = take(array<Vertex, Halfedge>(mesh, "v:halfedge"));
        EdgeProperty<std::uint8_t> crease = loop_rules::crease_property(mesh);
        if (crease) {
            old.crease = take(crease.vector());
        }

        {
            // The new positions replace the old ones already here: at size V', the position
            // array is left alone by the resize below; the old positions are freed.
            std::vector<Vec3> positions =
                loop_positions(old, mesh.position_vector(), options.weights, progress);
            mesh.position_vector().swap(positions);
        }

        // Shrinking the edge, halfedge and face arrays to 0 resets every user property on
        // them to its default (their old values would describe the wrong elements). The
        // connectivity is then appended to the empty arrays, and the final resize only
        // sizes the rest (deletion flags, user properties): every array is allocated once,
        // at its exact final size.
        mesh.resize(new_nv, 0, 0);
        loop_connectivity(mesh, old, nv, progress);
        mesh.resize(new_nv, new_ne, new_nf);
    } catch (...) {
        mesh.clear();  // never leave half-built connectivity behind
        throw;
    }
    MESHEDIT_ASSERT(!validate(mesh));
    progress(1.0);
    return report;
}

}  // namespace meshedit
