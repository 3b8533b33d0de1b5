// Laplacian smoothing (explicit, Taubin, implicit) and the Laplacian's weights (laplacian.h).
// The explicit steps run on a compressed copy of the one-rings (offsets, neighbours,
// normalised weights) with two position buffers, so a step is one pass over arrays and its
// vertices are independent (Jacobi), in chunks on several threads with the same bits on any
// number. The implicit step solves one sparse symmetric system with Eigen.

#include "meshedit/core/smoothing.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "laplacian.h"
#include "mesh/mesh_arrays.h"
#include "mesh/parallel.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/number_text.h"

namespace meshedit {

namespace laplacian {

namespace {

// cot of the angle at `apex` between `a` and `b`; a degenerate corner gives a large finite
// value rather than infinity.
double cot_at(const Vec3& apex, const Vec3& a, const Vec3& b) {
    const Vec3 u = a - apex, v = b - apex;
    const double sine = norm(cross(u, v));
    return dot(u, v) / std::max(sine, 1e-10 * norm(u) * norm(v) + 1e-300);
}

}  // namespace

double edge_weight(const Mesh& mesh, Edge e, SmoothWeights weights) {
    if (weights == SmoothWeights::Uniform) {
        return 1.0;
    }
    double sum = 0.0;
    for (unsigned i = 0; i < 2; ++i) {
        const Halfedge h = Mesh::halfedge(e, i);
        if (!mesh.is_boundary(h)) {
            sum += cot_at(mesh.position(mesh.to_vertex(mesh.next(h))),
                          mesh.position(mesh.from_vertex(h)), mesh.position(mesh.to_vertex(h)));
        }
    }
    return std::max(0.5 * sum, 0.0);
}

std::vector<double> edge_weights(const Mesh& mesh, SmoothWeights weights) {
    std::vector<double> w(mesh.edges_size(), 0.0);
    for (const Edge e : mesh.edges()) {
        w[e.idx()] = edge_weight(mesh, e, weights);
    }
    return w;
}

std::string refuse_non_finite(const Mesh& mesh, const char* verb) {
    for (const Vertex v : mesh.vertices()) {
        const Vec3& p = mesh.position(v);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            return "cannot " + std::string(verb) + ": vertex " + std::to_string(v.idx()) +
                   " has a position that is not a finite number";
        }
    }
    return {};
}

std::vector<std::uint8_t> crease_vertices(const Mesh& mesh) {
    std::vector<std::uint8_t> out(mesh.vertices_size(), 0);
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    if (!crease) {
        return out;
    }
    for (const Edge e : mesh.edges()) {
        if (crease[e] != 0) {
            out[mesh.vertex(e, 0).idx()] = 1;
            out[mesh.vertex(e, 1).idx()] = 1;
        }
    }
    return out;
}

}  // namespace laplacian

namespace {

constexpr int kMaxIterations = 1000;
constexpr double kMaxTime = 1e6;
// Steps run on several threads from this many vertices, in chunks of kChunk.
constexpr std::size_t kParallelVertices = 50'000;
constexpr std::size_t kChunk = 4096;

std::string cannot(const std::string& why) {
    return "cannot smooth: " + why;
}

bool has_boundary(const Mesh& mesh) {
    for (const Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h)) {
            return true;
        }
    }
    return false;
}

// The one-rings with normalised weights w_ij / Σ_j w_ij, and which vertices move. A vertex
// whose weights sum to 0 (every cotangent clamped) cannot move. A fixed vertex has an empty
// ring, so a step needs nothing else to tell it apart. Uniform weights are the same around a
// ring, 1 / valence, so they are not stored: a step computes them from the ring's size (the
// same value as the sum of ones it replaces) and reads half the memory it would otherwise.
struct Rings {
    memory::Array<std::uint32_t> offset;  // vertices_size() + 1
    memory::Array<std::uint32_t> neighbour;
    memory::Array<double> weight;  // normalised, by neighbour (cotangent; empty for uniform)
    std::vector<double> sum;       // Σ_j w_ij (the implicit system's diagonal)
    std::vector<std::uint8_t> free;
    std::size_t n_free = 0;
    bool closed = true;  // no boundary vertex (so no boundary halfedge)
    bool uniform = true;

