// COLLADA reader and writer: one hand-written file per construct (tests/io/data/collada_*.dae),
// one per kind of bad input, and round trips through the writer.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/build.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/collada.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

fs::path data(const std::string& name) {
    return fs::path(MESHEDIT_TEST_DATA) / name;
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A scratch folder per test, removed afterwards.
class ColladaFiles : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               (std::string("meshedit_collada_") + info->name() + "_" +
                std::to_string(std::hash<std::string>{}(fs::current_path().string())));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write_bytes(const std::string& name, const std::string& bytes) {
        const fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }

    fs::path dir_;
};

void expect_positions(const MeshSoup& soup, const std::vector<Vec3>& expected, double tol = 0.0) {
    ASSERT_EQ(soup.soup.positions.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(soup.soup.positions[i][k], expected[i][k], tol)
                << "position " << i << " component " << k;
        }
    }
}

std::vector<std::vector<std::uint32_t>> faces_of(const PolygonSoup& soup) {
    std::vector<std::vector<std::uint32_t>> faces;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        faces.emplace_back(soup.indices.begin() + soup.face_offsets[f],
                           soup.indices.begin() + soup.face_offsets[f + 1]);
    }
    return faces;
}

using Faces = std::vector<std::vector<std::uint32_t>>;

// ----------------------------------------------------------------- node tree and transforms

TEST(ColladaRead, NestedNodesComposeTranslateAndScale) {
    const MeshSoup soup = read_collada(data("collada_nested_nodes.dae"));
    // outer translate (1,2,3), inner scale 2: p' = (1,2,3) + 2p
    expect_positions(soup, {{1, 2, 3}, {3, 2, 3}, {1, 4, 3}});
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 2}}));
    EXPECT_TRUE(soup.notices.empty());
    EXPECT_EQ(soup.unit_meter, 1.0);
}

TEST(ColladaRead, TransformsOfOneNodeApplyInDocumentOrder) {
    // <translate>1 0 0</translate><scale>1 3 1</scale>: p' = T(S p)
    const MeshSoup soup = read_collada(data("collada_transform_order.dae"));
    expect_positions(soup, {{1, 0, 0}, {2, 0, 0}, {1, 3, 0}});
}

TEST(ColladaRead, InstanceNodeWithRotateIsInstancedTwice) {
    const MeshSoup soup = read_collada(data("collada_instance_node.dae"));
    // rotate 90° about z: (x, y) -> (-y, x); the first instance also moves by (10, 0, 0).
    expect_positions(soup, {{10, 0, 0}, {10, 1, 0}, {9, 0, 0}, {0, 0, 0}, {0, 1, 0}, {-1, 0, 0}},
                     1e-15);
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 2}, {3, 4, 5}}));
}

TEST(ColladaRead, MatrixIsRowMajor) {
    // rows (1 0 0 5) (0 0 -1 0) (0 1 0 0): (x, y, z) -> (x + 5, -z, y)
    const MeshSoup soup = read_collada(data("collada_matrix.dae"));
    expect_positions(soup, {{5, 0, 0}, {6, 0, 0}, {5, 0, 1}});
}

TEST(ColladaRead, LookatPlacesNodeAtEyeLookingDownMinusZ) {
    // eye (5,0,0), interest origin, up +y: local x -> (0,0,-1), y -> (0,1,0), z -> (1,0,0).
    const MeshSoup soup = read_collada(data("collada_lookat.dae"));
    expect_positions(soup, {{5, 0, 0}, {5, 0, -1}, {5, 1, 0}});
}

TEST(ColladaRead, SeveralGeometriesAreConcatenated) {
    const MeshSoup soup = read_collada(data("collada_two_geometries.dae"));
    expect_positions(soup,
                     {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {5, 5, 5}});
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 2}, {6, 4, 5}}));
}

// ----------------------------------------------------------------- asset

TEST(ColladaRead, ZUpIsRotatedToYUp) {
    const MeshSoup soup = read_collada(data("collada_z_up.dae"));
    // (x, y, z) -> (x, z, -y)
    expect_positions(soup, {{0, 0, 0}, {1, 0, 0}, {0, 2, -1}});
    ASSERT_EQ(soup.notices.size(), 1u);
    EXPECT_NE(soup.notices[0].find("Z_UP"), std::string::npos);
}

