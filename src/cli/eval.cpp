// `meshedit eval FILE.bzc --t T [--levels]` and `meshedit eval FILE.bez --uv U,V [--patch I]`.

#include <charconv>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli.h"
#include "meshedit/core/budget.h"
#include "meshedit/io/io.h"

namespace meshedit::cli {
namespace {

// Curves live in the 2D [0,1] view (z = 0), so they print as "x y".
std::string point2(const Vec3& p) {
    return format_number(p.x) + " " + format_number(p.y);
}
std::string point3(const Vec3& p) {
    return format_number(p.x) + " " + format_number(p.y) + " " + format_number(p.z);
}

struct Settings {
    std::filesystem::path file;
    double t = 0.0;
    bool levels = false;
    std::vector<double> uv;
    int patch = 0;
    CLI::Option* t_option = nullptr;
    CLI::Option* levels_option = nullptr;
    CLI::Option* uv_option = nullptr;
    CLI::Option* patch_option = nullptr;
};

// A number in [0, 1] (CLI::Range lets NaN through).
const CLI::Validator kUnitInterval(
    [](const std::string& text) {
        double x = 0.0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
        if (ec != std::errc() || end != text.data() + text.size() || !(x >= 0.0 && x <= 1.0)) {
            return "bad number '" + text + "' (expected 0 to 1)";
        }
        return std::string();
    },
    "");

int eval_curve(const std::filesystem::path& path, const Settings& s) {
    if (s.t_option->count() == 0) {
        throw UsageError("eval: a .bzc needs --t T (see meshedit eval --help)");
    }
    if (s.uv_option->count() > 0 || s.patch_option->count() > 0) {
        throw UsageError("eval: --uv and --patch are for .bez patches; a .bzc takes --t");
    }
    const double t = s.t;
    const BezierCurve curve = read_bzc(path);
    if (s.levels) {
        // Every level printed: n(n+1)/2 points, each a Vec3 and about 40 bytes of text.
        check_budget(64.0 * de_casteljau_level_points(curve.control_points.size()),
                     path.string() + ": printing every de Casteljau level of a curve of " +
                         std::to_string(curve.control_points.size()) + " points");
        const auto levels = curve.levels(t);
        for (std::size_t k = 0; k < levels.size(); ++k) {
            std::string line = "level " + std::to_string(k) + ":";
            for (const Vec3& p : levels[k]) {
                line += " (" + point2(p) + ")";
            }
            std::printf("%s\n", line.c_str());
        }
    }
    std::printf("B(%s) = (%s)\n", format_number(t).c_str(), point2(curve.evaluate(t)).c_str());
    return 0;
}

int eval_patch(const std::filesystem::path& path, const Settings& s) {
    if (s.uv_option->count() == 0) {
        throw UsageError("eval: a .bez needs --uv U,V (see meshedit eval --help)");
    }
    if (s.t_option->count() > 0 || s.levels_option->count() > 0) {
        throw UsageError("eval: --t and --levels are for .bzc curves; a .bez takes --uv U,V");
    }
    const double u = s.uv[0];
    const double v = s.uv[1];
    const std::vector<BezierPatch> patches = read_bez(path);
    const int index = s.patch;
    if (static_cast<std::size_t>(index) >= patches.size()) {
        throw UsageError("eval: --patch " + std::to_string(index) + " is out of range (" +
                         path.string() + " has " + std::to_string(patches.size()) +
                         " patches, numbered from 0)");
    }
    const PatchPoint p = patches[static_cast<std::size_t>(index)].evaluate_with_derivatives(u, v);
    std::printf("patch %d at (u, v) = (%s, %s)\n", index, format_number(u).c_str(),
                format_number(v).c_str());
    std::printf("position: %s\n", point3(p.position).c_str());
    std::printf("normal:   %s\n", point3(p.normal).c_str());
    return 0;
}

}  // namespace

Command add_eval(CLI::App& meshedit) {
    auto s = std::make_shared<Settings>();
    CLI::App* app = meshedit.add_subcommand(
        "eval", "evaluate a Bezier curve at t or a patch at (u, v) (de Casteljau)");
    app->add_option("FILE", s->file, "a .bzc curve or a .bez patch set")->required();
    s->t_option = app->add_option("--t", s->t, "curve parameter in [0, 1]; prints \"B(T) = (x y)\"")
                      ->type_name("T")
                      ->check(kUnitInterval);
    s->levels_option = app->add_flag(
        "--levels", s->levels,
        "also print every de Casteljau level, one line each: \"level K: (x y) (x y) ...\" "
        "(level 0 = the control points)");
    s->uv_option = app->add_option("--uv", s->uv,
                                   "patch parameters in [0, 1]; prints the position and the unit "
                                   "normal")
                       ->type_name("U,V")
                       ->delimiter(',')
                       ->expected(2)
                       ->check(kUnitInterval);
    s->patch_option = app->add_option("--patch", s->patch, "which patch (default 0)")
                          ->type_name("I")
                          ->check(CLI::NonNegativeNumber);
    app->footer(
        "Evaluates a Bezier curve (FILE.bzc) at t, or patch I (default 0, numbered from 0) of a\n"
        "patch set (FILE.bez) at (u, v), by de Casteljau's algorithm. Parameters are in [0, 1].\n"
        "\n"
        "Examples:\n"
        "  meshedit eval bez/curve1.bzc --t 0.5 --levels\n"
        "  meshedit eval bez/teapot.bez --uv 0.5,0.5 --patch 3\n"
        "\n"
        "Exit status: 0 ok, 2 bad usage or an unreadable file.");
    return {app, [s] {
                const std::filesystem::path& path = s->file;
                const std::string ext = file_extension(path);
                if (ext == ".bzc") {
                    return eval_curve(path, *s);
                }
                if (ext == ".bez") {
                    return eval_patch(path, *s);
                }
                throw IoError(path.string(), "",
                              "unknown extension '" + path.extension().string() +
                                  "' for eval (expected a .bzc curve or a .bez patch set)");
            }};
}

}  // namespace meshedit::cli