    /// The normalised weight of neighbour k of vertex i.
    double w(std::size_t i, std::size_t k) const {
        return uniform ? 1.0 / static_cast<double>(offset[i + 1] - offset[i]) : weight[k];
    }
};

std::vector<std::uint8_t> movable(const Mesh& mesh, const SmoothOptions& options) {
    std::vector<std::uint8_t> free(mesh.vertices_size(), 0);
    if (options.vertices.empty()) {
        for (const Vertex v : mesh.vertices()) {
            free[v.idx()] = 1;
        }
    } else {
        for (const Vertex v : options.vertices) {
            free[v.idx()] = 1;
        }
    }
    const std::vector<std::uint8_t> crease =
        options.fix_creases ? laplacian::crease_vertices(mesh) : std::vector<std::uint8_t>();
    for (const Vertex v : mesh.vertices()) {
        if (mesh.is_isolated(v) || mesh.is_boundary(v) ||
            (options.fix_creases && crease[v.idx()] != 0)) {
            free[v.idx()] = 0;
        }
    }
    return free;
}

// The rings, read straight from the connectivity arrays: each outgoing halfedge of a vertex,
// counter-clockwise from its anchor (the order of Mesh::halfedges(v), so the sums of a step
// add in the same order as they always did).
Rings rings(const Mesh& mesh, const SmoothOptions& options) {
    Rings r;
    r.free = movable(mesh, options);
    const bool uniform = options.weights == SmoothWeights::Uniform;
    r.uniform = uniform;
    const std::vector<double> w =
        uniform ? std::vector<double>() : laplacian::edge_weights(mesh, options.weights);
    const std::size_t n = mesh.vertices_size();
    const memory::Array<Halfedge>& prev = MeshArrays::prev(mesh);
    const memory::Array<Vertex>& to = MeshArrays::to_vertex(mesh);
    const memory::Array<Halfedge>& anchor = MeshArrays::vertex_halfedge(mesh);
    r.offset.resize_for_overwrite(n + 1);
    r.offset[0] = 0;
    r.sum.assign(n, 0.0);
    r.neighbour.resize_for_overwrite(mesh.halfedges_size());
    if (!uniform) {
        r.weight.resize_for_overwrite(mesh.halfedges_size());
    }
    std::uint32_t* out = r.neighbour.data();
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vertex v(static_cast<std::uint32_t>(i));
        const Halfedge first = anchor[i];
        if (first.is_valid() && !mesh.is_deleted(v) && mesh.is_boundary(first)) {
            r.closed = false;
        }
        if (r.free[i] != 0) {
            const std::size_t begin = k;
            double sum = 0.0;
            Halfedge h = first;
            do {
                out[k] = to[h.idx()].idx();
                if (!uniform) {
                    r.weight[k] = w[Mesh::edge(h).idx()];
                    sum += r.weight[k];
                }
                ++k;
                h = Mesh::twin(prev[h.idx()]);
            } while (h != first);
            if (uniform) {
                sum = static_cast<double>(k - begin);  // Σ 1.0, exact
            } else {
                for (std::size_t j = begin; j < k; ++j) {
                    r.weight[j] /= sum;
                }
            }
            if (sum > 0.0) {
                r.sum[i] = sum;
                ++r.n_free;
            } else {
                k = begin;
                r.free[i] = 0;
            }
        }
        r.offset[i + 1] = static_cast<std::uint32_t>(k);
    }
    r.neighbour.resize(k);
    if (!uniform) {
        r.weight.resize(k);
    }
    return r;
}

