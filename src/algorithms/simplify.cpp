// QEM simplification (Garland–Heckbert 1997), with area-weighted face quadrics, penalty
// quadrics on boundary and crease edges, optimal placement, and a normal-flip guard.
//
// One collapse of edge a-b (collapse() keeps the smaller index, here a):
//
//          c                         c
//        /   \                       |
//      a ----- b        ==>          a'       a' = argmin (Q_a + Q_b)(x)
//        \   /                       |        Q_a' = Q_a + Q_b
//          d                         d
//
// Crease vertices stay exactly on their creases (remesh.cpp's rule, not only the soft pull of
// the feature planes, which let them drift off by a share of an edge): along a crease the
// survivor takes an end's place, the corner's if there is one; across, the crease end's; an
// edge between two crease vertices that is no crease would cut a chord, and never collapses.
// Without crease marks none of this runs and the result is as before.
//
// With texture coordinates, colours or materials (SimplifyAttributes::Aware), the attribute
// quadrics of simplify_attributes.h join the position quadric and plan each collapse's corner
// values; the blind instantiation of the simplifier is the one of before.
//
// Candidates live in an indexed 4-ary min-heap of (cost, edge), 8 bytes an entry, with each
// edge's place in it: a collapse re-keys the edges around the survivor in place and removes
// the deleted ones, so the heap never holds more than one entry per edge. (A heap of stale
// entries grew to twice the edges and its cache misses took two thirds of the time.)

#include "meshedit/core/simplify.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "local_ops/collapse_guard.h"
#include "mesh/triangles_only.h"
#include "mesh/unit_scale.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/memory.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/number_text.h"
#include "meshedit/core/validate.h"
#include "simplify_attributes.h"
#include "simplify_quadric.h"

namespace meshedit {
namespace {

using qem::AttributeSimplifier;
using qem::CornerPlan;
using qem::Quadric;

// The weight of a boundary or crease edge's constraint plane, times its squared length: large
// against the face quadrics (area-weighted), so features move only along themselves.
constexpr double kFeatureWeight = 100.0;

// A min-heap of edges keyed by a float, 4 children a node, with the place of every edge in it
// (kInvalidIndex when absent) so a key can change in place.
class EdgeHeap {
public:
    explicit EdgeHeap(std::size_t edges) : place_(edges, kInvalidIndex) {}

    bool empty() const { return entries_.empty(); }
    std::uint32_t top() const { return entries_.front().edge; }

    // Builds the heap from every (edge, cost) at once (O(n)).
    void assign(const std::vector<std::pair<std::uint32_t, float>>& all) {
        entries_.clear();
        entries_.reserve(all.size());
        for (const auto& [edge, cost] : all) {
            place_[edge] = static_cast<std::uint32_t>(entries_.size());
            entries_.push_back({cost, edge});
        }
        for (std::size_t i = entries_.size(); i-- > 0;) {
            down(i);
        }
    }
    // Inserts `edge` or changes its cost.
    void set(std::uint32_t edge, float cost) {
        const std::uint32_t i = place_[edge];
        if (i == kInvalidIndex) {
            entries_.push_back({cost, edge});
            up(entries_.size() - 1);
            return;
        }
        const float old = entries_[i].cost;
        entries_[i].cost = cost;
        if (cost < old) {
            up(i);
        } else {
            down(i);
        }
    }
    void remove(std::uint32_t edge) {
        const std::uint32_t i = place_[edge];
        if (i == kInvalidIndex) {
            return;
        }
        place_[edge] = kInvalidIndex;
        const Entry last = entries_.back();
        entries_.pop_back();
        if (i == entries_.size()) {
            return;
        }
        entries_[i] = last;
        if (i > 0 && last.cost < entries_[(i - 1) / 4].cost) {
            up(i);
        } else {
            down(i);
        }
    }

private:
    struct Entry {
        float cost;
        std::uint32_t edge;
    };
    void put(std::size_t i, const Entry& e) {
        entries_[i] = e;
        place_[e.edge] = static_cast<std::uint32_t>(i);
    }
    void up(std::size_t i) {
        const Entry e = entries_[i];
        while (i > 0) {
            const std::size_t parent = (i - 1) / 4;
            if (!(e.cost < entries_[parent].cost)) {
                break;
            }
            put(i, entries_[parent]);
            i = parent;
        }
        put(i, e);
    }
    void down(std::size_t i) {
        const Entry e = entries_[i];
        const std::size_t n = entries_.size();
        for (;;) {
            const std::size_t first = 4 * i + 1;
            if (first >= n) {
                break;
            }
            std::size_t best = first;
            for (std::size_t c = first + 1; c < std::min(first + 4, n); ++c) {
                if (entries_[c].cost < entries_[best].cost) {
                    best = c;
                }
            }
            if (!(entries_[best].cost < e.cost)) {
                break;
            }
            put(i, entries_[best]);
            i = best;
        }
        put(i, e);
    }

