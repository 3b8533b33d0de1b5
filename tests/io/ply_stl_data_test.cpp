// PLY and STL on data no one here wrote: every PLY and STL of Debian's assimp-testmodels loads
// (or is refused with its reason) and round-trips exactly; CGAL's demo meshes (libcgal-demo)
// convert OFF → PLY → mesh with identical geometry and OFF → STL → mesh at float precision.
// Without the packages the tests skip and say which package to install.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

#include "io/formats_test_util.h"
#include "meshedit/io/ply.h"
#include "meshedit/io/stl.h"
#include "support/demo_meshes.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

const fs::path kAssimpModels = "/usr/share/assimp/models";

// Positions and faces, by index, bit for bit.
void expect_identical(const Mesh& actual, const Mesh& expected) {
    const PolygonSoup a = to_polygon_soup(actual);
    const PolygonSoup e = to_polygon_soup(expected);
    EXPECT_EQ(a.positions, e.positions);
    EXPECT_EQ(a.indices, e.indices);
    EXPECT_EQ(a.face_offsets, e.face_offsets);
}

// Each user property of `soup` as "name type: values".
std::vector<std::string> columns_of(const MeshSoup& soup) {
    std::vector<std::string> out;
    for (const auto* list : {&soup.vertex_properties, &soup.face_properties}) {
        for (const UserProperty& p : *list) {
            std::string line = p.name + " " + std::to_string(static_cast<int>(p.type)) + ":";
            for (const double x : p.values) {
                char text[32];
                std::snprintf(text, sizeof text, " %.17g", x);
                line += text;
            }
            out.push_back(line);
        }
    }
    return out;
}

// The corner positions of each triangle of `soup`, without the faces listed in `skip`.
std::vector<Vec3> triangles_of(const MeshSoup& soup, const std::vector<std::uint32_t>& skip = {}) {
    std::vector<Vec3> corners;
    for (std::size_t f = 0; f < soup.soup.n_faces(); ++f) {
        if (std::find(skip.begin(), skip.end(), f) != skip.end()) {
            continue;
        }
        for (std::uint32_t c = soup.soup.face_offsets[f]; c < soup.soup.face_offsets[f + 1]; ++c) {
            corners.push_back(soup.soup.positions[soup.soup.indices[c]]);
        }
    }
    return corners;
}

