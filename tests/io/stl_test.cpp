// STL: ASCII (several solids) and binary (also with a header starting "solid") give the
// exact welded soup, the weld and facet normals that disagree with the winding are reported,
// the writer round-trips at float precision, and sizes that lie or truncated text are refused.

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <limits>

#include "io/formats_test_util.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/stl.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using test::Faces;
using test::faces_of;
using test::io_error_of;

std::string stl_error(const std::string& bytes) {
    return io_error_of([&] { parse_stl(bytes, "t.stl"); });
}

// A binary STL of `triangles` (normal, then three corners), with `header` padded to 80 bytes.
std::string binary_stl(const std::string& header, const std::vector<std::array<Vec3, 4>>& tris,
                       std::uint32_t count) {
    std::string out = header;
    out.resize(80, ' ');
    out.append(reinterpret_cast<const char*>(&count), 4);
    for (const auto& t : tris) {
        for (const Vec3& v : t) {
            for (int i = 0; i < 3; ++i) {
                const auto f = static_cast<float>(v[i]);
                out.append(reinterpret_cast<const char*>(&f), 4);
            }
        }
        out.append(2, '\0');
    }
    return out;
}

// Two triangles of a square sharing an edge; the second's stored normal points the wrong way.
const std::vector<std::array<Vec3, 4>> kSquare = {
    {Vec3(0, 0, 1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)},
    {Vec3(0, 0, -1), Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, -0.0)}};
const std::vector<Vec3> kSquarePositions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

TEST(Stl, BinaryEvenWhenTheHeaderSaysSolid) {
    for (const std::string header : {"binary from a tool", "solid but binary"}) {
        SCOPED_TRACE(header);
        const MeshSoup s = parse_stl(binary_stl(header, kSquare, 2), "b.stl");
        EXPECT_EQ(s.soup.positions, kSquarePositions);
        EXPECT_FALSE(std::signbit(s.soup.positions[3].z));  // −0 welded with +0 as one vertex
        EXPECT_EQ(faces_of(s.soup), (Faces{{0, 1, 2}, {0, 2, 3}}));
        EXPECT_EQ(s.notices,
                  (std::vector<std::string>{"welded 2 vertices by exact position",
                                            "1 of 2 facets have a stored normal opposite to "
                                            "their winding (the winding is kept)"}));
    }
}

TEST(Stl, AsciiWithSeveralSolidsAndAnEmptyOne) {
    const MeshSoup s = parse_stl(
        "solid first part\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n"
        "      vertex 1 0 0\n      vertex 1 1 0\n    endloop\n  endfacet\nendsolid first part\n"
        "solid empty\nendsolid\n"
        "solid\r\nfacet normal 0 0 0\r\nouter loop\r\nvertex 0 0 0\r\nvertex 1 1 0\r\n"
        "vertex 0 1 0.0\r\nendloop\r\nendfacet\r\nendsolid\r\n",
        "a.stl");
    EXPECT_EQ(s.soup.positions, kSquarePositions);
    EXPECT_EQ(faces_of(s.soup), (Faces{{0, 1, 2}, {0, 2, 3}}));
    // A zero normal does not count as disagreeing.
    EXPECT_EQ(s.notices, std::vector<std::string>{"welded 2 vertices by exact position"});
    // A byte-order mark before "solid"; text coordinates are the floats they mean, said once.
    const MeshSoup bom = parse_stl(
        "\xEF\xBB\xBFsolid\nfacet normal 0 0 1\nouter loop\nvertex 0.1 0 0\nvertex 1 0 0\n"
        "vertex 1 1 0\nendloop\nendfacet\nendsolid\n",
        "bom.stl");
    EXPECT_EQ(bom.soup.positions[0], Vec3(test::to_float(0.1), 0, 0));
    EXPECT_EQ(bom.notices,
              std::vector<std::string>{"coordinates rounded to 32-bit floats (STL stores floats)"});
}

TEST(Stl, RoundTripAtFloatPrecisionInBinaryAndAscii) {
    test::ScratchDir dir;
    Mesh mesh = shapes::quad_sphere(3);
    for (const Vertex v : mesh.vertices()) {
        mesh.position(v) = mesh.position(v) * 3.0 + Vec3(0.1, -1.0 / 3.0, 1e-5);
    }
    const PolygonSoup original = to_polygon_soup(mesh);
    for (const bool ascii : {false, true}) {
        SCOPED_TRACE(ascii ? "ascii" : "binary");
        IoFlags flags;
        flags.ascii = ascii;
        const auto path = dir / (ascii ? "a.stl" : "b.stl");
        const std::vector<std::string> unkept = write_mesh(mesh, path, flags);
        EXPECT_EQ(unkept, (std::vector<std::string>{
                              std::to_string(mesh.n_faces()) +
                                  " polygons (STL stores triangles: each is fanned)",
                              "coordinates beyond 32-bit float precision (STL stores floats)"}));
        const std::string bytes = test::slurp(path);
        if (ascii) {
            EXPECT_EQ(bytes.substr(0, 15), "solid meshedit\n");
        } else {
            EXPECT_EQ(bytes.size(), 84 + 50 * 2 * mesh.n_faces());
            EXPECT_NE(bytes.substr(0, 5), "solid");
        }
        const MeshSoup s = read_stl(path);
        // Every corner is the float of the original's corner, fanned; the quad sphere has no
        // two vertices at one float position, so the weld finds each vertex once.
        EXPECT_EQ(s.soup.positions.size(), original.positions.size());
        ASSERT_EQ(s.soup.n_faces(), 2 * original.n_faces());
        const auto rounded = [&](std::uint32_t v) {
            const Vec3& p = original.positions[v];
            return Vec3(test::to_float(p.x), test::to_float(p.y), test::to_float(p.z));
        };
        for (std::size_t f = 0; f < original.n_faces(); ++f) {
            const std::uint32_t* q = &original.indices[original.face_offsets[f]];
            const std::uint32_t* a = &s.soup.indices[s.soup.face_offsets[2 * f]];
            const std::uint32_t order[6] = {q[0], q[1], q[2], q[0], q[2], q[3]};
            for (int c = 0; c < 6; ++c) {
                EXPECT_EQ(s.soup.positions[a[c]], rounded(order[c]));
            }
        }
        // Once at float precision, the next round is exact: the same bytes.
        const LoadedMesh again = read_mesh(path);
        EXPECT_TRUE(write_mesh(again.mesh, dir / "again.stl", flags).empty());
        EXPECT_EQ(test::slurp(dir / "again.stl"), bytes);
    }
}

