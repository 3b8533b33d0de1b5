// COLLADA number lists: the reader's own decimal scanner and its parallel parse of big lists
// must give exactly what std::from_chars gives, and report the first bad token by its index
// in the whole list, wherever the list was cut into pieces.

#include <gtest/gtest.h>

#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "formats_test_util.h"
#include "meshedit/files/io_error.h"
#include "meshedit/io/collada.h"

namespace meshedit {
namespace {

// A one-geometry COLLADA document with `positions_text` as its float_array (count numbers)
// and `p_text` as the triangles' <p>. The array starts on line 8, the <p> on line 19.
std::string document(const std::string& positions_text, std::size_t count,
                     const std::string& p_text, std::size_t n_triangles) {
    return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><up_axis>Y_UP</up_axis></asset>
  <library_geometries>
    <geometry id="g">
      <mesh>
        <source id="g-pos">
          <float_array id="g-pos-array" count=")" +
           std::to_string(count) + "\">" + positions_text + R"(</float_array>
          <technique_common>
            <accessor source="#g-pos-array" count=")" +
           std::to_string(count / 3) + R"(" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/>
              <param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="g-vtx"><input semantic="POSITION" source="#g-pos"/></vertices>
        <triangles count=")" +
           std::to_string(n_triangles) + R"(">
          <input semantic="VERTEX" source="#g-vtx" offset="0"/>
          <p>)" +
           p_text +
           R"(</p>
        </triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";
}

// Number texts in the shapes files hold: shortest round-trip floats and doubles, fixed
// decimals of every length up to 17 digits, exponents, signs, "-0", integers.
std::vector<std::string> number_texts(std::size_t n) {
    std::mt19937_64 rng(20261123);
    std::uniform_real_distribution<double> uniform(-1000.0, 1000.0);
    std::vector<std::string> out;
    out.reserve(n);
    char buffer[64];
    for (std::size_t i = 0; i < n; ++i) {
        const double x = uniform(rng) * (i % 7 == 0 ? 1e-6 : 1.0);
        switch (i % 8) {
            case 0: {  // shortest round trip of a double (up to 17 digits)
                const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
                out.emplace_back(buffer, r.ptr);
                break;
            }
            case 1: {  // shortest round trip of a float
                const auto r = std::to_chars(buffer, buffer + sizeof buffer, static_cast<float>(x));
                out.emplace_back(buffer, r.ptr);
                break;
            }
            case 2:
                std::snprintf(buffer, sizeof buffer, "%.*f", static_cast<int>(i % 13), x);
                out.emplace_back(buffer);
                break;
            case 3:
                std::snprintf(buffer, sizeof buffer, "%.*e", static_cast<int>(i % 17), x);
                out.emplace_back(buffer);
                break;
            case 4:
                std::snprintf(buffer, sizeof buffer, "%.15g", x);
                out.emplace_back(buffer);
                break;
            case 5:
                out.emplace_back(i % 3 == 0 ? "-0" : (i % 3 == 1 ? "+2.5" : "7"));
                break;
            case 6:
                std::snprintf(buffer, sizeof buffer, "%.16f", x / 1000.0);  // 16-17 digits
                out.emplace_back(buffer);
                break;
            default:
                std::snprintf(buffer, sizeof buffer, "%ld", static_cast<long>(x * 1e6));
                out.emplace_back(buffer);
                break;
        }
    }
    return out;
}

double from_chars_value(std::string token) {
    if (token.size() > 1 && token[0] == '+') {
        token.erase(0, 1);
    }
    double value = 0;
    std::from_chars(token.data(), token.data() + token.size(), value);
    return value;
}

// Big enough (several MB of text) that the reader cuts every list into pieces.
constexpr std::size_t kPositions = 300'000;

std::string joined(const std::vector<std::string>& tokens, std::size_t line_every) {
    std::string text;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        text += tokens[i];
        text += (i + 1) % line_every == 0 ? "\n" : (i % 5 == 0 ? "\t " : " ");
    }
    return text;
}

