// `meshedit`: dispatch to the subcommands, usage, and the one place where exceptions become
// "meshedit: <message>" lines and exit statuses (docs/cli.md).

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <string_view>
#include <vector>

#include "cli.h"
#include "command_line.h"
#include "exit_status.h"
#include "meshedit/core/budget.h"
#include "meshedit/files/io_error.h"
#include "meshedit/ops/ops.h"

namespace {

// The commands run_builtin() runs (it registers one of each); any other name is a
// meshedit-COMMAND beside this executable, or a file to view.
constexpr std::array<std::string_view, 10> kBuiltins{"info",    "convert", "subdivide", "simplify",
                                                     "remesh",  "repair",  "check",     "eval",
                                                     "compare", "grade"};

using namespace meshedit::cli;

// What the help lists beside the built-in subcommands: the ones other executables answer.
constexpr const char* kMoreCommands =
    "Also:\n"
    "  [view] FILE [--size WxH]                the interactive viewer (meshedit-view)\n"
    "  render FILE -o OUT.png [options]        render headless (meshedit-render)\n"
    "\n"
    "Run 'meshedit COMMAND --help' for a command's options and examples, 'meshedit --version'\n"
    "for the version.\n"
    "Exit status: 0 success, 1 failure (refused op, invalid mesh), 2 bad usage or input.";

void print_error(const std::string& message) {
    meshedit::command_line::print_error("meshedit", message);
}

// Git-style external subcommand: `meshedit render …` runs `meshedit-render …` from the
// folder of this executable, when it exists. Returns only if there is none.
void exec_external(const std::string& command, char** argv) {
    if (command.empty() || command.find('/') != std::string::npos || command[0] == '-') {
        return;  // a path or an option is never a subcommand name
    }
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) {
        return;
    }
    const std::filesystem::path tool = self.parent_path() / ("meshedit-" + command);
    if (::access(tool.c_str(), X_OK) == 0) {
        ::setenv("MESHEDIT_CALLED_AS", "meshedit", 1);  // its messages say "meshedit:" too
        argv[1] = const_cast<char*>(tool.c_str());
        ::execv(tool.c_str(), argv + 1);
    }
}

// `meshedit FILE …` and `meshedit view FILE …`: runs meshedit-view with argv[first…].
int exec_viewer(int argc, char** argv, int first) {
    std::vector<char*> args{const_cast<char*>("view")};
    args.insert(args.end(), argv + first, argv + argc);
    args.push_back(nullptr);
    std::vector<char*> with_program{argv[0]};
    with_program.insert(with_program.end(), args.begin(), args.end());
    exec_external("view", with_program.data());
    print_error(
        "the viewer (meshedit-view) is not installed beside meshedit; render headless "
        "with 'meshedit render FILE -o out.png'");
    return 1;
}

bool looks_like_file(const std::string& word) {
    std::error_code ec;
    return word.find('.') != std::string::npos || word.find('/') != std::string::npos ||
           std::filesystem::exists(word, ec);
}

// The subcommands built into this executable, parsed by CLI11 (command_line.h).
int run_builtin(int argc, char** argv) {
    CLI::App app(
        "MeshEdit's command line: describe, convert, edit, subdivide, repair, check and compare "
        "meshes, evaluate Bezier curves and patches, and grade student libraries.",
        "meshedit");
    meshedit::command_line::style(app);
    app.set_version_flag("--version", std::string("meshedit ") + MESHEDIT_VERSION);
    app.require_subcommand(1, 1);
    meshedit::command_line::add_memory_budget_option(app);
    const CLI::Option* threads = meshedit::command_line::add_threads_option(app);
    app.footer(kMoreCommands);
    const Command commands[] = {
        add_info(app),   add_convert(app), add_subdivide(app), add_simplify(app), add_remesh(app),
        add_repair(app), add_check(app),   add_eval(app),      add_compare(app),  add_grade(app)};
    static_assert(std::size(commands) == kBuiltins.size(), "kBuiltins lists every command");
    for (const Command& c : commands) {
        c.app->group("Commands");
        c.app->fallthrough();  // --memory-budget, --threads after the command name work too
    }
    const std::string command = argc > 1 ? argv[1] : "";
    if (command.empty()) {
        std::fputs(meshedit::command_line::help(app).c_str(), stderr);
        return 2;
    }
    const bool known = std::any_of(std::begin(commands), std::end(commands),
                                   [&](const Command& c) { return c.app->get_name() == command; });
    if (const int status =
            meshedit::command_line::parse(app, argc, argv, "meshedit", known ? command : "");
        status >= 0) {
        return status;
    }
    // --threads wins over the variable, which is only checked when it is used.
    if (threads->count() == 0 && !meshedit::command_line::check_thread_environment("meshedit")) {
        return 2;
    }
    for (const Command& c : commands) {
        if (c.app->parsed()) {
            return c.run();
        }
    }
    return 2;  // require_subcommand makes this unreachable
}

int dispatch(int argc, char** argv) {
    const std::string command = argc > 1 ? argv[1] : "";
    if (command == "help") {
        // `meshedit help convert` is `meshedit convert --help`.
        std::vector<char*> args{argv[0]};
        if (argc > 2) {
            args.push_back(argv[2]);
        }
        args.push_back(const_cast<char*>("--help"));
        return dispatch(static_cast<int>(args.size()), args.data());
    }
    if (command == "view") {
        return exec_viewer(argc, argv, 2);
    }
    if (command == "render") {
        exec_external(command, argv);
        print_error(
            "meshedit-render is not installed beside meshedit (it needs EGL or OSMesa at build "
            "time); use 'meshedit info FILE' for a description");
        return 1;
    }
    const bool builtin = std::find(kBuiltins.begin(), kBuiltins.end(), command) != kBuiltins.end();
    if (!builtin && !command.empty() && command[0] != '-') {
        exec_external(command, argv);  // a meshedit-COMMAND beside this executable
        if (looks_like_file(command)) {
            return exec_viewer(argc, argv, 1);
        }
        throw UsageError("unknown command '" + command + "' (see meshedit --help)");
    }
    return run_builtin(argc, argv);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return dispatch(argc, argv);
    } catch (...) {
        return meshedit::command_line::exit_status_of_current_exception("meshedit");
    }
}
