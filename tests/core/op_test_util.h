#pragma once
/// \file
/// Helpers for local-op specifications: the expected mesh is written by editing the input's
/// indexed face list by hand (remove these faces, add those, rename a vertex), then built
/// with build_mesh(); it never comes from the op under test.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "meshedit/core/build.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit::test {

using Corners = std::vector<std::uint32_t>;

/// An indexed mesh to edit: positions and corner cycles.
struct Indexed {
    std::vector<Vec3> positions;
    std::vector<Corners> faces;

    /// Removes `face` (in any rotation); fails the current test if it is not there.
    void remove(const Corners& face) {
        for (auto it = faces.begin(); it != faces.end(); ++it) {
            if (same_cycle(*it, face)) {
                faces.erase(it);
                return;
            }
        }
        ADD_FAILURE() << "face to remove not found: " << describe(face);
    }
    void add(const Corners& face) { faces.push_back(face); }
    /// Appends a vertex at `p` and returns its index.
    std::uint32_t add_vertex(const Vec3& p) {
        positions.push_back(p);
        return static_cast<std::uint32_t>(positions.size() - 1);
    }
    /// Replaces every corner `from` by `to`.
    void rename(std::uint32_t from, std::uint32_t to) {
        for (Corners& f : faces) {
            std::replace(f.begin(), f.end(), from, to);
        }
    }
    /// Drops vertex `v` (referenced by no face) and shifts higher indices down.
    void erase_vertex(std::uint32_t v) {
        positions.erase(positions.begin() + v);
        for (Corners& f : faces) {
            for (std::uint32_t& c : f) {
                c -= c > v ? 1 : 0;
            }
        }
    }
    Mesh build() const { return mesh_from_faces(positions, faces); }

    static bool same_cycle(const Corners& a, const Corners& b) {
        if (a.size() != b.size()) {
            return false;
        }
        const std::size_t n = a.size();
        for (std::size_t r = 0; r < n; ++r) {
            bool same = true;
            for (std::size_t i = 0; i < n && same; ++i) {
                same = a[i] == b[(i + r) % n];
            }
            if (same) {
                return true;
            }
        }
        return false;
    }
    static std::string describe(const Corners& f) {
        std::string s = "(";
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (i > 0) {
                s += ',';
            }
            s += std::to_string(f[i]);
        }
        s += ')';
        return s;
    }
};

/// The input's faces as an editable list (dense indices: call before any op).
inline Indexed indexed(const Mesh& mesh) {
    const PolygonSoup soup = to_polygon_soup(mesh);
    Indexed out;
    out.positions = soup.positions;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        out.faces.emplace_back(soup.indices.begin() + soup.face_offsets[f],
                               soup.indices.begin() + soup.face_offsets[f + 1]);
    }
    return out;
}

/// The two triangles beside an interior edge, named as in docs/spec.md §3: halfedge(e, 0) runs
/// b -> c inside (a,b,c); its twin runs c -> b inside (c,b,d). Read from the input mesh.
struct Diamond {
    std::uint32_t a, b, c, d;
};
inline Diamond diamond(const Mesh& mesh, Edge e) {
    const Halfedge h = Mesh::halfedge(e, 0);
    const Halfedge t = Mesh::twin(h);
    return {mesh.to_vertex(mesh.next(h)).idx(), mesh.from_vertex(h).idx(), mesh.to_vertex(h).idx(),
            mesh.to_vertex(mesh.next(t)).idx()};
}

inline Vec3 midpoint(const Mesh& mesh, std::uint32_t a, std::uint32_t b) {
    return 0.5 * (mesh.position(Vertex(a)) + mesh.position(Vertex(b)));
}

/// The endpoints of `e`, smaller index first.
inline std::pair<std::uint32_t, std::uint32_t> endpoints(const Mesh& mesh, Edge e) {
    const std::uint32_t u = mesh.vertex(e, 0).idx();
    const std::uint32_t v = mesh.vertex(e, 1).idx();
    return {std::min(u, v), std::max(u, v)};
}

/// Runs `op(mesh)`, which must be refused with `reason`, and checks that the mesh is bit for
/// bit what it was.
template <class Op>
void expect_refused_by(Mesh& mesh, Op op, std::string_view reason) {
    const Mesh before = mesh;
    const auto r = op(mesh);
    EXPECT_FALSE(r);
    EXPECT_EQ(r.reason(), reason);
    EXPECT_TRUE(identical(mesh, before));
}

/// The live face whose corners are `corners` in this cyclic order; the test fails if none.
inline Face face_with(const Mesh& mesh, const Corners& corners) {
    for (const Face f : mesh.faces()) {
        Corners c;
        for (const Vertex v : mesh.vertices(f)) {
            c.push_back(v.idx());
        }
        if (Indexed::same_cycle(c, corners)) {
            return f;
        }
    }
    ADD_FAILURE() << "no face " << Indexed::describe(corners);
    return Face();
}

/// The number of boundary loops.
inline std::size_t boundary_loops(const Mesh& mesh) {
    std::vector<char> seen(mesh.halfedges_size(), 0);
    std::size_t loops = 0;
    for (const Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h) && seen[h.idx()] == 0) {
            ++loops;
            for (const Halfedge x : mesh.loop(h)) {
                seen[x.idx()] = 1;
            }
        }
    }
    return loops;
}

/// V - E + F over live elements.
inline long euler(const Mesh& mesh) {
    return static_cast<long>(mesh.n_vertices()) - static_cast<long>(mesh.n_edges()) +
           static_cast<long>(mesh.n_faces());
}

}  // namespace meshedit::test
