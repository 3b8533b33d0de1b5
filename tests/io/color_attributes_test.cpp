// Vertex colours (kColorProperty, attributes.h): kept through edits by the attribute carry
// like positions, and through every format that has them with an exact round trip; the
// formats that cannot hold them say so.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "io/formats_test_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/material.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/io/io.h"
#include "support/demo_meshes.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

constexpr Vec4 kRed{1, 0, 0, 1};
constexpr Vec4 kBlue{0, 0, 1, 1};

// A colour that is an affine function of the position: every blend with weights summing to
// one (a split, Loop's stencils) gives the colour of the blended position back.
Vec4 color_at(const Vec3& p) {
    return {0.5 + 0.25 * p.x, 0.5 - 0.25 * p.y, 0.5 + 0.125 * (p.x + p.z), 1.0};
}

// The midpoint of an edge between a red and a blue vertex is their mean.
TEST(ColorAttributes, SplitBlendsTheEndsColours) {
    Mesh mesh = shapes::tetrahedron();
    auto color = mesh.property<Vertex, Vec4>(kColorProperty);
    for (const Vertex v : mesh.vertices()) {
        color[v] = v.idx() == 0 ? kRed : kBlue;
    }
    const Vertex m = *split(mesh, mesh.find_edge(Vertex(0), Vertex(1)));
    color = mesh.get_property<Vertex, Vec4>(kColorProperty);
    EXPECT_EQ(color[m], (Vec4{0.5, 0, 0.5, 1}));
    EXPECT_EQ(color[Vertex(0)], kRed);
    EXPECT_EQ(color[Vertex(1)], kBlue);
}

// Loop gives every vertex its colour by the positions' weights: an affine colour stays the
// same function of the new positions, and stays in [0, 1] (the weights are positive).
TEST(ColorAttributes, LoopKeepsColoursOnThePositionsWeights) {
    Mesh mesh = shapes::icosahedron();
    auto color = mesh.property<Vertex, Vec4>(kColorProperty);
    for (const Vertex v : mesh.vertices()) {
        color[v] = color_at(mesh.position(v));
    }
    loop_subdivide(mesh);
    loop_subdivide(mesh);
    color = mesh.get_property<Vertex, Vec4>(kColorProperty);
    ASSERT_TRUE(color);
    ASSERT_EQ(mesh.n_vertices(), 162u);
    for (const Vertex v : mesh.vertices()) {
        const Vec4 want = color_at(mesh.position(v));
        const Vec4 got = color[v];
        EXPECT_NEAR(got.x, want.x, 1e-12) << v.idx();
        EXPECT_NEAR(got.y, want.y, 1e-12) << v.idx();
        EXPECT_NEAR(got.z, want.z, 1e-12) << v.idx();
        EXPECT_EQ(got.w, 1.0) << v.idx();
        for (const double c : {got.x, got.y, got.z}) {
            EXPECT_TRUE(c >= 0.0 && c <= 1.0) << v.idx();
        }
    }
}

// Everything a format may keep of a mesh's attributes, in element order: each vertex's
// colour, each face's colour and its corners' UVs and normals from halfedge(f).
struct Attributes {
    std::vector<Vec4> colors, face_colors;
    std::vector<Vec2> uvs;
    std::vector<Vec3> normals;
    std::vector<std::uint32_t> face_materials;
    std::vector<Material> materials;
    bool operator==(const Attributes&) const = default;
};

Attributes attributes_of(const Mesh& mesh) {
    Attributes a;
    if (const auto c = mesh.get_property<Vertex, Vec4>(kColorProperty)) {
        a.colors.assign(c.vector().begin(), c.vector().end());
    }
    const auto fc = mesh.get_property<Face, Vec4>(kFaceColorProperty);
    const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const auto n = mesh.get_property<Halfedge, Vec3>(kCornerNormalProperty);
    const auto m = mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
    if (m) {
        a.materials = mesh.materials();
    }
    for (const Face f : mesh.faces()) {
        if (m) {
            a.face_materials.push_back(m[f]);
        }
        if (fc) {
            a.face_colors.push_back(fc[f]);
        }
        for (const Halfedge h : mesh.halfedges(f)) {
            if (uv) {
                a.uvs.push_back(uv[h]);
            }
            if (n) {
                a.normals.push_back(n[h]);
            }
        }
    }
    return a;
}

