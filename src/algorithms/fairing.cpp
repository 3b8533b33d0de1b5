// Bi-Laplacian fairing of a region (smoothing.h). With K the Laplacian's matrix (K x_i =
// Σ_j w_ij (x_j − x_i)) and D a positive diagonal, L = D⁻¹K and the free rows of L² x = 0
// are, multiplied by D, the rows of K D⁻¹ K x = 0: symmetric, and positive definite on the
// free vertices when every piece of them touches a fixed vertex. For cotangent weights D is
// each vertex's mixed Voronoi area (Meyer et al. 2003, as CGAL's and pmp's fairing), which
// makes L the discrete Laplace-Beltrami operator; for uniform weights, Σ_j w_ij. (Dividing
// cotangent weights by their sum instead left the patches of 6 of the fill bench's 8 faired
// holes 4–36% farther from the surface cut away; 2 came out closer.) Only the free vertices and two
// rings around them take part, so a small region of a big mesh costs its own size.

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "laplacian.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/smoothing.h"

namespace meshedit {
namespace {

// Sets over element indices. Hash sets, not arrays over the whole mesh: a small region of a
// big mesh (a hole's patch in a scan) then costs its own size, not the mesh's.
using IndexSet = std::unordered_set<std::uint32_t>;
using LocalIndex = std::unordered_map<std::uint32_t, std::int64_t>;

// The region's inner vertices: every face around them in the region, not on the boundary.
std::vector<Vertex> inner_vertices(const Mesh& mesh, std::span<const Face> region) {
    // Membership of the region's faces: flags over the span of their indices when it is
    // compact (a fill's patch: the faces it appended), else a hash set.
    std::uint32_t lo = UINT32_MAX, hi = 0;
    for (const Face f : region) {
        lo = std::min(lo, f.idx());
        hi = std::max(hi, f.idx());
    }
    const bool compact = !region.empty() && hi - lo < 4 * region.size() + 64;
    std::vector<std::uint8_t> flags(compact ? hi - lo + 1 : 0, 0);
    IndexSet in_set(compact ? 0 : region.size());
    for (const Face f : region) {
        if (compact) {
            flags[f.idx() - lo] = 1;
        } else {
            in_set.insert(f.idx());
        }
    }
    const auto in_region = [&](Face f) {
        if (!f.is_valid()) {
            return false;
        }
        if (compact) {
            return f.idx() >= lo && f.idx() <= hi && flags[f.idx() - lo] != 0;
        }
        return in_set.contains(f.idx());
    };
    // Each vertex is looked at once, from the face of its anchor (mesh.halfedge(v)): when
    // that face is outside the region, the vertex is not inner. Boundary vertices never are.
    std::vector<Vertex> inner;
    for (const Face f : region) {
        for (const Vertex v : mesh.vertices(f)) {
            if (mesh.is_boundary(v) || mesh.face(mesh.halfedge(v)) != f) {
                continue;
            }
            bool all = true;
            for (const Halfedge h : mesh.halfedges(v)) {
                all = all && in_region(mesh.face(h));
            }
            if (all) {
                inner.push_back(v);
            }
        }
    }
    std::sort(inner.begin(), inner.end());
    return inner;
}

// Whether every piece of `inner` (joined by edges) has a vertex outside it as a neighbour.
bool every_piece_held(const Mesh& mesh, const std::vector<Vertex>& inner) {
    std::unordered_map<std::uint32_t, std::uint8_t> state(inner.size());  // 1 inner, 2 visited
    for (const Vertex v : inner) {
        state[v.idx()] = 1;
    }
    std::vector<Vertex> stack;
    for (const Vertex start : inner) {
        if (state[start.idx()] != 1) {
            continue;
        }
        bool held = false;
        stack.push_back(start);
        state[start.idx()] = 2;
        while (!stack.empty()) {
            const Vertex v = stack.back();
            stack.pop_back();
            for (const Vertex w : mesh.vertices(v)) {
                const auto it = state.find(w.idx());
                if (it == state.end()) {
                    held = true;
                } else if (it->second == 1) {
                    it->second = 2;
                    stack.push_back(w);
                }
            }
        }
        if (!held) {
            return false;
        }
    }
    return true;
}

// The vertices the solve reads: the free ones, then the first ring around them (the rows of
// K), then the second ring, each ring in index order; `local` numbers them.
struct Stencil {
    std::vector<Vertex> order;
    LocalIndex local;
    std::size_t n_free = 0;
    std::size_t n_rows = 0;
};

Stencil stencil_of(const Mesh& mesh, const std::vector<Vertex>& inner) {
    Stencil st;
    st.order = inner;
    st.n_free = inner.size();
    st.local.reserve(inner.size() * 3);
    for (std::size_t i = 0; i < st.order.size(); ++i) {
        st.local[st.order[i].idx()] = static_cast<std::int64_t>(i);
    }
    const auto add_ring = [&](std::size_t from, std::size_t to) {
        std::vector<Vertex> ring;
        for (std::size_t i = from; i < to; ++i) {
            for (const Vertex w : mesh.vertices(st.order[i])) {
                if (st.local.try_emplace(w.idx(), 0).second) {  // claimed; numbered below
                    ring.push_back(w);
                }
            }
        }
        std::sort(ring.begin(), ring.end());
        for (const Vertex w : ring) {
            st.local[w.idx()] = static_cast<std::int64_t>(st.order.size());
            st.order.push_back(w);
        }
        return st.order.size();
    };
    st.n_rows = add_ring(0, inner.size());  // free and first ring
    add_ring(inner.size(), st.n_rows);      // the second ring
    return st;
}

// The mixed Voronoi area around v (Meyer et al. 2003): of each triangle, the part nearer v
// than its other corners, or a half of the triangle when its angle at v is obtuse and a
// quarter when another is. Faces that are not triangles give their area over their corners.
double mixed_area(const Mesh& mesh, Vertex v) {
    const Vec3 p = mesh.position(v);
    double area = 0.0;
    for (const Halfedge h : mesh.halfedges(v)) {
        const Face f = mesh.face(h);
        if (!f.is_valid()) {
            continue;
        }
        const double whole = 0.5 * norm(face_area_vector(mesh, f));
        if (mesh.valence(f) != 3) {
            area += whole / static_cast<double>(mesh.valence(f));
            continue;
        }
        const Vec3 q = mesh.position(mesh.to_vertex(h));
        const Vec3 r = mesh.position(mesh.to_vertex(mesh.next(h)));
        if (dot(q - p, r - p) < 0.0) {
            area += 0.5 * whole;
        } else if (dot(p - q, r - q) < 0.0 || dot(p - r, q - r) < 0.0) {
            area += 0.25 * whole;
        } else if (whole > 0.0) {
            // |pr|² cot q + |pq|² cot r, over 8; cot q = (p−q)·(r−q) / (2 · area).
            area += (sqrnorm(r - p) * dot(p - q, r - q) + sqrnorm(q - p) * dot(p - r, q - r)) /
                    (16.0 * whole);
        }
    }
    return area;
}

// Whether each piece of the free vertices (the first x.rows() of `order`, joined by K's
// entries `start`/`col`) solved within half a diagonal of the box of the fixed vertices its
// rows read.
bool within_reach(const Mesh& mesh, const std::vector<Vertex>& order,
                  const std::vector<std::size_t>& start, const std::vector<std::int64_t>& col,
                  const Eigen::MatrixX3d& x) {
    const auto n_free = static_cast<std::size_t>(x.rows());
    std::vector<std::size_t> piece(n_free);
    for (std::size_t i = 0; i < n_free; ++i) {
        piece[i] = i;
    }
    const auto root = [&](std::size_t i) {
        while (piece[i] != i) {
            i = piece[i] = piece[piece[i]];
        }
        return i;
    };
    for (std::size_t i = 0; i < n_free; ++i) {
        for (std::size_t e = start[i]; e < start[i + 1]; ++e) {
            if (static_cast<std::size_t>(col[e]) < n_free) {
                piece[root(i)] = root(static_cast<std::size_t>(col[e]));
            }
        }
    }
    std::vector<BoundingBox> around(n_free);  // by root
    for (std::size_t i = 0; i < n_free; ++i) {
        for (std::size_t e = start[i]; e < start[i + 1]; ++e) {
            const auto j = static_cast<std::size_t>(col[e]);
            if (j >= n_free) {
                around[root(i)].add(mesh.position(order[j]));
            }
        }
    }
    for (std::size_t i = 0; i < n_free; ++i) {
        const BoundingBox& box = around[root(i)];
        const Vec3 p{x(static_cast<Eigen::Index>(i), 0), x(static_cast<Eigen::Index>(i), 1),
                     x(static_cast<Eigen::Index>(i), 2)};
        const Vec3 below = box.min - p, above = p - box.max;
        if (std::max({below.x, below.y, below.z, above.x, above.y, above.z}) >
            0.5 * box.diagonal()) {
            return false;
        }
    }
    return true;
}

// Solves the free rows of K D⁻¹ K x = 0 for the first `n_free` vertices of `order` (then its
// first ring up to `n_rows`, then the second ring; `local` numbers them). False when the
// factorisation fails or the result is not finite (cotangent weights all clamped to 0 around a
// vertex, a degenerate triangle) or, for cotangent weights, lands far outside the fixed
// vertices around it (within_reach()): the caller tries uniform weights.
bool solve(const Mesh& mesh, const std::vector<Vertex>& order, const LocalIndex& local,
           std::size_t n_free, std::size_t n_rows, SmoothWeights weights, Eigen::MatrixX3d& x) {
    // K's rows, compressed: row i's entries are [start[i], start[i + 1]) of col and val.
    std::vector<std::size_t> start(n_rows + 1, 0);
    std::vector<std::int64_t> col;
    std::vector<double> val;
    std::vector<double> inverse_d(n_rows);
    for (std::size_t i = 0; i < n_rows; ++i) {
        double sum = 0.0;
        for (const Halfedge h : mesh.halfedges(order[i])) {
            const double wij = laplacian::edge_weight(mesh, Mesh::edge(h), weights);
            col.push_back(local.at(mesh.to_vertex(h).idx()));
            val.push_back(wij);
            sum += wij;
        }
        col.push_back(static_cast<std::int64_t>(i));
        val.push_back(-sum);
        start[i + 1] = col.size();
        const double d = weights == SmoothWeights::Cotangent ? mixed_area(mesh, order[i]) : sum;
        // A vertex whose weights (or area) vanish adds nothing to its neighbours' rows.
        inverse_d[i] = sum > 0.0 && d > 0.0 ? 1.0 / d : 0.0;
    }
    // Row i of K D⁻¹ K, for each free i, gathered in a sparse accumulator (the free vertices'
    // neighbours are all rows of K): the free columns go to the matrix, the fixed ones times
    // their positions to the right-hand side. (Eigen's sparse products did the same in three
    // passes and two copies: a fifth of the fairing's time on a 300-edge hole.)
    const std::size_t all = order.size();
    std::vector<double> sum(all, 0.0);
    std::vector<std::uint8_t> seen(all, 0);
    std::vector<std::int64_t> touched;
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(static_cast<Eigen::Index>(n_free), 3);
    for (std::size_t i = 0; i < n_free; ++i) {
        for (std::size_t e = start[i]; e < start[i + 1]; ++e) {
            const auto j = static_cast<std::size_t>(col[e]);
            const double f = val[e] * inverse_d[j];
            for (std::size_t e2 = start[j]; f != 0.0 && e2 < start[j + 1]; ++e2) {
                const auto l = static_cast<std::size_t>(col[e2]);
                if (seen[l] == 0) {
                    seen[l] = 1;
                    touched.push_back(col[e2]);
                }
                sum[l] += f * val[e2];
            }
        }
        for (const std::int64_t l : touched) {
            const auto at = static_cast<std::size_t>(l);
            if (at < n_free) {
                entries.emplace_back(static_cast<Eigen::Index>(i), l, sum[at]);
            } else {
                const Vec3& p = mesh.position(order[at]);
                const auto row = static_cast<Eigen::Index>(i);
                rhs(row, 0) -= sum[at] * p.x;
                rhs(row, 1) -= sum[at] * p.y;
                rhs(row, 2) -= sum[at] * p.z;
            }
            sum[at] = 0.0;
            seen[at] = 0;
        }
        touched.clear();
    }
    const auto free = static_cast<Eigen::Index>(n_free);
    Eigen::SparseMatrix<double> a_free(free, free);
    a_free.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> solver(a_free);
    if (solver.info() != Eigen::Success) {
        return false;
    }
    x = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !x.allFinite()) {
        return false;
    }
    // Cotangent weights over areas are only as well conditioned as the triangles: near-flat
    // ones around a hole (assimp's regr01.obj) put new vertices 10⁹ away. A patch (a piece
    // of the free vertices) reaches past the box of the fixed vertices around it by a
    // fraction of that box (a sphere's cap cut at its equator: a fifth of its diagonal);
    // past half of it is a failed solve, and the caller takes uniform weights.
    if (weights == SmoothWeights::Cotangent && !within_reach(mesh, order, start, col, x)) {
        return false;
    }
    return true;
}

}  // namespace