TEST(ColladaRead, XUpIsRotatedToYUp) {
    const MeshSoup soup = read_collada(data("collada_x_up.dae"));
    // (x, y, z) -> (-y, x, z)
    expect_positions(soup, {{0, 0, 0}, {0, 1, 0}, {-1, 0, 2}});
    ASSERT_EQ(soup.notices.size(), 1u);
    EXPECT_NE(soup.notices[0].find("X_UP"), std::string::npos);
}

TEST(ColladaRead, UnitMeterIsRecorded) {
    const MeshSoup soup = read_collada(data("collada_unit.dae"));
    EXPECT_EQ(soup.unit_meter, 0.0254);
    expect_positions(soup, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});  // not scaled
}

// ----------------------------------------------------------------- sources and inputs

TEST(ColladaRead, AccessorStrideFourWithOffset) {
    const MeshSoup soup = read_collada(data("collada_stride4.dae"));
    expect_positions(soup, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
}

TEST(ColladaRead, SharedOffsetsIndexSoupByPosition) {
    const MeshSoup soup = read_collada(data("collada_shared_offsets.dae"));
    expect_positions(soup, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 2}, {0, 2, 3}}));
    ASSERT_EQ(soup.normals.size(), 4u);  // every corner of a position agrees
    for (const Vec3& n : soup.normals) {
        EXPECT_EQ(n, Vec3(0, 0, 1));
    }
}

// ----------------------------------------------------------------- primitives

TEST(ColladaRead, PolylistKeepsQuads) {
    const MeshSoup soup = read_collada(data("collada_polylist.dae"));
    EXPECT_EQ(soup.soup.positions.size(), 8u);
    EXPECT_EQ(soup.soup.positions[3], Vec3(1, 1, -1));
    EXPECT_EQ(
        faces_of(soup.soup),
        (Faces{
            {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}));
    const Mesh mesh = build_mesh(soup.soup);
    EXPECT_EQ(mesh.n_edges(), 12u);
    EXPECT_VALID(mesh);
}

TEST(ColladaRead, PolygonsEachPIsOnePolygon) {
    const MeshSoup soup = read_collada(data("collada_polygons.dae"));
    EXPECT_EQ(soup.soup.positions.size(), 6u);
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 1, 2, 3, 4}, {1, 0, 5}}));
}

TEST(ColladaRead, SeveralPrimitiveBlocksAndIgnoredLines) {
    const MeshSoup soup = read_collada(data("collada_multi_blocks.dae"));
    EXPECT_EQ(soup.soup.positions.size(), 8u);
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 4, 6},
                                          {0, 6, 2},
                                          {1, 3, 7, 5},
                                          {0, 1, 5, 4},
                                          {2, 6, 7, 3},
                                          {0, 2, 3, 1},
                                          {4, 5, 7, 6}}));
    ASSERT_EQ(soup.notices.size(), 1u);
    EXPECT_NE(soup.notices[0].find("ignored 1 <lines> block"), std::string::npos);
    EXPECT_VALID(build_mesh(soup.soup));
}

TEST(ColladaRead, TriangleStripsAndFans) {
    const MeshSoup soup = read_collada(data("collada_strips.dae"));
    // strip 0 2 1 3 3: odd triangles swap their first corners; (1,3,3) only stitches
    EXPECT_EQ(faces_of(soup.soup), (Faces{{0, 2, 1}, {1, 2, 3}, {2, 4, 5}, {2, 5, 3}}));
    EXPECT_TRUE(soup.notices.empty());
    EXPECT_VALID(build_mesh(soup.soup));
}

TEST(ColladaRead, CreaseExtension) {
    const MeshSoup soup = read_collada(data("collada_creases.dae"));
    using Pair = std::pair<std::uint32_t, std::uint32_t>;
    EXPECT_EQ(soup.creases, (std::vector<Pair>{{0, 1}, {2, 3}}));
    EXPECT_EQ(soup.soup.n_faces(), 4u);
}

// ----------------------------------------------------------------- encodings

