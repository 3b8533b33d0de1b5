// validate(): every invariant of docs/halfedge.md, checked in dependency order so that the
// first failure reported is the root cause (references before orbits, orbits before anchors).
#include "meshedit/core/validate.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace meshedit {
namespace {

const char* kind_name(ElementKind k) {
    switch (k) {
        case ElementKind::Vertex:
            return "vertex";
        case ElementKind::Halfedge:
            return "halfedge";
        case ElementKind::Edge:
            return "edge";
        case ElementKind::Face:
            return "face";
    }
    return "element";
}

// Collects the first failure; later checks are skipped once one is found.
class Checker {
public:
    explicit Checker(const Mesh& mesh) : m_(mesh) {}

    bool failed() const { return error_.has_value(); }
    std::optional<ValidationError> result() { return std::move(error_); }

    template <class... Parts>
    void fail(const char* invariant, ElementKind kind, std::uint32_t index, const Parts&... parts) {
        if (failed()) {
            return;
        }
        std::ostringstream s;
        s << kind_name(kind) << " " << index << ": ";
        (s << ... << parts);
        error_ = ValidationError{invariant, kind, index, s.str()};
    }

    void check_counts();
    void check_halfedge_references();
    void check_halfedge_orbits();
    void check_faces();
    void check_vertices();
    void check_simple();

private:
    static std::uint32_t id(auto h) { return h.idx(); }
    // A reference is usable if it is in range and the element is live.
    bool live(Halfedge h) const { return m_.is_valid(h) && !m_.is_deleted(h); }
    bool live(Vertex v) const { return m_.is_valid(v) && !m_.is_deleted(v); }
    bool live(Face f) const { return m_.is_valid(f) && !m_.is_deleted(f); }

