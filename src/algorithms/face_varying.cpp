// Corner values through one level of subdivision as face-varying values (face_varying.h).
//
// The rules are those of OpenSubdiv's face-varying channels (Vtr::FVarLevel, Far::
// PrimvarRefiner::InterpolateFaceVarying) with infinitely sharp creases and the boundary "edge
// only", re-derived here per level from the values themselves: a vertex's values are its
// corners' distinct values, a seam is an edge whose faces disagree at either end.

#include "face_varying.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "algorithms/loop_rules.h"
#include "meshedit/core/attributes.h"

namespace meshedit::refine {
namespace {

// What the option turns on (OpenSubdiv's FVarLevel reads its option the same way).
struct Switches {
    bool linear = false;             // everything linear (option all, or linear subdivision)
    bool linear_boundaries = false;  // every value on a seam or boundary stays
    bool corners_sharp = false;      // a value with one face stays
    bool dependent = false;          // corners+1, corners+2: values sharpen each other
    bool sharpen_both = false;       // corners+2: one corner of two makes both corners
    bool sharpen_darts = false;      // corners+2, boundaries: a seam's end inside stays
};

Switches switches(const FaceVaryingRules& rules) {
    using U = UvInterpolation;
    Switches s;
    s.linear = rules.uv == U::All || rules.scheme == Scheme::Linear;
    s.linear_boundaries = rules.uv == U::All || rules.uv == U::Boundaries;
    s.corners_sharp = rules.uv != U::None;
    s.dependent = rules.uv == U::CornersPlus1 || rules.uv == U::CornersPlus2;
    s.sharpen_both = rules.uv == U::CornersPlus2;
    s.sharpen_darts = s.sharpen_both || s.linear_boundaries;
    return s;
}

template <class T>
class Refiner {
public:
    Refiner(const Mesh& m, const FaceVaryingRules& rules, const memory::Array<T>& uv,
            FaceVaryingLevel<T>& level)
        : m_(m),
          rules_(rules),
          s_(switches(rules)),
          uv_(uv),
          crease_(loop_rules::crease_property(m)),
          weight_(rules.weights),
          face_(level.face),
          edge_(level.edge),
          vertex_(level.vertex) {}

    void run() {
        face_values();
        seams();
        edge_values();
        vertex_values();
    }

private:
    bool sharp(Edge e) const { return m_.is_boundary(e) || (crease_ && crease_[e] != 0); }
    // The value of face(o) at to_vertex(o), for an outgoing o of a boundary too.
    T far_value(Halfedge o) const {
        return m_.is_boundary(o) ? uv_[m_.prev(Mesh::twin(o)).idx()] : uv_[o.idx()];
    }

    // Face points (Catmull-Clark and linear): the centroid of the face's values.
    void face_values() {
        if (rules_.scheme == Scheme::Loop) {
            return;
        }
        face_.resize(m_.faces_size());
        for (const Face f : m_.faces()) {
            T sum{};
            std::size_t k = 0;
            for (const Halfedge h : m_.halfedges(f)) {
                sum = sum + uv_[h.idx()];
                ++k;
            }
            face_[f.idx()] = sum * (1.0 / static_cast<double>(k));
        }
    }

    // An interior edge is a seam when its faces give either end different values.
    void seams() {
        seam_.assign(m_.edges_size(), 0);
        for (const Edge e : m_.edges()) {
            const Halfedge a = Mesh::halfedge(e, 0), b = Mesh::halfedge(e, 1);
            if (!m_.is_boundary(a) && !m_.is_boundary(b)) {
                seam_[e.idx()] = !(uv_[a.idx()] == uv_[m_.prev(b).idx()]) ||
                                 !(uv_[m_.prev(a).idx()] == uv_[b.idx()]);
            }
        }
    }

