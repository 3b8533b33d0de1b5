// .bez and .bzc: exact parsing, every error with file, line and problem, write_bzc round
// trips, and the sample files (the Newell teaset, the wavy cube, the curves).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "io/formats_test_util.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/topology.h"
#include "meshedit/core/validate.h"
#include "meshedit/io/io.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using test::data_file;
using test::io_error_of;
using test::sample_file;

TEST(Bez, ParsesCommentsAndOddWhitespaceExactly) {
    const std::vector<BezierPatch> patches = read_bez(data_file("bez_two_patches.bez"));
    ASSERT_EQ(patches.size(), 2u);
    for (const BezierPatch& p : patches) {
        EXPECT_EQ(p.rows, 4);
        EXPECT_EQ(p.cols, 4);
        ASSERT_EQ(p.control_points.size(), 16u);
    }
    for (int k = 0; k < 16; ++k) {
        const double d = k;
        // Row-major: point k is cp[k / 4][k % 4].
        EXPECT_EQ(patches[0].cp(k / 4, k % 4), Vec3(d, d * 0.5, -d * 0.25)) << k;
        EXPECT_EQ(patches[1].cp(k / 4, k % 4), Vec3(d / 8, 100 + d, 1e-3)) << k;
    }
}

TEST(Bez, PatchWith47NumbersNamesFileLineAndPatch) {
    const std::string what = io_error_of([] { read_bez(data_file("bez_47_numbers.bez")); });
    EXPECT_CONTAINS(what, "bez_47_numbers.bez");
    EXPECT_CONTAINS(what, "patch 3 has 47 numbers, expected 48");
    EXPECT_CONTAINS(what, "line 14");
}

TEST(Bez, GarbageNamesTheTokenAndLine) {
    const std::string what = io_error_of([] { read_bez(data_file("bez_garbage.bez")); });
    EXPECT_CONTAINS(what, "bez_garbage.bez: line 3: expected a number, found 'abc'");
}

TEST(Bez, NanIsRejected) {
    const std::string what = io_error_of([] { read_bez(data_file("bez_nan.bez")); });
    EXPECT_CONTAINS(what, "bez_nan.bez: line 2");
    EXPECT_CONTAINS(what, "'nan'");
    EXPECT_CONTAINS(what, "NaN or infinity");
}

TEST(Bez, TrailingDataIsRejected) {
    const std::string what = io_error_of([] { read_bez(data_file("bez_trailing.bez")); });
    EXPECT_CONTAINS(what, "bez_trailing.bez: line 3: unexpected '2.5' after the last");
}

TEST(Bez, BadCountsAreRejected) {
    EXPECT_CONTAINS(io_error_of([] { read_bez(data_file("bez_negative.bez")); }),
                    "bez_negative.bez: line 2: the number of patches must not be negative");
    EXPECT_CONTAINS(io_error_of([] { read_bez(data_file("bez_absurd.bez")); }), "is absurd");
    EXPECT_CONTAINS(io_error_of([] { read_bez(data_file("bez_empty.bez")); }),
                    "bez_empty.bez: no data");
}

TEST(Bez, LargeCountWithLittleDataFailsWithoutAllocating) {
    // 50 million patches would be 38 GB of control points; the reader must notice the text
    // ends instead of reserving that.
    test::ScratchDir dir;
    test::spit(dir / "big.bez", "50000000\n1 2 3\n");
    EXPECT_CONTAINS(io_error_of([&] { read_bez(dir / "big.bez"); }),
                    "patch 1 has 3 numbers, expected 48");
}

TEST(Bez, BinaryGarbageAndMissingFile) {
    test::ScratchDir dir;
    test::spit(dir / "noise.bez", std::string("\x7f"
                                              "ELF\x02\x01\x01\0\0\0\xff\xfe",
                                              12));
    const std::string what = io_error_of([&] { read_bez(dir / "noise.bez"); });
    EXPECT_CONTAINS(what, "noise.bez: line 1");
    EXPECT_CONTAINS(what, "\\x7fELF");  // escaped, never raw bytes
    EXPECT_CONTAINS(io_error_of([&] { read_bez(dir / "absent.bez"); }), "absent.bez: no such file");
    EXPECT_CONTAINS(io_error_of([&] { read_bez(dir.path()); }), "is a folder");
}

TEST(Bzc, ParsesCommentsAndOddWhitespaceExactly) {
    const BezierCurve c = read_bzc(data_file("bzc_curve.bzc"));
    ASSERT_EQ(c.control_points.size(), 4u);
    EXPECT_EQ(c.control_points[0], Vec3(0, 0, 0));
    EXPECT_EQ(c.control_points[1], Vec3(0.25, 1, 0));
    EXPECT_EQ(c.control_points[2], Vec3(0.75, 1, 0));
    EXPECT_EQ(c.control_points[3], Vec3(1, 0, 0));
}

