// `meshedit eval FILE.bzc --t T [--levels]` and `meshedit eval FILE.bez --uv U,V [--patch I]`.

#include <cstdio>
#include <string>
#include <vector>

#include "cli.h"
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

double unit_parameter(const std::string& text, const std::string& option) {
    const double x = parse_double(text, option);
    if (x < 0.0 || x > 1.0) {
        throw UsageError("bad number '" + text + "' for " + option + " (expected 0 to 1)");
    }
    return x;
}

int eval_curve(const std::filesystem::path& path, const Args& args) {
    if (args.value("--t") == nullptr) {
        throw UsageError("eval: a .bzc needs --t T (see meshedit eval --help)");
    }
    if (args.has("--uv") || args.has("--patch")) {
        throw UsageError("eval: --uv and --patch are for .bez patches; a .bzc takes --t");
    }
    const double t = unit_parameter(*args.value("--t"), "--t");
    const BezierCurve curve = read_bzc(path);
    if (args.has("--levels")) {
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

int eval_patch(const std::filesystem::path& path, const Args& args) {
    if (args.value("--uv") == nullptr) {
        throw UsageError("eval: a .bez needs --uv U,V (see meshedit eval --help)");
    }
    if (args.has("--t") || args.has("--levels")) {
        throw UsageError("eval: --t and --levels are for .bzc curves; a .bez takes --uv U,V");
    }
    const std::string& uv = *args.value("--uv");
    const auto comma = uv.find(',');
    if (comma == std::string::npos) {
        throw UsageError("bad value '" + uv + "' for --uv (expected U,V such as 0.5,0.25)");
    }
    const double u = unit_parameter(uv.substr(0, comma), "--uv");
    const double v = unit_parameter(uv.substr(comma + 1), "--uv");
    const std::vector<BezierPatch> patches = read_bez(path);
    int index = 0;
    if (const std::string* text = args.value("--patch")) {
        index = parse_int(*text, "--patch", 0, 1 << 30);
    }
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

int run_eval(const std::vector<std::string>& argv) {
    const Args args = parse_args(
        "eval", argv, {{"--t", true}, {"--levels", false}, {"--uv", true}, {"--patch", true}});
    if (args.help) {
        std::printf(
            "usage: meshedit eval FILE.bzc --t T [--levels]\n"
            "       meshedit eval FILE.bez --uv U,V [--patch I]\n"
            "\n"
            "Evaluates a Bezier curve at t, or patch I (default 0, numbered from 0) of a patch\n"
            "set at (u, v), by de Casteljau's algorithm. Parameters are in [0, 1].\n"
            "\n"
            "  --t T        curve parameter; prints \"B(T) = (x y)\"\n"
            "  --levels     also print every de Casteljau level, one line each:\n"
            "               \"level K: (x y) (x y) ...\" (level 0 = the control points)\n"
            "  --uv U,V     patch parameters; prints the position and the unit normal\n"
            "  --patch I    which patch\n"
            "\n"
            "Example:\n"
            "  meshedit eval bez/curve1.bzc --t 0.5 --levels\n"
            "\n"
            "Exit status: 0 ok, 2 bad usage or an unreadable file.\n");
        return 0;
    }
    expect_positionals("eval", args, 1, "FILE");
    const std::filesystem::path path = args.positional[0];
    const std::string ext = file_extension(path);
    if (ext == ".bzc") {
        return eval_curve(path, args);
    }
    if (ext == ".bez") {
        return eval_patch(path, args);
    }
    throw IoError(path.string(), "",
                  "unknown extension '" + path.extension().string() +
                      "' for eval (expected a .bzc curve or a .bez patch set)");
}

}  // namespace meshedit::cli