    // The point of each edge, per face side: one value on smooth edges (both sides share
    // its bits), the midpoint of the side's own values on seams, boundaries and creases.
    void edge_values() {
        edge_.resize(m_.halfedges_size());
        for (const Edge e : m_.edges()) {
            const Halfedge a = Mesh::halfedge(e, 0), b = Mesh::halfedge(e, 1);
            if (s_.linear || seam_[e.idx()] != 0 || sharp(e)) {
                for (const Halfedge h : {a, b}) {
                    if (!m_.is_boundary(h)) {
                        edge_[h.idx()] = (uv_[h.idx()] + uv_[m_.prev(h).idx()]) * 0.5;
                    }
                }
                continue;
            }
            const T ends = uv_[a.idx()] + uv_[m_.prev(a).idx()];
            T point;
            if (rules_.scheme == Scheme::Loop) {
                point = ends * 0.375 + (uv_[m_.next(a).idx()] + uv_[m_.next(b).idx()]) * 0.125;
            } else {
                point = (ends + face_[m_.face(a).idx()] + face_[m_.face(b).idx()]) * 0.25;
            }
            edge_[a.idx()] = point;
            edge_[b.idx()] = point;
        }
    }

    void vertex_values() {
        vertex_.resize(m_.halfedges_size());
        for (const Vertex v : m_.vertices()) {
            vertex(v);
        }
    }

    // The new values of old vertex v's corners.
    void vertex(Vertex v) {
        const Halfedge start = m_.halfedge(v);
        if (!start.is_valid()) {
            return;
        }
        // Faces around v in OpenSubdiv's order: from face k to k + 1 across face k's incoming
        // edge; a boundary vertex's first face leaves it along a boundary edge.
        ring_.clear();
        std::size_t gaps = 0, valence = 0;
        bool on_seam = false;
        Halfedge o = start;
        do {
            ++valence;
            gaps += m_.is_boundary(o) ? 1 : 0;
            on_seam = on_seam || seam_[Mesh::edge(o).idx()] != 0;
            o = m_.ccw_rotated(o);
            if (!m_.is_boundary(o)) {
                ring_.push_back(o);
            }
        } while (o != start);
        const bool boundary = gaps > 0;
        const std::size_t n = ring_.size();
        if (n == 0) {
            return;
        }
        // Where the faces do not close into one fan, values can differ without a seam.
        bool split_fans = false;
        for (std::size_t k = 1; gaps > 1 && k < n; ++k) {
            split_fans =
                split_fans || !(uv_[m_.prev(ring_[k]).idx()] == uv_[m_.prev(ring_[0]).idx()]);
        }
        const bool mismatch = on_seam || split_fans ||
                              (boundary && (s_.linear_boundaries || (n == 1 && s_.corners_sharp)));
        if (!mismatch) {
            const T p = uv_[m_.prev(ring_[0]).idx()];
            const T q = s_.linear ? p : smooth(v, p, valence);
            for (const Halfedge f : ring_) {
                vertex_[m_.prev(f).idx()] = q;
            }
            return;
        }
        // The distinct values and, per face, which one it has, numbered as OpenSubdiv does:
        // around an interior vertex from its lowest face on, and a value that comes back
        // after two others (A B A B) counted again, as a value of its own.
        if (!boundary) {
            const auto lowest = std::min_element(
                ring_.begin(), ring_.end(),
                [&](Halfedge a, Halfedge b) { return m_.face(a).idx() < m_.face(b).idx(); });
            std::rotate(ring_.begin(), lowest, ring_.end());
        }
        values_.clear();
        sibling_.assign(n, 0);
        values_.push_back(uv_[m_.prev(ring_[0]).idx()]);
        for (std::size_t k = 1; k < n; ++k) {
            const T x = uv_[m_.prev(ring_[k]).idx()];
            if (x == uv_[m_.prev(ring_[k - 1]).idx()]) {
                sibling_[k] = sibling_[k - 1];
                continue;
            }
            std::size_t i = values_.size();
            if (values_.size() > 2 || (values_.size() == 2 && values_[0] == x)) {
                i = 0;
                while (i < values_.size() && !(values_[i] == x)) {
                    ++i;
                }
            }
            if (i == values_.size()) {
                values_.push_back(x);
            }
            sibling_[k] = static_cast<std::uint32_t>(i);
        }
        const std::size_t nv = values_.size();
        bool all_corners = s_.linear || s_.linear_boundaries || gaps > 1 ||
                           (s_.dependent && nv > 2) || (s_.sharpen_darts && nv == 1 && !boundary);
        spans(v, boundary);
        if (!all_corners && s_.dependent && nv == 2) {
            all_corners = span_[0].disjoint || span_[1].disjoint ||
                          (s_.sharpen_both && (span_[0].size == 1 || span_[1].size == 1));
        }
        for (std::size_t i = 0; i < nv; ++i) {
            const Span& s = span_[i];
            T q = values_[i];
            if (!(all_corners || s.disjoint || (s.size == 1 && s_.corners_sharp))) {
                // A crease along the run's two bounding edges: the first face's outgoing
                // edge, the last face's incoming edge.
                const T a = uv_[ring_[s.first].idx()];
                const T b = uv_[m_.prev(m_.prev(ring_[s.last])).idx()];
                q = q * 0.75 + (a + b) * 0.125;
            }
            for (std::size_t k = 0; k < n; ++k) {
                if (sibling_[k] == i) {
                    vertex_[m_.prev(ring_[k]).idx()] = q;
                }
            }
        }
    }