// The uniform step on x86-64 with AVX2: a position's three coordinates (and the next one's x,
// unused) in one 4-wide register, so each neighbour costs one load, one multiply and one add
// instead of two of each. The same operations in the same order on each coordinate as the
// portable loop (no fused multiply-add), so the same bits. Reads 8 bytes past the last
// position: the position buffers carry one padding element (kPadding).
#if defined(__x86_64__) && defined(__GNUC__)
#define MESHEDIT_SMOOTH_AVX2 1
static_assert(sizeof(Vec3) == 3 * sizeof(double), "a Vec3 is three packed doubles");
__attribute__((target("avx2"))) void uniform_step_avx2(const Vec3* x, const std::uint32_t* offset,
                                                       const std::uint32_t* neighbour, Vec3* y,
                                                       std::size_t begin, std::size_t end,
                                                       double step) {
    const __m256d s = _mm256_set1_pd(step);
    for (std::size_t i = begin; i < end; ++i) {
        const std::uint32_t first = offset[i], last = offset[i + 1];
        if (first == last) {  // fixed
            y[i] = x[i];
            continue;
        }
        const __m256d w = _mm256_set1_pd(1.0 / static_cast<double>(last - first));
        __m256d mean = _mm256_setzero_pd();
        for (std::uint32_t k = first; k < last; ++k) {
            mean = _mm256_add_pd(mean, _mm256_mul_pd(_mm256_loadu_pd(&x[neighbour[k]].x), w));
        }
        const __m256d p = _mm256_loadu_pd(&x[i].x);
        const __m256d moved = _mm256_add_pd(p, _mm256_mul_pd(_mm256_sub_pd(mean, p), s));
        _mm_storeu_pd(&y[i].x, _mm256_castpd256_pd128(moved));
        _mm_store_sd(&y[i].z, _mm256_extractf128_pd(moved, 1));
    }
}

bool has_avx2() {
    static const bool yes = __builtin_cpu_supports("avx2") != 0;
    return yes;
}
#endif

// Elements after the last position in the step's buffers (uniform_step_avx2's wide loads).
constexpr std::size_t kPadding = 1;

// One Jacobi step x ← x + step · L x over the first `n` positions of `from` into `to`.
void laplace_step(const Rings& r, std::size_t n, const memory::Array<Vec3>& from,
                  memory::Array<Vec3>& to, double step) {
    const unsigned threads = parallel::thread_count(n, kParallelVertices);
    const Vec3* x = from.data();
    const std::uint32_t* offset = r.offset.data();
    const std::uint32_t* neighbour = r.neighbour.data();
    const double* weight = r.weight.data();
    parallel::for_chunks(n, kChunk, threads, [&](std::size_t begin, std::size_t end) {
        Vec3* y = to.data();
#ifdef MESHEDIT_SMOOTH_AVX2
        if (r.uniform && has_avx2()) {
            uniform_step_avx2(x, offset, neighbour, y, begin, end, step);
            return;
        }
#endif
        for (std::size_t i = begin; i < end; ++i) {
            const Vec3& p = x[i];
            const std::uint32_t first = offset[i], last = offset[i + 1];
            if (first == last) {  // fixed
                y[i] = p;
                continue;
            }
            Vec3 mean;
            if (r.uniform) {
                const double w = 1.0 / static_cast<double>(last - first);
                for (std::uint32_t k = first; k < last; ++k) {
                    mean += x[neighbour[k]] * w;
                }
            } else {
                for (std::uint32_t k = first; k < last; ++k) {
                    mean += x[neighbour[k]] * weight[k];
                }
            }
            y[i] = p + (mean - p) * step;
        }
    });
}

