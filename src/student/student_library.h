#pragma once
/// \file
/// Loading a student library (meshedit/student/student.h): what `meshedit grade` and
/// `meshedit-view --student` both do before calling its functions.

#include <filesystem>

#include "meshedit/student/student.h"

namespace meshedit::cli::grade {

/// dlopen()s `path` and asks it for its table of functions. The library stays loaded for the
/// program's life; forked children inherit it. Its initialisers are student code: a caller
/// that must not go down loads it in run_isolated() first.
/// \throws std::runtime_error naming the library and what is wrong (cannot be opened, no
/// table, built against another student API version).
const student::StudentTasks& load_student_library(const std::filesystem::path& path);

}  // namespace meshedit::cli::grade
