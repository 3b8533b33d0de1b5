#pragma once
/// \file
/// Shared pieces of the `meshedit` subcommands: argument parsing, the two error kinds the
/// CLI adds to IoError and OpError, number parsing, and loading any mesh-like input.
///
/// Exit status (docs/cli.md): 0 success, 1 failure (a refused op, an invalid mesh), 2 bad
/// usage or bad input. main() maps exceptions to these: UsageError, IoError and an OpError
/// that names a missing element give 2; Failure and a refused OpError give 1.

#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshedit/io/document.h"

namespace meshedit::cli {

/// Bad usage: an unknown option, a missing argument, a bad number (exit 2).
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The command ran but could not do its job for a reason that is not bad input: exit 1.
class Failure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// An option a subcommand accepts.
struct OptionSpec {
    std::string name;  ///< "--json", "-n"
    bool takes_value;  ///< "--ops LIST" / "--ops=LIST" vs a flag
};

/// Parsed command line of one subcommand.
struct Args {
    std::vector<std::string> positional;
    std::map<std::string, std::string> values;  ///< option name → value
    std::set<std::string> flags;                ///< flags given
    bool help = false;                          ///< -h or --help

    bool has(const std::string& name) const {
        return flags.count(name) != 0 || values.count(name) != 0;
    }
    const std::string* value(const std::string& name) const {
        const auto it = values.find(name);
        return it == values.end() ? nullptr : &it->second;
    }
};

/// Parses `argv` (the words after the subcommand name). Options and positionals may be
/// mixed; `--` ends the options. \throws UsageError naming `command` and the bad word.
Args parse_args(const std::string& command, const std::vector<std::string>& argv,
                const std::vector<OptionSpec>& options);

/// \throws UsageError unless `args` has exactly `count` positionals.
void expect_positionals(const std::string& command, const Args& args, std::size_t count,
                        const std::string& what);

/// Strict number parsing: the whole word, finite. \throws UsageError naming `option`.
double parse_double(const std::string& text, const std::string& option);
int parse_int(const std::string& text, const std::string& option, int min, int max);

/// Shortest round-trip text for a double ("0.1", "-1", "1e-300").
std::string format_number(double x);

/// A mesh from any input the mesh commands accept: read_document() on a mesh file, or a .bez
/// tessellated at `density`. \throws IoError naming the file (a .bzc is refused: it is not a
/// surface).
LoadedDocument load_surface(const std::filesystem::path& path, int density);

/// Subcommands; each returns the exit status (errors are thrown).
int run_info(const std::vector<std::string>& argv);
int run_convert(const std::vector<std::string>& argv);
int run_subdivide(const std::vector<std::string>& argv);
int run_check(const std::vector<std::string>& argv);
int run_eval(const std::vector<std::string>& argv);

/// Prints a notice on stderr as "meshedit: note: <text>".
void print_notice(const std::string& text);

}  // namespace meshedit::cli