    memory::Array<Entry> entries_;  // huge pages: fewer page faults on big meshes
    memory::Array<std::uint32_t> place_;
};

// Where an edge's survivor goes and what that costs.
struct Candidate {
    double cost;
    Vec3 position;
    bool allowed = true;  ///< false: it would pull a crease vertex off its crease
    Vertex at;            ///< the end it is pinned to (a crease vertex), if any
};

// Aware: with the attribute quadrics (simplify_attributes.h). The blind instantiation is the
// simplifier of before, branch for branch: a mesh without attributes pays nothing for them.
template <bool Aware>
class Simplifier {
public:
    Simplifier(Mesh& mesh, const SimplifyOptions& options)
        : mesh_(mesh),
          options_(options),
          quadric_(mesh.vertices_size()),
          heap_(mesh.edges_size()),
          cos_limit_(std::cos(options.max_normal_change_deg * M_PI / 180.0)),
          diagonal_(mesh.bounds().diagonal()),
          crease_(mesh.get_property<Edge, std::uint8_t>(kCreaseProperty)) {
        if constexpr (Aware) {
            attributes_.emplace(mesh, diagonal_);
        }
        if (!options.vertices.empty()) {
            movable_.assign(mesh.vertices_size(), 0);
            for (const Vertex v : options.vertices) {
                movable_[v.idx()] = 1;
            }
        }
    }

    SimplifyReport run() {
        gather_quadrics();
        if constexpr (Aware) {
            attributes_->gather(quadric_);
        }
        std::vector<std::pair<std::uint32_t, float>> all;
        all.reserve(mesh_.n_edges());
        for (Edge e : mesh_.edges()) {
            if (movable(e)) {
                all.emplace_back(e.idx(), key(error_of(candidate(e), e)));
            }
        }
        heap_.assign(all);
        const std::size_t start = mesh_.n_faces();
        const double span = static_cast<double>(start - std::min(start, options_.target_faces));
        while (mesh_.n_faces() > options_.target_faces && !heap_.empty()) {
            const Edge e(heap_.top());
            heap_.remove(e.idx());  // back in when a neighbour's collapse changes its cost
            // Computed again rather than stored: the quadrics are read here anyway, and a
            // stored place per edge was one more cache miss per pop.
            const Candidate c = candidate(e);
            if (!c.allowed) {
                ++report_.refused_crease;
                continue;
            }
            const double error = error_of(c, e);
            if (error > options_.max_error) {
                continue;
            }
            if (!is_collapse_ok(mesh_, e)) {
                ++report_.refused_topology;
                continue;
            }
            if (collapse_turns_a_face(mesh_, e, c.position, cos_limit_)) {
                ++report_.refused_normal;
                continue;
            }
            if constexpr (Aware) {
                const CornerPlan plan = attributes_->plan(e, c.position, c.at);
                if (plan != CornerPlan::Ok) {
                    ++(plan == CornerPlan::Seam ? report_.refused_seam : report_.refused_uv_flip);
                    continue;
                }
            }
            apply(e, c.position);
            report_.largest_error = std::max(report_.largest_error, error);
            if ((++report_.collapses & 4095u) == 0 && options_.progress && span > 0) {
                options_.progress(static_cast<double>(start - mesh_.n_faces()) / span);
            }
        }
        report_.stopped_early = mesh_.n_faces() > options_.target_faces;
        if (options_.progress) {
            options_.progress(1.0);
        }
        return report_;
    }

private:
    void gather_quadrics() {
        for (Face f : mesh_.faces()) {
            const Vec3 twice_area = face_area_vector(mesh_, f);
            const double length = norm(twice_area);
            if (!(length > 0.0)) {
                continue;  // a degenerate face has no plane
            }
            const Vec3 n = twice_area * (1.0 / length);
            const double d = -dot(n, mesh_.position(mesh_.to_vertex(mesh_.halfedge(f))));
            for (Vertex v : mesh_.vertices(f)) {
                quadric_[v.idx()].add_plane(n, d, 0.5 * length);
                quadric_[v.idx()].area += 0.5 * length;
            }
        }
        const auto crease = mesh_.get_property<Edge, std::uint8_t>(kCreaseProperty);
        for (Edge e : mesh_.edges()) {
            // With attributes, material borders too: a colour's edge stays where it was.
            if (!mesh_.is_boundary(e) && !(crease && crease[e] != 0) &&
                !(Aware && attributes_->is_material_border(e))) {
                continue;
            }
            const Vertex a = mesh_.vertex(e, 0), b = mesh_.vertex(e, 1);
            const Vec3 along = mesh_.position(b) - mesh_.position(a);
            for (unsigned side = 0; side < 2; ++side) {
                const Face f = mesh_.face(e, side);
                if (!f.is_valid()) {
                    continue;
                }
                const Vec3 m = cross(along, face_area_vector(mesh_, f));
                const double length = norm(m);
                if (!(length > 0.0)) {
                    continue;
                }
                const Vec3 n = m * (1.0 / length);
                const double d = -dot(n, mesh_.position(a));
                const double w = kFeatureWeight * dot(along, along);
                quadric_[a.idx()].add_plane(n, d, w);
                quadric_[b.idx()].add_plane(n, d, w);
            }
        }
    }

