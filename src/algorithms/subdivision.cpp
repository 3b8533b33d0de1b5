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
// the old one-ring); then one new connectivity array at a time (to, face, next with the face
// anchors, prev, vertex anchors), each from a pass over the old halfedges and one over the old
// faces. Every new element is written once, by index, into an array sized to its exact final
// size; no allocation happens per element, and no hashing: every new index is a formula of
// old indices. Each old array is freed as soon as no later pass reads it, so the peak memory
// is about the result's own (69 bytes per new face) instead of result + old mesh (86). Each
// pass writes every element from one chunk of its range only, so on meshes of 100,000 faces
// or more the chunks run on thread_count() threads (threads.h), with the same result on any
// number of threads. Big arrays live in huge pages (memory.h): their first touch, page
// faults, was the largest single cost.
//
// Why it equals loop_subdivide_classic(): splitting edge e there appends vertex V + e (edges
// are split in index order), and after the flips each old triangle (c0, c1, c2) is replaced
// by exactly the four triangles (c_i, m_i+1, m_i) and (m0, m1, m2) written here; Loop
// connectivity has no other choice. Positions go through the same rules (loop_rules.h) from
// the same old mesh. The tests compare both on several meshes.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "algorithms/loop_rules.h"
#include "algorithms/refine_carry.h"
#include "algorithms/refine_util.h"
#include "mesh/mesh_arrays.h"
#include "mesh/parallel.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/memory.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/validate.h"

namespace meshedit {
namespace {

using loop_rules::Progress;
using refine::chunked;
using refine::release;
using refine::sized;
using refine::u32;

using refine::OldMesh;

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

// The connectivity of the refined mesh, one array at a time, so that each old array is freed
// before the next new one is allocated and the peak memory stays near the result's own size
// (the old mesh is a quarter of it). Each pass writes every element of its array once, by
// index, in chunks on `threads` threads. Halfedges [0, 4E) come from the old halfedges h:
// 2h = first(h) and 2h+1 = second(twin(h)); halfedges [4E, 4E + 6F) and all faces from the
// old faces.
class LoopConnectivity {
public:
    LoopConnectivity(Mesh& mesh, OldMesh& old, std::size_t nv, unsigned threads, Progress& progress)
        : mesh_(mesh),
          old_(old),
          nv_(nv),
          nh_(old.to.size()),
          ne_(nh_ / 2),
          nf_(old.face_halfedge.size()),
          threads_(threads),
          progress_(progress) {}

    void run() {
        write_to();
        release(old_.to);
        write_face();
        release(old_.face);  // from here on the new face[2h] tells f and the corner of old h
        write_next_and_face_anchors();
        release(old_.next);
        release(old_.face_halfedge);
        refine::write_prev_from_next(mesh_, threads_, progress_, 0.75, 0.9);
        write_vertex_anchors();
        release(old_.vertex_halfedge);
    }

private:
    std::size_t new_nh() const { return 2 * (2 * ne_ + 3 * nf_); }