TEST(ColladaNumbers, BigListsParseBitForBitLikeFromChars) {
    test::ScratchDir dir;
    const std::vector<std::string> numbers = number_texts(3 * kPositions);
    std::string p;
    for (std::size_t t = 0; t + 2 < kPositions; t += 3) {
        p += std::to_string(t) + " " + std::to_string(t + 1) + " " + std::to_string(t + 2) + " ";
    }
    const std::size_t n_triangles = kPositions / 3;
    const auto path = dir / "numbers.dae";
    std::ofstream(path) << document(joined(numbers, 9), numbers.size(), p, n_triangles);

    const MeshSoup soup = read_collada(path.string());
    ASSERT_EQ(soup.soup.positions.size(), kPositions);
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < numbers.size(); ++i) {
        const double got = soup.soup.positions[i / 3][static_cast<int>(i % 3)];
        const double want = from_chars_value(numbers[i]);
        // Bit-for-bit: -0 must stay -0.
        if (std::memcmp(&got, &want, sizeof got) != 0 && ++mismatches <= 5) {
            ADD_FAILURE() << "number " << i << " \"" << numbers[i] << "\": " << got
                          << " != " << want;
        }
    }
    EXPECT_EQ(mismatches, 0u);
    ASSERT_EQ(soup.soup.n_faces(), n_triangles);
    EXPECT_EQ(soup.soup.indices[3 * 1234 + 2], 3 * 1234 + 2u);
}

::testing::AssertionResult fails_with(const std::filesystem::path& path,
                                      const std::string& expected) {
    try {
        read_collada(path.string());
    } catch (const IoError& e) {
        if (std::string(e.what()).find(expected) != std::string::npos) {
            return ::testing::AssertionSuccess();
        }
        return ::testing::AssertionFailure() << "message: " << e.what();
    }
    return ::testing::AssertionFailure() << "no error";
}

TEST(ColladaNumbers, FirstBadNumberOfABigListIsNamedByItsIndexAndLine) {
    test::ScratchDir dir;
    for (const std::size_t bad : {std::size_t{5}, 3 * kPositions / 2 + 1, 3 * kPositions - 1}) {
        SCOPED_TRACE(bad);
        std::vector<std::string> numbers(3 * kPositions, "0.25");
        numbers[bad] = "1.5.3";
        if (bad + 7 < numbers.size()) {
            numbers[bad + 7] = "later";  // a second bad one, not reported
        }
        const auto path = dir / ("bad_" + std::to_string(bad) + ".dae");
        std::ofstream(path) << document(joined(numbers, 1000), numbers.size(), "0 1 2", 1);
        // The array starts on line 8; 1000 numbers per line.
        EXPECT_TRUE(fails_with(path, "line 8, "));
        EXPECT_TRUE(
            fails_with(path, "number " + std::to_string(bad) + " \"1.5.3\" is not a number"));
    }
}

TEST(ColladaNumbers, FirstBadIndexOfABigListIsNamedByItsIndex) {
    test::ScratchDir dir;
    std::vector<std::string> indices(3 * kPositions, "1");
    const std::size_t bad = 2 * kPositions + 3;
    indices[bad] = "-4";
    const auto path = dir / "bad_index.dae";
    std::ofstream(path) << document("0 0 0 1 0 0 0 1 0", 9, joined(indices, 50), kPositions);
    EXPECT_TRUE(fails_with(path, "value " + std::to_string(bad) + " \"-4\" is not an index"));
}

TEST(ColladaNumbers, OutOfRangeNumbersAreRefused) {
    test::ScratchDir dir;
    const auto path = dir / "range.dae";
    std::ofstream(path) << document("0 0 0 1 0 0 0 1e999 0", 9, "0 1 2", 1);
    EXPECT_TRUE(fails_with(path, "number 7 \"1e999\" is out of range"));
}

}  // namespace
}  // namespace meshedit