    // The scheme's own rule for a vertex on no seam, as for the positions.
    T smooth(Vertex v, const T& p, std::size_t valence) const {
        T neighbours{}, sharp_ends{}, faces{};
        std::size_t n_sharp = 0;
        for (const Halfedge o : m_.halfedges(v)) {
            const T far = far_value(o);
            neighbours = neighbours + far;
            if (sharp(Mesh::edge(o))) {
                sharp_ends = sharp_ends + far;
                ++n_sharp;
            }
            if (rules_.scheme != Scheme::Loop && !m_.is_boundary(o)) {
                faces = faces + face_[m_.face(o).idx()];
            }
        }
        switch (loop_rules::classify(n_sharp)) {
            case loop_rules::VertexRule::Smooth: {
                const double n = static_cast<double>(valence);
                if (rules_.scheme == Scheme::Loop) {
                    const double u = weight_(valence);
                    return p * (1.0 - n * u) + neighbours * u;
                }
                return p * ((n - 2.0) / n) + (neighbours + faces) * (1.0 / (n * n));
            }
            case loop_rules::VertexRule::Crease:
                return p * 0.75 + sharp_ends * 0.125;
            case loop_rules::VertexRule::Corner:
                break;
        }
        return p;
    }

    // Per value: how many faces have it, whether they are one run unbroken by a seam or a
    // sharp edge, and the run's first and last face.
    struct Span {
        std::size_t size = 0, first = 0, last = 0;
        bool disjoint = false;
    };
    void spans(Vertex v, bool boundary) {
        const std::size_t n = ring_.size();
        span_.assign(values_.size(), Span{});
        // The edge between faces k - 1 and k is face k's outgoing edge.
        const auto breaks = [&](std::size_t k) {
            const Edge e = Mesh::edge(ring_[k]);
            return seam_[e.idx()] != 0 || sharp(e);
        };
        if (values_.size() == 1 && !boundary) {
            // One value with a seam at v: a dart when exactly one seam ends here.
            Span& s = span_[0];
            s.size = n;
            std::size_t seams = 0;
            for (const Halfedge o : m_.halfedges(v)) {
                const Edge e = Mesh::edge(o);
                s.disjoint = s.disjoint || sharp(e);
                seams += seam_[e.idx()];
            }
            s.disjoint = s.disjoint || seams > 1;
            for (std::size_t k = 0; k < n && !s.disjoint; ++k) {
                if (seam_[Mesh::edge(ring_[k]).idx()] != 0) {
                    s.first = k;
                    s.last = (k + n - 1) % n;
                }
            }
            return;
        }
        // Around an interior vertex, begin where the value changes so runs do not wrap.
        std::size_t begin = 0;
        while (!boundary && sibling_[begin] == sibling_[(begin + n - 1) % n]) {
            ++begin;
        }
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t k = (begin + j) % n;
            Span& s = span_[sibling_[k]];
            if (j > 0 && sibling_[k] == sibling_[(k + n - 1) % n]) {
                s.disjoint = s.disjoint || breaks(k);
            } else {
                s.disjoint = s.disjoint || s.size > 0;
                s.first = k;
            }
            s.last = k;
            ++s.size;
        }
    }