    // Halfedge 2I_i of old face f (the inner edge cutting off corner i, corner side).
    Halfedge inner(std::size_t f, std::uint32_t i) const {
        return Halfedge(u32(2 * (2 * ne_ + 3 * f + i)));
    }
    // first(h) = 2h, second(h) = 2·twin(h) + 1.
    static Halfedge first(std::size_t h) { return Halfedge(u32(2 * h)); }
    static Halfedge second(std::size_t h) { return Halfedge(u32(2 * (h ^ 1) + 1)); }
    // The halfedges h0 = halfedge(f), h1, h2 of old face f.
    void face_halfedges(std::size_t f, std::uint32_t hs[3]) const {
        hs[0] = old_.face_halfedge[f].idx();
        hs[1] = old_.next[hs[0]].idx();
        hs[2] = old_.next[hs[1]].idx();
    }
    // body(i, j, a) for each corner i of old face f, with j = i + 1 (mod 3) and a = 2I_i.
    template <class Body>
    void for_each_corner(std::size_t f, const Body& body) const {
        for (std::uint32_t i = 0; i < 3; ++i) {
            body(i, i == 2 ? 0 : i + 1, std::size_t{inner(f, i).idx()});
        }
    }
    // Position (0, 1, 2) of interior old halfedge h in its face, counted from halfedge(f).
    std::uint32_t corner(std::size_t h) const {
        const Halfedge h0 = old_.face_halfedge[old_.face[h].idx()];
        return h0.idx() == h ? 0 : (old_.next[h0.idx()].idx() == h ? 1 : 2);
    }
    // Runs `per_halfedge(h)` over the old halfedges, then `per_face(f)` over the old faces.
    template <class PerHalfedge, class PerFace>
    void passes(double lo, double hi, const PerHalfedge& per_halfedge, const PerFace& per_face) {
        const double mid = lo + (hi - lo) * static_cast<double>(nh_) /
                                    static_cast<double>(std::max<std::size_t>(nh_ + nf_, 1));
        chunked(nh_, threads_, progress_, lo, mid, [&](std::size_t begin, std::size_t end) {
            for (std::size_t h = begin; h < end; ++h) {
                per_halfedge(h);
            }
        });
        chunked(nf_, threads_, progress_, mid, hi, [&](std::size_t begin, std::size_t end) {
            for (std::size_t f = begin; f < end; ++f) {
                per_face(f);
            }
        });
    }

    // 2h = first(h) ends at m_h; 2h+1 = second(twin(h)) at to(twin(h)). The inner halfedge
    // 2I_i runs m_j -> m_i (j = i + 1), its twin back.
    void write_to() {
        auto& to = sized(MeshArrays::to_vertex(mesh_), new_nh());
        passes(
            0.4, 0.5,
            [&](std::size_t h) {
                to[2 * h] = Vertex(u32(nv_ + h / 2));
                to[2 * h + 1] = old_.to[h ^ 1];
            },
            [&](std::size_t f) {
                std::uint32_t hs[3];
                face_halfedges(f, hs);
                for_each_corner(f, [&](std::uint32_t i, std::uint32_t j, std::size_t a) {
                    to[a] = Vertex(u32(nv_ + hs[i] / 2));
                    to[a + 1] = Vertex(u32(nv_ + hs[j] / 2));
                });
            });
    }

    // Interior h = h_j of face f: 2h is side b of corner i = j - 1 (face 4f+i), 2h+1 =
    // second(twin) side a of corner k of the twin's face g (face 4g+k). Boundary halves stay
    // boundary. Inner halfedges: 2I_i in corner face 4f+i, 2I_i + 1 in the centre 4f+3.
    void write_face() {
        auto& face = sized(MeshArrays::face(mesh_), new_nh());
        passes(
            0.5, 0.6,
            [&](std::size_t h) {
                const Face f = old_.face[h];
                face[2 * h] = f.is_valid() ? Face(4 * f.idx() + (corner(h) + 2) % 3) : Face();
                const std::size_t t = h ^ 1;
                const Face g = old_.face[t];
                face[2 * h + 1] = g.is_valid() ? Face(4 * g.idx() + corner(t)) : Face();
            },
            [&](std::size_t f) {
                for_each_corner(f, [&](std::uint32_t i, std::uint32_t, std::size_t a) {
                    face[a] = Face(u32(4 * f + i));
                    face[a + 1] = Face(u32(4 * f + 3));
                });
            });
    }

