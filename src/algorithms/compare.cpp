// Topological equality up to renumbering (compare.h): a halfedge of A matched with one of B
// fixes the whole component, since next and twin reach every halfedge of it, so one try is a
// propagation that either covers the component or meets an inconsistency.

#include "meshedit/core/compare.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <tuple>
#include <utility>

#include "meshedit/core/hash.h"

namespace meshedit {
namespace {

constexpr std::uint32_t kNone = kInvalidIndex;
// Position candidates tried per component before the signatures (copies stacked in place).
constexpr int kPositionTries = 16;

// A position as bits, so that sorting and equality are total even for NaN.
using PositionKey = std::array<std::uint64_t, 3>;
PositionKey key_of(const Vec3& p) {
    return {std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y),
            std::bit_cast<std::uint64_t>(p.z)};
}

constexpr std::uint64_t mix(std::uint64_t x) {
    return splitmix64(x);
}

std::string count_text(const char* what, std::size_t a, std::size_t b) {
    return std::string("the ") + what + " counts differ: " + std::to_string(a) + " in A, " +
           std::to_string(b) + " in B";
}

// What the matching reads of one mesh, by element index: halfedges into each vertex, corners
// of each face, and (only when the positions give no start) refined halfedge signatures.
struct Side {
    const Mesh& mesh;
    std::vector<std::uint32_t> valence, degree;
    std::vector<std::uint64_t> signature;

    explicit Side(const Mesh& m)
        : mesh(m), valence(m.vertices_size(), 0), degree(m.faces_size(), 0) {
        for (const Halfedge h : m.halfedges()) {
            ++valence[m.to_vertex(h).idx()];
            if (!m.is_boundary(h)) {
                ++degree[m.face(h).idx()];
            }
        }
    }
    std::size_t isolated() const {
        std::size_t n = 0;
        for (const Vertex v : mesh.vertices()) {
            n += mesh.is_isolated(v) ? 1 : 0;
        }
        return n;
    }
    std::uint64_t face_word(Halfedge h) const {
        return mesh.is_boundary(h) ? 0 : degree[mesh.face(h).idx()] + 1;
    }
    // Valences and face degree, then two rounds over next, prev and twin: invariant under
    // renumbering, so a halfedge can only match one of equal signature.
    void compute_signatures() {
        const Mesh& m = mesh;
        std::vector<std::uint64_t> s(m.halfedges_size(), 0);
        for (const Halfedge h : m.halfedges()) {
            s[h.idx()] =
                mix(valence[m.to_vertex(h).idx()] ^
                    (std::uint64_t(valence[m.from_vertex(h).idx()]) << 20) ^ (face_word(h) << 40));
        }
        for (int round = 0; round < 2; ++round) {
            std::vector<std::uint64_t> t(s.size(), 0);
            for (const Halfedge h : m.halfedges()) {
                t[h.idx()] = mix(s[h.idx()] ^ mix(s[m.next(h).idx()] + 1) ^
                                 mix(s[m.prev(h).idx()] + 2) ^ mix(s[Mesh::twin(h).idx()] + 3));
            }
            s.swap(t);
        }
        signature = std::move(s);
    }
    // An order-free hash of the multiset of signatures: equal for isomorphic meshes.
    std::pair<std::uint64_t, std::uint64_t> histogram_hash() const {
        std::uint64_t sum = 0, other = 0;
        for (const Halfedge h : mesh.halfedges()) {
            sum += mix(signature[h.idx()]);
            other += mix(signature[h.idx()] ^ 0x5851f42d4c957f2dull);
        }
        return {sum, other};
    }
};

class Matcher {
public:
    Matcher(const Mesh& a, const Mesh& b)
        : a_(a),
          b_(b),
          h_ab_(a.halfedges_size(), kNone),
          h_ba_(b.halfedges_size(), kNone),
          v_ab_(a.vertices_size(), kNone),
          v_ba_(b.vertices_size(), kNone),
          f_ab_(a.faces_size(), kNone),
          f_ba_(b.faces_size(), kNone) {}

