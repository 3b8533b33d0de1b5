// Round trips through the command line: every sample .dae → .dae, .dae → .gltf → .dae,
// .dae → .glb, .dae → .obj → .dae keeps the same vertices (to 1e-6, by index) and faces.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "meshedit/core/build.h"
#include "meshedit/files/files.h"
#include "meshedit/io/io.h"
#include "run.h"
#include "support/mesh_compare.h"

namespace meshedit::test {
namespace {

const char* const kSamples[] = {
    "dae/cube.dae",
    "dae/icosahedron.dae",
    "dae/torus.dae",
    "dae/quadball.dae",
    "dae/bowl.dae",
    "dae/creased.dae",
    "dae/teapot.dae",
    "dae/cube/input.dae",
    "dae/cube/flip.dae",
    "dae/cube/split.dae",
    "dae/cube/collapse.dae",
    "dae/icosahedron/input.dae",
    "dae/icosahedron/flip.dae",
    "dae/icosahedron/split.dae",
    "dae/icosahedron/collapse.dae",
    "dae/torus/input.dae",
    "dae/torus/flip.dae",
    "dae/torus/split.dae",
    "dae/torus/collapse.dae",
};

// glTF holds triangles only: the writer fans each polygon from its first corner, so the
// expected faces of a polygon mesh are its fans.
std::vector<std::vector<std::uint32_t>> fan_faces(const Mesh& mesh) {
    const PolygonSoup soup = to_polygon_soup(mesh);
    PolygonSoup fans;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        const std::uint32_t* c = &soup.indices[soup.face_offsets[f]];
        const std::size_t n = soup.face_offsets[f + 1] - soup.face_offsets[f];
        for (std::size_t i = 1; i + 1 < n; ++i) {
            fans.add_face({c[0], c[i], c[i + 1]});
        }
    }
    fans.positions = soup.positions;
    return canonical_faces(build_mesh(fans));
}

void expect_same(const std::filesystem::path& actual_file, const Mesh& expected,
                 bool triangles_only) {
    SCOPED_TRACE(actual_file.filename().string());
    const Mesh actual = read_mesh(actual_file).mesh;
    ASSERT_EQ(actual.n_vertices(), expected.n_vertices());
    double worst = 0.0;
    for (const Vertex v : expected.vertices()) {
        worst = std::max(worst, distance(actual.position(v), expected.position(v)));
    }
    EXPECT_LE(worst, 1e-6);
    EXPECT_EQ(canonical_faces(actual),
              triangles_only ? fan_faces(expected) : canonical_faces(expected));
}

// Converts, expecting silence or exactly the note on what OUT's format cannot keep (the
// torus's doubles in glTF's floats, say).
void convert(const std::filesystem::path& in, const std::filesystem::path& out) {
    const RunResult r = run_meshedit({"convert", in.string(), out.string()});
    ASSERT_EQ(r.exit_code, 0) << in << " → " << out << ": " << r.err;
    const std::vector<std::string> unkept =
        unkept_by_format(read_mesh(in).mesh, file_extension(out));
    std::string expected;
    for (const std::string& item : unkept) {
        expected += "meshedit: note: " + out.string() + ": not kept: " + item + "\n";
    }
    EXPECT_EQ(r.err, expected);
}

class RoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(RoundTrip, KeepsVerticesAndFaces) {
    const std::filesystem::path sample = repo_root() / GetParam();
    const Mesh original = read_mesh(sample).mesh;
    TempDir tmp;

    convert(sample, tmp / "same.dae");
    expect_same(tmp / "same.dae", original, false);

    convert(sample, tmp / "mesh.gltf");
    convert(tmp / "mesh.gltf", tmp / "from_gltf.dae");
    expect_same(tmp / "from_gltf.dae", original, true);

    convert(sample, tmp / "mesh.glb");
    expect_same(tmp / "mesh.glb", original, true);

    convert(sample, tmp / "mesh.obj");
    convert(tmp / "mesh.obj", tmp / "from_obj.dae");
    expect_same(tmp / "from_obj.dae", original, false);

    // Writers leave no temporary files behind.
    EXPECT_EQ(tmp.entries(), (std::vector<std::string>{"from_gltf.dae", "from_obj.dae", "mesh.glb",
                                                       "mesh.gltf", "mesh.obj", "same.dae"}));
}

std::string test_name(const ::testing::TestParamInfo<const char*>& info) {
    std::string name = info.param;
    name = name.substr(4, name.size() - 8);  // strip "dae/" and ".dae"
    for (char& c : name) {
        c = c == '/' ? '_' : c;
    }
    return name;
}

INSTANTIATE_TEST_SUITE_P(Samples, RoundTrip, ::testing::ValuesIn(kSamples), test_name);

TEST(RoundTripCreases, SurviveDaeToDae) {
    TempDir tmp;
    const RunResult r = run_meshedit(
        {"convert", (repo_root() / "dae/creased.dae").string(), (tmp / "out.dae").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Mesh a = read_mesh(repo_root() / "dae/creased.dae").mesh;
    const Mesh b = read_mesh(tmp / "out.dae").mesh;
    const auto ca = a.get_property<Edge, std::uint8_t>("e:crease");
    const auto cb = b.get_property<Edge, std::uint8_t>("e:crease");
    ASSERT_TRUE(ca && cb);
    for (const Edge e : a.edges()) {
        const Edge f = b.find_edge(a.vertex(e, 0), a.vertex(e, 1));
        ASSERT_TRUE(f.is_valid());
        EXPECT_EQ(ca[e] != 0, cb[f] != 0);
    }
}

}  // namespace
}  // namespace meshedit::test
