/// \file
/// The golden-image rule itself (support/image_compare.h), on synthetic PNGs: so a golden
/// test that passes means "within tolerance", not "the comparison never looked".

#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <filesystem>
#include <string>

#include "cli/run.h"
#include "support/image_compare.h"

namespace meshedit::test {
namespace {

namespace fs = std::filesystem;
using OIIO::ImageBuf;

// 384 × 288 = 110,592 pixels: 0.1% is 110.6 pixels.
constexpr int kW = 384;
constexpr int kH = 288;

// A grey RGBA image with `count` pixels (from the top-left, row by row) raised by `delta`.
ImageBuf grey(int count = 0, float delta = 0.0f, int w = kW, int h = kH) {
    ImageBuf image(OIIO::ImageSpec(w, h, 4, OIIO::TypeDesc::FLOAT));
    const float base[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    OIIO::ImageBufAlgo::fill(image, base);
    const float raised[4] = {0.5f + delta, 0.5f, 0.5f, 1.0f};
    for (int i = 0; i < count; ++i) {
        image.setpixel(i % w, i / w, raised);
    }
    return image;
}

fs::path save(const ImageBuf& image, const fs::path& path) {
    EXPECT_TRUE(image.write(path.string(), OIIO::TypeDesc::UINT8)) << image.geterror();
    return path;
}

TEST(ImageCompare, IdenticalImagesMatchAndLeaveNoArtefacts) {
    TempDir dir;
    const auto a = save(grey(), dir / "a.png");
    const auto b = save(grey(), dir / "b.png");
    EXPECT_TRUE(images_match(a, b, dir.path() / "out", "same"));
    EXPECT_FALSE(fs::exists(dir.path() / "out" / "same.actual.png"));
    EXPECT_FALSE(fs::exists(dir.path() / "out" / "same.diff.png"));
}

TEST(ImageCompare, FewSmallDifferencesPass) {
    TempDir dir;
    // 100 pixels off by 13/255 ≈ 0.05: above the per-pixel threshold, under the 0.1% share.
    const auto a = save(grey(100, 13.0f / 255.0f), dir / "a.png");
    const auto b = save(grey(), dir / "b.png");
    EXPECT_TRUE(images_match(a, b, dir.path(), "few"));
}

TEST(ImageCompare, TooManySmallDifferencesFail) {
    TempDir dir;
    const auto a = save(grey(120, 13.0f / 255.0f), dir / "a.png");
    const auto b = save(grey(), dir / "b.png");
    const auto result = images_match(a, b, dir.path(), "many");
    EXPECT_FALSE(result);
    EXPECT_NE(std::string(result.message()).find("120 of 110592 pixels"), std::string::npos)
        << result.message();
    EXPECT_TRUE(fs::exists(dir.path() / "many.actual.png"));
    EXPECT_TRUE(fs::exists(dir.path() / "many.diff.png"));
}

TEST(ImageCompare, OneLargeDifferenceFailsAndNamesTheArtefacts) {
    TempDir dir;
    // One pixel off by 77/255 ≈ 0.3 > 0.25.
    const auto a = save(grey(1, 77.0f / 255.0f), dir / "a.png");
    const auto b = save(grey(), dir / "b.png");
    const auto result = images_match(a, b, dir.path(), "one");
    ASSERT_FALSE(result);
    const std::string message = result.message();
    EXPECT_NE(message.find("largest difference 0.30"), std::string::npos) << message;
    EXPECT_NE(message.find("at pixel (0, 0)"), std::string::npos) << message;
    EXPECT_NE(message.find((dir.path() / "one.actual.png").string()), std::string::npos);
    EXPECT_NE(message.find((dir.path() / "one.diff.png").string()), std::string::npos);

    // The diff is black where the images agree and bright where they do not.
    ImageBuf diff((dir.path() / "one.diff.png").string());
    float at_error[3];
    float elsewhere[3];
    diff.getpixel(0, 0, at_error, 3);
    diff.getpixel(10, 10, elsewhere, 3);
    EXPECT_GT(at_error[0], 0.99f);
    EXPECT_EQ(elsewhere[0], 0.0f);
}

TEST(ImageCompare, DifferentSizesFailClearly) {
    TempDir dir;
    const auto a = save(grey(0, 0.0f, 320, 240), dir / "a.png");
    const auto b = save(grey(), dir / "b.png");
    const auto result = images_match(a, b, dir.path(), "size");
    ASSERT_FALSE(result);
    EXPECT_NE(std::string(result.message()).find("size differs: actual 320x240, reference 384x288"),
              std::string::npos)
        << result.message();
    EXPECT_TRUE(fs::exists(dir.path() / "size.actual.png"));
}

TEST(ImageCompare, MissingReferenceIsNamed) {
    TempDir dir;
    const auto a = save(grey(), dir / "a.png");
    const auto result = images_match(a, dir / "nope.png", dir.path(), "missing");
    ASSERT_FALSE(result);
    EXPECT_NE(std::string(result.message()).find("missing file"), std::string::npos);
}

}  // namespace
}  // namespace meshedit::test
