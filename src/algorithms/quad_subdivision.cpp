// Catmull-Clark and linear subdivision, fast path: the refined mesh is written directly into
// exactly sized arrays, as Loop's fast path (subdivision.cpp) does.
//
// Index layout of the result (V, E, F = old counts after garbage collection; C = the number
// of face corners, the sum of the face degrees; V' = V + E + F, E' = 2E + C, F' = C):
//
//   vertices   [0, V)         the old vertices, same indices
//              V + e          the edge point m_e of old edge e
//              V + E + f      the face point of old face f
//   edges      [0, 2E)        new edge g is the half of old edge g/2 at the tail of old
//                             halfedge g: first(g) = 2g runs from_vertex(g) -> m, 2g+1 back;
//                             so old halfedge h becomes first(h) = 2h, then
//                             second(h) = 2·twin(h) + 1 (m -> to_vertex(h))
//              2E + corner(h) the inner edge from m of old interior halfedge h to its face
//                             point: halfedge 2I(h) runs m -> face point, 2I(h) + 1 back
//   faces      corner(h)      the quad at to_vertex(h), for every old interior halfedge h;
//                             corner(h) numbers the corners face by face, each face from
//                             halfedge(f) on (its first corner is to_vertex(halfedge(f)))
//
// The quad at corner c = to_vertex(h) of old face f, with n = next(h):
//
//          c = to(h) ---- first(n) ----> m_n
//             ^                            |
//             |                          2I(n)
//         second(h)                        |
//             |                            v
//            m_h <------ 2I(h) + 1 ------ face point
//
// Passes: corners (each face's degree, a prefix sum, each interior halfedge's corner), then
// positions (face points, edge points, vertex points, in that order, each reading the ones
// before), then one new connectivity array at a time, each from one pass over the old
// halfedges, so every new element is written once, by index, into an array sized to its
// final size, and each old array is freed once no later pass reads it. On meshes of 100,000
// faces or more the passes run in chunks on several threads, with the same result on any
// number of threads.
//
// Why it equals quad_subdivide_classic(): that builds the same quads (to(h), m_n, face
// point, m_h) in the same corner order from the same vertex numbering; the connectivity of
// a set of oriented quads is unique. Positions go through the same rules (catmark_rules.h).

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "algorithms/catmark_rules.h"
#include "algorithms/loop_rules.h"
#include "algorithms/refine_carry.h"
#include "algorithms/refine_util.h"
#include "mesh/mesh_arrays.h"
#include "mesh/parallel.h"
#include "meshedit/core/memory.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/validate.h"

namespace meshedit {
namespace {

using loop_rules::Progress;
using refine::chunked;
using refine::release;
using refine::sized;
using refine::u32;

using refine::OldMesh;

class QuadRefinement {
public:
    QuadRefinement(Mesh& mesh, OldMesh& old, std::size_t nv, unsigned threads, Progress& progress)
        : mesh_(mesh),
          old_(old),
          nv_(nv),
          nh_(old.to.size()),
          ne_(nh_ / 2),
          nf_(old.face_halfedge.size()),
          threads_(threads),
          progress_(progress) {}

    // Numbers the corners; returns C.
    std::size_t number_corners() {
        memory::Array<std::uint32_t> offset;
        offset.resize_for_overwrite(nf_ + 1);
        offset[0] = 0;
        chunked(nf_, threads_, progress_, 0.0, 0.03, [&](std::size_t begin, std::size_t end) {
            for (std::size_t f = begin; f < end; ++f) {
                std::uint32_t k = 0;
                const Halfedge h0 = old_.face_halfedge[f];
                Halfedge h = h0;
                do {
                    ++k;
                    h = old_.next[h.idx()];
                } while (h != h0);
                offset[f + 1] = k;
            }
        });
        std::size_t corners = 0;
        for (std::size_t f = 1; f <= nf_; ++f) {
            corners += offset[f];
            if (corners >= kInvalidIndex) {
                throw std::length_error("quad_subdivide: the result would exceed 2^32 - 1 faces");
            }
            offset[f] = u32(corners);
        }
        auto& corner = sized(corner_, nh_);
        chunked(nh_, threads_, progress_, 0.03, 0.05, [&](std::size_t begin, std::size_t end) {
            for (std::size_t h = begin; h < end; ++h) {
                if (!old_.face[h].is_valid()) {
                    corner[h] = kInvalidIndex;
                }
            }
        });
        chunked(nf_, threads_, progress_, 0.05, 0.08, [&](std::size_t begin, std::size_t end) {
            for (std::size_t f = begin; f < end; ++f) {
                std::uint32_t c = offset[f];
                const Halfedge h0 = old_.face_halfedge[f];
                Halfedge h = h0;
                do {
                    corner[h.idx()] = c++;
                    h = old_.next[h.idx()];
                } while (h != h0);
            }
        });
        corners_ = corners;
        return corners;
    }

