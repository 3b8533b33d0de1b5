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
// Passes: one over the old edges (edge points), one over the old vertices (vertex points from
// the old one-ring), one over the old halfedges (new halfedges 2h and 2h+1), one over the old
// faces (the inner halfedges and the faces), one over the new vertices (anchors). Every new
// element is written once, by index, into arrays sized to their exact final size beforehand;
// no allocation happens per element, and no hashing: every new index is a formula of old
// indices. Each pass writes every element from one chunk of its range only, so on meshes of
// 100,000 faces or more the chunks run on std::thread::hardware_concurrency() threads, with
// the same result on any number of threads. Sizing the arrays (the first touch of fresh
// memory, page faults: the largest single cost) runs one array per thread.
//
// Why it equals loop_subdivide_classic(): splitting edge e there appends vertex V + e (edges
// are split in index order), and after the flips each old triangle (c0, c1, c2) is replaced
// by exactly the four triangles (c_i, m_i+1, m_i) and (m0, m1, m2) written here; Loop
// connectivity has no other choice. Positions go through the same rules (loop_rules.h) from
// the same old mesh. The tests compare both on several meshes.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "loop_rules.h"
#include "meshedit/core/memory.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/validate.h"
#include "parallel.h"

namespace meshedit {
namespace {

using loop_rules::Progress;

// Below this many faces everything runs on the calling thread.
constexpr std::size_t kParallelFaces = 100'000;
// Elements per chunk of work handed to a thread (small enough to balance two threads on a
// 100,000-face mesh), and at least this many between two progress reports.
constexpr std::size_t kChunk = std::size_t{1} << 14;
constexpr std::size_t kReportEvery = std::size_t{1} << 16;

// Runs body(begin, end) over [0, n) in chunks on `threads` threads, reporting a fraction
// that goes from `lo` to `hi` from the calling thread.
template <class Body>
void chunked(std::size_t n, unsigned threads, Progress& progress, double lo, double hi,
             const Body& body) {
    std::size_t reported = 0;
    parallel::for_chunks(n, kChunk, threads, body, [&](std::size_t done) {
        if (done - reported >= kReportEvery) {
            reported = done;
            progress(lo + (hi - lo) * static_cast<double>(done) / static_cast<double>(n));
        }
    });
    progress(hi);
}

// Moves the contents out of a property array, leaving it empty (and unallocated).
template <class T>
memory::Array<T> take(memory::Array<T>& v) {
    memory::Array<T> out;
    out.swap(v);
    return out;
}

template <class H, class T>
memory::Array<T>& array(Mesh& mesh, const char* name) {
    return mesh.get_property<H, T>(name).vector();
}

constexpr std::uint32_t u32(std::size_t i) {
    return static_cast<std::uint32_t>(i);
}

// The old mesh's connectivity, moved out of the mesh before the new arrays are allocated.
struct OldMesh {
    memory::Array<Halfedge> next;
    memory::Array<Halfedge> prev;
    memory::Array<Vertex> to;
    memory::Array<Face> face;
    memory::Array<Halfedge> face_halfedge;
    memory::Array<Halfedge> vertex_halfedge;
    memory::Array<std::uint8_t> crease;  // empty when the mesh has no crease flags

    bool is_sharp(std::size_t e) const {
        const bool boundary = !face[2 * e].is_valid() || !face[2 * e + 1].is_valid();
        return loop_rules::is_sharp(boundary, crease.empty() ? 0 : crease[e]);
    }
};

// The arrays of the refined mesh, sized before any pass writes them by index. The sizing
// (first touch of fresh memory, i.e. page faults: the largest single cost) is spread over
// the threads, one array per task; the deletion flags (and crease flags) are sized here too,
// so that the final Mesh::resize only sizes user properties.
struct NewArrays {
    explicit NewArrays(Mesh& mesh)
        : next(array<Halfedge, Halfedge>(mesh, "h:next")),
          prev(array<Halfedge, Halfedge>(mesh, "h:prev")),
          to(array<Halfedge, Vertex>(mesh, "h:vertex")),
          face(array<Halfedge, Face>(mesh, "h:face")),
          face_halfedge(array<Face, Halfedge>(mesh, "f:halfedge")),
          vertex_halfedge(array<Vertex, Halfedge>(mesh, "v:halfedge")),
          vertex_deleted(array<Vertex, std::uint8_t>(mesh, "v:deleted")),
          edge_deleted(array<Edge, std::uint8_t>(mesh, "e:deleted")),
          face_deleted(array<Face, std::uint8_t>(mesh, "f:deleted")),
          crease(crease_flags(mesh)) {}

    static memory::Array<std::uint8_t>* crease_flags(Mesh& mesh) {
        EdgeProperty<std::uint8_t> flags = loop_rules::crease_property(mesh);
        return flags ? &flags.vector() : nullptr;
    }