// Reads `path`, writes it as `ext` (binary and, for PLY, ASCII too), reads that back: the
// attributes come back bit for bit, and a second write gives the same bytes. Returns the
// attributes of the first read.
Attributes expect_round_trip(const fs::path& path, const std::string& ext,
                             const test::ScratchDir& dir) {
    const LoadedMesh first = read_mesh(path);
    const Attributes a = attributes_of(first.mesh);
    for (const bool ascii : {false, true}) {
        SCOPED_TRACE(path.string() + " as " + ext + (ascii ? " ascii" : ""));
        const fs::path out = dir / ("out" + ext);
        const std::vector<std::string> unkept = write_mesh(first.mesh, out, {true, ascii});
        EXPECT_TRUE(unkept.empty()) << unkept.front();
        const LoadedMesh back = read_mesh(out);
        EXPECT_EQ(back.mesh.n_faces(), first.mesh.n_faces());
        EXPECT_TRUE(attributes_of(back.mesh) == a);
        write_mesh(back.mesh, dir / ("again" + ext), {true, ascii});
        EXPECT_EQ(test::slurp(out), test::slurp(dir / ("again" + ext)));
    }
    return a;
}

// The soup a file would hold of a mesh (what the repair verbs edit) keeps its vertex and
// face colours, and building it gives them back.
TEST(ColorAttributes, SoupFromMeshKeepsColours) {
    test::ScratchDir dir;
    test::spit(dir / "c.off",
               "COFF\n4 2 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
               "1 1 0 0 0 255 255\n0 1 0 1 2 3 4\n3 0 1 2 9 8 7 6\n"
               "3 0 2 3 5 4 3 2\n");
    const LoadedMesh loaded = read_mesh(dir / "c.off");
    std::vector<std::string> unkept;
    const MeshSoup soup = soup_from_mesh(loaded.mesh, &unkept);
    EXPECT_TRUE(unkept.empty());
    EXPECT_EQ(soup.colors.size(), 4u);
    EXPECT_EQ(soup.face_colors.size(), 2u);
    const LoadedMesh back = build_loaded_mesh(soup, "soup");
    EXPECT_TRUE(attributes_of(back.mesh) == attributes_of(loaded.mesh));
    EXPECT_EQ(attributes_of(back.mesh).face_colors[1],
              (Vec4{5 / 255.0, 4 / 255.0, 3 / 255.0, 2 / 255.0}));
}

// ------------------------------------------------------------------------- PLY