    // 2h = first(h): next is 2I_i in corner face 4f+i (read back from the new face array),
    // or second(h) on the boundary. 2h+1 = second(t): next is first(next(t)) either way.
    // Inner: 2I_i -> second(h_i) (corner face), 2I_i + 1 -> 2I_j + 1 (centre). Faces 4f+i are
    // anchored at first(h_i+1), the centre at 2I_0 + 1.
    void write_next_and_face_anchors() {
        auto& next = sized(MeshArrays::next(mesh_), new_nh());
        auto& anchors = sized(MeshArrays::face_halfedge(mesh_), 4 * nf_);
        const memory::Array<Face>& face = MeshArrays::face(mesh_);
        passes(
            0.6, 0.75,
            [&](std::size_t h) {
                const Face corner_face = face[2 * h];
                next[2 * h] = corner_face.is_valid()
                                  ? inner(corner_face.idx() / 4, corner_face.idx() % 4)
                                  : second(h);
                next[2 * h + 1] = first(old_.next[h ^ 1].idx());
            },
            [&](std::size_t f) {
                std::uint32_t hs[3];
                face_halfedges(f, hs);
                for_each_corner(f, [&](std::uint32_t i, std::uint32_t j, std::size_t a) {
                    next[a] = second(hs[i]);
                    next[a + 1] = Halfedge(inner(f, j).idx() + 1);
                });
                Halfedge* face_anchors = &anchors[4 * f];
                face_anchors[0] = first(hs[1]);
                face_anchors[1] = first(hs[2]);
                face_anchors[2] = first(hs[0]);
                face_anchors[3] = Halfedge(inner(f, 0).idx() + 1);
            });
    }

    // Vertex anchors, keeping the boundary-anchor rule: an old vertex's first(h) is on the
    // boundary iff h was; m_e leaves along second() of e's boundary halfedge, if any. Old h
    // was a boundary halfedge iff the new 2h has no face.
    void write_vertex_anchors() {
        auto& anchor = sized(MeshArrays::vertex_halfedge(mesh_), nv_ + ne_);
        const memory::Array<Face>& face = MeshArrays::face(mesh_);
        chunked(nv_ + ne_, threads_, progress_, 0.9, 0.95, [&](std::size_t begin, std::size_t end) {
            for (std::size_t v = begin; v < end; ++v) {
                if (v < nv_) {
                    const Halfedge h = old_.vertex_halfedge[v];
                    anchor[v] = h.is_valid() ? first(h.idx()) : Halfedge();
                } else {
                    const std::size_t e = v - nv_;
                    const bool h1_boundary = !face[2 * (2 * e + 1)].is_valid();
                    anchor[v] = second(h1_boundary ? 2 * e + 1 : 2 * e);
                }
            }
        });
    }

