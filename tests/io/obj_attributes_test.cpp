// Texture coordinates, normals and materials through OBJ (attributes.h, mtl.h): read per
// corner, kept through edits by the attribute carry, written back exactly; the formats that
// cannot keep them yet say so.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "io/formats_test_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/io.h"
#include "meshedit/io/obj.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

// A textured quad of two materials, split normals on one corner, and a library with a
// texture, a colour, an opacity and lines MeshEdit has no meaning for.
const char* kQuadObj =
    "mtllib quad.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.25 0.5\n"
    "vn 0 0 1\nvn 0 1 0\n"
    "usemtl red paint\n"
    "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
    "usemtl wood\n"
    "f 2/5/2 5/1/1 3/3/1\n";
const char* kQuadMtl =
    "newmtl red paint\nKd 1 0 0\nd 0.5\nKs 0.1 0.1 0.1\nillum 2\n"
    "newmtl wood\nKd 0.5 0.25 0\nmap_Kd wood.png\n";

// The quad, its library and its texture in `dir`.
void write_quad(const test::ScratchDir& dir, bool with_library = true) {
    test::spit(dir / "quad.obj", kQuadObj);
    if (with_library) {
        test::spit(dir / "quad.mtl", kQuadMtl);
        test::spit(dir / "wood.png", "not really a png");
    }
}

struct Corner {
    Vec3 at;  // the corner's vertex position
    Vec2 uv;
    Vec3 normal;
    bool operator==(const Corner& o) const = default;
    bool operator<(const Corner& o) const {
        return std::tie(at.x, at.y, at.z, uv.x, uv.y, normal.x, normal.y, normal.z) <
               std::tie(o.at.x, o.at.y, o.at.z, o.uv.x, o.uv.y, o.normal.x, o.normal.y, o.normal.z);
    }
};

// Every face corner with its values, and the material name of every face, order-free.
std::multiset<Corner> corners_of(const Mesh& mesh) {
    const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const auto n = mesh.get_property<Halfedge, Vec3>(kCornerNormalProperty);
    std::multiset<Corner> out;
    for (const Face f : mesh.faces()) {
        for (const Halfedge h : mesh.halfedges(f)) {
            out.insert({mesh.position(mesh.to_vertex(h)), uv ? uv[h] : Vec2{}, n ? n[h] : Vec3{}});
        }
    }
    return out;
}

std::multiset<std::string> face_materials(const Mesh& mesh) {
    const auto m = mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
    std::multiset<std::string> out;
    for (const Face f : mesh.faces()) {
        out.insert(m ? mesh.materials()[m[f]].name : "");
    }
    return out;
}

TEST(ObjAttributes, TexCoordsNormalsAndMaterialsAreReadPerCorner) {
    test::ScratchDir dir;
    write_quad(dir);
    const LoadedMesh loaded = read_mesh(dir / "quad.obj");
    const Mesh& mesh = loaded.mesh;
    EXPECT_TRUE(loaded.notices.empty()) << loaded.notices.front();
    const std::multiset<Corner> expected = {
        {{0, 0, 0}, {0, 0}, {0, 0, 1}},      {{1, 0, 0}, {1, 0}, {0, 0, 1}},
        {{1, 1, 0}, {1, 1}, {0, 0, 1}},      {{0, 1, 0}, {0, 1}, {0, 0, 1}},
        {{1, 0, 0}, {0.25, 0.5}, {0, 1, 0}}, {{2, 0, 0}, {0, 0}, {0, 0, 1}},
        {{1, 1, 0}, {1, 1}, {0, 0, 1}}};
    EXPECT_EQ(corners_of(mesh), expected);
    EXPECT_EQ(face_materials(mesh), (std::multiset<std::string>{"red paint", "wood"}));
    ASSERT_EQ(mesh.materials().size(), 2u);
    const Material& red = mesh.materials()[0];
    EXPECT_EQ(red.base_colour, Vec3(1, 0, 0));
    EXPECT_EQ(red.opacity, 0.5);
    EXPECT_EQ(red.other, (std::vector<std::string>{"Ks 0.1 0.1 0.1", "illum 2"}));
    EXPECT_EQ(mesh.materials()[1].base_colour_texture,
              fs::absolute(dir / "wood.png").lexically_normal().string());
}