std::string to_utf16(const std::string& ascii, bool big_endian) {
    std::string out = big_endian ? "\xFE\xFF" : "\xFF\xFE";
    for (char c : ascii) {
        out += big_endian ? std::string{'\0', c} : std::string{c, '\0'};
    }
    return out;
}

std::string utf16_declared(std::string text) {
    const std::string from = "encoding=\"utf-8\"";
    text.replace(text.find(from), from.size(), "encoding=\"UTF-16\"");
    return text;
}

TEST_F(ColladaFiles, Utf16LittleAndBigEndian) {
    const std::string text = utf16_declared(read_text(data("collada_polylist.dae")));
    const MeshSoup expected = read_collada(data("collada_polylist.dae"));
    for (bool big_endian : {false, true}) {
        const fs::path path =
            write_bytes(big_endian ? "be.dae" : "le.dae", to_utf16(text, big_endian));
        const MeshSoup soup = read_collada(path);
        EXPECT_EQ(soup.soup.positions, expected.soup.positions);
        EXPECT_EQ(faces_of(soup.soup), faces_of(expected.soup));
    }
}

TEST_F(ColladaFiles, Utf16ErrorsReportFileLines) {
    const std::string text = utf16_declared(read_text(data("collada_index_range.dae")));
    const fs::path path = write_bytes("le.dae", to_utf16(text, false));
    try {
        read_collada(path);
        FAIL() << "no IoError";
    } catch (const IoError& e) {
        EXPECT_EQ(e.where(), "line 24, <geometry id=\"box\">/<mesh>/<triangles>/<p>");
    }
}

TEST_F(ColladaFiles, Utf8ByteOrderMark) {
    const fs::path path =
        write_bytes("bom.dae", "\xEF\xBB\xBF" + read_text(data("collada_polylist.dae")));
    const MeshSoup soup = read_collada(path);
    EXPECT_EQ(soup.soup.positions.size(), 8u);
    EXPECT_EQ(soup.soup.n_faces(), 6u);
}

// ----------------------------------------------------------------- bad input

// Reads `path` expecting an IoError whose message names the file and holds every `parts`.
::testing::AssertionResult fails_with(const fs::path& path, const std::vector<std::string>& parts) {
    try {
        read_collada(path);
    } catch (const IoError& e) {
        const std::string what = e.what();
        if (what.rfind(path.string() + ": ", 0) != 0) {
            return ::testing::AssertionFailure()
                   << "message does not start with the file: " << what;
        }
        for (const std::string& part : parts) {
            if (what.find(part) == std::string::npos) {
                return ::testing::AssertionFailure() << "\"" << part << "\" missing in: " << what;
            }
        }
        return ::testing::AssertionSuccess() << what;
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure() << "not an IoError: " << e.what();
    }
    return ::testing::AssertionFailure() << "no error";
}

TEST(ColladaErrors, EmptyFile) {
    EXPECT_TRUE(fails_with(data("collada_empty.dae"), {"empty file"}));
}

TEST(ColladaErrors, MissingFile) {
    EXPECT_TRUE(fails_with(data("collada_no_such_file.dae"), {"no such file"}));
}

TEST(ColladaErrors, TruncatedXml) {
    EXPECT_TRUE(fails_with(data("collada_truncated.dae"),
                           {"line 24", "truncated XML: the file ends inside <vcount>"}));
}

TEST_F(ColladaFiles, BinaryGarbage) {
    std::string bytes = "\x89PNG\r\n\x1a\n";
    for (int i = 0; i < 200; ++i) {
        bytes += static_cast<char>((i * 73 + 11) % 256);
    }
    EXPECT_TRUE(fails_with(write_bytes("garbage.dae", bytes), {"line 2", "binary data"}));
}

TEST(ColladaErrors, NotCollada) {
    EXPECT_TRUE(fails_with(data("collada_not_collada.dae"),
                           {"line 2, <mesh>", "no <COLLADA> root element"}));
}

TEST(ColladaErrors, MissingP) {
    EXPECT_TRUE(fails_with(data("collada_missing_p.dae"),
                           {"line 22, <geometry id=\"box\">/<mesh>/<triangles>: missing <p>"}));
}