// Every truncation and many single-byte changes of valid files: a soup or an IoError, never
// a crash or another exception (run under ASan in the sanitizer build).
TEST(Stl, TruncatedAndDamagedFilesGiveASoupOrAnIoError) {
    const std::vector<std::string> files = {
        binary_stl("solid binary", kSquare, 2),
        "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
        "endloop\nendfacet\nendsolid s\n"};
    std::size_t soups = 0;
    std::size_t errors = 0;
    const auto attempt = [&](const std::string& bytes) {
        try {
            parse_stl(bytes, "d.stl");
            ++soups;
        } catch (const IoError&) {
            ++errors;
        }
    };
    for (const std::string& file : files) {
        for (std::size_t n = 0; n < file.size(); ++n) {
            attempt(file.substr(0, n));
        }
        for (std::size_t i = 0; i < file.size(); ++i) {
            for (const char c : {'\0', '\xFF', '\x7F', '9', ' '}) {
                std::string damaged = file;
                damaged[i] = c;
                attempt(damaged);
            }
        }
    }
    EXPECT_GT(errors, 0u);
    EXPECT_GT(soups, 0u);
}

TEST(Stl, SizesThatLieAndTruncatedTextAreRefused) {
    const std::string good = binary_stl("tool", kSquare, 2);
    EXPECT_EQ(stl_error(binary_stl("tool", kSquare, 3)),
              "t.stl: binary STL whose header announces 3 triangles (84 + 50 × 3 = 234 bytes), "
              "but the file is 184 bytes");
    EXPECT_EQ(stl_error(good.substr(0, 150)),
              "t.stl: binary STL whose header announces 2 triangles (84 + 50 × 2 = 184 bytes), "
              "but the file is 150 bytes");
    EXPECT_EQ(stl_error(binary_stl("tool", kSquare, 0xFFFFFFFF)),
              "t.stl: binary STL whose header announces 4294967295 triangles (84 + 50 × "
              "4294967295 = 214748364834 bytes), but the file is 184 bytes");
    // A header starting "solid" does not make a binary file whose count lies into text.
    EXPECT_EQ(stl_error(binary_stl("solid x", kSquare, 5)),
              "t.stl: binary STL whose header announces 5 triangles (84 + 50 × 5 = 334 bytes), "
              "but the file is 184 bytes");
    EXPECT_EQ(stl_error(""), "t.stl: empty file: no STL data");
    EXPECT_EQ(stl_error(std::string("\x01\x02", 2)),
              "t.stl: too short for binary STL (2 bytes; a binary STL has at least 84) and not "
              "ASCII STL");
    const std::string facet =
        "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
        "endloop\nendfacet\n";
    EXPECT_EQ(stl_error(facet),
              "t.stl: line 8: the file ends inside the solid that starts on "
              "line 1 (no 'endsolid')");
    EXPECT_EQ(stl_error(facet.substr(0, 51)), "t.stl: line 4: the file ends inside a facet");
    EXPECT_EQ(stl_error("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nendloop\n"),
              "t.stl: line 5: expected 'vertex' (a facet has three corners)");
    EXPECT_EQ(stl_error(facet.substr(0, 77)),
              "t.stl: line 6: the file ends inside a facet, before 'endloop'");
    EXPECT_EQ(stl_error("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 nan 0\n"),
              "t.stl: line 4: a vertex is not finite (NaN or infinity)");
    EXPECT_EQ(stl_error("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n"),
              "t.stl: line 4: a vertex: expected three numbers, found ''");
    EXPECT_EQ(stl_error("solid s\nfacet normal 0 0 1\nouter\n"),
              "t.stl: line 3: expected 'outer loop', found 'outer'");
    EXPECT_EQ(stl_error("solid s\nface 0 0 1\n"),
              "t.stl: line 2: expected 'facet normal' or 'endsolid', found 'face 0 0 1'");
    EXPECT_EQ(stl_error("solid s\nendsolid\nfoo\n"),
              "t.stl: line 3: expected 'solid' or the end of the file, found 'foo'");
    // Binary NaN.
    auto bad = kSquare;
    bad[1][2].y = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(stl_error(binary_stl("tool", bad, 2)),
              "t.stl: triangle 1: corner 1 is not finite (NaN or infinity)");
    // A solid with no facets loads nothing: the front door says so.
    test::ScratchDir dir;
    test::spit(dir / "empty.stl", "solid nothing\nendsolid nothing\n");
    EXPECT_EQ(io_error_of([&] { read_mesh(dir / "empty.stl"); }),
              (dir / "empty.stl").string() + ": holds no faces to load");
}

}  // namespace
}  // namespace meshedit
