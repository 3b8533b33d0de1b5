#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace meshedit::cli {
namespace {

constexpr int kWidth = 30;

}  // namespace

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)),
      enabled_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    if (drawn_) {
        // Erase the bar so the next message starts on a clean line.
        std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
    }
}

void ProgressBar::update(double fraction) {
    if (!enabled_) {
        return;
    }
    const int percent = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 100.0);
    if (percent == last_percent_) {
        return;
    }
    // Work under a second never shows a bar: it would only flicker.
    if (!drawn_ && std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) {
        return;
    }
    last_percent_ = percent;
    drawn_ = true;
    const int filled = percent * kWidth / 100;
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.append(static_cast<std::size_t>(kWidth - filled), '.');
    std::fprintf(stderr, "\r%s [%s] %3d%%", label_.c_str(), bar.c_str(), percent);
    std::fflush(stderr);
}

}  // namespace meshedit::cli