TEST(ColladaErrors, IndexOutOfRange) {
    EXPECT_TRUE(fails_with(
        data("collada_index_range.dae"),
        {"line 24, <geometry id=\"box\">/<mesh>/<triangles>/<p>: VERTEX index 40 out of range "
         "(3 positions)"}));
}

TEST(ColladaErrors, NanCoordinate) {
    EXPECT_TRUE(fails_with(data("collada_nan.dae"),
                           {"line 10, <geometry id=\"box\">/<mesh>/<source id=\"box-pos\">/"
                            "<float_array id=\"box-pos-array\">",
                            "position 1 has a non-finite coordinate (NaN)"}));
}

TEST(ColladaErrors, InfCoordinate) {
    EXPECT_TRUE(fails_with(data("collada_inf.dae"),
                           {"line 10", "position 2 has a non-finite coordinate (infinity)"}));
}

TEST(ColladaErrors, NotANumber) {
    EXPECT_TRUE(fails_with(data("collada_not_number.dae"),
                           {"line 10", "<float_array", "number 7 \"one\" is not a number"}));
}

TEST(ColladaErrors, PolygonHoles) {
    EXPECT_TRUE(fails_with(data("collada_holes.dae"),
                           {"line 24, <geometry id=\"box\">/<mesh>/<polygons>/<ph>",
                            "holes (<ph>) are not supported"}));
}

TEST(ColladaErrors, HugeCountAttributes) {
    EXPECT_TRUE(fails_with(
        data("collada_huge_count_array.dae"),
        {"<float_array id=\"box-pos-array\">", "count=\"999999999999\" but it holds 12 numbers"}));
    EXPECT_TRUE(fails_with(data("collada_huge_count_accessor.dae"),
                           {"<accessor>", "reads 999999999999 tuples", "(12 numbers)"}));
    EXPECT_TRUE(fails_with(data("collada_huge_count_triangles.dae"),
                           {"<triangles>/<p>", "holds 3 indices, but count=\"999999999999\""}));
}

TEST(ColladaErrors, WrongIndexCountForVcount) {
    EXPECT_TRUE(fails_with(data("collada_wrong_vcount.dae"),
                           {"<polylist>/<p>", "holds 7 indices, but <vcount> lists 8 corners"}));
}

TEST(ColladaErrors, UnknownUrl) {
    EXPECT_TRUE(fails_with(data("collada_unknown_url.dae"),
                           {"<instance_geometry>", "unknown URL \"#nowhere\""}));
}

TEST(ColladaErrors, MissingSource) {
    EXPECT_TRUE(fails_with(data("collada_missing_source.dae"),
                           {"<triangles>/<input>", "unknown URL \"#q-normals\""}));
}

TEST(ColladaErrors, InstanceNodeCycle) {
    EXPECT_TRUE(fails_with(data("collada_cycle.dae"), {"<instance_node>", "cycle"}));
}

// ----------------------------------------------------------------- writer round trips

class ColladaRoundTrip : public ColladaFiles {
protected:
    // Writes `mesh`, reads it back, and checks positions (exactly) and faces.
    MeshSoup round_trip(const Mesh& mesh, const IoFlags& flags = {}) {
        const fs::path path = dir_ / "out.dae";
        write_collada(mesh, path, flags);
        MeshSoup soup = read_collada(path);
        EXPECT_TRUE(std::ranges::equal(soup.soup.positions, mesh.position_vector()));
        const Mesh back = build_mesh(soup.soup);
        EXPECT_EQ(test::canonical_faces(back), test::canonical_faces(mesh));
        EXPECT_TRUE(soup.notices.empty());
        return soup;
    }
};

TEST_F(ColladaRoundTrip, Cube) {
    const MeshSoup soup = round_trip(shapes::cube());
    EXPECT_EQ(soup.normals.size(), 8u);
    EXPECT_TRUE(soup.creases.empty());
}

TEST_F(ColladaRoundTrip, TorusWithoutNormals) {
    const MeshSoup soup = round_trip(shapes::torus(12, 8), IoFlags{.write_normals = false});
    EXPECT_TRUE(soup.normals.empty());
    EXPECT_EQ(read_text(dir_ / "out.dae").find("NORMAL"), std::string::npos);
}

