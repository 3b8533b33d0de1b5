// Smoothing and fairing (core/smoothing.h): exact single steps on grids, cotangent against
// uniform weights, Taubin against plain Laplacian on a sphere, implicit smoothing of a noisy
// sphere, the volume option, fairing a bump flat, the same bits on any number of threads, and
// refusals that leave the mesh bit for bit.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "algorithms/laplacian.h"
#include "mesh/parallel.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/build.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/smoothing.h"
#include "meshedit/core/threads.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

// Positions bit for bit (NaN included) and the same faces: what a refusal leaves.
bool unchanged(const Mesh& a, const Mesh& b) {
    const auto& pa = a.position_vector();
    const auto& pb = b.position_vector();
    // memcmp of an empty mesh's null data is undefined (UBSan says so): nothing to compare.
    return pa.size() == pb.size() &&
           (pa.empty() || std::memcmp(pa.data(), pb.data(), pa.size() * sizeof(Vec3)) == 0) &&
           test::canonical_faces(a) == test::canonical_faces(b);
}

SmoothReport smoothed(Mesh& mesh, const SmoothOptions& options) {
    EXPECT_EQ(check_smooth(mesh, options), "");
    const SmoothReport report = smooth(mesh, options);
    EXPECT_VALID(mesh);
    return report;
}

SmoothOptions steps(int n, double lambda, SmoothWeights weights = SmoothWeights::Uniform) {
    SmoothOptions options;
    options.iterations = n;
    options.lambda = lambda;
    options.weights = weights;
    return options;
}

// Every vertex of an icosphere pushed along its radius by up to ±`amount`, reproducibly.
Mesh noisy_sphere(int k, double amount) {
    Mesh mesh = shapes::icosphere(k);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> noise(-amount, amount);
    for (const Vertex v : mesh.vertices()) {
        mesh.position(v) = mesh.position(v) * (1.0 + noise(rng));
    }
    return mesh;
}

// The spread of the distances to the centre, relative to their mean: 0 on a sphere.
double roughness(const Mesh& mesh) {
    double sum = 0.0, sum2 = 0.0;
    for (const Vertex v : mesh.vertices()) {
        const double r = norm(mesh.position(v));
        sum += r;
        sum2 += r * r;
    }
    const double n = static_cast<double>(mesh.n_vertices());
    const double mean = sum / n;
    return std::sqrt(std::max(0.0, sum2 / n - mean * mean)) / mean;
}

// The flat grid on [0,1]², vertex (i, j) = j·(n+1) + i, with vertex (2, 2) lifted to z = 1:
//
//   (1,3)  (2,3)  (3,3)        one uniform step of λ moves (2,2) to z = 1 − λ (its six
//     | \    | \    |          neighbours are flat) and each neighbour up by λ/6; (3,3), on
//   (1,2)--(2,2)--(3,2)        the diagonal through (2,2), is one of them; the border stays.
//     | \    | \    |
//   (1,1)  (2,1)  (3,1)
TEST(Smooth, OneUniformStepMovesTheLiftedVertexExactly) {
    Mesh mesh = shapes::grid(4, 4);
    const Vertex lifted(2 * 5 + 2);
    mesh.position(lifted).z = 1.0;
    const Mesh before = mesh;
    const SmoothReport report = smoothed(mesh, steps(1, 0.5));
    EXPECT_EQ(mesh.position(lifted).z, 0.5);
    EXPECT_DOUBLE_EQ(mesh.position(lifted).x, 0.5);
    EXPECT_DOUBLE_EQ(mesh.position(lifted).y, 0.5);
    EXPECT_DOUBLE_EQ(mesh.position(Vertex(3 * 5 + 3)).z, 0.5 / 6.0);
    EXPECT_EQ(mesh.position(Vertex(1 * 5 + 3)).z, 0.0);  // (3,1) is not a neighbour
    EXPECT_EQ(report.moved, 9u);
    EXPECT_EQ(report.iterations, 1);
    EXPECT_DOUBLE_EQ(report.max_displacement, 0.5);
    EXPECT_FALSE(report.closed);
    for (const Vertex v : mesh.vertices()) {
        if (mesh.is_boundary(v)) {
            EXPECT_EQ(mesh.position(v), before.position(v)) << v.idx();
        }
    }
}

