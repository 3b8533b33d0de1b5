#pragma once
/// \file
/// Shared pieces of the `meshedit` subcommands: the two error kinds the CLI adds to IoError
/// and ops::OpError, loading any mesh-like input, and the subcommands themselves, each a
/// CLI11 subcommand with its options bound to its own settings.
///
/// Exit status (docs/cli.md): 0 success, 1 failure (a refused op, an invalid mesh), 2 bad
/// usage or bad input. main() maps exceptions to these through the ladder every program
/// shares (command_line/exit_status.h).

#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "exit_status.h"
#include "meshedit/core/number_text.h"
#include "meshedit/io/document.h"
#include "meshedit/io/io.h"

namespace meshedit::cli {

/// Bad usage the parser cannot see (exit 2) and a failure that is not bad input (exit 1):
/// command_line/exit_status.h's, which main() maps to exit statuses.
using command_line::Failure;
using command_line::UsageError;

/// Shortest round-trip text for a double ("0.1", "-1", "1e-300"; "0" for -0 too). A number
/// as a person reads it is the core's readable_number() (number_text.h); --json keeps every
/// digit.
std::string format_number(double x);

/// One "key:  value" line of a text report, the values aligned in one column.
void print_row(const std::string& key, const std::string& value);

/// Prints a notice on stderr as "meshedit: note: <text>".
void print_notice(const std::string& text);

/// Refuses an output we cannot write before doing any work, so a typo in the output name
/// does not cost a long subdivision first. \throws IoError naming it.
void check_mesh_output(const std::filesystem::path& out);

/// `--strict` on a command that writes a mesh: write_output() then refuses to drop anything.
void add_strict_option(CLI::App& command);
/// Writes `mesh` to `out` and names in notes what its format could not keep; with --strict
/// refuses instead (\throws Failure naming the output and what, nothing written).
void write_output(const Mesh& mesh, const std::filesystem::path& out, const IoFlags& flags = {});

/// What the output's format could not keep (write_mesh()'s answer), as notes: never lost
/// without a word.
void report_unkept(const std::filesystem::path& out, const std::vector<std::string>& unkept);

/// A mesh from any input the mesh commands accept: read_document() on a mesh file, or a .bez
/// tessellated at `density`. \throws IoError naming the file (a .bzc is refused: it is not a
/// surface).
LoadedDocument load_surface(const std::filesystem::path& path, int density);

/// The `--density N` option of the commands that read .bez files.
CLI::Option* add_density_option(CLI::App& command, int& density);

/// A subcommand: its CLI11 app (options bound to its settings) and what runs when it is
/// chosen; run() returns the exit status and throws the errors main() maps.
struct Command {
    CLI::App* app = nullptr;
    std::function<int()> run;
};

/// `check --problems`: prints the problems of `input` read from `path` (one line each and a
/// summary, or one JSON object with `json`). \return 0 for none, 1 for some or an invalid mesh.
int print_problems(const std::filesystem::path& path, const LoadedDocument& input, bool json);

Command add_info(CLI::App& meshedit);
Command add_convert(CLI::App& meshedit);
Command add_subdivide(CLI::App& meshedit);
Command add_simplify(CLI::App& meshedit);
Command add_remesh(CLI::App& meshedit);
Command add_repair(CLI::App& meshedit);
Command add_check(CLI::App& meshedit);
Command add_eval(CLI::App& meshedit);
Command add_compare(CLI::App& meshedit);
Command add_grade(CLI::App& meshedit);

}  // namespace meshedit::cli