TEST_F(ColladaRoundTrip, QuadSpherePolygons) {
    round_trip(shapes::quad_sphere(3));
}

TEST_F(ColladaRoundTrip, OpenGrid) {
    round_trip(shapes::grid(4, 3));
}

TEST_F(ColladaRoundTrip, Creases) {
    Mesh mesh = shapes::cube();
    auto crease = mesh.add_property<Edge, std::uint8_t>(kCreaseProperty, 0);
    using Pair = std::pair<std::uint32_t, std::uint32_t>;
    std::vector<Pair> expected;
    for (auto [a, b] : {Pair{0, 1}, Pair{1, 3}, Pair{6, 7}}) {
        const Edge e = mesh.find_edge(Vertex(a), Vertex(b));
        ASSERT_TRUE(e.is_valid());
        crease[e] = 1;
        expected.emplace_back(mesh.vertex(e, 0).idx(), mesh.vertex(e, 1).idx());
    }
    std::sort(expected.begin(), expected.end());
    MeshSoup soup = round_trip(mesh);
    std::sort(soup.creases.begin(), soup.creases.end());
    EXPECT_EQ(soup.creases, expected);
}

TEST_F(ColladaRoundTrip, GarbageIsCollectedFirst) {
    Mesh mesh = shapes::icosahedron();
    ASSERT_TRUE(collapse(mesh, Edge(0)).ok());
    ASSERT_TRUE(mesh.has_garbage());
    Mesh compact = mesh;
    compact.garbage_collection();
    const fs::path path = dir_ / "gc.dae";
    write_collada(mesh, path, {});
    const MeshSoup soup = read_collada(path);
    EXPECT_TRUE(std::ranges::equal(soup.soup.positions, compact.position_vector()));
    EXPECT_EQ(test::canonical_faces(build_mesh(soup.soup)), test::canonical_faces(compact));
}

TEST_F(ColladaRoundTrip, DoublesRoundTripExactly) {
    Mesh mesh = shapes::icosahedron();
    for (Vertex v : mesh.vertices()) {
        mesh.position(v) *= 1.0 / 3.0;  // long binary fractions
        mesh.position(v).x += 1e-9 * std::numbers::pi;
    }
    round_trip(mesh);
}

// A mesh whose only texture coordinates are its second set: readers take a file's lowest
// set as the first, so MeshEdit's <extra> says it is the second, and it reads back as such
// (with the material bound to it), bit for bit.
TEST_F(ColladaFiles, AMeshWithOnlyASecondSetReadsBackWithOnlyASecondSet) {
    Mesh mesh = shapes::cube();
    auto uv1 = mesh.add_property<Halfedge, Vec2>(kTexCoord1Property, Vec2{});
    for (const Halfedge h : mesh.halfedges()) {
        uv1[h] = mesh.is_boundary(h) ? Vec2{} : Vec2{0.125 * h.idx(), 1.0 / (1.0 + h.idx())};
    }
    const fs::path path = dir_ / "second.dae";
    write_collada(mesh, path);
    const MeshSoup soup = read_collada(path);
    EXPECT_TRUE(soup.corner_texcoords.empty());
    ASSERT_EQ(soup.corner_texcoords1.size(), soup.soup.indices.size());
    // The soup's corner i of face f is the face's corner at vertex indices[i].
    ASSERT_EQ(soup.soup.n_faces(), mesh.n_faces());
    for (const Face f : mesh.faces()) {
        for (std::uint32_t c = soup.soup.face_offsets[f.idx()];
             c < soup.soup.face_offsets[f.idx() + 1]; ++c) {
            Halfedge at;
            for (const Halfedge h : mesh.halfedges(f)) {
                at = mesh.to_vertex(h).idx() == soup.soup.indices[c] ? h : at;
            }
            ASSERT_TRUE(at.is_valid()) << c;
            EXPECT_EQ(soup.corner_texcoords1[c].x, uv1[at].x) << c;
            EXPECT_EQ(soup.corner_texcoords1[c].y, uv1[at].y) << c;
        }
    }
}

}  // namespace
}  // namespace meshedit
