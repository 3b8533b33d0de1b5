// Our COLLADA writer's output must load in Assimp too (issue: "the reader and Assimp both
// load back"). Every sample in dae/ was written by write_collada(), so `assimp info` on each
// must succeed and agree with our reader: same vertex count, and as many triangles as our
// faces give when fan-triangulated (Assimp triangulates polygons).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "meshedit/io/io.h"
#include "run.h"

namespace meshedit::test {
namespace {

const char* const kAssimp = "/usr/bin/assimp";

// The number after `label` in `assimp info` output ("Vertices:           8").
long field(const std::string& text, const std::string& label) {
    const std::size_t at = text.find(label);
    return at == std::string::npos ? -1 : std::stol(text.substr(at + label.size()));
}

TEST(Assimp, LoadsEverySampleWeWrote) {
    if (!std::filesystem::exists(kAssimp)) {
        GTEST_SKIP() << "assimp-utils is not installed";
    }
    std::size_t checked = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(repo_root() / "dae")) {
        if (entry.path().extension() != ".dae") {
            continue;
        }
        SCOPED_TRACE(entry.path().string());
        const LoadedMesh ours = read_mesh(entry.path());
        long triangles = 0;
        for (Face f : ours.mesh.faces()) {
            triangles += static_cast<long>(ours.mesh.valence(f)) - 2;
        }
        const RunResult r = run_program(kAssimp, {"info", entry.path().string()}, 20.0);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(field(r.out, "Vertices:"), static_cast<long>(ours.mesh.n_vertices()));
        EXPECT_EQ(field(r.out, "Faces:"), triangles);
        ++checked;
    }
    EXPECT_GE(checked, 19u);  // the 7 samples and 12 reference files
}

}  // namespace
}  // namespace meshedit::test