    const Mesh& m_;
    const FaceVaryingRules& rules_;
    const Switches s_;
    const memory::Array<T>& uv_;
    const EdgeProperty<std::uint8_t> crease_;
    const loop_rules::WeightTable weight_;
    // The level's values, filled here.
    memory::Array<T>& face_;
    memory::Array<T>& edge_;
    memory::Array<T>& vertex_;
    std::vector<std::uint8_t> seam_;
    // Scratch of vertex().
    std::vector<Halfedge> ring_;
    std::vector<T> values_;
    std::vector<std::uint32_t> sibling_;
    std::vector<Span> span_;
};

}  // namespace

template <class T>
FaceVaryingLevel<T> prepare_face_varying(const Mesh& base, const FaceVaryingRules& rules,
                                         const memory::Array<T>& old) {
    FaceVaryingLevel<T> level;
    level.scheme = rules.scheme;
    level.edges = base.edges_size();
    Refiner<T>(base, rules, old, level).run();
    level.boundary.resize(base.halfedges_size());
    for (std::size_t h = 0; h < base.halfedges_size(); ++h) {
        level.boundary[h] = base.is_boundary(Halfedge(static_cast<std::uint32_t>(h))) ? 1 : 0;
    }
    level.corner_start.reserve(base.faces_size() + 1);
    level.corners.reserve(base.halfedges_size());
    for (std::uint32_t f = 0; f < base.faces_size(); ++f) {
        level.corner_start.push_back(static_cast<std::uint32_t>(level.corners.size()));
        for (const Halfedge h : base.halfedges(Face(f))) {
            level.corners.push_back(h.idx());
        }
    }
    level.corner_start.push_back(static_cast<std::uint32_t>(level.corners.size()));
    return level;
}

// Each new corner takes the value of what it stands on, named by the layouts' formulas
// (subdivision.cpp, quad_subdivision.cpp) without reading the refined mesh: old halfedge h
// (in face f) becomes 2h, ending at h's edge point in f, and 2h + 1, ending at from_vertex(h)
// in twin(h)'s face. Loop's inner halfedges 2I_i and 2I_i + 1 of face f (I_i = 2E + 3f + i)
// end at the edge points of h_i and h_i+1 in f; the quads' corners are numbered face by face
// from halfedge(f), and the inner halfedge 2(2E + corner(h)) ends at f's face point, its
// twin at h's edge point in f.
template <class T>
void write_face_varying(const FaceVaryingLevel<T>& level, std::size_t refined_halfedges,
                        memory::Array<T>& out) {
    const std::size_t nh = level.boundary.size(), ne = level.edges;
    out.resize_for_overwrite(refined_halfedges);
    for (std::size_t h = 0; h < nh; ++h) {
        out[2 * h] = level.boundary[h] != 0 ? T{} : level.edge[h];
        out[2 * h + 1] = level.boundary[h ^ 1] != 0 ? T{} : level.vertex[h ^ 1];
    }
    const std::size_t nf = level.corner_start.size() - 1;
    for (std::size_t f = 0; f < nf; ++f) {
        const std::uint32_t first = level.corner_start[f], end = level.corner_start[f + 1];
        for (std::uint32_t c = first; c < end; ++c) {
            const std::uint32_t h = level.corners[c];
            if (level.scheme == Scheme::Loop) {
                const std::size_t a = 2 * (2 * ne + c);  // c = 3f + i
                out[a] = level.edge[h];
                out[a + 1] = level.edge[level.corners[c + 1 == end ? first : c + 1]];
            } else {
                const std::size_t inner = 2 * (2 * ne + c);
                out[inner] = level.face[f];
                out[inner + 1] = level.edge[h];
            }
        }
    }
}

#define MESHEDIT_FACE_VARYING(T)                                                               \
    template FaceVaryingLevel<T> prepare_face_varying<T>(const Mesh&, const FaceVaryingRules&, \
                                                         const memory::Array<T>&);             \
    template void write_face_varying<T>(const FaceVaryingLevel<T>&, std::size_t, memory::Array<T>&);
MESHEDIT_FACE_VARYING(Vec2)
MESHEDIT_FACE_VARYING(Vec3)
#undef MESHEDIT_FACE_VARYING

}  // namespace meshedit::refine