std::vector<fs::path> assimp_files() {
    std::vector<fs::path> files;
    for (const char* folder : {"PLY", "STL", "invalid"}) {
        if (!fs::is_directory(kAssimpModels / folder)) {
            continue;
        }
        for (const auto& entry : fs::directory_iterator(kAssimpModels / folder)) {
            const std::string ext = file_extension(entry.path());
            if (ext == ".ply" || ext == ".stl") {
                files.push_back(entry.path());
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(PlyStlData, EveryAssimpTestModelLoadsOrIsRefusedWithItsReasonAndRoundTrips) {
    if (!fs::is_directory(kAssimpModels / "PLY")) {
        GTEST_SKIP() << "no " << kAssimpModels.string()
                     << ": install assimp-testmodels (scripts/install-deps.sh does)";
    }
    // The files that hold no mesh, and why (the rest must load).
    const std::map<std::string, std::string> refused = {
        {"empty.ply", "empty file: no PLY header"},
        {"points.ply", "holds no faces to load"},
        // 69 bytes short of its 70051 vertices (and a point cloud anyway).
        {"pond.0.ply",
         "the header announces 70051 'vertex' records of at least 31 bytes, but "
         "only 2171512 bytes of the binary body remain"},
        // Its vertex element declares a vertex_indices list its lines do not hold.
        {"issue623.ply", "line 13: vertex 0: the line ends before its 'vertex_indices' value"},
    };
    test::ScratchDir dir;
    std::size_t loaded_count = 0;
    for (const fs::path& file : assimp_files()) {
        SCOPED_TRACE(file.string());
        const std::string name = file.filename().string();
        if (const auto it = refused.find(name); it != refused.end()) {
            EXPECT_CONTAINS(test::io_error_of([&] { read_mesh(file); }),
                            file.string() + ": " + it->second);
            continue;
        }
        LoadedMesh loaded;
        ASSERT_NO_THROW(loaded = read_mesh(file));
        ++loaded_count;
        EXPECT_GT(loaded.mesh.n_faces(), 0u);
        const std::string ext = file_extension(file);
        for (const bool ascii : {false, true}) {
            IoFlags flags;
            flags.ascii = ascii;
            const fs::path copy = dir / ((ascii ? "ascii_" : "binary_") + name);
            write_mesh(loaded.mesh, copy, flags);
            if (ext == ".ply") {
                // PLY keeps the mesh as it is, repairs included: the same mesh, bit for bit.
                const LoadedMesh again = read_mesh(copy);
                EXPECT_FALSE(again.repairs.repaired());
                expect_identical(again.mesh, loaded.mesh);
                // Colours, texture coordinates and unknown properties come back by name and
                // type with the same values (the file's own where the load repaired nothing).
                const MeshSoup written = read_soup(copy);
                write_mesh(again.mesh, dir / "again.ply", flags);
                const MeshSoup rewritten = read_soup(dir / "again.ply");
                EXPECT_EQ(columns_of(rewritten), columns_of(written));
                if (!loaded.repairs.repaired()) {
                    EXPECT_EQ(columns_of(written), columns_of(read_soup(file)));
                }
            } else {
                // STL has only positions: the file's triangles come back, bit for bit, less
                // those build_mesh() dropped (vertices it split weld again).
                const MeshSoup before = read_soup(file);
                const MeshSoup after = read_soup(copy);
                EXPECT_EQ(triangles_of(after), triangles_of(before, loaded.repairs.dropped_faces));
            }
        }
    }
    EXPECT_EQ(loaded_count, assimp_files().size() - refused.size());
}

TEST(PlyStlData, AssimpFilesHoldWhatTheySay) {
    if (!fs::is_directory(kAssimpModels / "PLY")) {
        GTEST_SKIP() << "install assimp-testmodels (scripts/install-deps.sh does)";
    }
    // Binary with a "solid"-free header, 12 triangles of a cube: 8 corners after the weld.
    const MeshSoup cube = read_ply(kAssimpModels / "PLY/cube_binary.ply");
    EXPECT_EQ(cube.soup.positions.size(), 8u);
    EXPECT_EQ(cube.soup.n_faces(), 12u);
    const MeshSoup uv = read_ply(kAssimpModels / "PLY/cube_uv.ply");
    EXPECT_EQ(uv.normals.size(), 24u);
    EXPECT_TRUE(uv.notices.empty());
    // s t become the texture coordinates of every corner at their vertex.
    EXPECT_TRUE(uv.vertex_properties.empty());
    ASSERT_EQ(uv.corner_texcoords.size(), uv.soup.indices.size());
    for (std::size_t c = 0; c < uv.soup.indices.size(); ++c) {
        if (uv.soup.indices[c] == 1) {
            EXPECT_EQ(uv.corner_texcoords[c].x, 1.0);  // the second line's s
        } else if (uv.soup.indices[c] == 2) {
            EXPECT_EQ(uv.corner_texcoords[c].y, 1.0);  // the third line's t
        }
    }
    const MeshSoup two = read_stl(kAssimpModels / "STL/triangle_with_two_solids.stl");
    EXPECT_EQ(two.soup.n_faces(), 2u);
    const MeshSoup spider_text = read_stl(kAssimpModels / "STL/Spider_ascii.stl");
    const MeshSoup spider = read_stl(kAssimpModels / "STL/Spider_binary.stl");
    EXPECT_EQ(spider.soup.n_faces(), 1368u);
    EXPECT_EQ(spider_text.soup.n_faces(), spider.soup.n_faces());
}

TEST(PlyStlData, CgalDemoMeshesConvertToPlyAndStlAndBack) {
    if (!fs::exists(test::kDemoDataTarball)) {
        GTEST_SKIP() << "no " << test::kDemoDataTarball << ": install libcgal-demo";
    }
    test::ScratchDir dir;
    for (const char* stem : {"bunny00", "cow", "cube_poly", "cross_quad", "elephant", "anchor"}) {
        SCOPED_TRACE(stem);
        const fs::path off = test::demo_mesh(stem, fs::path(MESHEDIT_BUILD_DIR) / "demo_data");
        const LoadedMesh original = read_mesh(off);
        write_mesh(original.mesh, dir / "m.ply");
        expect_identical(read_mesh(dir / "m.ply").mesh, original.mesh);

        write_mesh(original.mesh, dir / "m.stl");
        const MeshSoup stl = read_stl(dir / "m.stl");
        // Same triangles (each polygon fanned), every corner the float of the original's.
        const PolygonSoup soup = to_polygon_soup(original.mesh);
        std::size_t triangles = 0;
        for (std::size_t f = 0; f < soup.n_faces(); ++f) {
            triangles += soup.face_offsets[f + 1] - soup.face_offsets[f] - 2;
        }
        ASSERT_EQ(stl.soup.n_faces(), triangles);
        std::size_t t = 0;
        bool same = true;
        const auto rounded = [](const Vec3& p) {
            return Vec3(test::to_float(p.x), test::to_float(p.y), test::to_float(p.z));
        };
        for (std::size_t f = 0; f < soup.n_faces(); ++f) {
            const std::uint32_t b = soup.face_offsets[f];
            for (std::uint32_t c = b + 1; c + 1 < soup.face_offsets[f + 1]; ++c, ++t) {
                const std::uint32_t corners[3] = {b, c, c + 1};
                for (int k = 0; k < 3; ++k) {
                    same = same && stl.soup.positions[stl.soup.indices[3 * t + k]] ==
                                       rounded(soup.positions[soup.indices[corners[k]]]);
                }
            }
        }
        EXPECT_TRUE(same);
        // And back: the STL's mesh written as OFF reads back as the same mesh.
        const LoadedMesh from_stl = read_mesh(dir / "m.stl");
        EXPECT_EQ(from_stl.mesh.n_faces(), triangles);
        write_mesh(from_stl.mesh, dir / "back.off");
        expect_identical(read_mesh(dir / "back.off").mesh, from_stl.mesh);
    }
}

}  // namespace
}  // namespace meshedit