// On this grid (right triangles) the cotangent weights are 1 on inner axis edges and 0 on
// the diagonals; on a lattice of equilateral triangles every inner weight is cot 60° = 1/√3:
// there the cotangent Laplacian is the uniform one times a constant (normalised, equal).
TEST(Smooth, CotangentWeightsOnRegularGrids) {
    const Mesh grid = shapes::grid(4, 4);
    const std::vector<double> w = laplacian::edge_weights(grid, SmoothWeights::Cotangent);
    for (const Edge e : grid.edges()) {
        const Vec3 d = grid.position(grid.vertex(e, 1)) - grid.position(grid.vertex(e, 0));
        const bool diagonal = d.x != 0.0 && d.y != 0.0;
        const double expected =
            grid.is_boundary(e) ? (diagonal ? 0.0 : 0.5) : (diagonal ? 0.0 : 1.0);
        EXPECT_NEAR(w[e.idx()], expected, 1e-15) << e.idx();
    }
    PolygonSoup soup;
    const int n = 6;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            soup.positions.push_back({i + 0.5 * j, j * std::sqrt(3.0) / 2.0, 0.0});
        }
    }
    const auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            soup.add_face({id(i, j), id(i + 1, j), id(i, j + 1)});
            soup.add_face({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    const Mesh lattice = build_mesh(soup);
    const std::vector<double> c = laplacian::edge_weights(lattice, SmoothWeights::Cotangent);
    for (const Edge e : lattice.edges()) {
        EXPECT_NEAR(c[e.idx()], (lattice.is_boundary(e) ? 0.5 : 1.0) / std::sqrt(3.0), 1e-15);
    }
    // A lifted vertex drops to 1 − λ with either weights (its neighbours are flat).
    for (const SmoothWeights weights : {SmoothWeights::Uniform, SmoothWeights::Cotangent}) {
        Mesh lifted = lattice;
        lifted.position(Vertex(id(3, 3))).z = 1.0;
        smoothed(lifted, steps(1, 0.5, weights));
        EXPECT_EQ(lifted.position(Vertex(id(3, 3))).z, 0.5);
    }
}

// Ten steps of λ = 0.5 shrink a unit icosphere; Taubin's λ|μ keeps its volume.
TEST(Smooth, TaubinKeepsTheVolumeThatLaplacianLoses) {
    const Mesh sphere = noisy_sphere(3, 0.02);
    Mesh laplace = sphere, taubin = sphere;
    const SmoothReport l = smoothed(laplace, steps(10, 0.5));
    SmoothOptions t = steps(10, 0.5);
    t.method = SmoothMethod::Taubin;
    t.mu = -0.53;
    const SmoothReport r = smoothed(taubin, t);
    ASSERT_TRUE(l.closed);
    const double lost = 1.0 - l.volume_after / l.volume_before;
    const double taubin_change = std::abs(1.0 - r.volume_after / r.volume_before);
    EXPECT_GT(lost, 0.12);  // measured: 15.7 %
    EXPECT_LT(lost, 0.20);
    EXPECT_LT(taubin_change, 0.012);  // measured: 0.90 %
    EXPECT_LT(roughness(taubin), 0.5 * roughness(sphere));
}

// Each implicit step takes most of the noise away and moves less than the step before.
TEST(Smooth, ImplicitSmoothingOfANoisySphereConverges) {
    Mesh mesh = noisy_sphere(3, 0.05);
    const double start = roughness(mesh);
    SmoothOptions options;
    options.method = SmoothMethod::Implicit;
    options.weights = SmoothWeights::Cotangent;
    options.time = 1.0;
    options.iterations = 1;
    double last_move = std::numeric_limits<double>::infinity();
    double last_roughness = start;
    for (int i = 0; i < 4; ++i) {
        const SmoothReport report = smoothed(mesh, options);
        EXPECT_LT(report.max_displacement, last_move) << i;
        EXPECT_LT(roughness(mesh), last_roughness) << i;
        EXPECT_GE(report.solve_seconds, 0.0);
        last_move = report.max_displacement;
        last_roughness = roughness(mesh);
    }
    EXPECT_LT(last_roughness, 0.35 * start);  // measured: 0.27
}

// The volume option scales back to the volume before, to rounding.
TEST(Smooth, TheVolumeOptionRestoresTheVolume) {
    for (const SmoothMethod method : {SmoothMethod::Explicit, SmoothMethod::Implicit}) {
        for (Mesh mesh : {noisy_sphere(2, 0.05), shapes::torus(24, 12)}) {
            SmoothOptions options = steps(20, 0.5, SmoothWeights::Cotangent);
            options.method = method;
            options.keep_volume = true;
            const double before = enclosed_volume(mesh);
            const SmoothReport report = smoothed(mesh, options);
            EXPECT_NEAR(enclosed_volume(mesh) / before, 1.0, 1e-9);
            EXPECT_NEAR(report.volume_after / report.volume_before, 1.0, 1e-9);
            EXPECT_GT(report.max_displacement, 0.0);
        }
    }
}

// Crease vertices stay unless told otherwise; a vertex subset moves alone.
TEST(Smooth, CreasesAndUnlistedVerticesStay) {
    Mesh mesh = noisy_sphere(2, 0.05);
    const Edge e(7);
    mesh.add_property<Edge, std::uint8_t>(kCreaseProperty, 0)[e] = 1;
    const Vertex a = mesh.vertex(e, 0), b = mesh.vertex(e, 1);
    const Vec3 pa = mesh.position(a), pb = mesh.position(b);
    Mesh free = mesh;
    smoothed(mesh, steps(5, 0.5));
    EXPECT_EQ(mesh.position(a), pa);
    EXPECT_EQ(mesh.position(b), pb);
    SmoothOptions loose = steps(5, 0.5);
    loose.fix_creases = false;
    smoothed(free, loose);
    EXPECT_NE(free.position(a), pa);

    Mesh part = noisy_sphere(2, 0.05);
    const Mesh before = part;
    SmoothOptions some = steps(3, 0.5);
    some.vertices = {Vertex(3), Vertex(9)};
    const SmoothReport report = smoothed(part, some);
    EXPECT_EQ(report.moved, 2u);
    for (const Vertex v : part.vertices()) {
        EXPECT_EQ(part.position(v) == before.position(v), v.idx() != 3 && v.idx() != 9) << v.idx();
    }
}

// Chunks of vertices run on several threads give the bits of one.
TEST(Smooth, TheSameBitsOnAnyNumberOfThreads) {
    const parallel::ScopedSerialBelow small(1);
    Mesh one = noisy_sphere(4, 0.03), two = one;
    set_thread_count(1);
    smoothed(one, steps(3, 0.5, SmoothWeights::Cotangent));
    set_thread_count(3);
    smoothed(two, steps(3, 0.5, SmoothWeights::Cotangent));
    set_thread_count(0);
    EXPECT_TRUE(test::identical(one, two));
}

// The faces of a unit grid whose centroids lie inside [0.25, 0.75]².
std::vector<Face> middle_faces(const Mesh& mesh) {
    std::vector<Face> region;
    for (const Face f : mesh.faces()) {
        Vec3 c;
        for (const Vertex v : mesh.vertices(f)) {
            c += mesh.position(v) * (1.0 / 3.0);
        }
        if (c.x > 0.25 && c.x < 0.75 && c.y > 0.25 && c.y < 0.75) {
            region.push_back(f);
        }
    }
    return region;
}

// A 12 × 12 grid with a bump on the faces inside [0.25, 0.75]²: fairing puts every inner
// vertex back in the plane z = 0 (the border and the rings around it are flat), and with
// uniform weights back at its grid place too (a linear function is harmonic there).
TEST(Fair, ABumpOnAGridComesOutFlat) {
    for (const SmoothWeights weights : {SmoothWeights::Cotangent, SmoothWeights::Uniform}) {
        Mesh mesh = shapes::grid(12, 12);
        const Mesh flat = mesh;
        const std::vector<Face> region = middle_faces(mesh);
        for (const Vertex v : mesh.vertices()) {
            const Vec3 p = mesh.position(v);
            if (p.x > 0.3 && p.x < 0.7 && p.y > 0.3 && p.y < 0.7) {
                mesh.position(v).z = 0.3 * std::sin(p.x * 7.0) * std::cos(p.y * 5.0);
                mesh.position(v).x += 0.01 * std::sin(p.y * 13.0);
            }
        }
        const FairOptions options{weights};
        ASSERT_EQ(check_fair(mesh, region, options), "");
        const FairReport report = fair(mesh, region, options);
        ASSERT_VALID(mesh);
        EXPECT_EQ(report.moved, 25u);  // the 5 × 5 vertices strictly inside
        EXPECT_GT(report.max_displacement, 0.05);
        for (const Vertex v : mesh.vertices()) {
            EXPECT_NEAR(mesh.position(v).z, 0.0, 1e-9) << v.idx();
            if (weights == SmoothWeights::Uniform) {
                EXPECT_NEAR(norm(mesh.position(v) - flat.position(v)), 0.0, 1e-9) << v.idx();
            }
        }
    }
}

// Fairing reads the region and two rings around it, nothing else: a NaN in a far corner of
// the grid neither stops it nor changes what it computes (the check and the solve cost the
// region's size, not the mesh's).
TEST(Fair, ANaNFarFromTheRegionDoesNotTouchIt) {
    Mesh mesh = shapes::grid(12, 12);
    const std::vector<Face> region = middle_faces(mesh);
    for (const Vertex v : mesh.vertices()) {
        Vec3& p = mesh.position(v);
        p.z = 0.2 * std::sin(p.x * 5.0 + p.y * 3.0);  // not flat, so fairing moves the inside
    }
    Mesh far = mesh;
    Vertex corner;  // (0, 0): outside the region's two rings
    for (const Vertex v : far.vertices()) {
        if (norm(far.position(v) - Vec3{0.0, 0.0, far.position(v).z}) < 1e-12) {
            corner = v;
        }
    }
    ASSERT_TRUE(corner.is_valid());
    far.position(corner).x = std::numeric_limits<double>::quiet_NaN();
    const FairOptions options{SmoothWeights::Cotangent};
    ASSERT_EQ(check_fair(mesh, region, options), "");
    ASSERT_EQ(check_fair(far, region, options), "");
    const FairReport a = fair(mesh, region, options);
    const FairReport b = fair(far, region, options);
    EXPECT_EQ(a.moved, 25u);
    EXPECT_EQ(b.moved, 25u);
    for (const Vertex v : mesh.vertices()) {
        if (v != corner) {
            EXPECT_EQ(mesh.position(v), far.position(v)) << v.idx();
        }
    }
}

// Every refusal names its reason and leaves the mesh bit for bit.
TEST(Smooth, RefusalsLeaveTheMeshAsItWas) {
    const auto refused = [](Mesh mesh, const SmoothOptions& options, const char* reason) {
        const Mesh before = mesh;
        const OpStatus why = check_smooth(mesh, options);
        EXPECT_NE(why.text().find(reason), std::string::npos) << why.text();
        EXPECT_TRUE(unchanged(mesh, before));
    };
    Mesh nan = shapes::icosphere(1);
    nan.position(Vertex(4)).y = std::numeric_limits<double>::quiet_NaN();
    refused(nan, steps(1, 0.5), "vertex 4 has a position that is not a finite number");
    refused(Mesh(), steps(1, 0.5), "the mesh has no faces");
    refused(shapes::icosphere(1), steps(0, 0.5), "iterations must be a whole number");
    refused(shapes::icosphere(1), steps(1, 1.5), "λ must be above 0 and at most 1");
    SmoothOptions taubin = steps(1, 0.5);
    taubin.method = SmoothMethod::Taubin;
    taubin.mu = -0.4;
    refused(shapes::icosphere(1), taubin, "μ must be below");
    SmoothOptions implicit;
    implicit.method = SmoothMethod::Implicit;
    implicit.time = 0.0;
    refused(shapes::icosphere(1), implicit, "the time step t must be above 0");
    refused(shapes::quad_grid(3, 3), steps(1, 0.5, SmoothWeights::Cotangent),
            "cotangent weights need triangles");
    SmoothOptions keep = steps(1, 0.5);
    keep.keep_volume = true;
    refused(shapes::grid(3, 3), keep, "keeping the volume needs a closed mesh");
    refused(shapes::grid(1, 1), steps(1, 0.5), "every vertex is fixed");
    SmoothOptions missing = steps(1, 0.5);
    missing.vertices = {Vertex(999)};
    refused(shapes::icosphere(1), missing, "vertex 999 is not in the mesh");
}

TEST(Fair, RefusalsLeaveTheMeshAsItWas) {
    const auto refused = [](const Mesh& mesh, const std::vector<Face>& region, const char* reason) {
        const Mesh before = mesh;
        const OpStatus why = check_fair(mesh, region, FairOptions{});
        EXPECT_NE(why.text().find(reason), std::string::npos) << why.text();
        EXPECT_TRUE(unchanged(mesh, before));
    };
    const Mesh sphere = shapes::icosphere(1);
    std::vector<Face> all;
    for (const Face f : sphere.faces()) {
        all.push_back(f);
    }
    refused(sphere, all, "covers a whole closed part of the mesh");
    refused(sphere, {Face(0)}, "has no inner vertex");
    refused(sphere, {}, "the region is empty");
    refused(sphere, {Face(5000)}, "face 5000 is not in the mesh");
    Mesh nan = shapes::grid(6, 6);
    nan.position(Vertex(3)).x = std::numeric_limits<double>::infinity();
    std::vector<Face> middle;
    for (const Face f : nan.faces()) {
        middle.push_back(f);
    }
    refused(nan, middle, "not a finite number");
}

}  // namespace
}  // namespace meshedit