TEST(ColorAttributes, PlyUcharColoursUvsAndNormalsRoundTripExactly) {
    test::ScratchDir dir;
    test::spit(dir / "c.ply",
               "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
               "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
               "property uchar red\nproperty uchar green\nproperty uchar blue\n"
               "property uchar alpha\nproperty float s\nproperty float t\nelement face 2\n"
               "property list uchar int vertex_indices\nend_header\n"
               "0 0 0 0 0 1 255 0 0 255 0 0\n1 0 0 0 0.6 0.8 0 0 255 128 1 0\n"
               "1 1 0 0 0 1 10 20 30 40 1 1\n0 1 0 1 0 0 0 0 0 0 0 1\n3 0 1 2\n3 0 2 3\n");
    const Attributes a = expect_round_trip(dir / "c.ply", ".ply", dir);
    EXPECT_EQ(a.colors, (std::vector<Vec4>{{1, 0, 0, 1},
                                           {0, 0, 1, 128 / 255.0},
                                           {10 / 255.0, 20 / 255.0, 30 / 255.0, 40 / 255.0},
                                           {0, 0, 0, 0}}));
    EXPECT_EQ(a.uvs.size(), 6u);
    EXPECT_EQ(a.normals.size(), 6u);
    // Written back as uchar, because every value is k/255; the file's normals as they were
    // (an ASCII "0.6" is kept as the double it spells, so written as double).
    const std::string text = test::slurp(dir / "out.ply");
    EXPECT_CONTAINS(text,
                    "property double nx\nproperty double ny\nproperty double nz\n"
                    "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                    "property uchar alpha\nproperty float s\nproperty float t\n");
    EXPECT_CONTAINS(text, "\n1 0 0 0 0.6 0.8 0 0 255 128 1 0\n");
}

// Float colours stay floats; 0 and 1 (assimp's float-color.ply) are k/255 and go as uchar; a
// blended colour that no float holds goes as double, so the round trip stays exact after an
// edit too.
TEST(ColorAttributes, PlyFloatColoursStayExactThroughEdits) {
    test::ScratchDir dir;
    const fs::path file = "/usr/share/assimp/models/PLY/float-color.ply";
    if (fs::exists(file)) {
        const Attributes a = expect_round_trip(file, ".ply", dir);
        EXPECT_EQ(a.colors, std::vector<Vec4>(3, Vec4{0, 0, 1, 1}));
        EXPECT_CONTAINS(test::slurp(dir / "out.ply"), "property uchar red\n");
    }
    test::spit(dir / "f.ply",
               "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
               "property float y\nproperty float z\nproperty float red\nproperty float green\n"
               "property float blue\nelement face 1\nproperty list uchar int vertex_indices\n"
               "end_header\n");
    std::string body;
    const float values[3][6] = {
        {0, 0, 0, 0.1f, 0.5f, 1}, {1, 0, 0, 0.2f, 0.5f, 0}, {0, 1, 0, 0.3f, 0, 0}};
    body.append(reinterpret_cast<const char*>(values), sizeof values);
    const char face[13] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0};
    body.append(face, sizeof face);
    test::spit(dir / "f.ply", test::slurp(dir / "f.ply") + body);
    const Attributes a = expect_round_trip(dir / "f.ply", ".ply", dir);
    EXPECT_EQ(a.colors[1], (Vec4{double{0.2f}, 0.5, 0, 1}));
    EXPECT_CONTAINS(test::slurp(dir / "out.ply"), "property float red\n");

    LoadedMesh loaded = read_mesh(dir / "f.ply");
    const Vertex m = *split(loaded.mesh, loaded.mesh.find_edge(Vertex(0), Vertex(1)));
    const auto color = loaded.mesh.get_property<Vertex, Vec4>(kColorProperty);
    EXPECT_EQ(color[m], (Vec4{0.5 * double{0.1f} + 0.5 * double{0.2f}, 0.5, 0.5, 1}));
    write_mesh(loaded.mesh, dir / "split.ply");
    EXPECT_CONTAINS(test::slurp(dir / "split.ply"), "property double red\n");
    EXPECT_TRUE(attributes_of(read_mesh(dir / "split.ply").mesh) == attributes_of(loaded.mesh));
}

// MeshLab's per-corner UVs (a face texcoord list) keep their seams, in both encodings.
TEST(ColorAttributes, PlyFaceTexcoordListsKeepSeams) {
    test::ScratchDir dir;
    test::spit(dir / "t.ply",
               "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
               "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
               "property list uchar float texcoord\nend_header\n"
               "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2 6 0 0 1 0 1 1\n3 0 2 3 6 0.5 0.5 1 1 0 1\n");
    const Attributes a = expect_round_trip(dir / "t.ply", ".ply", dir);
    EXPECT_EQ(a.uvs.size(), 6u);
    EXPECT_CONTAINS(test::slurp(dir / "out.ply"), "property list uchar float texcoord\n");
    // A seam: vertex 0 has (0, 0) in one face and (0.5, 0.5) in the other.
    const LoadedMesh loaded = read_mesh(dir / "t.ply");
    const auto uv = loaded.mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    std::vector<Vec2> at_zero;
    for (const Halfedge h : loaded.mesh.halfedges()) {
        if (!loaded.mesh.is_boundary(h) && loaded.mesh.to_vertex(h) == Vertex(0)) {
            at_zero.push_back(uv[h]);
        }
    }
    ASSERT_EQ(at_zero.size(), 2u);
    EXPECT_NE(at_zero[0], at_zero[1]);
}

