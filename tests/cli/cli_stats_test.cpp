// `meshedit info --stats`: area, volume, Gauss–Bonnet and every field's summary, in text and
// JSON, checked on the cube [-1, 1]³ (dae/cube.dae, each side cut by a diagonal).

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "run.h"

namespace meshedit::test {
namespace {

TEST(CliInfo, StatsOfTheCube) {
    const std::string cube = (repo_root() / "dae/cube.dae").string();
    const RunResult r = run_meshedit({"info", cube, "--stats", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json stats = nlohmann::json::parse(r.out)["stats"];
    EXPECT_NEAR(stats["area"].get<double>(), 24.0, 1e-12);
    EXPECT_NEAR(stats["volume"].get<double>(), 8.0, 1e-12);
    EXPECT_NEAR(stats["total_angle_defect"].get<double>(), 4.0 * std::numbers::pi, 1e-12);
    const nlohmann::json& f = stats["fields"];
    EXPECT_EQ(f["valence"]["min"].get<double>(), 4.0);
    EXPECT_EQ(f["valence"]["max"].get<double>(), 6.0);
    EXPECT_NEAR(f["dihedral"]["max"].get<double>(), 90.0, 1e-9);
    EXPECT_NEAR(f["edge_length"]["min"].get<double>(), 2.0, 1e-12);
    EXPECT_NEAR(f["face_area"]["mean"].get<double>(), 2.0, 1e-12);
    EXPECT_NEAR(f["min_angle"]["min"].get<double>(), 45.0, 1e-9);
    EXPECT_EQ(f["gauss"]["count"].get<std::size_t>(), 8u);

    const RunResult text = run_meshedit({"info", cube, "--stats"});
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("angle defect:          4 pi (Gauss-Bonnet: 2 pi chi = 4 pi)"),
              std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("volume:                8\n"), std::string::npos) << text.out;
    // What a person reads: six significant digits (the JSON above keeps them all).
    EXPECT_NE(text.out.find("gauss:                 min 0.523599, mean 0.523599, max 0.523599"),
              std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("bounding box:          (-1, -1, -1) .. (1, 1, 1)"), std::string::npos)
        << text.out;
}

}  // namespace
}  // namespace meshedit::test
