#pragma once
/// \file
/// The cases `meshedit grade` runs: the standard battery per task (the course's meshes,
/// random meshes, boundaries, valence 3 and 12, creases, inputs that must be refused) and a
/// teacher's folder of extra cases.

#include <array>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "grade_bridge.h"

namespace meshedit::cli::grade {

/// The six tasks, in the course's order, by the names of their functions in student.h.
inline constexpr std::array<const char*, 6> kTasks = {
    "evaluate_step", "evaluate_patch", "vertex_normal", "flip_edge", "split_edge", "upsample"};

struct Case {
    std::string task;  ///< one of kTasks
    std::string name;  ///< "cube.dae edge 7 (0-6)"
    bool hidden = false;
    /// "" for a pass, else what is wrong (grade_checks.h).
    std::function<std::string(const st::StudentTasks&)> run;
};

/// The standard battery. `samples` is the folder holding dae/ and bez/ (empty when none was
/// found: the cases that need its files are left out and `notes` says so).
std::vector<Case> standard_cases(const std::filesystem::path& samples,
                                 std::vector<std::string>& notes);

/// A teacher's cases from `dir`: every mesh file (triangles only) gives a normals, a flip, a
/// split and a Loop case; every `.ops` file a session of flip:A-B and split:A-B steps on
/// the mesh its `# input:` line names (relative to `dir`) or the mesh of the same stem. A
/// case is hidden when its file's name contains ".hidden." or starts with "hidden", or when
/// `dir/manifest.txt` has a line `hidden FILE`. \throws UsageError for a bad session line.
std::vector<Case> folder_cases(const std::filesystem::path& dir);

/// The folder with dae/cube.dae above the current folder or the executable's, or empty.
std::filesystem::path find_samples();

}  // namespace meshedit::cli::grade