// Bad values drop only that attribute, with one line naming where; the mesh loads.
TEST(ColorAttributes, PlyBadColoursAndUvsAreNamedAndDropped) {
    test::ScratchDir dir;
    test::spit(dir / "n.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nproperty float red\nproperty float green\nproperty float "
               "blue\nelement face 1\nproperty list uchar int vertex_indices\n"
               "property list uchar float texcoord\nend_header\n"
               "0 0 0 1 0 0\n1 0 0 nan 0 0\n0 1 0 0 0 1\n3 0 1 2 4 0 0 1 0\n");
    const LoadedMesh loaded = read_mesh(dir / "n.ply");
    EXPECT_EQ(loaded.mesh.n_faces(), 1u);
    EXPECT_FALSE(loaded.mesh.has_property<Vertex>(kColorProperty));
    EXPECT_FALSE(loaded.mesh.has_property<Halfedge>(kTexCoordProperty));
    EXPECT_EQ(loaded.notices,
              (std::vector<std::string>{
                  "vertex colours not kept: vertex 1's red is not a number; the mesh loads "
                  "without colours",
                  "per-corner texture coordinates (face.texcoord) not kept: face 0 (line 17) has "
                  "4 texcoord values for 3 corners; the mesh loads without them"}));
}

// assimp's PLY files with colours, UVs and normals keep them through PLY.
TEST(ColorAttributes, AssimpPlyFilesRoundTripExactly) {
    const fs::path models = "/usr/share/assimp/models/PLY";
    if (!fs::is_directory(models)) {
        GTEST_SKIP() << "install assimp-testmodels (scripts/install-deps.sh does)";
    }
    test::ScratchDir dir;
    const Attributes uv = expect_round_trip(models / "cube_uv.ply", ".ply", dir);
    EXPECT_EQ(uv.uvs.size(), 24u);
    const Attributes wuson = expect_round_trip(models / "Wuson.ply", ".ply", dir);
    EXPECT_EQ(wuson.uvs.size(), 3u * 3732u);
}

// ------------------------------------------------------------------------- OFF

// COFF as CGAL writes it (integers 0–255 with alpha) comes back as the same integers.
TEST(ColorAttributes, OffIntegerColoursRoundTripExactly) {
    test::ScratchDir dir;
    test::spit(dir / "c.off",
               "COFF\n4 2 0\n0 0 0 192 192 192 255\n1 0 0 255 0 0 128\n1 1 0 0 0 0 0\n"
               "0 1 0 1 2 3 4\n3 0 1 2\n3 0 2 3\n");
    const Attributes a = expect_round_trip(dir / "c.off", ".off", dir);
    EXPECT_EQ(a.colors, (std::vector<Vec4>{{192 / 255.0, 192 / 255.0, 192 / 255.0, 1},
                                           {1, 0, 0, 128 / 255.0},
                                           {0, 0, 0, 0},
                                           {1 / 255.0, 2 / 255.0, 3 / 255.0, 4 / 255.0}}));
    EXPECT_EQ(test::slurp(dir / "out.off"),
              "COFF\n4 2 5\n0 0 0 192 192 192 255\n1 0 0 255 0 0 128\n1 1 0 0 0 0 0\n"
              "0 1 0 1 2 3 4\n3 0 1 2\n3 0 2 3\n");
}