// Backward Euler: (I − t L) x' = x, multiplied by D = diag(Σ w) into the symmetric
// ((1 + t) D − t W) x' = D x over the free vertices, the fixed ones moved to the right.
// Diagonally dominant and positive definite: conjugate gradients converge in few steps.
void implicit_steps(const Rings& r, memory::Array<Vec3>& x, const SmoothOptions& options) {
    const std::size_t n = r.free.size();
    std::vector<std::int64_t> index(n, -1);
    Eigen::Index m = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (r.free[i] != 0) {
            index[i] = m++;
        }
    }
    const double t = options.time;
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(r.neighbour.size() + static_cast<std::size_t>(m));
    Eigen::MatrixX3d fixed_part = Eigen::MatrixX3d::Zero(m, 3);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int64_t row = index[i];
        if (row < 0) {
            continue;
        }
        entries.emplace_back(row, row, (1.0 + t) * r.sum[i]);
        for (std::uint32_t k = r.offset[i]; k < r.offset[i + 1]; ++k) {
            const std::uint32_t j = r.neighbour[k];
            const double w = t * r.w(i, k) * r.sum[i];  // t w_ij
            if (index[j] >= 0) {
                entries.emplace_back(row, index[j], -w);
            } else {
                fixed_part.row(row) += w * Eigen::RowVector3d(x[j].x, x[j].y, x[j].z);
            }
        }
    }
    Eigen::SparseMatrix<double> a(m, m);
    a.setFromTriplets(entries.begin(), entries.end());
    entries = {};
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> solver;
    solver.setTolerance(1e-12);
    solver.compute(a);
    Eigen::VectorXd b(m), solution(m);
    for (int step = 0; step < options.iterations; ++step) {
        for (int c = 0; c < 3; ++c) {
            for (std::size_t i = 0; i < n; ++i) {
                if (index[i] >= 0) {
                    const double value = c == 0 ? x[i].x : c == 1 ? x[i].y : x[i].z;
                    b[index[i]] = r.sum[i] * value + fixed_part(index[i], c);
                    solution[index[i]] = value;  // the start: the positions now
                }
            }
            solution = solver.solveWithGuess(b, solution);
            for (std::size_t i = 0; i < n; ++i) {
                if (index[i] >= 0) {
                    (c == 0 ? x[i].x : c == 1 ? x[i].y : x[i].z) = solution[index[i]];
                }
            }
        }
        if (options.progress) {
            options.progress(static_cast<double>(step + 1) / options.iterations);
        }
    }
}

}  // namespace

double enclosed_volume(const Mesh& mesh) {
    double six = 0.0;
    for (const Face f : mesh.faces()) {
        const Halfedge first = mesh.halfedge(f);
        const Vec3& a = mesh.position(mesh.to_vertex(first));
        for (Halfedge h = mesh.next(first); mesh.next(h) != first; h = mesh.next(h)) {
            six += dot(a, cross(mesh.position(mesh.to_vertex(h)),
                                mesh.position(mesh.to_vertex(mesh.next(h)))));
        }
    }
    return six / 6.0;
}

OpStatus check_smooth(const Mesh& mesh, const SmoothOptions& options) {
    if (mesh.n_faces() == 0) {
        return OpStatus::refused("cannot smooth: the mesh has no faces");
    }
    const int n = options.iterations;
    if (n < 1 || n > kMaxIterations) {
        return OpStatus::composed(cannot("iterations must be a whole number from 1 to " +
                                         std::to_string(kMaxIterations) + ", not " +
                                         std::to_string(n)));
    }
    const double lambda = options.lambda, mu = options.mu;
    if (options.method != SmoothMethod::Implicit && !(lambda > 0.0 && lambda <= 1.0)) {
        return OpStatus::composed(
            cannot("the step λ must be above 0 and at most 1, not " + number_text(lambda)));
    }
    if (options.method == SmoothMethod::Taubin && !(mu < -lambda && mu >= -1.0)) {
        return OpStatus::composed(cannot("Taubin's μ must be below -λ = " + number_text(-lambda) +
                                         " and at least -1, not " + number_text(mu)));
    }
    if (options.method == SmoothMethod::Implicit &&
        !(options.time > 0.0 && options.time <= kMaxTime)) {
        return OpStatus::composed(cannot("the time step t must be above 0 and at most 1e6, not " +
                                         number_text(options.time)));
    }
    if (const std::string why = laplacian::refuse_non_finite(mesh, "smooth"); !why.empty()) {
        return OpStatus::composed(why);
    }
    if (options.weights == SmoothWeights::Cotangent && !mesh.is_triangle_mesh()) {
        return OpStatus::refused(
            "cannot smooth: cotangent weights need triangles (triangulate first: the "
            "`triangulate` step, Ctrl+T in the viewer)");
    }
    for (const Vertex v : options.vertices) {
        if (!mesh.is_valid(v) || mesh.is_deleted(v)) {
            return OpStatus::composed(
                cannot("vertex " + std::to_string(v.idx()) + " is not in the mesh"));
        }
    }
    if (options.keep_volume) {
        if (!options.vertices.empty()) {
            return OpStatus::refused(
                "cannot smooth: keeping the volume scales the whole mesh, so it needs every "
                "vertex free to move, not a part");
        }
        if (has_boundary(mesh)) {
            return OpStatus::refused(
                "cannot smooth: keeping the volume needs a closed mesh and this one has a "
                "boundary (fill its holes first)");
        }
        const double volume = enclosed_volume(mesh);
        if (!(std::abs(volume) > 0.0) || !std::isfinite(volume)) {
            return OpStatus::refused(
                "cannot smooth: keeping the volume needs a mesh that "
                "encloses some, and this one encloses none");
        }
    }
    const std::vector<std::uint8_t> free = movable(mesh, options);
    if (std::find(free.begin(), free.end(), 1) == free.end()) {
        return OpStatus::refused(
            "cannot smooth: every vertex is fixed (on the boundary or on a crease)");
    }
    // Rings and two position buffers; the implicit system adds its matrix and vectors.
    const auto v = static_cast<double>(mesh.vertices_size());
    const auto h = static_cast<double>(mesh.halfedges_size());
    double bytes =
        v * (2 * sizeof(Vec3) + 16) + h * 12 + static_cast<double>(mesh.edges_size()) * 8;
    if (options.method == SmoothMethod::Implicit) {
        bytes += h * 40 + v * 80;
    }
    if (const auto why = over_budget(bytes)) {
        return OpStatus::composed(cannot(*why));
    }
    return OpStatus::ok();
}

