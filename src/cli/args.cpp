// Number formatting, notices and input loading shared by the subcommands.

#include <cstdio>

#include "cli.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/number_text.h"
#include "meshedit/io/io.h"

namespace meshedit::cli {

std::string format_number(double x) {
    if (x == 0.0) {
        return "0";  // also for -0, which would only confuse readers
    }
    return number_text(x);
}

void print_row(const std::string& key, const std::string& value) {
    std::printf("%-22s %s\n", (key + ":").c_str(), value.c_str());
}

void print_notice(const std::string& text) {
    std::fprintf(stderr, "meshedit: note: %s\n", text.c_str());
}

void check_mesh_output(const std::filesystem::path& out) {
    if (!is_mesh_extension(file_extension(out))) {
        throw IoError(out.string(), "",
                      "unknown extension '" + out.extension().string() + "' (meshedit writes " +
                          mesh_extensions() + ")");
    }
}

namespace {
bool strict_output = false;  // --strict: one command runs per process
}  // namespace

void add_strict_option(CLI::App& command) {
    command.add_flag("--strict", strict_output,
                     "refuse (exit 1, nothing written) when OUT's format cannot keep something "
                     "the mesh carries, instead of naming it in a note");
}

void write_output(const Mesh& mesh, const std::filesystem::path& out, const IoFlags& flags) {
    if (strict_output) {
        const std::vector<std::string> unkept = unkept_by_format(mesh, file_extension(out));
        if (!unkept.empty()) {
            std::string what;
            for (const std::string& item : unkept) {
                what += (what.empty() ? "" : "; ") + item;
            }
            throw Failure(out.string() + ": not written (--strict): the format cannot keep " +
                          what);
        }
    }
    report_unkept(out, write_mesh(mesh, out, flags));
}

void report_unkept(const std::filesystem::path& out, const std::vector<std::string>& unkept) {
    for (const std::string& what : unkept) {
        print_notice(out.string() + ": not kept: " + what);
    }
}

LoadedDocument load_surface(const std::filesystem::path& path, int density) {
    if (file_extension(path) == ".bzc") {
        throw IoError(path.string(), "",
                      "a .bzc file is a curve, not a surface (use meshedit eval or info)");
    }
    ReadOptions options;
    options.density = density;
    return read_document(path, options);
}

CLI::Option* add_density_option(CLI::App& command, int& density) {
    density = TessellationOptions{}.density;
    return command
        .add_option("--density", density,
                    "quads per patch side when a .bez is tessellated, 1 to 256 (default 8)")
        ->type_name("N")
        ->check(CLI::Range(1, 256));
}

}  // namespace meshedit::cli
