// Files MeshEdit writes as .bzc and .bez open in the CS184 course's skeleton. Its readers are
// fscanf calls: "%d" for the count, then "%lf %lf" per curve point or "%lf %lf %lf" per
// patch point, 16 a patch, row-major. The strict reader below follows that grammar and
// nothing more: no comments, nothing after the last number, every conversion must succeed.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/formats_test_util.h"
#include "meshedit/files/files.h"
#include "meshedit/io/io.h"
#include "support/scratch_dir.h"

namespace meshedit {
namespace {

using File = std::unique_ptr<FILE, int (*)(FILE*)>;

File open_for_reading(const std::filesystem::path& path) {
    return File(std::fopen(path.c_str(), "r"), &std::fclose);
}

// True when only whitespace is left, as a course file ends.
bool at_end(FILE* f) {
    char c = 0;
    return std::fscanf(f, " %c", &c) == EOF;
}

// The course's curve reader: the count, then x y per point. nullopt where it would fail.
std::optional<std::vector<Vec3>> course_read_bzc(const std::filesystem::path& path) {
    const File f = open_for_reading(path);
    int n = 0;
    if (!f || std::fscanf(f.get(), "%d", &n) != 1 || n < 2) {
        return std::nullopt;
    }
    std::vector<Vec3> points(static_cast<std::size_t>(n));
    for (Vec3& p : points) {
        if (std::fscanf(f.get(), "%lf %lf", &p.x, &p.y) != 2) {
            return std::nullopt;
        }
    }
    if (!at_end(f.get())) {
        return std::nullopt;
    }
    return points;
}

// The course's patch reader: the count, then 16 × x y z per patch.
std::optional<std::vector<std::vector<Vec3>>> course_read_bez(const std::filesystem::path& path) {
    const File f = open_for_reading(path);
    int n = 0;
    if (!f || std::fscanf(f.get(), "%d", &n) != 1 || n < 1) {
        return std::nullopt;
    }
    std::vector<std::vector<Vec3>> patches(static_cast<std::size_t>(n), std::vector<Vec3>(16));
    for (auto& patch : patches) {
        for (Vec3& p : patch) {
            if (std::fscanf(f.get(), "%lf %lf %lf", &p.x, &p.y, &p.z) != 3) {
                return std::nullopt;
            }
        }
    }
    if (!at_end(f.get())) {
        return std::nullopt;
    }
    return patches;
}

TEST(CourseGrammar, TheStrictReaderRejectsWhatTheCourseCannotRead) {
    test::ScratchDir dir;
    const auto bzc_with = [&](const std::string& text) {
        write_file(dir / "c.bzc", text);
        return course_read_bzc(dir / "c.bzc").has_value();
    };
    EXPECT_TRUE(bzc_with("2\n0 0\n1 1\n"));
    EXPECT_FALSE(bzc_with("# a comment\n2\n0 0\n1 1\n"));
    EXPECT_FALSE(bzc_with("2\n0 0 # a comment\n1 1\n"));
    EXPECT_FALSE(bzc_with("3\n0 0\n1 1\n"));
    EXPECT_FALSE(bzc_with("2\n0 0\n1 1\n5\n"));
}

TEST(CourseGrammar, CurvesAreWrittenExactlyAsTheCourseWritesThem) {
    test::ScratchDir dir;
    BezierCurve curve;
    curve.control_points = {{0, 0, 0}, {0.5, 1, 0}, {1, 0.25, 0}};
    write_bzc(curve, dir / "c.bzc");
    EXPECT_EQ(read_file(dir / "c.bzc"), "3\n0 0\n0.5 1\n1 0.25\n");
}

TEST(CourseGrammar, WrittenCurvesReadBackInTheCourseReaderBitForBit) {
    test::ScratchDir dir;
    std::vector<BezierCurve> curves;
    for (const char* name : {"bez/curve1.bzc", "bez/curve2.bzc", "bez/curve6.bzc"}) {
        curves.push_back(read_bzc(test::sample_file(name)));
    }
    // Numbers a drag leaves behind, and the awkward ones.
    BezierCurve dragged;
    dragged.control_points = {{0.30750003457069397, 1.0 / 3.0, 0},
                              {-0.0, 1e-300, 0},
                              {std::numeric_limits<double>::denorm_min(), 12345678.901234567, 0},
                              {std::nextafter(1.0, 2.0), -7.25, 0}};
    curves.push_back(dragged);
    for (const BezierCurve& curve : curves) {
        write_bzc(curve, dir / "c.bzc");
        const auto read = course_read_bzc(dir / "c.bzc");
        ASSERT_TRUE(read.has_value()) << read_file(dir / "c.bzc");
        ASSERT_EQ(read->size(), curve.control_points.size());
        for (std::size_t i = 0; i < read->size(); ++i) {
            EXPECT_EQ((*read)[i].x, curve.control_points[i].x) << i;
            EXPECT_EQ((*read)[i].y, curve.control_points[i].y) << i;
        }
    }
}

TEST(CourseGrammar, WrittenPatchesReadBackInTheCourseReaderBitForBit) {
    test::ScratchDir dir;
    for (const char* name :
         {"bez/teapot.bez", "bez/teacup.bez", "bez/teaspoon.bez", "bez/wavy_cube.bez"}) {
        const std::vector<BezierPatch> patches = read_bez(test::sample_file(name));
        write_bez(patches, dir / "p.bez");
        const auto read = course_read_bez(dir / "p.bez");
        ASSERT_TRUE(read.has_value()) << name;
        ASSERT_EQ(read->size(), patches.size()) << name;
        for (std::size_t p = 0; p < patches.size(); ++p) {
            for (std::size_t k = 0; k < 16; ++k) {
                EXPECT_EQ((*read)[p][k], patches[p].control_points[k]) << name << " " << p;
            }
        }
        // And MeshEdit's own reader agrees.
        const std::vector<BezierPatch> back = read_bez(dir / "p.bez");
        ASSERT_EQ(back.size(), patches.size());
        for (std::size_t p = 0; p < patches.size(); ++p) {
            EXPECT_EQ(back[p].control_points, patches[p].control_points);
        }
    }
}

TEST(CourseGrammar, PatchWriterRefusesWhatTheFormatCannotHold) {
    test::ScratchDir dir;
    BezierPatch flat;
    for (int i = 0; i < 16; ++i) {
        flat.control_points.push_back({static_cast<double>(i % 4), static_cast<double>(i / 4), 0});
    }
    BezierPatch cubic_by_quadratic = flat;
    cubic_by_quadratic.cols = 3;
    cubic_by_quadratic.control_points.resize(12);
    EXPECT_CONTAINS(test::io_error_of([&] {
                        write_bez({flat, cubic_by_quadratic}, dir / "p.bez");
                    }),
                    "p.bez: patch 2 is 4 × 3; a .bez file holds 4 × 4 patches");
    BezierPatch broken = flat;
    broken.control_points[5].z = NAN;
    EXPECT_CONTAINS(test::io_error_of([&] { write_bez({broken}, dir / "p.bez"); }),
                    "p.bez: patch 1, point 6 is not finite");
    EXPECT_CONTAINS(test::io_error_of([&] { write_bez({}, dir / "p.bez"); }),
                    "p.bez: no patches to write");
    EXPECT_TRUE(dir.entries().empty()) << "nothing written, no temporary left";
}

}  // namespace
}  // namespace meshedit
