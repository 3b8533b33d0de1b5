#include "image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>

namespace meshedit::test {
namespace {

namespace fs = std::filesystem;
using OIIO::ImageBuf;
namespace IBA = OIIO::ImageBufAlgo;

// The diff image multiplies errors by this: the pass threshold (0.02) becomes 0.2 of full
// scale, clearly visible, while the background (exact zero) stays black.
constexpr float kDiffGain = 10.0f;

// Reads `path` fully as float so both images are compared in the same pixel type whatever
// their files store. Empty string on success, the reason otherwise.
std::string load(const fs::path& path, ImageBuf& image) {
    if (!fs::exists(path)) {
        return "missing file " + path.string();
    }
    image.reset(path.string());
    if (!image.read(0, 0, /*force=*/true, OIIO::TypeDesc::FLOAT)) {
        return "cannot read " + path.string() + ": " + image.geterror();
    }
    return {};
}

// The channels of `image` as RGB: grey replicated, alpha dropped.
ImageBuf as_rgb(const ImageBuf& image) {
    const int n = image.nchannels();
    const int order[3] = {0, n >= 3 ? 1 : 0, n >= 3 ? 2 : 0};
    return IBA::channels(image, 3, order);
}

// |a − b| per channel, amplified, as an opaque RGB image. Alpha differences are folded into
// all three channels (max) so a coverage change is visible even where the colours agree.
ImageBuf difference_image(const ImageBuf& a, const ImageBuf& b) {
    const ImageBuf diff = IBA::absdiff(a, b);
    ImageBuf rgb = as_rgb(diff);
    if (diff.nchannels() >= 4) {
        const int alpha[3] = {3, 3, 3};
        rgb = IBA::max(rgb, IBA::channels(diff, 3, alpha));
    }
    return IBA::clamp(IBA::mul(rgb, kDiffGain), 0.0f, 1.0f);
}

// Writes `image` as an 8-bit PNG; a note for the failure message if that fails.
std::string save(const ImageBuf& image, const fs::path& path) {
    if (!image.write(path.string(), OIIO::TypeDesc::UINT8)) {
        return "\n  (could not write " + path.string() + ": " + image.geterror() + ")";
    }
    return {};
}

}  // namespace

bool same_file_bytes(const fs::path& a, const fs::path& b) {
    std::ifstream fa(a, std::ios::binary);
    std::ifstream fb(b, std::ios::binary);
    if (!fa || !fb) {
        return false;
    }
    return std::equal(std::istreambuf_iterator<char>(fa), std::istreambuf_iterator<char>(),
                      std::istreambuf_iterator<char>(fb), std::istreambuf_iterator<char>());
}

::testing::AssertionResult images_match(const fs::path& actual, const fs::path& reference,
                                        const fs::path& out_dir, const std::string& name,
                                        const ImageTolerance& tol) {
    const fs::path actual_copy = out_dir / (name + ".actual.png");
    const fs::path diff_path = out_dir / (name + ".diff.png");
    std::error_code ec;
    fs::create_directories(out_dir, ec);
    // Stale artefacts from an earlier failure would mislead whoever looks in the folder.
    fs::remove(actual_copy, ec);
    fs::remove(diff_path, ec);

    ImageBuf a;
    ImageBuf b;
    if (std::string why = load(actual, a); !why.empty()) {
        return ::testing::AssertionFailure() << name << ": actual image: " << why;
    }
    if (std::string why = load(reference, b); !why.empty()) {
        return ::testing::AssertionFailure() << name << ": reference image: " << why;
    }

    // Keeps the actual image for inspection whatever went wrong below.
    auto fail_with_actual = [&]() {
        fs::copy_file(actual, actual_copy, fs::copy_options::overwrite_existing, ec);
        return ::testing::AssertionFailure();
    };

    const OIIO::ImageSpec& sa = a.spec();
    const OIIO::ImageSpec& sb = b.spec();
    if (sa.width != sb.width || sa.height != sb.height) {
        return fail_with_actual() << name << ": size differs: actual " << sa.width << "x"
                                  << sa.height << ", reference " << sb.width << "x" << sb.height
                                  << " (" << reference.string()
                                  << ")\n  actual: " << actual_copy.string();
    }
    if (sa.nchannels != sb.nchannels) {
        return fail_with_actual() << name << ": channel count differs: actual " << sa.nchannels
                                  << ", reference " << sb.nchannels << " (" << reference.string()
                                  << ")\n  actual: " << actual_copy.string();
    }

    const IBA::CompareResults r = IBA::compare(a, b, tol.pixel_threshold, tol.pixel_threshold);
    // r.error is not checked: OIIO 2.4 sets it whenever any pixel exceeds failthresh, which
    // the share rule below is meant to tolerate. Both images were read above, so a genuine
    // failure to compare cannot happen here.
    const auto pixels = static_cast<double>(sa.width) * sa.height;
    const double failed_fraction = static_cast<double>(r.nfail) / pixels;
    const bool too_many = failed_fraction > tol.max_failed_fraction;
    const bool too_far = r.maxerror > tol.max_difference;
    if (!too_many && !too_far) {
        return ::testing::AssertionSuccess();
    }

    auto result = fail_with_actual();
    std::ostringstream why;
    why << name << ": render differs from " << reference.string() << "\n  " << r.nfail << " of "
        << static_cast<long>(pixels) << " pixels (" << 100.0 * failed_fraction
        << "%) differ by more than " << tol.pixel_threshold << " (allowed "
        << 100.0 * tol.max_failed_fraction << "%)\n  largest difference " << r.maxerror
        << " at pixel (" << r.maxx << ", " << r.maxy << ") channel " << r.maxc << " (allowed "
        << tol.max_difference << ")\n  actual: " << actual_copy.string()
        << "\n  diff:   " << diff_path.string() << " (|actual - reference| x" << kDiffGain << ")";
    why << save(difference_image(a, b), diff_path);
    return result << why.str();
}

}  // namespace meshedit::test