    Mesh& mesh_;
    OldMesh& old_;
    std::size_t nv_;
    std::size_t nh_;
    std::size_t ne_;
    std::size_t nf_;
    unsigned threads_;
    Progress& progress_;
};

}  // namespace

OpStatus is_loop_ok(const Mesh& mesh) {
    // Without doubled edges, two triangles that share two edges share all three corners.
    for (const Face f : mesh.faces()) {
        const Halfedge h = mesh.halfedge(f);
        const Face g = mesh.face(Mesh::twin(h));
        if (mesh.is_triangle(f) && g.is_valid() && g == mesh.face(Mesh::twin(mesh.next(h)))) {
            return OpStatus::refused(
                "cannot subdivide: two triangles on the same three corners (a closed pillow) "
                "would be joined by doubled edges");
        }
    }
    return OpStatus::ok();
}

SubdivisionPlan plan_loop(const Mesh& mesh, int levels) {
    SubdivisionPlan plan;
    plan.status = is_loop_ok(mesh);
    if (!plan.ok()) {
        return plan;
    }
    // Triangulating a k-gon first makes k - 2 triangles and k - 3 new edges.
    double v = static_cast<double>(mesh.n_vertices());
    double e = static_cast<double>(mesh.n_edges());
    double f = 0.0;
    for (const Face g : mesh.faces()) {
        const double k = static_cast<double>(mesh.valence(g));
        f += k - 2.0;
        e += k - 3.0;
    }
    // Bytes per face as this mesh stores them (user properties included), at least the 69
    // bytes of a Loop result's own arrays.
    const double per_face = std::max(69.0, f > 0.0 ? static_cast<double>(mesh.bytes()) / f : 0.0);
    for (int level = 1; level <= levels; ++level) {
        v += e;
        e = 2.0 * e + 3.0 * f;
        f *= 4.0;
        if (!refine::plan_level(plan, level, v, e, f, per_face)) {
            return plan;
        }
    }
    return plan;
}

namespace {
void loop_subdivide_arrays(Mesh& mesh, const LoopOptions& options,
                           refine::ChannelGroups* groups = nullptr);

constexpr std::pair<UvInterpolation, std::string_view> kUvNames[] = {
    {UvInterpolation::None, "none"},
    {UvInterpolation::CornersOnly, "corners"},
    {UvInterpolation::CornersPlus1, "corners+1"},
    {UvInterpolation::CornersPlus2, "corners+2"},
    {UvInterpolation::Boundaries, "boundaries"},
    {UvInterpolation::All, "all"},
};
}  // namespace

std::string_view uv_interpolation_name(UvInterpolation uv) {
    for (const auto& [value, name] : kUvNames) {
        if (value == uv) {
            return name;
        }
    }
    return "corners";
}

std::optional<UvInterpolation> parse_uv_interpolation(std::string_view name) {
    for (const auto& [value, spelled] : kUvNames) {
        if (spelled == name) {
            return value;
        }
    }
    return std::nullopt;
}

std::string uv_interpolation_names() {
    std::string out;
    for (const auto& [value, name] : kUvNames) {
        out += (out.empty() ? "" : ", ") + std::string(name);
    }
    return out;
}

LoopReport loop_subdivide(Mesh& mesh, const LoopOptions& options) {
    LoopReport report = loop_rules::prepare(mesh);
    if (!refine::has_attributes(mesh)) {
        loop_subdivide_arrays(mesh, options);
        return report;
    }
    const refine::FaceVaryingRules rules{refine::Scheme::Loop, options.weights, options.uv};
    refine::refine_carrying(mesh, rules, [&](Mesh& m, refine::ChannelGroups& groups) {
        loop_subdivide_arrays(m, options, &groups);
    });
    return report;
}

namespace {
// One level on a prepared mesh (loop_rules::prepare()), array by array; `groups`, if any,
// refined by the positions' rules beside them.
void loop_subdivide_arrays(Mesh& mesh, const LoopOptions& options, refine::ChannelGroups* groups) {
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
        // Move the old connectivity out of the mesh. prev is not needed: the new prev is the
        // inverse of the new next.
        OldMesh old;
        EdgeProperty<std::uint8_t> crease = refine::take_connectivity(mesh, old, false);
        const unsigned threads =
            parallel::thread_count(nf, refine::kParallelFaces, options.max_threads);
        progress(0.1);

        // Positions first: the old ones are freed before any connectivity is allocated.
        refine::replace_positions(
            mesh, new_nv, [&](memory::Array<Vec3>& out, const memory::Array<Vec3>& p) {
                loop_positions(out, old, p, options.weights, threads, progress);
            });
        if (groups != nullptr) {
            groups->out.resize(groups->in.size());
            for (std::size_t i = 0; i < groups->in.size(); ++i) {
                groups->out[i].resize_for_overwrite(new_nv);
                loop_positions(groups->out[i], old, groups->in[i], options.weights, threads,
                               progress);
            }
        }
        LoopConnectivity(mesh, old, nv, threads, progress).run();

        // Both children of a crease edge stay creases; inner edges are not creases.
        refine::give_crease_halves(crease, old, new_ne);
        // Sizes what is left (deletion flags, user properties) to the new counts.
        mesh.resize(new_nv, new_ne, new_nf);
    } catch (...) {
        mesh.clear();  // never leave half-built connectivity behind
        throw;
    }
    MESHEDIT_ASSERT(!validate(mesh));
    progress(1.0);
}
}  // namespace

}  // namespace meshedit