    // The cheapest place for the survivor of e and its cost.
    Candidate candidate(Edge e) const {
        const Vertex a = mesh_.vertex(e, 0), b = mesh_.vertex(e, 1);
        Quadric q = quadric_[a.idx()] + quadric_[b.idx()];
        if constexpr (Aware) {
            attributes_->reduce_into(a, b, q);  // each attribute at its best for a place
        }
        const Vec3& pa = mesh_.position(a);
        const Vec3& pb = mesh_.position(b);
        if (crease_) {
            if (const std::optional<Candidate> held = on_crease(e, q)) {
                return *held;
            }
        }
        Candidate c{0.0, {}, true, {}};
        Vec3 best;
        // The minimiser, unless it lies far from the edge (a nearly singular system that
        // passed the determinant test): then the best of the ends and the midpoint.
        if (q.minimiser(best) && distance(best, (pa + pb) * 0.5) <= 2.0 * distance(pa, pb)) {
            c.position = best;
            c.cost = q(best);
            return c;
        }
        c.position = pa;
        c.cost = q(pa);
        for (const Vec3& p : {pb, (pa + pb) * 0.5}) {
            if (const double cost = q(p); cost < c.cost) {
                c.cost = cost;
                c.position = p;
            }
        }
        return c;
    }

    bool is_crease(Edge e) const { return crease_[e] != 0; }
    bool on_a_crease(Vertex v) const {
        for (Edge g : mesh_.edges(v)) {
            if (is_crease(g)) {
                return true;
            }
        }
        return false;
    }
    // Where the survivor of e must go when an end is on a crease (the file's comment), or
    // nothing when neither is.
    std::optional<Candidate> on_crease(Edge e, const Quadric& q) const {
        const Vertex a = mesh_.vertex(e, 0), b = mesh_.vertex(e, 1);
        const bool on_a = on_a_crease(a), on_b = on_a_crease(b);
        if (!on_a && !on_b) {
            return std::nullopt;
        }
        const Candidate never{std::numeric_limits<double>::infinity(), {}, false, {}};
        const auto at = [&](Vertex v) {
            return Candidate{q(mesh_.position(v)), mesh_.position(v), true, v};
        };
        if (!is_crease(e)) {
            return on_a && on_b ? never : at(on_a ? a : b);
        }
        const auto crease = [this](Edge g) { return is_crease(g); };
        const bool corner_a = is_feature_corner(mesh_, a, crease);
        const bool corner_b = is_feature_corner(mesh_, b, crease);
        if (corner_a || corner_b) {
            return corner_a && corner_b ? never : at(corner_a ? a : b);
        }
        const Candidate ca = at(a), cb = at(b);
        return cb.cost < ca.cost ? cb : ca;
    }

    // The area-weighted mean squared distance to the planes the collapse gathers: the cost
    // over the area behind it. The heap orders by it (by its root), not by the cost: the cost grows
    // with the area, so ordering by it simplified big faces too little and small ones too much, and
    // the bench's Hausdorff distances were 9-25% worse than CGAL's (docs/simplify.md).
    double mean_square(const Candidate& c, Edge e) const {
        const double area =
            quadric_[mesh_.vertex(e, 0).idx()].area + quadric_[mesh_.vertex(e, 1).idx()].area;
        return area > 0.0 ? std::max(0.0, c.cost) / area : 0.0;
    }

    // The root of mean_square(), over the bbox diagonal; also the heap's key: a float of the
    // square itself has half the resolution, and its ties cost the torus bench 8% of
    // Hausdorff distance (0.0033% against 0.0031%).
    double error_of(const Candidate& c, Edge e) const {
        return diagonal_ > 0.0 ? std::sqrt(mean_square(c, e)) / diagonal_ : 0.0;
    }

    // The heap orders by a float: plenty to choose the next collapse, half the bytes.
    static float key(double cost) { return static_cast<float>(std::clamp(cost, 0.0, 3.0e38)); }

