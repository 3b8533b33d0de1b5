// glTF 2.0: .gltf and .glb round trips, a hand-written file with node transforms and
// instancing, and IoErrors for broken files.

#include <gtest/gtest.h>

#include <cmath>
#include <span>

#include "io/formats_test_util.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/gltf.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using test::data_file;
using test::io_error_of;

/// Positions equal to `tol` (glTF stores floats), index for index.
::testing::AssertionResult same_positions(std::span<const Vec3> a, std::span<const Vec3> b,
                                          double tol) {
    if (a.size() != b.size()) {
        return ::testing::AssertionFailure() << a.size() << " vs " << b.size() << " positions";
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (distance(a[i], b[i]) > tol) {
            return ::testing::AssertionFailure()
                   << "position " << i << ": (" << a[i].x << ", " << a[i].y << ", " << a[i].z
                   << ") vs (" << b[i].x << ", " << b[i].y << ", " << b[i].z << ")";
        }
    }
    return ::testing::AssertionSuccess();
}

void expect_round_trip(const Mesh& mesh, const std::string& name) {
    test::ScratchDir dir;
    write_gltf(mesh, dir / name, {});
    const LoadedMesh loaded = read_mesh(dir / name);
    EXPECT_FALSE(loaded.repairs.repaired()) << loaded.repairs.summary();
    // Vertex i is position i of the accessor, so faces compare by index.
    EXPECT_TRUE(same_positions(loaded.mesh.position_vector(), mesh.position_vector(), 1e-6));
    EXPECT_EQ(test::canonical_faces(loaded.mesh), test::canonical_faces(mesh));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{name});
}

TEST(Gltf, RoundTripText) {
    expect_round_trip(shapes::icosphere(2), "ball.gltf");
    expect_round_trip(shapes::cube(), "cube.gltf");
}

TEST(Gltf, RoundTripBinary) {
    expect_round_trip(shapes::torus(9, 6), "torus.glb");
    expect_round_trip(shapes::grid(4, 3), "grid.GLB");
}

TEST(Gltf, TextFileEmbedsItsBufferAndBinaryFileIsGlb) {
    test::ScratchDir dir;
    write_gltf(shapes::tetrahedron(), dir / "t.gltf", {});
    write_gltf(shapes::tetrahedron(), dir / "t.glb", {});
    EXPECT_NE(test::slurp(dir / "t.gltf").find("data:application/octet-stream;base64,"),
              std::string::npos);
    EXPECT_EQ(test::slurp(dir / "t.glb").substr(0, 4), "glTF");
    EXPECT_EQ(read_gltf(dir / "t.glb").normals.size(), 4u);
    IoFlags flags;
    flags.write_normals = false;
    write_gltf(shapes::tetrahedron(), dir / "n.gltf", flags);
    EXPECT_TRUE(read_gltf(dir / "n.gltf").normals.empty());
}

TEST(Gltf, PolygonsAreFanTriangulated) {
    test::ScratchDir dir;
    const Mesh quads = shapes::quad_sphere(2);
    write_gltf(quads, dir / "q.glb", {});
    const LoadedMesh loaded = read_mesh(dir / "q.glb");
    EXPECT_EQ(loaded.mesh.n_vertices(), quads.n_vertices());
    EXPECT_EQ(loaded.mesh.n_faces(), 2 * quads.n_faces());
    EXPECT_TRUE(same_positions(loaded.mesh.position_vector(), quads.position_vector(), 1e-6));
}

TEST(Gltf, MeshWithGarbageIsWrittenCompacted) {
    Mesh mesh = shapes::icosphere(1);
    ASSERT_TRUE(collapse(mesh, Edge(0)));
    ASSERT_TRUE(mesh.has_garbage());
    Mesh compact = mesh;
    compact.garbage_collection();
    test::ScratchDir dir;
    write_mesh(mesh, dir / "c.gltf");
    const LoadedMesh loaded = read_mesh(dir / "c.gltf");
    EXPECT_TRUE(same_positions(loaded.mesh.position_vector(), compact.position_vector(), 1e-6));
    EXPECT_EQ(test::canonical_faces(loaded.mesh), test::canonical_faces(compact));
}

TEST(Gltf, HandWrittenFileWithNodeTransformsAndInstancing) {
    const MeshSoup soup = read_gltf(data_file("gltf_transform.gltf"));
    // The triangle (0,0,0) (1,0,0) (0,1,0), instanced under node 0 (translate 10 in x) →
    // node 1 (rotate 90° about z, scale 2), and under node 2 (matrix: translate 5 in z).
    const std::vector<Vec3> expected = {{10, 0, 0}, {10, 2, 0}, {8, 0, 0},
                                        {0, 0, 5},  {1, 0, 5},  {0, 1, 5}};
    EXPECT_TRUE(same_positions(soup.soup.positions, expected, 1e-12));
    ASSERT_EQ(soup.soup.n_faces(), 2u);
    EXPECT_EQ(soup.soup.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    // The LINES primitive is skipped, and said (once per instance).
    ASSERT_EQ(soup.notices.size(), 1u);
    EXPECT_CONTAINS(soup.notices[0], "ignored 2 point or line primitive(s)");
}

TEST(Gltf, MirroringTransformKeepsFacesOutward) {
    test::ScratchDir dir;
    // Re-use the hand-written file with node 2's matrix mirrored in x.
    std::string text = test::slurp(data_file("gltf_transform.gltf"));
    const std::string from = "\"matrix\": [\n    1,";
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, from.size(), "\"matrix\": [\n    -1,");
    test::spit(dir / "mirror.gltf", text);
    const MeshSoup soup = read_gltf(dir / "mirror.gltf");
    // (0,0,5) (-1,0,5) (0,1,5) is clockwise seen from +z; the reader reverses it so the
    // face normal stays +z as in the untransformed triangle.
    const auto& p = soup.soup.positions;
    const auto& i = soup.soup.indices;
    const Vec3 n = cross(p[i[4]] - p[i[3]], p[i[5]] - p[i[3]]);
    EXPECT_GT(n.z, 0.0);
}

TEST(Gltf, Errors) {
    EXPECT_CONTAINS(io_error_of([] { read_gltf(data_file("gltf_bad_index.gltf")); }),
                    "gltf_bad_index.gltf: mesh 0, primitive 0: index 7 (element 2) is out of "
                    "range (3 positions)");
    EXPECT_CONTAINS(io_error_of([] { read_gltf(data_file("gltf_overrun.gltf")); }),
                    "gltf_overrun.gltf: mesh 0, primitive 0, POSITION accessor 0: 300 "
                    "elements do not fit");
    EXPECT_CONTAINS(io_error_of([] { read_gltf(data_file("gltf_truncated.gltf")); }),
                    "gltf_truncated.gltf: ");
    test::ScratchDir dir;
    EXPECT_CONTAINS(io_error_of([&] { read_mesh(dir / "absent.glb"); }),
                    "absent.glb: no such file");
    test::spit(dir / "noise.glb", std::string("glTF\x02\0\0\0\xff\xff\xff\x7f garbage", 20));
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "noise.glb"); }), "noise.glb: ");
    test::spit(dir / "empty.gltf", "");
    EXPECT_CONTAINS(io_error_of([&] { read_gltf(dir / "empty.gltf"); }), "empty.gltf: ");
    EXPECT_CONTAINS(io_error_of([&] { write_gltf(Mesh(), dir / "none.gltf", {}); }),
                    "none.gltf: the mesh has no faces");
    EXPECT_TRUE(dir.entries() == (std::vector<std::string>{"empty.gltf", "noise.glb"}));
}

}  // namespace
}  // namespace meshedit
