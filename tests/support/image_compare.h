#pragma once
/// \file
/// Golden-image comparison for tests: an actual render against a reference PNG through
/// OpenImageIO's ImageBufAlgo::compare, with the actual and an amplified difference image
/// written beside each other on failure so a reviewer can open them.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace meshedit::test {

/// When two renders count as the same picture. The defaults are the project's golden rule
/// (issue 4): small per-channel noise is tolerated on a few pixels, a wrong colour anywhere is
/// not.
struct ImageTolerance {
    /// A pixel fails when any channel differs by more than this (channel values in [0, 1]).
    float pixel_threshold = 0.02f;
    /// The comparison fails when more than this share of the pixels fail.
    double max_failed_fraction = 0.001;
    /// The comparison fails when any channel of any pixel differs by more than this.
    float max_difference = 0.25f;
};

/// Compares the image at `actual` with the one at `reference`. On a mismatch (including a
/// different size or channel count, or an unreadable file) writes `out_dir/NAME.actual.png`
/// (a copy of the actual image) and `out_dir/NAME.diff.png` (|actual − reference| per channel,
/// amplified so small errors show, alpha folded into RGB) and names both in the message. On a
/// match removes any such files left from an earlier failing run.
::testing::AssertionResult images_match(const std::filesystem::path& actual,
                                        const std::filesystem::path& reference,
                                        const std::filesystem::path& out_dir,
                                        const std::string& name, const ImageTolerance& tol = {});

/// True when both files exist and hold the same bytes.
bool same_file_bytes(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace meshedit::test
