#pragma once
/// \file
/// How many threads MeshEdit's parallel passes (Loop and Catmull-Clark subdivision, vertex
/// normals, the halfedge build, remeshing's smoothing, COLLADA parsing) may use. One setting
/// for the whole process, taken from, in order:
///
/// 1. set_thread_count() (the `--threads N` option of the programs, `meshedit.set_threads(n)`
///    in Python);
/// 2. the environment variable MESHEDIT_THREADS, read once, at the first use;
/// 3. all cores (std::thread::hardware_concurrency()).
///
/// 0 means all cores wherever a count is given. Every parallel pass gives the same bits on any
/// number of threads, so the setting changes only the time.

#include <optional>
#include <string>
#include <string_view>

namespace meshedit {

/// The largest count accepted: more would be a typing mistake, not a machine.
inline constexpr unsigned kMaxThreads = 1024;

/// The cores of this machine (std::thread::hardware_concurrency(), at least 1).
unsigned hardware_threads();

/// The threads a parallel pass may use now (see the file comment): at least 1.
unsigned thread_count();

/// Sets the count for this process; 0 means all cores. Overrides MESHEDIT_THREADS.
/// \throws std::invalid_argument above kMaxThreads.
void set_thread_count(unsigned n);

/// Forgets set_thread_count(): back to MESHEDIT_THREADS or all cores.
void reset_thread_count();

/// A count as a person writes it: digits only, 0 to kMaxThreads; nullopt otherwise ("-1",
/// "two", "4.5", "", "100000").
std::optional<unsigned> parse_thread_count(std::string_view text);

/// What is wrong with MESHEDIT_THREADS, as one sentence naming it ("MESHEDIT_THREADS: 'abc' is
/// not a thread count …"),
/// or nullopt when it is unset or good. The programs refuse to start with it; a bad value is
/// otherwise ignored (all cores).
std::optional<std::string> thread_environment_problem();

/// Why `text` is not a count: "'two' is not a thread count (a whole number from 0, …)", for
/// the caller to put after what gave it ("--threads: ", "MESHEDIT_THREADS: ").
std::string bad_thread_count(std::string_view text);

}  // namespace meshedit