    // Face points, then edge points (reading the face points), then vertex points (reading
    // both), into `out` (V + E + F points).
    void positions(memory::Array<Vec3>& out, const memory::Array<Vec3>& p, QuadScheme scheme) {
        const std::size_t fp = nv_ + ne_;  // index of face 0's point
        chunked(nf_, threads_, progress_, 0.08, 0.15, [&](std::size_t begin, std::size_t end) {
            for (std::size_t f = begin; f < end; ++f) {
                Vec3 sum;
                std::size_t k = 0;
                const Halfedge h0 = old_.face_halfedge[f];
                Halfedge h = h0;
                do {
                    sum += p[old_.to[h.idx()].idx()];
                    ++k;
                    h = old_.next[h.idx()];
                } while (h != h0);
                out[fp + f] = catmark_rules::face_point(sum, k);
            }
        });
        chunked(ne_, threads_, progress_, 0.15, 0.25, [&](std::size_t begin, std::size_t end) {
            for (std::size_t e = begin; e < end; ++e) {
                const Vec3& a = p[old_.to[2 * e + 1].idx()];
                const Vec3& b = p[old_.to[2 * e].idx()];
                const bool sharp = old_.is_sharp(e);
                out[nv_ + e] = sharp ? catmark_rules::edge_point(scheme, true, a, b, a, b)
                                     : catmark_rules::edge_point(
                                           scheme, false, a, b, out[fp + old_.face[2 * e].idx()],
                                           out[fp + old_.face[2 * e + 1].idx()]);
            }
        });
        chunked(nv_, threads_, progress_, 0.25, 0.4, [&](std::size_t begin, std::size_t end) {
            for (std::size_t v = begin; v < end; ++v) {
                catmark_rules::Ring ring;
                const Halfedge start = old_.vertex_halfedge[v];
                if (start.is_valid()) {
                    Halfedge h = start;  // outgoing, clockwise: h -> next(twin(h))
                    do {
                        const Vec3& q = p[old_.to[h.idx()].idx()];
                        ring.neighbour_sum += q;
                        ++ring.valence;
                        if (const Face f = old_.face[h.idx()]; f.is_valid()) {
                            ring.face_point_sum += out[fp + f.idx()];
                        }
                        if (old_.is_sharp(h.idx() >> 1)) {
                            ring.sharp_sum += q;
                            ++ring.n_sharp;
                        }
                        h = old_.next[h.idx() ^ 1u];
                    } while (h != start);
                }
                out[v] = catmark_rules::vertex_point(scheme, p[v], ring);
            }
        });
    }

    void connectivity() {
        write_to();
        release(old_.to);
        write_face();
        release(old_.face);
        release(old_.prev);
        write_next_and_face_anchors();
        release(old_.next);
        refine::write_prev_from_next(mesh_, threads_, progress_, 0.8, 0.9);
        write_vertex_anchors();
    }

private:
    std::size_t new_nh() const { return 2 * (2 * ne_ + corners_); }
    // 2I(h): the inner halfedge from m of interior old halfedge h to its face point.
    std::size_t inner(std::size_t h) const { return 2 * (2 * ne_ + corner_[h]); }
    static Halfedge second(std::size_t h) { return Halfedge(u32(2 * (h ^ 1) + 1)); }

    template <class PerHalfedge>
    void over_halfedges(double lo, double hi, const PerHalfedge& per_halfedge) {
        chunked(nh_, threads_, progress_, lo, hi, [&](std::size_t begin, std::size_t end) {
            for (std::size_t h = begin; h < end; ++h) {
                per_halfedge(h);
            }
        });
    }