// Decimal colours of three values (alpha 1), normals, texture coordinates and face colours
// together: STCNOFF, each in Geomview's order on the vertex line.
TEST(ColorAttributes, OffDecimalColoursNormalsUvsAndFaceColours) {
    test::ScratchDir dir;
    test::spit(dir / "a.off",
               "STCNOFF\n3 1 0\n0 0 0 0 0 1 0.9 0 0 0.25 0.5\n1 0 0 0 0.6 0.8 0 0 0.9 1 0\n"
               "0 1 0 1 0 0 0.5 0.5 0.5 0 1\n3 0 1 2 0.1 0.2 0.3 0.4\n");
    const Attributes a = expect_round_trip(dir / "a.off", ".off", dir);
    EXPECT_EQ(a.colors, (std::vector<Vec4>{{0.9, 0, 0, 1}, {0, 0, 0.9, 1}, {0.5, 0.5, 0.5, 1}}));
    EXPECT_EQ(a.face_colors, (std::vector<Vec4>{{0.1, 0.2, 0.3, 0.4}}));
    EXPECT_EQ(a.normals.size(), 3u);
    EXPECT_EQ(a.uvs.size(), 3u);
    EXPECT_EQ(test::slurp(dir / "out.off"),
              "STCNOFF\n3 1 3\n0 0 0 0 0 1 0.9 0 0 1 0.25 0.5\n1 0 0 0 0.6 0.8 0 0 0.9 1 1 0\n"
              "0 1 0 1 0 0 0.5 0.5 0.5 1 0 1\n3 0 1 2 0.1 0.2 0.3 0.4\n");
}

// Bad colours or texture coordinates drop that attribute with one line naming the line; the
// mesh still loads. Formats without colours say they drop them.
TEST(ColorAttributes, OffBadValuesAreNamedAndDropped) {
    test::ScratchDir dir;
    test::spit(dir / "n.off",
               "STCOFF\n3 1 0\n0 0 0 1 0 0 1 0 0\n1 0 0 nan 0 0 1 1 0\n"
               "0 1 0 0 0 1 1 0 x\n3 0 1 2\n");
    const LoadedMesh n = read_mesh(dir / "n.off");
    EXPECT_EQ(n.mesh.n_faces(), 1u);
    EXPECT_FALSE(n.mesh.has_property<Vertex>(kColorProperty));
    EXPECT_FALSE(n.mesh.has_property<Halfedge>(kTexCoordProperty));
    EXPECT_EQ(n.notices, (std::vector<std::string>{
                             "vertex colours not kept: vertex 1 (line 4) has a colour value that "
                             "is not a number ('nan'); the mesh loads without them",
                             "texture coordinates not kept: vertex 2 (line 5) has no two numbers "
                             "for its texture coordinates; the mesh loads without them"}));
    test::spit(dir / "w.off", "COFF\n3 1 0\n0 0 0 1 0\n1 0 0 0 0 1\n0 1 0 0 1 0\n3 0 1 2\n");
    EXPECT_EQ(read_mesh(dir / "w.off").notices,
              (std::vector<std::string>{"vertex colours not kept: vertex 0 (line 3) has 2 colour "
                                        "values (3 or 4 expected); the mesh loads without them"}));

    test::spit(dir / "c.off",
               "COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0 0 1 0\n0 1 0 0 0 1\n3 0 1 2 0 0 1\n");
    const std::vector<std::string> unkept =
        write_mesh(read_mesh(dir / "c.off").mesh, dir / "c.stl");
    ASSERT_EQ(unkept.size(), 2u);
    EXPECT_CONTAINS(unkept[0], "vertex colours (STL has no colours; ");
    EXPECT_EQ(unkept[1], "face colours (only OFF keeps them)");
}

