#pragma once
/// \file
/// A progress bar on stderr for long work. It draws only when stderr is a terminal and the
/// work has already taken more than a second, so scripts, pipes and quick runs stay quiet.

#include <chrono>
#include <string>

namespace meshedit::cli {

class ProgressBar {
public:
    /// `label` prefixes the bar ("subdividing").
    explicit ProgressBar(std::string label);
    /// Clears the bar's line if it was drawn.
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    /// Reports the fraction done (0…1); cheap when nothing needs drawing.
    void update(double fraction);

private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    int last_percent_ = -1;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace meshedit::cli