TEST(ObjAttributes, RoundTripKeepsEveryCornerAndMaterialExactly) {
    test::ScratchDir dir;
    write_quad(dir);
    const LoadedMesh first = read_mesh(dir / "quad.obj");
    fs::create_directory(dir / "out");
    EXPECT_TRUE(write_mesh(first.mesh, dir / "out" / "copy.obj").empty());
    ASSERT_TRUE(fs::exists(dir / "out" / "copy.mtl"));
    // The texture is found from the new folder.
    EXPECT_NE(test::slurp(dir / "out" / "copy.mtl").find("map_Kd ../wood.png"), std::string::npos);
    const LoadedMesh second = read_mesh(dir / "out" / "copy.obj");
    EXPECT_EQ(corners_of(second.mesh), corners_of(first.mesh));
    EXPECT_EQ(face_materials(second.mesh), face_materials(first.mesh));
    EXPECT_EQ(second.mesh.materials(), first.mesh.materials());
    // And the second write is the first, byte for byte.
    write_mesh(second.mesh, dir / "out" / "again.obj");
    std::string a = test::slurp(dir / "out" / "copy.obj");
    std::string b = test::slurp(dir / "out" / "again.obj");
    a.replace(a.find("copy.mtl"), 8, "again.mtl");
    EXPECT_EQ(a, b);
}

// The attribute carry: a split's new corners blend the corners at the edge's ends.
TEST(ObjAttributes, EditsCarryTexCoordsAndMaterials) {
    test::ScratchDir dir;
    write_quad(dir);
    LoadedMesh loaded = read_mesh(dir / "quad.obj");
    Mesh& mesh = loaded.mesh;
    const Edge e = mesh.find_edge(Vertex(0), Vertex(1));  // the quad's bottom, uv (0,0)-(1,0)
    const Vertex m = *split(mesh, e);
    const auto uv = mesh.get_property<Halfedge, Vec2>(kTexCoordProperty);
    for (const Halfedge out : mesh.halfedges(m)) {
        const Halfedge in = Mesh::twin(out);  // the corner at m of face(in)
        if (!mesh.is_boundary(in)) {
            EXPECT_EQ(uv[in], (Vec2{0.5, 0})) << in.idx();
        }
    }
    // The quad gained a corner (split divides only triangles); a poke makes five parts of it.
    EXPECT_EQ(face_materials(mesh), (std::multiset<std::string>{"red paint", "wood"}));
    Face quad;
    for (const Face f : mesh.faces(m)) {
        quad = mesh.valence(f) == 5 ? f : quad;
    }
    ASSERT_TRUE(quad.is_valid());
    ASSERT_TRUE(poke(mesh, quad));
    EXPECT_EQ(face_materials(mesh),
              (std::multiset<std::string>{"red paint", "red paint", "red paint", "red paint",
                                          "red paint", "wood"}));
}

// glTF keeps them too: corners by a vertex per distinct corner (welded back on reading), a
// primitive per material; a .gltf names the texture, a .glb embeds it.
TEST(ObjAttributes, GltfKeepsThemAndWeldsItsSeamsBack) {
    test::ScratchDir dir;
    write_quad(dir);
    const LoadedMesh obj = read_mesh(dir / "quad.obj");
    for (const char* name : {"q.gltf", "q.glb"}) {
        SCOPED_TRACE(name);
        EXPECT_EQ(write_mesh(obj.mesh, dir / name),
                  std::vector<std::string>{"1 polygon (glTF stores triangles: each is fanned)"});
        const LoadedMesh back = read_mesh(dir / name);
        EXPECT_EQ(back.mesh.n_vertices(), obj.mesh.n_vertices());  // seams welded back
        EXPECT_EQ(back.mesh.n_edges(), obj.mesh.n_edges() + 1);    // the quad is fanned
        std::multiset<std::string> expected = {"red paint", "red paint", "wood"};
        EXPECT_EQ(face_materials(back.mesh), expected);
        std::multiset<std::pair<double, double>> uvs;
        for (const Corner& c : corners_of(back.mesh)) {
            uvs.insert({c.uv.x, c.uv.y});
        }
        // The quad fanned from its first corner, and the triangle.
        EXPECT_EQ(
            uvs, (std::multiset<std::pair<double, double>>{
                     {0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}, {0.25, 0.5}, {0, 0}, {1, 1}}));
        const std::vector<Material>& m = back.mesh.materials();
        ASSERT_EQ(m.size(), 2u);
        EXPECT_EQ(m[0].base_colour, Vec3(1, 0, 0));
        EXPECT_EQ(m[0].opacity, 0.5);
        if (std::string(name) == "q.gltf") {
            EXPECT_EQ(m[1].base_colour_texture, obj.mesh.materials()[1].base_colour_texture);
        } else {
            EXPECT_TRUE(test::slurp(dir / name).find("image/png") != std::string::npos);
        }
    }
}