// Real files: CGAL's coloured OFFs (integers with alpha; decimals without, face colours)
// and assimp's OFFs keep everything through OFF, and their vertex colours through PLY.
TEST(ColorAttributes, RealOffFilesRoundTripExactly) {
    test::ScratchDir dir;
    if (fs::exists(test::kDemoDataTarball)) {
        const fs::path data = fs::path(MESHEDIT_BUILD_DIR) / "demo_data";
        const Attributes cactus = expect_round_trip(test::demo_mesh("cactus", data), ".off", dir);
        EXPECT_EQ(cactus.colors.size(), 620u);
        EXPECT_EQ(cactus.colors[0], (Vec4{192 / 255.0, 192 / 255.0, 192 / 255.0, 1}));
        const fs::path mixed = test::demo_mesh("mesh_with_colors", data);
        const Attributes m = expect_round_trip(mixed, ".off", dir);
        EXPECT_EQ(m.colors[0], (Vec4{0.9, 0, 0, 1}));
        EXPECT_EQ(m.face_colors.size(), 4u);
        EXPECT_EQ(m.face_colors[3], (Vec4{0, 0, 0.9, 1}));
        const LoadedMesh off = read_mesh(test::demo_mesh("cactus", data));
        write_mesh(off.mesh, dir / "cactus.ply");
        EXPECT_EQ(attributes_of(read_mesh(dir / "cactus.ply").mesh).colors, cactus.colors);
    }
    const fs::path models = "/usr/share/assimp/models/OFF";
    if (fs::is_directory(models)) {
        for (const char* name : {"Wuson.off", "Cube.off"}) {
            const Attributes a = expect_round_trip(models / name, ".off", dir);
            EXPECT_TRUE(a.colors.empty());
        }
    }
}

// ------------------------------------------------------------------------- glTF

// COLOR_0 as normalized bytes when every colour is k/255 (an OFF of CGAL's integers), shorts
// when k/65535, else floats: each reads back bit for bit, through the seams that split glTF
// vertices.
TEST(ColorAttributes, GltfColoursRoundTripExactly) {
    test::ScratchDir dir;
    test::spit(dir / "c.off",
               "COFF\n4 2 0\n0 0 0 192 192 192 255\n1 0 0 255 0 0 128\n1 1 0 0 0 0 0\n"
               "0 1 0 1 2 3 4\n3 0 1 2\n3 0 2 3\n");
    Mesh mesh = read_mesh(dir / "c.off").mesh;
    const Attributes bytes = attributes_of(mesh);
    auto uv = mesh.property<Halfedge, Vec2>(kTexCoordProperty);
    for (const Halfedge h : mesh.halfedges()) {
        uv[h] = Vec2{h.idx() / 8.0, 0.5};  // a seam at every vertex
    }
    for (const char* name : {"c.gltf", "c.glb"}) {
        SCOPED_TRACE(name);
        EXPECT_TRUE(write_mesh(mesh, dir / name).empty());
        EXPECT_EQ(attributes_of(read_mesh(dir / name).mesh).colors, bytes.colors);
    }
    auto color = mesh.get_property<Vertex, Vec4>(kColorProperty);
    color[Vertex(1)] = Vec4{1000 / 65535.0, 0, 1, 1};
    write_mesh(mesh, dir / "s.glb");
    EXPECT_EQ(attributes_of(read_mesh(dir / "s.glb").mesh).colors, attributes_of(mesh).colors);
    for (const Vertex v : mesh.vertices()) {
        color[v] = Vec4{double{0.1f * static_cast<float>(v.idx())}, 0.25, 1, 1};
    }
    write_mesh(mesh, dir / "f.gltf");
    EXPECT_EQ(attributes_of(read_mesh(dir / "f.gltf").mesh).colors, attributes_of(mesh).colors);
}

// ------------------------------------------------------------------------- OBJ

