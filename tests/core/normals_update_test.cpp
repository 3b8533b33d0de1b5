// Vertex normals brought up to date after a local edit (update_vertex_normals) are bit for bit
// what a full compute_vertex_normals() gives: on a mesh of several of the full pass's chunks
// (65,536 faces each), where an edit that appends elements moves the chunks' vertex ranges.

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b, std::size_t& first) {
    if (a.size() != b.size()) {
        first = std::min(a.size(), b.size());
        return false;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::memcmp(&a[i], &b[i], sizeof(Vec3)) != 0) {
            first = i;
            return false;
        }
    }
    return true;
}

void check_edits(Mesh mesh, int edits, unsigned seed) {
    std::vector<Vec3> normals;
    compute_vertex_normals(mesh, normals);
    std::mt19937 rng(seed);
    int applied = 0, moved = 0;
    std::vector<Vec3> full;
    for (int i = 0; i < edits; ++i) {
        const std::size_t nv = mesh.vertices_size(), nf = mesh.faces_size();
        MeshRecorder recorder(mesh);
        const Edge e(static_cast<std::uint32_t>(rng() % mesh.edges_size()));
        const Vertex v(static_cast<std::uint32_t>(rng() % mesh.vertices_size()));
        bool ok = false;
        switch (rng() % 4) {
            case 0:
                ok = !mesh.is_deleted(e) && flip(mesh, e).ok();
                break;
            case 1:
                ok = !mesh.is_deleted(e) && split(mesh, e).ok();
                break;
            case 2:
                ok = !mesh.is_deleted(e) && collapse(mesh, e).ok();
                break;
            default:
                if (!mesh.is_deleted(v)) {
                    mesh.position(v) += Vec3{0.01, -0.02, 0.005};
                    ok = true;
                    ++moved;
                }
        }
        const MeshChange change = recorder.finish();
        if (!ok) {
            continue;
        }
        ++applied;
        const MeshChange::Region region = change.region();
        std::vector<Vertex> recomputed;
        update_vertex_normals(mesh, region.faces, region.vertices, nv, nf, normals, recomputed);
        compute_vertex_normals(mesh, full);
        std::size_t first = 0;
        ASSERT_TRUE(same_bits(normals, full, first))
            << "edit " << i << ": vertex " << first << " differs from the full pass";
        EXPECT_LT(recomputed.size(), 200u) << "an edit's update should stay local";
    }
    EXPECT_GT(applied, edits / 2);
    EXPECT_GT(moved, 0);
}

TEST(NormalsUpdate, LocalEditsMatchTheFullPassBitForBit) {
    check_edits(shapes::torus(40, 30), 300, 1);  // one chunk: plain face order
}

TEST(NormalsUpdate, AcrossTheFullPassChunks) {
    // 150,000 faces: three chunks. On the grid (unlike the torus, where V = F / 2 whatever
    // splits do) every split moves the chunks' vertex ranges.
    check_edits(shapes::torus(300, 250), 40, 2);
    Mesh grid = shapes::grid(300, 250);
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
    for (const Vertex v : grid.vertices()) {  // sums in another order then differ in the bits
        grid.position(v) += Vec3{jitter(rng), jitter(rng), 100 * jitter(rng)};
    }
    check_edits(std::move(grid), 80, 3);
}

}  // namespace
}  // namespace meshedit