// glTF's texture v runs down the image, OBJ's (and MeshEdit's) up. assimp, an independent
// reader, converts BoxTextured.gltf to OBJ; MeshEdit reading the glTF must give that OBJ's
// corners (a reader that kept glTF's v would show every texture upside down after a
// conversion).
TEST(ObjAttributes, GltfTexcoordsAreThoseAssimpWritesToObj) {
    const fs::path gltf = "/usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf";
    if (!fs::exists(gltf)) {
        GTEST_SKIP() << "install assimp-testmodels (scripts/install-deps.sh does)";
    }
    test::ScratchDir dir;
    const fs::path obj = dir / "box.obj";
    const std::string command =
        "assimp export '" + gltf.string() + "' '" + obj.string() + "' > /dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    // assimp prints 8 significant digits: compare on a 1e-5 grid.
    const auto rounded = [](const Mesh& mesh) {
        std::multiset<std::vector<long>> out;
        for (const Corner& c : corners_of(mesh)) {
            std::vector<long> key;
            for (const double x : {c.at.x, c.at.y, c.at.z, c.uv.x, c.uv.y}) {
                key.push_back(std::lround(x * 1e5));
            }
            out.insert(key);
        }
        return out;
    };
    const Mesh ours = read_mesh(gltf).mesh;
    ASSERT_TRUE(ours.has_property<Halfedge>(kTexCoordProperty));
    EXPECT_EQ(rounded(ours), rounded(read_mesh(obj).mesh));
}

// An image a .glb embeds is kept as its bytes: written back embedded by .glb, as a data: URI
// by .gltf, the same material bit for bit when read again; OBJ, which names texture files,
// says it cannot keep it.
TEST(ObjAttributes, EmbeddedTexturesGoBackIntoGltf) {
    const fs::path glb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!fs::exists(glb)) {
        GTEST_SKIP() << "install assimp-testmodels (scripts/install-deps.sh does)";
    }
    const LoadedMesh box = read_mesh(glb);
    ASSERT_EQ(box.mesh.materials().size(), 1u);
    const Material& m = box.mesh.materials()[0];
    EXPECT_EQ(m.base_colour_texture, "Texture.png");
    EXPECT_EQ(m.base_colour_texture_bytes.substr(1, 3), "PNG");
    for (const std::string& notice : box.notices) {
        EXPECT_EQ(notice.find("not kept"), std::string::npos) << notice;
    }
    test::ScratchDir dir;
    for (const char* name : {"b.glb", "b.gltf"}) {
        SCOPED_TRACE(name);
        EXPECT_TRUE(write_mesh(box.mesh, dir / name).empty());
        const LoadedMesh back = read_mesh(dir / name);
        EXPECT_EQ(back.mesh.materials(), box.mesh.materials());
        EXPECT_EQ(corners_of(back.mesh), corners_of(box.mesh));
    }
    EXPECT_NE(test::slurp(dir / "b.gltf").find("\"data:image/png;base64,"), std::string::npos);
    const std::vector<std::string> unkept = write_mesh(box.mesh, dir / "b.obj");
    ASSERT_EQ(unkept.size(), 1u);
    EXPECT_EQ(unkept[0],
              "the embedded texture Texture.png of material 'Texture' (OBJ names texture files; "
              ".glb and .gltf embed it)");
}

TEST(ObjAttributes, FormatsThatCannotKeepThemSaySo) {
    test::ScratchDir dir;
    write_quad(dir);
    const LoadedMesh loaded = read_mesh(dir / "quad.obj");
    const std::vector<std::string> unkept = write_mesh(loaded.mesh, dir / "q.ply");
    // PLY keeps the UVs (seams as face texcoord lists), not the split normals nor materials.
    ASSERT_EQ(unkept.size(), 2u);
    EXPECT_NE(unkept[0].find("normals"), std::string::npos) << unkept[0];
    EXPECT_NE(unkept[1].find("2 material(s)"), std::string::npos) << unkept[1];
    // Normals that are what MeshEdit computes anyway are not kept, so a cube written with its
    // computed normals reads back without any: nothing to warn about.
    write_mesh(shapes::cube(), dir / "cube.obj");
    const LoadedMesh cube = read_mesh(dir / "cube.obj");
    EXPECT_FALSE(cube.mesh.has_property<Halfedge>(kCornerNormalProperty));
    EXPECT_TRUE(write_mesh(cube.mesh, dir / "cube.ply").empty());
}