std::vector<Vertex> region_inner_vertices(const Mesh& mesh, std::span<const Face> region) {
    return inner_vertices(mesh, region);
}

OpStatus check_fair(const Mesh& mesh, std::span<const Face> region, const FairOptions& options) {
    if (region.empty()) {
        return OpStatus::refused("cannot fair: the region is empty");
    }
    for (const Face f : region) {
        if (!mesh.is_valid(f) || mesh.is_deleted(f)) {
            return OpStatus::composed("cannot fair: face " + std::to_string(f.idx()) +
                                      " is not in the mesh");
        }
    }
    const std::vector<Vertex> inner = inner_vertices(mesh, region);
    if (inner.empty()) {
        return OpStatus::refused(
            "cannot fair: the region has no inner vertex (every vertex of it is on its border "
            "or the mesh's boundary); select a larger region");
    }
    // Only what the solve reads must be finite and, for cotangent weights, triangles: a
    // polygon or a NaN far from the region does not touch it.
    const Stencil st = stencil_of(mesh, inner);
    const auto finite = [&](Vertex v) {
        const Vec3& p = mesh.position(v);
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    if (!std::all_of(st.order.begin(), st.order.end(), finite)) {
        std::vector<Vertex> sorted = st.order;  // to name the first, by index
        std::sort(sorted.begin(), sorted.end());
        const Vertex v = *std::find_if_not(sorted.begin(), sorted.end(), finite);
        return OpStatus::composed("cannot fair: vertex " + std::to_string(v.idx()) +
                                  " has a position that is not a finite number");
    }
    if (options.weights == SmoothWeights::Cotangent) {
        for (std::size_t i = 0; i < st.n_rows; ++i) {
            for (const Face f : mesh.faces(st.order[i])) {
                if (mesh.valence(f) != 3) {
                    return OpStatus::refused(
                        "cannot fair: cotangent weights need triangles around the region "
                        "(triangulate first: the `triangulate` step, Ctrl+T in the viewer)");
                }
            }
        }
    }
    if (!every_piece_held(mesh, inner)) {
        return OpStatus::refused(
            "cannot fair: the region covers a whole closed part of the mesh, so no fixed "
            "border holds it; leave some faces of that part out");
    }
    return OpStatus::ok();
}

FairReport fair(Mesh& mesh, std::span<const Face> region, const FairOptions& options) {
    const auto begin = std::chrono::steady_clock::now();
    const std::vector<Vertex> inner = inner_vertices(mesh, region);
    const Stencil st = stencil_of(mesh, inner);
    const std::vector<Vertex>& order = st.order;
    const LocalIndex& local = st.local;
    const std::size_t n_rows = st.n_rows;

    Eigen::MatrixX3d x;
    if (!solve(mesh, order, local, inner.size(), n_rows, options.weights, x) &&
        !solve(mesh, order, local, inner.size(), n_rows, SmoothWeights::Uniform, x)) {
        // Cannot happen with uniform weights on the rows check_fair() allows (positive
        // definite); never write a failed solve.
        throw std::runtime_error("fair: the bi-Laplacian system could not be solved");
    }
    FairReport report;
    report.moved = inner.size();
    for (std::size_t i = 0; i < inner.size(); ++i) {
        const auto row = static_cast<Eigen::Index>(i);
        const Vec3 p{x(row, 0), x(row, 1), x(row, 2)};
        report.max_displacement =
            std::max(report.max_displacement, norm(p - mesh.position(inner[i])));
        mesh.position(inner[i]) = p;
    }
    report.solve_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    return report;
}

}  // namespace meshedit