TEST(Bzc, Errors) {
    EXPECT_CONTAINS(io_error_of([] { read_bzc(data_file("bzc_one_point.bzc")); }),
                    "bzc_one_point.bzc: line 2: a curve needs at least 2 points, the "
                    "file has 1");
    EXPECT_CONTAINS(io_error_of([] { read_bzc(data_file("bzc_short.bzc")); }),
                    "bzc_short.bzc: line 4: point 3 has 1 number, expected 2");
    EXPECT_CONTAINS(io_error_of([] { read_bzc(data_file("bzc_inf.bzc")); }),
                    "bzc_inf.bzc: line 3: expected a finite number, found 'inf'");
}

TEST(Bzc, WriteReadRoundTripIsExact) {
    test::ScratchDir dir;
    BezierCurve c;
    c.control_points = {{0.1, 1.0 / 3.0, 0},
                        {std::nextafter(0.5, 1.0), -0.0, 0},
                        {1e-300, 12345678.901234567, 0},
                        {std::numeric_limits<double>::denorm_min(), -7.25, 0},
                        {1, 0.7, 0}};
    write_bzc(c, dir / "c.bzc");
    const BezierCurve back = read_bzc(dir / "c.bzc");
    ASSERT_EQ(back.control_points.size(), c.control_points.size());
    for (std::size_t i = 0; i < c.control_points.size(); ++i) {
        EXPECT_EQ(back.control_points[i], c.control_points[i]) << i;
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"c.bzc"});
}

TEST(Bzc, WriteRefusesACurveOfOnePoint) {
    test::ScratchDir dir;
    BezierCurve c;
    c.control_points = {{0.5, 0.5, 0}};
    EXPECT_CONTAINS(io_error_of([&] { write_bzc(c, dir / "one.bzc"); }),
                    "one.bzc: a curve needs at least 2 points");
    EXPECT_TRUE(dir.entries().empty());
}

// ----------------------------------------------------------------- the sample files

TEST(BezSamples, CurvesHaveTheirPointCountsInTheUnitSquare) {
    const std::pair<const char*, std::size_t> curves[] = {
        {"bez/curve1.bzc", 4}, {"bez/curve2.bzc", 5}, {"bez/curve6.bzc", 6}};
    for (const auto& [name, n] : curves) {
        const BezierCurve c = read_bzc(sample_file(name));
        ASSERT_EQ(c.control_points.size(), n) << name;
        for (const Vec3& p : c.control_points) {
            EXPECT_GE(p.x, 0.0);
            EXPECT_LE(p.x, 1.0);
            EXPECT_GE(p.y, 0.0);
            EXPECT_LE(p.y, 1.0);
            EXPECT_EQ(p.z, 0.0);
        }
    }
}

TEST(BezSamples, TeasetPatchCounts) {
    EXPECT_EQ(read_bez(sample_file("bez/teapot.bez")).size(), 32u);
    EXPECT_EQ(read_bez(sample_file("bez/teacup.bez")).size(), 26u);
    EXPECT_EQ(read_bez(sample_file("bez/teaspoon.bez")).size(), 16u);
    EXPECT_EQ(read_bez(sample_file("bez/wavy_cube.bez")).size(), 6u);
}

TEST(BezSamples, TeapotTessellatesToAValidMesh) {
    const std::vector<BezierPatch> patches = read_bez(sample_file("bez/teapot.bez"));
    const Mesh mesh = tessellate(patches);
    EXPECT_VALID(mesh);
    const MeshStats s = compute_stats(mesh);
    // Body with bottom, lid, handle, spout: one welded mesh per part. Open ends: the body's
    // rim, the lid's rim, both ends of the handle and of the spout.
    EXPECT_EQ(s.components, 4u);
    EXPECT_EQ(s.boundary_loops, 6u);
    EXPECT_EQ(s.euler_characteristic, 2);  // two disks and two cylinders
    EXPECT_GT(s.faces, 32u * 8 * 8);
    // Y-up: it stands on y = 0 and is taller than nothing.
    const BoundingBox box = mesh.bounds();
    EXPECT_EQ(box.min.y, 0.0);
    EXPECT_GT(box.max.y, 3.0);
}

TEST(BezSamples, TeacupTeaspoonAndWavyCubeTessellate) {
    for (const char* name : {"bez/teacup.bez", "bez/teaspoon.bez"}) {
        const Mesh mesh = tessellate(read_bez(sample_file(name)));
        EXPECT_VALID(mesh) << name;
        EXPECT_GT(mesh.n_faces(), 0u) << name;
    }
    // The wavy cube's patches share their borders exactly: one closed sphere-like surface.
    const Mesh cube = tessellate(read_bez(sample_file("bez/wavy_cube.bez")));
    EXPECT_VALID(cube);
    const MeshStats s = compute_stats(cube);
    EXPECT_EQ(s.components, 1u);
    EXPECT_EQ(s.boundary_loops, 0u);
    EXPECT_EQ(s.euler_characteristic, 2);
}

}  // namespace
}  // namespace meshedit