TEST(ObjAttributes, MissingLibraryAndBadIndicesAreNamed) {
    test::ScratchDir dir;
    write_quad(dir, false);
    const LoadedMesh loaded = read_mesh(dir / "quad.obj");
    ASSERT_EQ(loaded.notices.size(), 1u);
    EXPECT_EQ(loaded.notices[0],
              "material library 'quad.mtl' not found: material names kept, colours and textures "
              "not");
    EXPECT_EQ(face_materials(loaded.mesh), (std::multiset<std::string>{"red paint", "wood"}));
    // Written back, the materials keep their names and get no colour the file never had; a
    // second round trip changes nothing.
    fs::create_directory(dir / "out");
    write_mesh(loaded.mesh, dir / "out" / "quad.obj");
    EXPECT_EQ(test::slurp(dir / "out" / "quad.mtl"),
              "# MeshEdit MTL: 2 materials\n\nnewmtl red paint\n\nnewmtl wood\n");
    const LoadedMesh again = read_mesh(dir / "out" / "quad.obj");
    EXPECT_TRUE(again.notices.empty());
    EXPECT_EQ(again.mesh.materials(), loaded.mesh.materials());
    // A library that is a FIFO is not opened (it could block for ever); the mesh loads.
    ASSERT_EQ(mkfifo((dir / "quad.mtl").c_str(), 0600), 0);
    const LoadedMesh piped = read_mesh(dir / "quad.obj");
    ASSERT_EQ(piped.notices.size(), 1u);
    EXPECT_EQ(piped.notices[0],
              "material library 'quad.mtl' is not a regular file: material names kept, colours and "
              "textures not");
    const MeshSoup no_uv = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/2 2/1 3/1\n", "t.obj");
    EXPECT_EQ(no_uv.soup.n_faces(), 1u);
    EXPECT_TRUE(no_uv.corner_texcoords.empty());
    EXPECT_EQ(
        no_uv.notices,
        std::vector<std::string>{
            "texture coordinates not kept: t.obj: line 4: face 1 refers to a texture coordinate "
            "that does not exist (the file has 3 vertices, 0 normals and 0 texture "
            "coordinates); the mesh loads without them"});
    EXPECT_EQ(test::io_error_of([] { parse_obj("vt nan 0\n", "n.obj"); }),
              "n.obj: line 1: texture coordinate 1 is not finite (NaN or infinity)");
}

// Real files: every OBJ of the assimp-testmodels package that loads keeps its texture
// coordinates through a write and a read.
TEST(ObjAttributes, AssimpTestModelsKeepTheirTexCoordsThroughARoundTrip) {
    const fs::path models = "/usr/share/assimp/models/OBJ";
    if (!fs::is_directory(models)) {
        GTEST_SKIP() << "install assimp-testmodels (scripts/install-deps.sh does)";
    }
    test::ScratchDir dir;
    std::size_t textured = 0;
    for (const auto& entry : fs::directory_iterator(models)) {
        if (entry.path().extension() != ".obj") {
            continue;
        }
        SCOPED_TRACE(entry.path().string());
        LoadedMesh loaded;
        try {
            loaded = read_mesh(entry.path());
        } catch (const IoError&) {
            continue;  // refused with its reason (the formats tests check which)
        }
        if (loaded.mesh.n_faces() == 0) {
            continue;  // every face dropped as broken (concave_polygon.obj repeats a corner)
        }
        const fs::path copy = dir / entry.path().filename();
        write_mesh(loaded.mesh, copy);
        const LoadedMesh back = read_mesh(copy);
        EXPECT_EQ(corners_of(back.mesh), corners_of(loaded.mesh));
        EXPECT_EQ(face_materials(back.mesh), face_materials(loaded.mesh));
        textured += loaded.mesh.has_property<Halfedge>(kTexCoordProperty) ? 1 : 0;
    }
    EXPECT_GE(textured, 3u);
}

}  // namespace
}  // namespace meshedit