    const Mesh& m_;
    std::optional<ValidationError> error_;
};

void Checker::check_counts() {
    std::size_t dv = 0, de = 0, df = 0;
    for (std::uint32_t i = 0; i < m_.vertices_size(); ++i) {
        dv += m_.is_deleted(Vertex(i));
    }
    for (std::uint32_t i = 0; i < m_.edges_size(); ++i) {
        de += m_.is_deleted(Edge(i));
    }
    for (std::uint32_t i = 0; i < m_.faces_size(); ++i) {
        df += m_.is_deleted(Face(i));
    }
    if (m_.vertices_size() - dv != m_.n_vertices()) {
        fail("deleted-count", ElementKind::Vertex, 0, "the live vertex count ", m_.n_vertices(),
             " disagrees with the tombstones (", m_.vertices_size() - dv, " live)");
    }
    if (m_.edges_size() - de != m_.n_edges()) {
        fail("deleted-count", ElementKind::Edge, 0, "the live edge count ", m_.n_edges(),
             " disagrees with the tombstones (", m_.edges_size() - de, " live)");
    }
    if (m_.faces_size() - df != m_.n_faces()) {
        fail("deleted-count", ElementKind::Face, 0, "the live face count ", m_.n_faces(),
             " disagrees with the tombstones (", m_.faces_size() - df, " live)");
    }
}

void Checker::check_halfedge_references() {
    for (Halfedge h : m_.halfedges()) {
        const std::uint32_t i = h.idx();
        if (!live(m_.next(h))) {
            fail("next-reference", ElementKind::Halfedge, i, "next is ", id(m_.next(h)),
                 ", which is out of range or deleted");
        } else if (!live(m_.prev(h))) {
            fail("prev-reference", ElementKind::Halfedge, i, "prev is ", id(m_.prev(h)),
                 ", which is out of range or deleted");
        } else if (!live(m_.to_vertex(h))) {
            fail("vertex-reference", ElementKind::Halfedge, i, "points to vertex ",
                 id(m_.to_vertex(h)), ", which is out of range or deleted");
        } else if (m_.face(h).is_valid() && !live(m_.face(h))) {
            fail("face-reference", ElementKind::Halfedge, i, "belongs to face ", id(m_.face(h)),
                 ", which is out of range or deleted");
        }
        if (failed()) {
            return;
        }
    }
}

void Checker::check_halfedge_orbits() {
    for (Halfedge h : m_.halfedges()) {
        const std::uint32_t i = h.idx();
        const Halfedge n = m_.next(h);
        if (m_.prev(n) != h) {
            fail("next-prev", ElementKind::Halfedge, i, "prev(next(h)) is ", id(m_.prev(n)),
                 ", not ", i);
        } else if (m_.next(m_.prev(h)) != h) {
            fail("prev-next", ElementKind::Halfedge, i, "next(prev(h)) is ",
                 id(m_.next(m_.prev(h))), ", not ", i);
        } else if (n == h) {
            fail("next-self", ElementKind::Halfedge, i, "is its own next");
        } else if (m_.to_vertex(h) == m_.from_vertex(h)) {
            fail("self-loop", ElementKind::Halfedge, i, "starts and ends at vertex ",
                 id(m_.to_vertex(h)));
        } else if (m_.from_vertex(n) != m_.to_vertex(h)) {
            fail("next-vertex", ElementKind::Halfedge, i, "ends at vertex ", id(m_.to_vertex(h)),
                 " but its next starts at vertex ", id(m_.from_vertex(n)));
        } else if (m_.face(n) != m_.face(h)) {
            fail("next-face", ElementKind::Halfedge, i, "and its next ", id(n),
                 " belong to different faces");
        } else if (m_.is_boundary(h) && m_.is_boundary(Mesh::twin(h))) {
            fail("edge-has-face", ElementKind::Edge, Mesh::edge(h).idx(),
                 "has no face on either side");
        }
        if (failed()) {
            return;
        }
    }
    // Every loop closes; faces have >= 3 sides, boundary loops >= 2.
    std::vector<std::uint8_t> visited(m_.halfedges_size(), 0);
    for (Halfedge h : m_.halfedges()) {
        if (visited[h.idx()]) {
            continue;
        }
        std::size_t length = 0;
        Halfedge g = h;
        do {
            if (visited[g.idx()]) {
                fail("loop", ElementKind::Halfedge, g.idx(), "is reached twice by next");
                return;
            }
            visited[g.idx()] = 1;
            g = m_.next(g);
            ++length;
        } while (g != h && length <= m_.halfedges_size());
        if (g != h) {
            fail("loop", ElementKind::Halfedge, h.idx(), "its next-loop never closes");
            return;
        }
        if (!m_.is_boundary(h) && length < 3) {
            fail("face-size", ElementKind::Face, m_.face(h).idx(), "has only ", length, " sides");
            return;
        }
    }
}

void Checker::check_faces() {
    std::vector<std::uint32_t> sides(m_.faces_size(), 0);
    for (Halfedge h : m_.halfedges()) {
        if (!m_.is_boundary(h)) {
            ++sides[m_.face(h).idx()];
        }
    }
    for (Face f : m_.faces()) {
        const Halfedge h = m_.halfedge(f);
        if (!live(h)) {
            fail("face-anchor", ElementKind::Face, f.idx(), "has halfedge ", id(h),
                 ", which is out of range or deleted");
        } else if (m_.face(h) != f) {
            fail("face-anchor", ElementKind::Face, f.idx(), "its halfedge ", id(h),
                 " belongs to face ", id(m_.face(h)));
        } else if (m_.valence(f) != sides[f.idx()]) {
            fail("face-loop", ElementKind::Face, f.idx(), "has ", sides[f.idx()],
                 " halfedges but its loop visits ", m_.valence(f));
        }
        if (failed()) {
            return;
        }
    }
}

void Checker::check_vertices() {
    std::vector<std::uint32_t> outgoing(m_.vertices_size(), 0);
    std::vector<std::uint8_t> on_boundary(m_.vertices_size(), 0);
    for (Halfedge h : m_.halfedges()) {
        ++outgoing[m_.from_vertex(h).idx()];
        if (m_.is_boundary(h)) {
            on_boundary[m_.from_vertex(h).idx()] = 1;
        }
    }
    for (Vertex v : m_.vertices()) {
        const std::uint32_t i = v.idx();
        const Halfedge h = m_.halfedge(v);
        if (!is_finite(m_.position(v))) {
            fail("finite-position", ElementKind::Vertex, i, "has a non-finite position");
        } else if (!h.is_valid()) {
            if (outgoing[i] != 0) {
                fail("vertex-anchor", ElementKind::Vertex, i, "has no halfedge but ", outgoing[i],
                     " edges");
            }
        } else if (!live(h)) {
            fail("vertex-anchor", ElementKind::Vertex, i, "has halfedge ", id(h),
                 ", which is out of range or deleted");
        } else if (m_.from_vertex(h) != v) {
            fail("vertex-anchor", ElementKind::Vertex, i, "its halfedge ", id(h),
                 " starts at vertex ", id(m_.from_vertex(h)));
        } else if (on_boundary[i] && !m_.is_boundary(h)) {
            fail("boundary-anchor", ElementKind::Vertex, i, "is on the boundary but its halfedge ",
                 id(h), " is not a boundary halfedge");
        } else if (m_.valence(v) != outgoing[i]) {
            fail("vertex-fan", ElementKind::Vertex, i, "has ", outgoing[i], " edges but only ",
                 m_.valence(v), " are reached around it (a non-manifold vertex)");
        }
        if (failed()) {
            return;
        }
    }
}

// What a face list can say: no face visits a vertex twice, and no two edges join the same
// two vertices. A mesh that breaks either cannot be written to a file and read back as the
// same mesh (a reader glues halfedges by their end vertices), and no operation creates one.
// Both walks mark vertices with the index of the face or vertex being walked (+1).
void Checker::check_simple() {
    std::vector<std::uint32_t> mark(m_.vertices_size(), 0);
    for (Face f : m_.faces()) {
        for (Vertex w : m_.vertices(f)) {
            if (mark[w.idx()] == f.idx() + 1) {
                fail("face-corner", ElementKind::Face, f.idx(), "visits vertex ", w.idx(),
                     " twice");
                return;
            }
            mark[w.idx()] = f.idx() + 1;
        }
    }
    std::fill(mark.begin(), mark.end(), 0);
    std::vector<std::uint32_t> edge_to(m_.vertices_size(), 0);
    for (Vertex v : m_.vertices()) {
        if (m_.is_isolated(v)) {
            continue;
        }
        for (Halfedge h : m_.halfedges(v)) {
            const Vertex w = m_.to_vertex(h);
            if (mark[w.idx()] == v.idx() + 1) {
                fail("multi-edge", ElementKind::Edge, Mesh::edge(h).idx(), "joins vertices ",
                     v.idx(), " and ", w.idx(), ", as edge ", edge_to[w.idx()], " does");
                return;
            }
            mark[w.idx()] = v.idx() + 1;
            edge_to[w.idx()] = Mesh::edge(h).idx();
        }
    }
}

}  // namespace

std::optional<ValidationError> validate(const Mesh& mesh) {
    Checker c(mesh);
    c.check_counts();
    if (!c.failed()) {
        c.check_halfedge_references();
    }
    if (!c.failed()) {
        c.check_halfedge_orbits();
    }
    if (!c.failed()) {
        c.check_faces();
    }
    if (!c.failed()) {
        c.check_vertices();
    }
    if (!c.failed()) {
        c.check_simple();
    }
    return c.result();
}

}  // namespace meshedit