    void write_to() {
        auto& to = sized(MeshArrays::to_vertex(mesh_), new_nh());
        over_halfedges(0.4, 0.5, [&](std::size_t h) {
            const Vertex m(u32(nv_ + h / 2));
            to[2 * h] = m;
            to[2 * h + 1] = old_.to[h ^ 1];
            if (const Face f = old_.face[h]; f.is_valid()) {
                const std::size_t x = inner(h);
                to[x] = Vertex(u32(nv_ + ne_ + f.idx()));
                to[x + 1] = m;
            }
        });
    }

    // first(h) lies in the quad of prev(h), second(h) and 2I(h) + 1 in the quad of h, 2I(h)
    // in the quad of prev(h); boundary halves stay boundary.
    void write_face() {
        auto& face = sized(MeshArrays::face(mesh_), new_nh());
        over_halfedges(0.5, 0.6, [&](std::size_t h) {
            const bool interior = old_.face[h].is_valid();
            const Face quad_of_prev = interior ? Face(corner_[old_.prev[h].idx()]) : Face();
            face[2 * h] = quad_of_prev;
            const std::uint32_t c = corner_[h ^ 1];
            face[2 * h + 1] = c != kInvalidIndex ? Face(c) : Face();
            if (interior) {
                const std::size_t x = inner(h);
                face[x] = quad_of_prev;
                face[x + 1] = Face(corner_[h]);
            }
        });
    }

    // The quad of h: second(h) -> first(next(h)) -> 2I(next(h)) -> 2I(h) + 1 -> second(h).
    // On the boundary: first(h) -> second(h) -> first(next(h)). Each quad is anchored at its
    // 2I(h) + 1.
    void write_next_and_face_anchors() {
        auto& next = sized(MeshArrays::next(mesh_), new_nh());
        auto& anchors = sized(MeshArrays::face_halfedge(mesh_), corners_);
        over_halfedges(0.6, 0.75, [&](std::size_t h) {
            const bool interior = corner_[h] != kInvalidIndex;
            next[2 * h + 1] = Halfedge(u32(2 * old_.next[h ^ 1].idx()));
            if (!interior) {
                next[2 * h] = second(h);
                return;
            }
            const std::size_t x = inner(h);
            next[2 * h] = Halfedge(u32(x));
            next[x + 1] = second(h);
            anchors[corner_[h]] = Halfedge(u32(x + 1));
        });
        // 2I(h) -> 2I(prev(h)) + 1: written from prev(h)'s side, as 2I(next(p)) -> 2I(p) + 1.
        over_halfedges(0.75, 0.8, [&](std::size_t p) {
            if (corner_[p] != kInvalidIndex) {
                next[inner(old_.next[p].idx())] = Halfedge(u32(inner(p) + 1));
            }
        });
    }