    void apply(Edge e, const Vec3& p) {
        const Vertex a = mesh_.vertex(e, 0), b = mesh_.vertex(e, 1);
        const Quadric q = quadric_[a.idx()] + quadric_[b.idx()];
        // The edges that may go (one of each pair the collapse merges): out of the heap
        // first; those that stay go back in with their new cost below. (Re-keying them in
        // place sifts most of them down a long way and was 15% slower in all.)
        for (const Vertex v : {a, b}) {
            for (Edge g : mesh_.edges(v)) {
                heap_.remove(g.idx());
            }
        }
        const Vertex s = *collapse(mesh_, e);
        mesh_.position(s) = p;
        quadric_[s.idx()] = q;
        if constexpr (Aware) {
            attributes_->apply(a, b, s, quadric_[s.idx()]);
        }
        for (Edge g : mesh_.edges(s)) {
            if (movable(g)) {
                heap_.set(g.idx(), key(error_of(candidate(g), g)));
            }
        }
    }

    // Whether e may collapse: both ends among SimplifyOptions::vertices (or no list).
    bool movable(Edge e) const {
        return movable_.empty() ||
               (movable_[mesh_.vertex(e, 0).idx()] != 0 && movable_[mesh_.vertex(e, 1).idx()] != 0);
    }

    Mesh& mesh_;
    const SimplifyOptions& options_;
    memory::Array<Quadric> quadric_;
    EdgeHeap heap_;
    double cos_limit_;
    double diagonal_;
    EdgeProperty<std::uint8_t> crease_;              // null: no crease marks, no crease rule
    std::optional<AttributeSimplifier> attributes_;  // none: blind, or nothing to weigh
    std::vector<std::uint8_t> movable_;              // empty: every vertex may go
    SimplifyReport report_;
};

// check_simplify()'s reason as text (composed: it names counts).
std::string why_not_simplify(const Mesh& mesh, const SimplifyOptions& options) {
    if (std::string why = refuse_unless_triangles(mesh, "simplify", "QEM"); !why.empty()) {
        return why;
    }
    if (options.target_faces == 0 || options.target_faces >= mesh.n_faces()) {
        return "cannot simplify: the target must be from 1 to " +
               std::to_string(mesh.n_faces() - 1) + " faces (the mesh has " +
               std::to_string(mesh.n_faces()) + "), not " + std::to_string(options.target_faces);
    }
    if (!(options.max_error >= 0.0)) {
        return "cannot simplify: the error bound must be a number of 0 or more";
    }
    for (const Vertex v : options.vertices) {
        if (v.idx() >= mesh.vertices_size() || mesh.is_deleted(v)) {
            return "cannot simplify: vertex " + std::to_string(v.idx()) + " does not exist";
        }
    }
    if (options.feature_angle_deg != kNoFeatureAngle &&
        !check_crease_by_angle(options.feature_angle_deg)) {
        return "cannot simplify: the feature angle must be from 0 to 180 degrees (infinity: "
               "off), not " +
               number_text(options.feature_angle_deg);
    }
    if (!(options.max_normal_change_deg > 0.0 && options.max_normal_change_deg <= 180.0)) {
        return "cannot simplify: the normal-change limit must be above 0 and at most 180 degrees";
    }
    // What the simplifier holds beside the mesh, per face: half a vertex's quadric (88 bytes
    // each) and 1.5 edges' heap entry, place and initial cost (20 bytes each), rounded up.
    const double faces = static_cast<double>(mesh.n_faces());
    const bool aware =
        options.attributes == SimplifyAttributes::Aware && AttributeSimplifier::applies(mesh);
    const double per_face = aware ? 100.0 + AttributeSimplifier::bytes_per_vertex() / 2 : 100.0;
    if (const auto over = over_budget(per_face * faces)) {
        return "cannot simplify: the quadrics and the queue of " + std::to_string(mesh.n_faces()) +
               " faces " + *over;
    }
    return {};
}

}  // namespace

OpStatus check_simplify(const Mesh& mesh, const SimplifyOptions& options) {
    return OpStatus::composed(why_not_simplify(mesh, options));
}

SimplifyReport simplify(Mesh& mesh, const SimplifyOptions& options) {
    MESHEDIT_ASSERT(check_simplify(mesh, options));
    if (options.progress) {
        options.progress(0.0);
    }
    // Sharp edges found become creases, which the simplifier holds.
    const std::size_t marked = options.feature_angle_deg == kNoFeatureAngle
                                   ? 0
                                   : crease_by_angle(mesh, options.feature_angle_deg);
    SimplifyReport report;
    {
        const UnitScale unit(mesh);  // quadrics square coordinates: keep them near 1
        report =
            options.attributes == SimplifyAttributes::Aware && AttributeSimplifier::applies(mesh)
                ? Simplifier<true>(mesh, options).run()
                : Simplifier<false>(mesh, options).run();
    }
    report.creases_marked = marked;
    MESHEDIT_ASSERT(!validate(mesh));
    return report;
}

}  // namespace meshedit