    memory::Array<Vec3> position;  // [0, V) moved old vertices, [V, V + E) edge points
    memory::Array<Halfedge>& next;
    memory::Array<Halfedge>& prev;
    memory::Array<Vertex>& to;
    memory::Array<Face>& face;
    memory::Array<Halfedge>& face_halfedge;
    memory::Array<Halfedge>& vertex_halfedge;
    memory::Array<std::uint8_t>& vertex_deleted;
    memory::Array<std::uint8_t>& edge_deleted;
    memory::Array<std::uint8_t>& face_deleted;
    memory::Array<std::uint8_t>* crease;  // null without crease flags
};

void size_arrays(NewArrays& out, const OldMesh& old, std::size_t nv, unsigned threads) {
    const std::size_t ne = old.to.size() / 2;
    const std::size_t nf = old.face_halfedge.size();
    const std::size_t new_ne = 2 * ne + 3 * nf;
    const std::function<void()> tasks[] = {
        [&] { out.next.resize(2 * new_ne); },
        [&] { out.prev.resize(2 * new_ne); },
        [&] { out.to.resize(2 * new_ne); },
        [&] { out.face.resize(2 * new_ne); },
        [&] { out.position.resize(nv + ne); },
        [&] { out.face_halfedge.resize(4 * nf); },
        [&] { out.vertex_halfedge.resize(nv + ne); },
        [&] { out.vertex_deleted.resize(nv + ne, 0); },
        [&] { out.edge_deleted.resize(new_ne, 0); },
        [&] { out.face_deleted.resize(4 * nf, 0); },
        [&] {
            if (out.crease != nullptr) {
                out.crease->resize(new_ne, 0);
            }
        },
    };
    parallel::for_chunks(std::size(tasks), 1, threads,
                         [&](std::size_t task, std::size_t) { tasks[task](); });
}

// New positions. Edge points: one pass over the edges. Vertex points: one pass over the
// vertices, each gathering its neighbour sum, valence and sharp edges from its old one-ring
// (clockwise, h -> next(twin(h))). Both write every element once, so both run in chunks on
// several threads.
void loop_positions(memory::Array<Vec3>& out, const OldMesh& old, const memory::Array<Vec3>& p,
                    LoopWeights weights, unsigned threads, Progress& progress) {
    const std::size_t nv = p.size();
    const std::size_t ne = old.to.size() / 2;

    chunked(ne, threads, progress, 0.1, 0.25, [&](std::size_t begin, std::size_t end) {
        for (std::size_t e = begin; e < end; ++e) {
            const std::uint32_t a = old.to[2 * e + 1].idx();
            const std::uint32_t b = old.to[2 * e].idx();
            if (old.is_sharp(e)) {
                out[nv + e] = loop_rules::sharp_edge_point(p[a], p[b]);
            } else {
                const Vertex c = old.to[old.next[2 * e].idx()];
                const Vertex d = old.to[old.next[2 * e + 1].idx()];
                out[nv + e] = loop_rules::smooth_edge_point(p[a], p[b], p[c.idx()], p[d.idx()]);
            }
        }
    });

    const loop_rules::WeightTable u(weights);
    chunked(nv, threads, progress, 0.25, 0.4, [&](std::size_t begin, std::size_t end) {
        for (std::size_t v = begin; v < end; ++v) {
            Vec3 sum;
            Vec3 sharp_sum;  // far ends of the sharp edges (used with exactly two)
            std::size_t valence = 0;
            std::size_t n_sharp = 0;
            const Halfedge start = old.vertex_halfedge[v];
            if (start.is_valid()) {
                Halfedge h = start;
                do {
                    const Vec3& q = p[old.to[h.idx()].idx()];
                    sum += q;
                    ++valence;
                    if (old.is_sharp(h.idx() >> 1)) {
                        sharp_sum += q;
                        ++n_sharp;
                    }
                    h = old.next[h.idx() ^ 1u];
                } while (h != start);
            }
            switch (loop_rules::classify(n_sharp)) {
                case loop_rules::VertexRule::Smooth:
                    out[v] = loop_rules::smooth_vertex_point(p[v], sum, valence, u(valence));
                    break;
                case loop_rules::VertexRule::Crease:
                    out[v] = loop_rules::crease_vertex_point(p[v], sharp_sum);
                    break;
                case loop_rules::VertexRule::Corner:
                    out[v] = p[v];
                    break;
            }
        }
    });
}

// Writes the connectivity of the refined mesh into the sized arrays, every element once.
// Halfedges [0, 4E) come from one pass over the old halfedges h: 2h = first(h) and
// 2h+1 = second(twin(h)). Halfedges [4E, 4E + 6F) and all faces come from one pass over the
// old faces. The vertex anchors come from one pass over the new vertices.
void loop_connectivity(NewArrays& out, const OldMesh& old, std::size_t nv, unsigned threads,
                       Progress& progress) {
    const std::size_t nh = old.to.size();
    const std::size_t ne = nh / 2;
    const std::size_t nf = old.face_halfedge.size();
    memory::Array<Halfedge>& next = out.next;
    memory::Array<Halfedge>& prev = out.prev;
    memory::Array<Vertex>& to = out.to;
    memory::Array<Face>& face = out.face;

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

    chunked(nh, threads, progress, 0.4, 0.7, [&](std::size_t begin, std::size_t end) {
        for (std::size_t h = begin; h < end; ++h) {
            const std::size_t t = h ^ 1;
            // 2h = first(h), from(h) -> m. Interior h = h_j of face f: side b of corner
            // i = j - 1, between second(h_i) and 2I_i. Boundary: between second(prev(h)) and
            // second(h). Either way prev is second(prev(h)).
            const Face f = old.face[h];
            prev[2 * h] = second(old.prev[h].idx());
            if (f.is_valid()) {
                const std::uint32_t i = (corner(h) + 2) % 3;
                next[2 * h] = inner(f.idx(), i);
                face[2 * h] = Face(4 * f.idx() + i);
            } else {
                next[2 * h] = second(h);
                face[2 * h] = Face();
            }
            to[2 * h] = Vertex(u32(nv + h / 2));

            // 2h+1 = second(t), m -> to(t). Interior t = h_k of face g: side a of corner k,
            // between 2I_k and first(h_k+1). Boundary: between first(t) and
            // first(next(t)). Either way next is first(next(t)).
            const Face g = old.face[t];
            next[2 * h + 1] = first(old.next[t].idx());
            if (g.is_valid()) {
                const std::uint32_t k = corner(t);
                prev[2 * h + 1] = inner(g.idx(), k);
                face[2 * h + 1] = Face(4 * g.idx() + k);
            } else {
                prev[2 * h + 1] = first(t);
                face[2 * h + 1] = Face();
            }
            to[2 * h + 1] = old.to[t];
        }
    });

    chunked(nf, threads, progress, 0.7, 0.9, [&](std::size_t begin, std::size_t end) {
        for (std::size_t f = begin; f < end; ++f) {
            std::uint32_t hs[3];
            hs[0] = old.face_halfedge[f].idx();
            hs[1] = old.next[hs[0]].idx();
            hs[2] = old.next[hs[1]].idx();
            for (std::uint32_t i = 0; i < 3; ++i) {
                const std::uint32_t j = i == 2 ? 0 : i + 1;  // i + 1 and i - 1, mod 3
                const std::uint32_t l = i == 0 ? 2 : i - 1;
                // 2I_i: m_j -> m_i in corner face 4f+i, between first(h_j) and second(h_i).
                const std::size_t a = inner(f, i).idx();
                next[a] = second(hs[i]);
                prev[a] = first(hs[j]);
                to[a] = Vertex(u32(nv + hs[i] / 2));
                face[a] = Face(u32(4 * f + i));
                // 2I_i + 1: m_i -> m_j around the centre face 4f+3.
                next[a + 1] = Halfedge(inner(f, j).idx() + 1);
                prev[a + 1] = Halfedge(inner(f, l).idx() + 1);
                to[a + 1] = Vertex(u32(nv + hs[j] / 2));
                face[a + 1] = Face(u32(4 * f + 3));
            }
            // Faces 4f+i are anchored at first(h_i+1), the centre at 2I_0 + 1.
            Halfedge* anchors = &out.face_halfedge[4 * f];
            anchors[0] = first(hs[1]);
            anchors[1] = first(hs[2]);
            anchors[2] = first(hs[0]);
            anchors[3] = Halfedge(inner(f, 0).idx() + 1);
        }
    });

    // Vertex anchors, keeping the boundary-anchor rule: an old vertex's first(h) is on the
    // boundary iff h was; m_e leaves along second() of e's boundary halfedge, if any.
    memory::Array<Halfedge>& vertex_halfedge = out.vertex_halfedge;
    chunked(nv + ne, threads, progress, 0.9, 0.95, [&](std::size_t begin, std::size_t end) {
        for (std::size_t v = begin; v < end; ++v) {
            if (v < nv) {
                const Halfedge h = old.vertex_halfedge[v];
                vertex_halfedge[v] = h.is_valid() ? first(h.idx()) : Halfedge();
            } else {
                const std::size_t e = v - nv;
                const bool h1_boundary = !old.face[2 * e + 1].is_valid();
                vertex_halfedge[v] = second(h1_boundary ? 2 * e + 1 : 2 * e);
            }
        }
    });
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

        // Shrinking the edge, halfedge and face arrays to 0 resets every user property on
        // them to its default (their old values would describe the wrong elements).
        mesh.resize(nv, 0, 0);
        const unsigned threads = parallel::thread_count(nf, kParallelFaces, options.max_threads);
        NewArrays out(mesh);
        out.vertex_halfedge.clear();  // refilled whole; nothing to keep
        size_arrays(out, old, nv, threads);
        progress(0.1);

        loop_positions(out.position, old, mesh.position_vector(), options.weights, threads,
                       progress);
        mesh.position_vector().swap(out.position);  // the old positions are freed below
        loop_connectivity(out, old, nv, threads, progress);

        // Both children of a crease edge stay creases; inner edges are not creases.
        if (out.crease != nullptr) {
            for (std::size_t g = 0; g < 2 * ne; ++g) {
                (*out.crease)[g] = old.crease[g / 2];
            }
        }
        // Sizes what is left (user properties) to the new counts.
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