    // Keeping the boundary-anchor rule: an old vertex's first(h) is on the boundary iff h
    // was; m_e leaves along second() of e's boundary halfedge, if any; a face point along
    // 2I(halfedge(f)) + 1.
    void write_vertex_anchors() {
        const std::size_t total = nv_ + ne_ + nf_;
        auto& anchor = sized(MeshArrays::vertex_halfedge(mesh_), total);
        chunked(total, threads_, progress_, 0.9, 0.95, [&](std::size_t begin, std::size_t end) {
            for (std::size_t v = begin; v < end; ++v) {
                if (v < nv_) {
                    const Halfedge h = old_.vertex_halfedge[v];
                    anchor[v] = h.is_valid() ? Halfedge(2 * h.idx()) : Halfedge();
                } else if (v < nv_ + ne_) {
                    const std::size_t e = v - nv_;
                    const bool h1_boundary = corner_[2 * e + 1] == kInvalidIndex;
                    anchor[v] = second(h1_boundary ? 2 * e + 1 : 2 * e);
                } else {
                    const std::size_t f = v - nv_ - ne_;
                    anchor[v] = Halfedge(u32(inner(old_.face_halfedge[f].idx()) + 1));
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
    std::size_t corners_ = 0;
    // corner(h) for interior old halfedges, kInvalidIndex for boundary ones.
    memory::Array<std::uint32_t> corner_;
    unsigned threads_;
    Progress& progress_;
};

}  // namespace

SubdivisionPlan plan_quad_subdivision(const Mesh& mesh, int levels) {
    SubdivisionPlan plan;
    double v = static_cast<double>(mesh.n_vertices());
    double e = static_cast<double>(mesh.n_edges());
    double f = static_cast<double>(mesh.n_faces());
    double corners = 0.0;
    for (const Face g : mesh.faces()) {
        corners += static_cast<double>(mesh.valence(g));
    }
    // Bytes per face as this mesh stores them, at least the 69 of a quad result's arrays
    // (per quad: 4 halfedges of 13 bytes, 1 vertex of 28 and 2 edges of 1, about).
    const double per_face = std::max(69.0, f > 0.0 ? static_cast<double>(mesh.bytes()) / f : 0.0);
    for (int level = 1; level <= levels; ++level) {
        v += e + f;
        e = 2.0 * e + corners;
        f = corners;
        corners = 4.0 * f;
        if (!refine::plan_level(plan, level, v, e, f, per_face)) {
            return plan;
        }
    }
    return plan;
}

namespace {
void quad_subdivide_arrays(Mesh& mesh, const QuadSubdivisionOptions& options,
                           refine::ChannelGroups* groups = nullptr);
}  // namespace

void quad_subdivide(Mesh& mesh, const QuadSubdivisionOptions& options) {
    if (mesh.has_garbage()) {
        mesh.garbage_collection();
    }
    if (!refine::has_attributes(mesh)) {
        quad_subdivide_arrays(mesh, options);
        return;
    }
    const refine::FaceVaryingRules rules{options.scheme == QuadScheme::Linear
                                             ? refine::Scheme::Linear
                                             : refine::Scheme::CatmullClark,
                                         LoopWeights::Warren, options.uv};
    refine::refine_carrying(mesh, rules, [&](Mesh& m, refine::ChannelGroups& groups) {
        quad_subdivide_arrays(m, options, &groups);
    });
}

namespace {
// One level on a collected mesh, array by array; `groups`, if any, refined by the positions'
// rules beside them.
void quad_subdivide_arrays(Mesh& mesh, const QuadSubdivisionOptions& options,
                           refine::ChannelGroups* groups) {
    Progress progress(options.progress);
    progress(0.0);
    const std::size_t nv = mesh.vertices_size();
    const std::size_t ne = mesh.edges_size();
    const std::size_t nf = mesh.faces_size();
    const std::size_t nh = 2 * ne;
    // C <= 2E (each halfedge is at most one corner).
    if (2 * (2 * ne + nh) >= kInvalidIndex || nv + ne + nf >= kInvalidIndex) {
        throw std::length_error("quad_subdivide: the result would exceed 2^32 - 1 elements");
    }
    try {
        OldMesh old;
        EdgeProperty<std::uint8_t> crease = refine::take_connectivity(mesh, old, true);
        // Threads from 100,000 faces out (the result has C <= 2E faces), as Loop's from
        // 100,000 in: a level of either writes about as much per output face.
        const unsigned threads =
            parallel::thread_count(nh, refine::kParallelFaces, options.max_threads);

        QuadRefinement refinement(mesh, old, nv, threads, progress);
        const std::size_t corners = refinement.number_corners();
        refine::replace_positions(mesh, nv + ne + nf,
                                  [&](memory::Array<Vec3>& out, const memory::Array<Vec3>& p) {
                                      refinement.positions(out, p, options.scheme);
                                  });
        if (groups != nullptr) {
            groups->out.resize(groups->in.size());
            for (std::size_t i = 0; i < groups->in.size(); ++i) {
                groups->out[i].resize_for_overwrite(nv + ne + nf);
                refinement.positions(groups->out[i], groups->in[i], options.scheme);
            }
        }
        refinement.connectivity();

        const std::size_t new_ne = 2 * ne + corners;
        refine::give_crease_halves(crease, old, new_ne);
        mesh.resize(nv + ne + nf, new_ne, corners);
    } catch (...) {
        mesh.clear();  // never leave half-built connectivity behind
        throw;
    }
    MESHEDIT_ASSERT(!validate(mesh));
    progress(1.0);
}
}  // namespace

}  // namespace meshedit
