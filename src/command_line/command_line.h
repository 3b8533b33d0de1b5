#pragma once
/// \file
/// What every MeshEdit program's command line shares (the `meshedit` subcommands,
/// meshedit-render, meshedit-view), on top of CLI11: the help's style, and usage errors
/// turned into one line "PROGRAM: [COMMAND: ]PROBLEM (see PROGRAM [COMMAND] --help)" with exit
/// status 2, as docs/cli.md promises.

#include <CLI/CLI.hpp>

#include "meshedit/core/budget.h"
#include "meshedit/core/threads.h"

#include <cstdio>
#include <string>
#include <string_view>

namespace meshedit::command_line {

/// CLI11's help, written as MeshEdit's programs wrote theirs: an option shows the name of its
/// value only ("--density N"), never CLI11's type, range or REQUIRED tags; what the value
/// means, its range and its default are in the option's own sentence.
class Formatter : public CLI::Formatter {
public:
    std::string make_option_opts(const CLI::Option* opt) const override {
        if (!opt->get_option_text().empty()) {
            return " " + opt->get_option_text();
        }
        if (!opt->nonpositional() || opt->get_type_size() == 0) {
            return "";
        }
        // CLI11 appends the checks to the type name ("N:INT in [1 - 256]").
        const std::string name = opt->get_type_name();
        return name.empty() ? "" : " " + name.substr(0, name.find(':'));
    }
};

/// MeshEdit's help style for `app` and the subcommands added to it later (CLI11 copies the
/// formatter into each): "usage:", value names only, a wide first column.
inline void style(CLI::App& app) {
    auto formatter = std::make_shared<Formatter>();
    formatter->label("Usage", "usage");
    formatter->label("OPTIONS", "options");
    formatter->label("SUBCOMMAND", "COMMAND");
    formatter->label("SUBCOMMANDS", "COMMAND");
    formatter->column_width(26);
    app.formatter(formatter);
}

/// `--memory-budget SIZE`: the memory budget of this run (meshedit/core/budget.h).
inline CLI::Option* add_memory_budget_option(CLI::App& app) {
    return app
        .add_option_function<std::string>(
            "--memory-budget",
            [](const std::string& text) { set_memory_budget(parse_byte_size(text).value_or(0)); },
            "how much memory a step may plan to use, e.g. 8G or 512M (default: half the "
            "physical memory, or MESHEDIT_MEMORY_BUDGET)")
        ->type_name("SIZE")
        ->check(CLI::Validator(
            [](const std::string& text) {
                return parse_byte_size(text) ? std::string()
                                             : "bad size '" + text + "' (expected e.g. 8G, 512M)";
            },
            ""));
}

/// `--threads N`: the threads of this run's parallel passes (meshedit/core/threads.h).
inline CLI::Option* add_threads_option(CLI::App& app) {
    return app
        .add_option_function<std::string>(
            "--threads",
            [](const std::string& text) { set_thread_count(parse_thread_count(text).value_or(0)); },
            "threads for subdivision, normals and loading, 0 for all cores (default: all, or "
            "MESHEDIT_THREADS); the result is the same on any number")
        ->type_name("N")
        ->check(CLI::Validator(
            [](const std::string& text) {
                return parse_thread_count(text) ? std::string() : bad_thread_count(text);
            },
            ""));
}

/// A bad MESHEDIT_THREADS stops a program before it starts, as a bad --threads would: prints
/// "PROGRAM: MESHEDIT_THREADS: …" on stderr. \return false then.
inline bool check_thread_environment(const std::string& program) {
    if (const auto problem = thread_environment_problem()) {
        std::fprintf(stderr, "%s: %s\n", program.c_str(), problem->c_str());
        return false;
    }
    return true;
}

/// The help of `app` with its full name in the usage line ("usage: meshedit info …").
inline std::string help(const CLI::App& app) {
    std::string prefix;
    for (const CLI::App* up = app.get_parent(); up != nullptr; up = up->get_parent()) {
        prefix = up->get_name() + (prefix.empty() ? "" : " " + prefix);
    }
    return app.help(prefix);
}

/// CLI11's sentence for a usage error in MeshEdit's words: "unknown option '--color'",
/// "missing FILE", "option '--ops' needs a value", else CLI11's own text.
inline std::string problem(const CLI::ParseError& e) {
    const std::string what = e.what();
    if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
        // "The following argument was not expected: --color" (or "arguments … : a b")
        const auto colon = what.find(": ");
        std::string first = colon == std::string::npos ? what : what.substr(colon + 2);
        first = first.substr(0, first.find(' '));
        return (!first.empty() && first[0] == '-' ? "unknown option '" : "unexpected argument '") +
               first + "'";
    }
    if (dynamic_cast<const CLI::RequiredError*>(&e) != nullptr) {
        const auto at = what.find(" is required");
        if (at != std::string::npos) {
            return "missing " + what.substr(0, at);
        }
    }
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) != nullptr) {
        const auto colon = what.find(':');
        if (colon != std::string::npos && what.find("missing") != std::string::npos) {
            return "option '" + what.substr(0, colon) + "' needs a value";
        }
    }
    return what;
}

/// Parses `argv` into `app`. \return -1 to go on; 0 after printing the help that was asked
/// for (on stdout); 2 after printing a usage error (on stderr). `command` is the subcommand's
/// name for the messages (empty for a program without subcommands).
inline int parse(CLI::App& app, int argc, const char* const* argv, const std::string& program,
                 const std::string& command = "") {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        // The help of the innermost subcommand given, as `git CMD --help` does.
        const CLI::App* shown = &app;
        for (const CLI::App* sub = &app; sub != nullptr;) {
            const auto chosen = sub->get_subcommands();
            sub = chosen.empty() ? nullptr : chosen.front();
            shown = sub != nullptr ? sub : shown;
        }
        std::fputs(help(*shown).c_str(), stdout);
        return 0;
    } catch (const CLI::CallForVersion& e) {
        std::puts(e.what());
        return 0;
    } catch (const CLI::ParseError& e) {
        const std::string where = command.empty() ? "" : command + ": ";
        const std::string see = program + (command.empty() ? "" : " " + command) + " --help";
        std::fprintf(stderr, "%s: %s%s (see %s)\n", program.c_str(), where.c_str(),
                     problem(e).c_str(), see.c_str());
        return 2;
    }
    return -1;
}

}  // namespace meshedit::command_line