SmoothReport smooth(Mesh& mesh, const SmoothOptions& options) {
    SmoothReport report;
    report.volume_before = enclosed_volume(mesh);
    const Rings r = rings(mesh, options);
    report.closed = r.closed;
    report.moved = r.n_free;
    // Every vertex's position, deleted ones too (never free, so never read as a neighbour),
    // and the padding the step's wide loads may touch.
    const std::size_t n = mesh.vertices_size();
    memory::Array<Vec3> x;
    x.resize_for_overwrite(n + kPadding);
    std::copy_n(std::as_const(mesh).position_vector().data(), n, x.data());  // read: recordable
    std::fill(x.begin() + static_cast<std::ptrdiff_t>(n), x.end(), Vec3());
    memory::Array<Vec3> y;
    if (options.method == SmoothMethod::Implicit) {
        const auto begin = std::chrono::steady_clock::now();
        implicit_steps(r, x, options);
        report.solve_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    } else {
        y.resize_for_overwrite(x.size());  // every step writes the first n
        std::fill(y.begin() + static_cast<std::ptrdiff_t>(n), y.end(), Vec3());
        for (int i = 0; i < options.iterations; ++i) {
            laplace_step(r, n, x, y, options.lambda);
            if (options.method == SmoothMethod::Taubin) {
                laplace_step(r, n, y, x, options.mu);
            } else {
                x.swap(y);
            }
            if (options.progress) {
                options.progress(static_cast<double>(i + 1) / options.iterations);
            }
        }
    }
    y = {};
    report.iterations = options.iterations;
    // The positions before: kept only for the volume's scale, which moves every vertex;
    // otherwise a vertex's move is measured as it is written.
    memory::Array<Vec3> start;
    if (options.keep_volume) {
        start = std::as_const(mesh).position_vector();
    }
    for (const Vertex v : mesh.vertices()) {
        if (r.free[v.idx()] != 0) {
            Vec3& p = mesh.position(v);
            if (!options.keep_volume) {
                report.max_displacement = std::max(report.max_displacement, norm(x[v.idx()] - p));
            }
            p = x[v.idx()];
        }
    }
    if (options.keep_volume) {
        const double after = enclosed_volume(mesh);
        if (after != 0.0 && after * report.volume_before > 0.0) {
            const double scale = std::cbrt(report.volume_before / after);
            Vec3 centre;
            for (const Vertex v : mesh.vertices()) {
                centre += mesh.position(v);
            }
            centre = centre * (1.0 / static_cast<double>(mesh.n_vertices()));
            for (const Vertex v : mesh.vertices()) {
                mesh.position(v) = centre + (mesh.position(v) - centre) * scale;
            }
        }
        for (const Vertex v : mesh.vertices()) {
            report.max_displacement =
                std::max(report.max_displacement, norm(mesh.position(v) - start[v.idx()]));
        }
    }
    report.volume_after = enclosed_volume(mesh);
    return report;
}

}  // namespace meshedit
