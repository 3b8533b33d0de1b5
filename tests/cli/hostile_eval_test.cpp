// Hostile inputs to `eval`, `info --stats` and `convert --ops @FILE`: a curve of a million
// points, patches and meshes at 1e200 and ±1.7e308, a session of half a million lines. Each
// ends in seconds with the right numbers or one line naming the file and the budget.

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "run.h"

namespace meshedit::test {
namespace {

// The command-line tool formats numbers with "%.17g"-like round trips; read them back.
std::vector<double> numbers_after(const std::string& text, const std::string& label) {
    const auto at = text.find(label);
    EXPECT_NE(at, std::string::npos) << text;
    std::istringstream in(text.substr(at + label.size()));
    std::vector<double> out;
    double x = 0;
    char c = 0;
    while (in >> std::ws && in.peek() != '\n' && in.peek() != EOF) {
        if (in.peek() == '(' || in.peek() == ')') {
            in >> c;
            continue;
        }
        if (!(in >> x)) {
            break;
        }
        out.push_back(x);
    }
    return out;
}

TEST(HostileEval, MillionPointCurveIsEvaluatedInSeconds) {
    // Pᵢ = (i/n, (i/n)²): B(t) = (t, t² + t(1−t)/n) exactly. By n²/2 lerps this took minutes.
    TempDir dir;
    const int n = 1'000'000;
    {
        std::FILE* f = std::fopen((dir / "long.bzc").c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fprintf(f, "%d\n", n + 1);
        for (int i = 0; i <= n; ++i) {
            const double x = static_cast<double>(i) / n;
            std::fprintf(f, "%.17g %.17g\n", x, x * x);
        }
        std::fclose(f);
    }
    for (const double t : {0.0, 0.3, 1.0}) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", t);
        const RunResult r = run_meshedit({"eval", (dir / "long.bzc").string(), "--t", text}, 20.0);
        ASSERT_FALSE(r.timed_out);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const std::vector<double> b = numbers_after(r.out, " = ");
        ASSERT_EQ(b.size(), 2u) << r.out;
        EXPECT_NEAR(b[0], t, 1e-12) << r.out;
        EXPECT_NEAR(b[1], t * t + t * (1.0 - t) / n, 1e-12) << r.out;
    }
    // Every level of it would be 5e11 points: refused before one is computed.
    const RunResult r =
        run_meshedit({"eval", (dir / "long.bzc").string(), "--t", "0.5", "--levels"}, 20.0);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("long.bzc: printing every de Casteljau level"), std::string::npos)
        << r.err;
}

// A bicubic patch: the wavy unit patch times `scale`.
void write_patch(const std::filesystem::path& file, double scale) {
    std::FILE* f = std::fopen(file.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fprintf(f, "1\n");
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            std::fprintf(f, "%.17g %.17g %.17g ", (c / 1.5 - 1.0) * scale, (r / 1.5 - 1.0) * scale,
                         0.3 * ((r * c) % 3 - 1) * scale);
        }
        std::fprintf(f, "\n");
    }
    std::fclose(f);
}

TEST(HostileEval, PatchesAtHugeCoordinatesHaveTheirNormal) {
    // The normal overflowed to NaN at 1e200 and was (0, 0, 0) at ±1.7e308.
    TempDir dir;
    write_patch(dir / "unit.bez", 1.0);
    const RunResult unit = run_meshedit({"eval", (dir / "unit.bez").string(), "--uv", "0.3,0.6"});
    ASSERT_EQ(unit.exit_code, 0) << unit.err;
    const std::vector<double> normal = numbers_after(unit.out, "normal:");
    const std::vector<double> position = numbers_after(unit.out, "position:");
    ASSERT_EQ(normal.size(), 3u) << unit.out;
    for (const double scale : {1e200, 1.7e308, 1e-200}) {
        write_patch(dir / "big.bez", scale);
        const RunResult r = run_meshedit({"eval", (dir / "big.bez").string(), "--uv", "0.3,0.6"});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const std::vector<double> n = numbers_after(r.out, "normal:");
        const std::vector<double> p = numbers_after(r.out, "position:");
        ASSERT_EQ(n.size(), 3u) << r.out;
        ASSERT_EQ(p.size(), 3u) << r.out;
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(n[k], normal[k], 1e-12) << scale << r.out;
            EXPECT_NEAR(p[k] / scale, position[k], 1e-12) << scale << r.out;
        }
    }
}

TEST(HostileEval, StatsAtHugeCoordinatesAreTheUnitMeshs) {
    // An irregular closed tetrahedron at 1 and at 1e200: the angle sums overflowed (every
    // angle atan2(inf, inf) = 45°) and Gauss–Bonnet came out wrong; the volume was NaN.
    TempDir dir;
    for (const auto& [name, s] : {std::pair{"unit.off", 1.0}, {"big.off", 1e200}}) {
        std::ofstream off(dir / name);
        off.precision(17);
        off << "OFF\n4 4 0\n0 0 0\n"
            << 3 * s << " 0 0\n0 " << 2 * s << " 0\n0 0 " << 1 * s
            << "\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    }
    nlohmann::json stats[2];
    for (int k = 0; k < 2; ++k) {
        const RunResult r = run_meshedit(
            {"info", (dir / (k == 0 ? "unit.off" : "big.off")).string(), "--stats", "--json"});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        stats[k] = nlohmann::json::parse(r.out)["stats"];
    }
    EXPECT_NEAR(stats[1]["total_angle_defect"].get<double>(), 4.0 * std::numbers::pi, 1e-12);
    EXPECT_EQ(stats[1]["volume"].dump(), "null") << "inf has no JSON number";  // not NaN either
    for (const char* field : {"min_angle", "aspect", "dihedral"}) {
        EXPECT_NEAR(stats[1]["fields"][field]["mean"].get<double>(),
                    stats[0]["fields"][field]["mean"].get<double>(), 1e-9)
            << field;
    }
    EXPECT_NEAR(stats[1]["fields"]["edge_length"]["max"].get<double>() / 1e200,
                stats[0]["fields"]["edge_length"]["max"].get<double>(), 1e-12);
}

TEST(HostileEval, HugeSessionIsRefusedBeforeItIsParsed) {
    // 500,000 lines: about 113 MB once parsed (estimated), over a budget of 64 MB; refused naming
    // the file.
    TempDir dir;
    {
        std::FILE* f = std::fopen((dir / "long.ops").c_str(), "w");
        ASSERT_NE(f, nullptr);
        for (int i = 0; i < 500000; ++i) {
            std::fputs("flip:0-1\n", f);
        }
        std::fclose(f);
    }
    ::setenv("MESHEDIT_MEMORY_BUDGET", "64M", 1);
    const RunResult r =
        run_meshedit({"convert", (repo_root() / "dae/cube.dae").string(),
                      (dir / "out.obj").string(), "--ops", "@" + (dir / "long.ops").string()});
    ::unsetenv("MESHEDIT_MEMORY_BUDGET");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
    EXPECT_NE(r.err.find("long.ops: parsing a session of 4500000 characters"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("over the budget of 67.1 MB"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.obj"));
}

}  // namespace
}  // namespace meshedit::test
