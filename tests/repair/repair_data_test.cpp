// Repair on real broken files no one here wrote: CGAL's demo meshes (libcgal-demo) with
// shuffled orientation, degenerate triangles and holes, and assimp-testmodels' engine whose
// vertices are split at normal seams. Each repaired mesh is valid, and repairing the file it
// was written to changes nothing. Without the packages the tests skip and name them.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "meshedit/core/topology.h"
#include "meshedit/core/validate.h"
#include "meshedit/repair/repair.h"
#include "support/demo_meshes.h"
#include "support/mesh_compare.h"
#include "support/scratch_dir.h"

namespace meshedit::test {
namespace {

namespace fs = std::filesystem;

// Repairs `file` with `options`, writes it as PLY (every double kept), and repairs that file
// again: the second repair changes nothing and gives the same mesh. \return the first.
RepairedMesh repair_twice(const fs::path& file, const RepairOptions& options) {
    RepairedMesh once = repair_and_build(read_soup(file), options, file.string());
    EXPECT_VALID(once.loaded.mesh);
    ScratchDir dir;
    write_mesh(once.loaded.mesh, dir / "once.ply");
    const RepairedMesh twice =
        repair_and_build(read_soup(dir / "once.ply"), options, (dir / "once.ply").string());
    for (const RepairResult& step : twice.report.steps) {
        EXPECT_FALSE(step.changed()) << step.sentence;
    }
    const PolygonSoup a = to_polygon_soup(once.loaded.mesh);
    const PolygonSoup b = to_polygon_soup(twice.loaded.mesh);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.face_offsets, b.face_offsets);
    return once;
}

TEST(RepairData, CgalDemoMeshesComeOutValidAndStayRepaired) {
    if (!fs::exists(kDemoDataTarball)) {
        GTEST_SKIP() << "no " << kDemoDataTarball << ": install libcgal-demo";
    }
    const fs::path data = fs::path(MESHEDIT_BUILD_DIR) / "demo_data";
    RepairOptions options;
    options.fill_holes = 40;
    options.components.min_faces = 5;

    // Faces wound at random: every edge agrees afterwards, the cube closed and outward.
    for (const char* stem : {"cube-shuffled", "blobby-shuffled"}) {
        SCOPED_TRACE(stem);
        const RepairedMesh r = repair_twice(demo_mesh(stem, data), options);
        EXPECT_FALSE(r.loaded.repairs.repaired());
        ASSERT_FALSE(r.report.steps.empty());
        EXPECT_GT(r.report.steps[3].count, 0u) << "orientation turned nothing";
    }
    // Four zero-area triangles on a line: removed, which leaves two pieces of two triangles,
    // each below 5 faces: the first stays. Its outline is no hole a fan can fill.
    {
        const RepairedMesh r = repair_twice(demo_mesh("degtri_sliding", data), options);
        EXPECT_EQ(r.report.steps[1].count, 4u);
        EXPECT_EQ(r.report.steps[4].count, 1u);
        EXPECT_EQ(r.loaded.mesh.n_faces(), 2u);
    }
    // Holes: the small ones filled, the large ones left and counted.
    {
        const RepairedMesh r = repair_twice(demo_mesh("elephant-with-holes", data), options);
        const RepairResult& holes = r.report.steps.back();
        EXPECT_GT(holes.count, 50u);
        EXPECT_GT(holes.left, 0u);
        EXPECT_LT(count_boundary_loops(r.loaded.mesh), 20u);
    }
    // An open cube: filled, closed and outward.
    {
        const RepairedMesh r = repair_twice(demo_mesh("open_cube", data), options);
        EXPECT_TRUE(is_closed(r.loaded.mesh));
    }
}

TEST(RepairData, AnEngineSplitAtNormalSeamsMergesIntoFarFewerParts) {
    const fs::path engine =
        "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    if (!fs::exists(engine)) {
        GTEST_SKIP() << "no " << engine << ": install assimp-testmodels";
    }
    const LoadedMesh plain = read_mesh(engine);
    const RepairedMesh r = repair_twice(engine, {});
    // Loaded as it is: 1,419 components and 2,553 boundary loops (issue 35).
    EXPECT_GT(count_components(plain.mesh), 1000u);
    EXPECT_LT(count_components(r.loaded.mesh), 150u);
    EXPECT_LT(count_boundary_loops(r.loaded.mesh), count_boundary_loops(plain.mesh) / 2);
}

}  // namespace
}  // namespace meshedit::test