// The common extension `v x y z r g b` (assimp's cube_with_vertexcolors.obj), alpha only when
// one is not 1; a colour on some vertices only, or one not a number, drops them with a line.
TEST(ColorAttributes, ObjVertexColoursRoundTripExactly) {
    test::ScratchDir dir;
    test::spit(dir / "c.obj",
               "v 0 0 0 1 0 0\nv 1 0 0 0 0.5 1 0.25\nv 0 1 0 0.1 0.2 0.3\nf 1 2 3\n");
    const Attributes a = expect_round_trip(dir / "c.obj", ".obj", dir);
    EXPECT_EQ(a.colors, (std::vector<Vec4>{{1, 0, 0, 1}, {0, 0.5, 1, 0.25}, {0.1, 0.2, 0.3, 1}}));
    EXPECT_CONTAINS(test::slurp(dir / "out.obj"), "v 1 0 0 0 0.5 1 0.25\n");

    const fs::path cube = "/usr/share/assimp/models/OBJ/cube_with_vertexcolors.obj";
    if (fs::exists(cube)) {
        const Attributes c = expect_round_trip(cube, ".obj", dir);
        ASSERT_EQ(c.colors.size(), 8u);
        EXPECT_EQ(c.colors[7], (Vec4{0.09020, 0, 0.78431, 1}));
        // And through every other format that keeps colours.
        const Mesh mesh = read_mesh(cube).mesh;
        for (const char* name : {"c.ply", "c.off"}) {
            write_mesh(mesh, dir / name);
            EXPECT_EQ(attributes_of(read_mesh(dir / name).mesh).colors, c.colors) << name;
        }
    }

    test::spit(dir / "m.obj", "v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
    const LoadedMesh m = read_mesh(dir / "m.obj");
    EXPECT_FALSE(m.mesh.has_property<Vertex>(kColorProperty));
    EXPECT_EQ(m.notices, (std::vector<std::string>{"vertex colours not kept: vertex 2 (line 2) "
                                                   "has none; the mesh loads without them"}));
    test::spit(dir / "n.obj", "v 0 0 0 1 0 0\nv 1 0 0 nan 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
    EXPECT_EQ(read_mesh(dir / "n.obj").notices,
              (std::vector<std::string>{"vertex colours not kept: vertex 2 (line 2) has a colour "
                                        "value that is not a number; the mesh loads without "
                                        "them"}));
}

// --------------------------------------------------------------------- COLLADA

// Texture coordinates and normals per corner with their own indices, colours per vertex,
// materials with their effect's diffuse colour or texture: assimp's COLLADA files read,
// write and read back bit for bit.
TEST(ColorAttributes, ColladaFilesRoundTripExactly) {
    const fs::path models = "/usr/share/assimp/models/Collada";
    if (!fs::is_directory(models)) {
        GTEST_SKIP() << "install assimp-testmodels (scripts/install-deps.sh does)";
    }
    test::ScratchDir dir;
    const Attributes duck = expect_round_trip(models / "duck.dae", ".dae", dir);
    EXPECT_EQ(duck.uvs.size(), duck.normals.size());
    ASSERT_EQ(duck.materials.size(), 1u);
    // The texture's path as read: the file beside it (the writer wrote it relative to the
    // scratch folder, the second read resolved it back).
    EXPECT_EQ(duck.materials[0].base_colour_texture, (models / "duckCM.tga").string());

    const Attributes colours = expect_round_trip(models / "kwxport_test_vcolors.dae", ".dae", dir);
    EXPECT_EQ(colours.colors.size(), 8u);
    EXPECT_EQ(colours.colors[0], (Vec4{1, 0, 0, 1}));
    ASSERT_EQ(colours.materials.size(), 3u);
    EXPECT_EQ(colours.materials[0].name, "bottom");
    EXPECT_EQ(colours.materials[0].base_colour_texture,
              (models.parent_path() / "X/bottom.tga").string());
    EXPECT_FALSE(colours.uvs.empty());

    // earthCylindrical.DAE writes decimal commas ("-7,589569", <unit meter="0,010000">, its
    // exporter's locale): read as points, said in one line; its texture is written
    // "\..\LWO\LWO2\MappingModes\EarthCylindric.jpg" and is ../LWO/LWO2/MappingModes/
    // earthCylindric.jpg beside the file.
    const LoadedMesh earth = read_mesh(models / "earthCylindrical.DAE");
    EXPECT_EQ(earth.unit_meter, 0.01);
    EXPECT_EQ(earth.mesh.n_faces(), 1920u);
    EXPECT_NE(std::find(earth.notices.begin(), earth.notices.end(),
                        "read numbers written with decimal commas (\"0,5\", the exporter's "
                        "locale) as decimal points"),
              earth.notices.end());
    ASSERT_FALSE(earth.mesh.materials().empty());
    EXPECT_EQ(earth.mesh.materials()[0].base_colour_texture,
              (models.parent_path() / "LWO/LWO2/MappingModes/earthCylindric.jpg").string());

    // Every file of the package that loads (the others hold no mesh).
    std::size_t loaded = 0, with_uvs = 0;
    for (const auto& entry : fs::directory_iterator(models)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".dae" && ext != ".DAE") {
            continue;
        }
        try {
            read_mesh(entry.path());
        } catch (const IoError&) {
            continue;
        }
        ++loaded;
        with_uvs += expect_round_trip(entry.path(), ".dae", dir).uvs.empty() ? 0 : 1;
    }
    EXPECT_EQ(loaded, 22u);
    EXPECT_EQ(with_uvs, 12u);
}

// A triangle whose TEXCOORD index is past its source and whose colour is not a number: the
// mesh loads without them, each named in one line with the place.
TEST(ColorAttributes, ColladaBadUvIndicesAndColoursAreNamedAndDropped) {
    test::ScratchDir dir;
    test::spit(dir / "bad.dae",
               "<?xml version=\"1.0\"?>\n<COLLADA version=\"1.4.1\">\n"
               "<library_geometries><geometry id=\"g\"><mesh>\n"
               "<source id=\"p\"><float_array id=\"pa\" count=\"9\">0 0 0 1 0 0 0 1 0"
               "</float_array><technique_common><accessor source=\"#pa\" count=\"3\" "
               "stride=\"3\"><param name=\"X\" type=\"float\"/><param name=\"Y\" "
               "type=\"float\"/><param name=\"Z\" type=\"float\"/></accessor>"
               "</technique_common></source>\n"
               "<source id=\"t\"><float_array id=\"ta\" count=\"2\">0.5 0.5</float_array>"
               "<technique_common><accessor source=\"#ta\" count=\"1\" stride=\"2\"><param "
               "name=\"S\" type=\"float\"/><param name=\"T\" type=\"float\"/></accessor>"
               "</technique_common></source>\n"
               "<source id=\"c\"><float_array id=\"ca\" count=\"3\">1 nan 0</float_array>"
               "<technique_common><accessor source=\"#ca\" count=\"1\" stride=\"3\"><param "
               "name=\"R\" type=\"float\"/><param name=\"G\" type=\"float\"/><param "
               "name=\"B\" type=\"float\"/></accessor></technique_common></source>\n"
               "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/></vertices>\n"
               "<triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" "
               "offset=\"0\"/><input semantic=\"TEXCOORD\" source=\"#t\" offset=\"1\"/>"
               "<input semantic=\"COLOR\" source=\"#c\" offset=\"2\"/>\n"
               "<p>0 0 0 1 0 0 2 7 0</p></triangles>\n"
               "</mesh></geometry></library_geometries>\n"
               "<scene/></COLLADA>\n");
    const LoadedMesh loaded = read_mesh(dir / "bad.dae");
    EXPECT_EQ(loaded.mesh.n_faces(), 1u);
    EXPECT_FALSE(loaded.mesh.has_property<Halfedge>(kTexCoordProperty));
    EXPECT_FALSE(loaded.mesh.has_property<Vertex>(kColorProperty));
    const std::string at = "line 9, <geometry id=\"g\">/<mesh>/<triangles>/<p>";
    EXPECT_EQ(loaded.notices,
              (std::vector<std::string>{"no <visual_scene>: loaded every <geometry> untransformed",
                                        "vertex colours not kept: " + at +
                                            " names one that is not a number; "
                                            "texture coordinates not kept: " +
                                            at +
                                            " names TEXCOORD index 7 of 1 entries; "
                                            "the mesh loads without them"}));
}

}  // namespace
}  // namespace meshedit
