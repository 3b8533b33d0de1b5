// `meshedit`: dispatch to the subcommands, usage, and the one place where exceptions become
// "meshedit: <message>" lines and exit statuses (docs/cli.md).

#include <unistd.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <vector>

#include "cli.h"
#include "meshedit/files/io_error.h"
#include "meshedit/ops/ops.h"

namespace {

using namespace meshedit::cli;

constexpr const char* kUsage =
    "usage: meshedit <command> [options]\n"
    "\n"
    "Commands:\n"
    "  info FILE [--json]                      counts, topology, bounding box, repairs\n"
    "  convert IN OUT [--ops LIST]             convert (.dae .gltf .glb .obj; .bez in),\n"
    "                                          applying edits such as flip:0-6,loop\n"
    "  subdivide IN OUT -n K [--weights W]     Loop subdivision, W = warren or loop\n"
    "  check FILE                              validate the halfedge invariants\n"
    "  eval FILE.bzc --t T [--levels]          evaluate a Bezier curve (de Casteljau)\n"
    "  eval FILE.bez --uv U,V [--patch I]      evaluate a Bezier patch\n"
    "  [view] FILE [--size WxH]                the interactive viewer (meshedit-view)\n"
    "  render FILE -o OUT.png [options]        render headless (meshedit-render)\n"
    "\n"
    "Run 'meshedit <command> --help' for a command's options and examples,\n"
    "'meshedit --version' for the version.\n"
    "Exit status: 0 success, 1 failure (refused op, invalid mesh), 2 bad usage or input.\n";

void print_error(const std::string& message) {
    std::fprintf(stderr, "meshedit: %s\n", message.c_str());
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

int dispatch(int argc, char** argv) {
    if (argc < 2) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    const std::string command = argv[1];
    const std::vector<std::string> rest(argv + 2, argv + argc);
    if (command == "-h" || command == "--help") {
        std::fputs(kUsage, stdout);
        return 0;
    }
    if (command == "--version") {
        std::printf("meshedit %s\n", MESHEDIT_VERSION);
        return 0;
    }
    if (command == "help") {
        if (rest.empty()) {
            std::fputs(kUsage, stdout);
            return 0;
        }
        return dispatch(3,
                        std::vector<char*>{argv[0], argv[2], const_cast<char*>("--help")}.data());
    }
    if (command == "info") {
        return run_info(rest);
    }
    if (command == "convert") {
        return run_convert(rest);
    }
    if (command == "subdivide") {
        return run_subdivide(rest);
    }
    if (command == "check") {
        return run_check(rest);
    }
    if (command == "eval") {
        return run_eval(rest);
    }
    if (command == "view") {
        return exec_viewer(argc, argv, 2);
    }
    exec_external(command, argv);
    if (command == "render") {
        print_error("render is not built yet; use 'meshedit info FILE' for a description");
        return 1;
    }
    if (command[0] != '-' && looks_like_file(command)) {
        return exec_viewer(argc, argv, 1);
    }
    throw UsageError("unknown command '" + command + "' (see meshedit --help)");
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return dispatch(argc, argv);
    } catch (const UsageError& e) {
        print_error(e.what());
        return 2;
    } catch (const meshedit::IoError& e) {
        print_error(e.what());
        return 2;
    } catch (const meshedit::ops::OpError& e) {
        print_error(e.what());
        return e.refused() ? 1 : 2;
    } catch (const Failure& e) {
        print_error(e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        print_error("out of memory");
        return 1;
    } catch (const std::exception& e) {
        print_error(std::string("internal error: ") + e.what());
        return 1;
    }
}