    TopologyMatch run();

private:
    bool counts_agree();
    bool match_component(Halfedge start);
    bool try_positions(Halfedge start);
    bool try_signatures(Halfedge start);
    bool attempt(Halfedge x, Halfedge y);
    bool bind(Halfedge x, Halfedge y);
    bool bind_element(ElementRef ra, ElementRef rb, std::uint32_t na, std::uint32_t nb,
                      const char* counted, std::vector<std::uint32_t>& ab,
                      std::vector<std::uint32_t>& ba, std::vector<std::uint32_t>& tried);
    bool fail(ElementRef at_a, ElementRef at_b, const std::string& what);
    void rollback();
    void match_isolated();
    std::vector<Halfedge> component_of(Halfedge start) const;

    const Mesh& a_;
    const Mesh& b_;
    Side sa_{a_}, sb_{b_};
    std::vector<std::uint32_t> h_ab_, h_ba_, v_ab_, v_ba_, f_ab_, f_ba_;
    // What the current try set (A's indices), to undo it when it fails.
    std::vector<std::uint32_t> tried_h_, tried_v_, tried_f_;
    // B's vertices sorted by position; B's halfedges sorted by signature (built when needed).
    std::vector<std::pair<PositionKey, std::uint32_t>> b_positions_;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> b_signatures_;
    bool signatures_differ_ = false;
    TopologyMatch result_;  // the first failure is the one reported
};

bool Matcher::fail(ElementRef at_a, ElementRef at_b, const std::string& what) {
    if (result_.difference.empty()) {
        result_.difference = what;
        result_.first_a = at_a;
        result_.first_b = at_b;
    }
    return false;
}

bool Matcher::counts_agree() {
    const std::tuple<const char*, std::size_t, std::size_t> counts[] = {
        {"vertex", a_.n_vertices(), b_.n_vertices()},
        {"edge", a_.n_edges(), b_.n_edges()},
        {"face", a_.n_faces(), b_.n_faces()},
        {"isolated vertex", sa_.isolated(), sb_.isolated()},
    };
    for (const auto& [what, na, nb] : counts) {
        if (na != nb) {
            result_.difference = count_text(what, na, nb);
            return false;
        }
    }
    return true;
}

// Takes vertex or face ra ↦ rb (of `na` and `nb` edges or corners), unless either is matched
// with another already.
bool Matcher::bind_element(ElementRef ra, ElementRef rb, std::uint32_t na, std::uint32_t nb,
                           const char* counted, std::vector<std::uint32_t>& ab,
                           std::vector<std::uint32_t>& ba, std::vector<std::uint32_t>& tried) {
    if (na != nb) {
        return fail(ra, rb,
                    describe(a_, ra) + " of A has " + std::to_string(na) + " " + counted + " and " +
                        describe(b_, rb) + " of B, its match, has " + std::to_string(nb));
    }
    if (ab[ra.index] == rb.index) {
        return true;
    }
    if (ab[ra.index] != kNone || ba[rb.index] != kNone) {
        return fail(ra, rb,
                    describe(a_, ra) + " of A and " + describe(b_, rb) +
                        " of B meet by next and twin, but one of them already matches another " +
                        kind_name(ra.kind) + " (the " + counted + " around it differ)");
    }
    ab[ra.index] = rb.index;
    ba[rb.index] = ra.index;
    tried.push_back(ra.index);
    return true;
}

// Takes x ↦ y, checking it against everything matched so far. The checks of valence and face
// degree are implied by the rest but fail earlier and say more.
bool Matcher::bind(Halfedge x, Halfedge y) {
    const auto hx = ElementRef::halfedge(x), hy = ElementRef::halfedge(y);
    auto pair = [&] { return describe(a_, hx) + " of A and " + describe(b_, hy) + " of B"; };
    if (h_ab_[x.idx()] != kNone || h_ba_[y.idx()] != kNone) {
        if (h_ab_[x.idx()] == y.idx()) {
            return true;
        }
        return fail(
            hx, hy,
            pair() + " meet by next and twin, but " +
                (h_ab_[x.idx()] != kNone
                     ? "the first already matches " +
                           describe(b_, ElementRef::halfedge(Halfedge(h_ab_[x.idx()]))) + " of B"
                     : "the second already matches " +
                           describe(a_, ElementRef::halfedge(Halfedge(h_ba_[y.idx()]))) + " of A"));
    }
    if (a_.is_boundary(x) != b_.is_boundary(y)) {
        return fail(hx, hy,
                    pair() + ": only the " + (a_.is_boundary(x) ? "first" : "second") +
                        " is on a boundary");
    }
    const Vertex vx = a_.to_vertex(x), vy = b_.to_vertex(y);
    if (!bind_element(ElementRef::vertex(vx), ElementRef::vertex(vy), sa_.valence[vx.idx()],
                      sb_.valence[vy.idx()], "edges", v_ab_, v_ba_, tried_v_)) {
        return false;
    }
    if (!a_.is_boundary(x)) {
        const Face fx = a_.face(x), fy = b_.face(y);
        if (!bind_element(ElementRef::face(fx), ElementRef::face(fy), sa_.degree[fx.idx()],
                          sb_.degree[fy.idx()], "corners", f_ab_, f_ba_, tried_f_)) {
            return false;
        }
    }
    h_ab_[x.idx()] = y.idx();
    h_ba_[y.idx()] = x.idx();
    tried_h_.push_back(x.idx());
    return true;
}

void Matcher::rollback() {
    for (const std::uint32_t x : tried_h_) {
        h_ba_[h_ab_[x]] = kNone;
        h_ab_[x] = kNone;
    }
    for (const std::uint32_t v : tried_v_) {
        v_ba_[v_ab_[v]] = kNone;
        v_ab_[v] = kNone;
    }
    for (const std::uint32_t f : tried_f_) {
        f_ba_[f_ab_[f]] = kNone;
        f_ab_[f] = kNone;
    }
}

// Propagates x ↦ y breadth first over next and twin (tried_h_ is the queue); undoes it all on
// the first inconsistency.
bool Matcher::attempt(Halfedge x, Halfedge y) {
    tried_h_.clear();
    tried_v_.clear();
    tried_f_.clear();
    bool ok = bind(x, y);
    for (std::size_t i = 0; ok && i < tried_h_.size(); ++i) {
        const Halfedge p(tried_h_[i]), q(h_ab_[tried_h_[i]]);
        ok = bind(a_.next(p), b_.next(q)) && bind(Mesh::twin(p), Mesh::twin(q));
    }
    if (!ok) {
        rollback();
    }
    return ok;
}

// A renumbered copy keeps its positions: B's halfedges with the same end positions as
// `start`, tried first.
bool Matcher::try_positions(Halfedge start) {
    if (b_positions_.empty()) {
        b_positions_.reserve(b_.n_vertices());
        for (const Vertex v : b_.vertices()) {
            b_positions_.emplace_back(key_of(b_.position(v)), v.idx());
        }
        std::sort(b_positions_.begin(), b_positions_.end());
    }
    const PositionKey from = key_of(a_.position(a_.from_vertex(start)));
    const PositionKey to = key_of(a_.position(a_.to_vertex(start)));
    auto it = std::lower_bound(b_positions_.begin(), b_positions_.end(),
                               std::make_pair(from, std::uint32_t{0}));
    int tries = 0;
    for (; it != b_positions_.end() && it->first == from && tries < kPositionTries; ++it) {
        const Vertex u(it->second);
        if (b_.is_isolated(u)) {
            continue;
        }
        for (const Halfedge g : b_.halfedges(u)) {
            if (h_ba_[g.idx()] == kNone && key_of(b_.position(b_.to_vertex(g))) == to) {
                ++tries;
                if (attempt(start, g)) {
                    return true;
                }
            }
        }
    }
    return false;
}

std::vector<Halfedge> Matcher::component_of(Halfedge start) const {
    std::vector<Halfedge> out{start};
    std::vector<std::uint8_t> seen(a_.halfedges_size(), 0);
    seen[start.idx()] = 1;
    for (std::size_t i = 0; i < out.size(); ++i) {
        for (const Halfedge n : {a_.next(out[i]), Mesh::twin(out[i])}) {
            if (!seen[n.idx()]) {
                seen[n.idx()] = 1;
                out.push_back(n);
            }
        }
    }
    return out;
}

// No position match: start at the halfedge of the component whose signature is rarest in B
// and try every free halfedge of B that has it.
bool Matcher::try_signatures(Halfedge start) {
    if (b_signatures_.empty()) {
        sa_.compute_signatures();
        sb_.compute_signatures();
        signatures_differ_ = sa_.histogram_hash() != sb_.histogram_hash();
        b_signatures_.reserve(b_.n_halfedges());
        for (const Halfedge h : b_.halfedges()) {
            b_signatures_.emplace_back(sb_.signature[h.idx()], h.idx());
        }
        std::sort(b_signatures_.begin(), b_signatures_.end());
    }
    auto candidates = [&](Halfedge x) {
        const std::uint64_t s = sa_.signature[x.idx()];
        return std::equal_range(b_signatures_.begin(), b_signatures_.end(), std::make_pair(s, 0u),
                                [](const auto& p, const auto& q) { return p.first < q.first; });
    };
    Halfedge best = start;
    std::size_t fewest = b_signatures_.size() + 1;
    for (const Halfedge x : component_of(start)) {
        const auto [lo, hi] = candidates(x);
        if (static_cast<std::size_t>(hi - lo) < fewest) {
            fewest = static_cast<std::size_t>(hi - lo);
            best = x;
        }
    }
    const auto [lo, hi] = candidates(best);
    if (lo == hi) {
        return fail(ElementRef::halfedge(best), {},
                    describe(a_, ElementRef::halfedge(best)) +
                        " of A has no counterpart in B: no halfedge of B has the same valences, "
                        "face degrees and boundary around it");
    }
    for (auto it = lo; it != hi; ++it) {
        if (h_ba_[it->second] == kNone && attempt(best, Halfedge(it->second))) {
            return true;
        }
        // Different histograms cannot match: one try names where, more would only cost.
        if (signatures_differ_ && !result_.difference.empty()) {
            return false;
        }
    }
    return false;
}

bool Matcher::match_component(Halfedge start) {
    if (try_positions(start)) {
        return true;
    }
    if (!b_signatures_.empty() && signatures_differ_ && !result_.difference.empty()) {
        return false;
    }
    return try_signatures(start);
}

// Isolated vertices have no halfedges to propagate along: paired in order of position, so
// equal positions pair up.
void Matcher::match_isolated() {
    auto sorted = [](const Mesh& m) {
        std::vector<std::pair<PositionKey, std::uint32_t>> out;
        for (const Vertex v : m.vertices()) {
            if (m.is_isolated(v)) {
                out.emplace_back(key_of(m.position(v)), v.idx());
            }
        }
        std::sort(out.begin(), out.end());
        return out;
    };
    const auto ia = sorted(a_), ib = sorted(b_);
    for (std::size_t i = 0; i < ia.size(); ++i) {
        v_ab_[ia[i].second] = ib[i].second;
    }
}

TopologyMatch Matcher::run() {
    if (!counts_agree()) {
        return std::move(result_);
    }
    for (const Halfedge h : a_.halfedges()) {
        if (h_ab_[h.idx()] == kNone && !match_component(h)) {
            if (result_.difference.empty()) {
                fail(ElementRef::halfedge(h), {},
                     "no part of B matches the part of A around " +
                         describe(a_, ElementRef::halfedge(h)));
            }
            return std::move(result_);
        }
    }
    match_isolated();
    result_ = TopologyMatch{};
    result_.isomorphic = true;
    result_.vertex = std::move(v_ab_);
    result_.halfedge = std::move(h_ab_);
    result_.face = std::move(f_ab_);
    return std::move(result_);
}

}  // namespace

TopologyMatch match_topology(const Mesh& a, const Mesh& b) {
    return Matcher(a, b).run();
}

}  // namespace meshedit
