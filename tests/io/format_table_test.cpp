// The one table of mesh formats (mesh_formats()): each row's claims hold for its writer and
// reader, what a row says a format cannot keep is named when it is dropped, and docs/cli.md's
// table is the table.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/build.h"
#include "meshedit/core/validate.h"
#include "meshedit/io/io.h"
#include "support/generated_text.h"
#include "support/scratch_dir.h"

namespace meshedit {
namespace {

// The second set's value at vertex v: one a float holds, so every format keeps it exactly.
Vec2 second_uv(Vertex v) {
    return Vec2{v.idx() / 4.0, 1 - v.idx() / 8.0};
}

// A quad beside a triangle; vertex 4 has a coordinate no float holds; the edge they share
// is creased; every corner has a texture coordinate in each of the two sets.
Mesh everything_a_format_may_drop() {
    PolygonSoup soup;
    soup.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.1, 0}};
    soup.add_face({0, 1, 2, 3});
    soup.add_face({1, 4, 2});
    Mesh mesh = build_mesh(soup);
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    crease[mesh.find_edge(Vertex(1), Vertex(2))] = 1;
    auto uv = mesh.property<Halfedge, Vec2>(kTexCoordProperty, Vec2{0, 0});
    auto uv1 = mesh.property<Halfedge, Vec2>(kTexCoord1Property, Vec2{0, 0});
    for (const Halfedge h : mesh.halfedges()) {
        if (!mesh.is_boundary(h)) {
            const Vec3& p = mesh.position(mesh.to_vertex(h));
            uv[h] = Vec2{p.x / 2, p.y};
            uv1[h] = second_uv(mesh.to_vertex(h));
        }
    }
    auto color = mesh.property<Vertex, Vec4>(kColorProperty);
    for (const Vertex v : mesh.vertices()) {
        color[v] = Vec4{v.idx() / 4.0, 0.5, 1, 1};
    }
    return mesh;
}

bool mentions(const std::vector<std::string>& notes, const std::string& part) {
    for (const std::string& note : notes) {
        if (note.find(part) != std::string::npos) {
            return true;
        }
    }
    return false;
}

TEST(FormatTable, EachRowIsTrueOfItsWriterAndReader) {
    test::ScratchDir dir;
    const Mesh mesh = everything_a_format_may_drop();
    for (const MeshFormat& format : mesh_formats()) {
        SCOPED_TRACE(format.extension);
        const auto path = dir.path() / (std::string("mesh") + format.extension);
        const std::vector<std::string> notes = write_mesh(mesh, path);
        const LoadedMesh back = read_mesh(path);
        ASSERT_FALSE(validate(back.mesh).has_value());

        std::size_t polygons = 0;
        for (const Face f : back.mesh.faces()) {
            polygons += back.mesh.is_triangle(f) ? 0 : 1;
        }
        EXPECT_EQ(polygons, format.polygons ? 1u : 0u);
        EXPECT_EQ(mentions(notes, "1 polygon ("), !format.polygons);

        bool exact = false;
        for (const Vertex v : back.mesh.vertices()) {
            exact = exact || back.mesh.position(v).y == 0.1;
        }
        EXPECT_EQ(exact, format.doubles);
        EXPECT_EQ(mentions(notes, "32-bit float"), !format.doubles);

        EXPECT_EQ(back.mesh.has_property<Edge>(kCreaseProperty), format.creases);
        EXPECT_EQ(mentions(notes, "1 crease mark"), !format.creases);

        // The UVs have no seams: a format of per-vertex UVs keeps them too.
        const bool uvs = format.corner_attributes || format.vertex_attributes;
        EXPECT_EQ(back.mesh.has_property<Halfedge>(kTexCoordProperty), uvs);
        EXPECT_EQ(mentions(notes, "texture coordinates"), !uvs);

        EXPECT_EQ(back.mesh.has_property<Halfedge>(kTexCoord1Property), format.second_texcoords);
        EXPECT_EQ(mentions(notes, "the second texture coordinate set ("), !format.second_texcoords);
        if (const auto b = back.mesh.get_property<Halfedge, Vec2>(kTexCoord1Property)) {
            for (const Face f : back.mesh.faces()) {
                for (const Halfedge h : back.mesh.halfedges(f)) {
                    ASSERT_TRUE(b[h] == second_uv(back.mesh.to_vertex(h))) << "corner " << h.idx();
                }
            }
        }

        EXPECT_EQ(back.mesh.has_property<Vertex>(kColorProperty), format.colors);
        EXPECT_EQ(mentions(notes, "vertex colours"), !format.colors);
    }
}

TEST(FormatTable, ExtensionsInMessagesComeFromTheTable) {
    EXPECT_EQ(mesh_extension_list(" "), ".dae .gltf .glb .obj .off .ply .stl");
    EXPECT_STREQ(mesh_extensions(), ".dae, .gltf, .glb, .obj, .off, .ply or .stl");
    for (const MeshFormat& format : mesh_formats()) {
        EXPECT_TRUE(is_mesh_extension(format.extension));
        EXPECT_EQ(find_mesh_format(format.extension), &format);
    }
    EXPECT_FALSE(is_mesh_extension(".bez"));
    EXPECT_EQ(find_mesh_format(".OBJ"), nullptr);  // callers lower-case (file_extension())
}

std::string yes_no(bool keeps) {
    return keeps ? "yes" : "no";
}

TEST(FormatTable, DocsTableIsGenerated) {
    std::string table =
        "| extension | format | polygons | every double | creases | texture coordinates, the "
        "file's normals, materials | PLY properties | vertex colours | UVs and normals one per "
        "vertex | a second UV set |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const MeshFormat& format : mesh_formats()) {
        table += std::string("| `") + format.extension + "` | " + format.name + " | " +
                 (format.polygons ? "yes" : "fanned into triangles") + " | " +
                 (format.doubles ? "yes" : "32-bit floats") + " | " + yes_no(format.creases) +
                 " | " + yes_no(format.corner_attributes) + " | " + yes_no(format.ply_properties) +
                 " | " + yes_no(format.colors) + " | " +
                 yes_no(format.corner_attributes || format.vertex_attributes) + " | " +
                 yes_no(format.second_texcoords) + " |\n";
    }
    EXPECT_TRUE(test::block_is_generated(MESHEDIT_SOURCE_DIR "/docs/cli.md", "formats", table));
}

}  // namespace
}  // namespace meshedit
