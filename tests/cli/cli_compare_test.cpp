// `meshedit compare A B`: a flat 4×4 grid against a renumbered copy (exit 0), the copy with its
// middle vertex lifted by 0.25 (exit 1, distances in JSON, --tolerance, --field read back),
// with an edge flipped (exit 1, the first difference named), other counts, and bad input
// (exit 2).

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/io.h"
#include "run.h"
#include "support/renumber.h"

namespace meshedit::test {
namespace {

using Json = nlohmann::json;

const Vec3 kMiddle{0.5, 0.5, 0.0};  // vertex 12 of shapes::grid(4, 4)

// A's file, and B's: A renumbered, then changed by `edit`.
struct Pair {
    TempDir dir;
    std::string a = (dir / "a.obj").string();
    std::string b = (dir / "b.ply").string();

    template <class Edit>
    explicit Pair(Edit edit) {
        const Mesh mesh = shapes::grid(4, 4);
        write_mesh(mesh, a);
        Mesh copy = renumbered(mesh, 36);
        edit(copy);
        write_mesh(copy, b);
    }
};

Vertex vertex_at(const Mesh& mesh, const Vec3& p) {
    for (const Vertex v : mesh.vertices()) {
        if (mesh.position(v) == p) {
            return v;
        }
    }
    ADD_FAILURE() << "no vertex there";
    return Vertex(0);
}

TEST(CliCompare, ARenumberedCopyIsTheSame) {
    const Pair files([](Mesh&) {});
    RunResult r = run_meshedit({"compare", files.a, files.b});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("topology:              the same up to renumbering\n"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("result:                the same (tolerance 0)\n"), std::string::npos)
        << r.out;

    r = run_meshedit({"compare", files.a, files.b, "--json", "--mapping"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_TRUE(j["isomorphic"].get<bool>());
    EXPECT_TRUE(j["same"].get<bool>());
    EXPECT_TRUE(j["difference"].is_null());
    EXPECT_EQ(j["a"]["vertices"].get<int>(), 25);
    EXPECT_EQ(j["b"]["faces"].get<int>(), 32);
    EXPECT_EQ(j["deviation"]["by"], "mapping");
    EXPECT_EQ(j["deviation"]["max"].get<double>(), 0.0);
    EXPECT_EQ(j["deviation"]["hausdorff"].get<double>(), 0.0);
    // The mapping carries every vertex of A to B's vertex at the same place.
    const Mesh a = read_mesh(files.a).mesh, b = read_mesh(files.b).mesh;
    const auto vertices = j["mapping"]["vertices"].get<std::vector<std::uint32_t>>();
    ASSERT_EQ(vertices.size(), 25u);
    for (std::uint32_t i = 0; i < 25; ++i) {
        EXPECT_EQ(a.position(Vertex(i)), b.position(Vertex(vertices[i])));
    }
    EXPECT_EQ(j["mapping"]["faces"].size(), 32u);
}

TEST(CliCompare, ALiftedVertexIsMeasured) {
    const Pair files([](Mesh& m) { m.position(vertex_at(m, kMiddle)).z = 0.25; });
    RunResult r = run_meshedit({"compare", files.a, files.b, "--json"});
    ASSERT_EQ(r.exit_code, 1) << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_TRUE(j["isomorphic"].get<bool>());
    EXPECT_FALSE(j["same"].get<bool>());
    const Json& d = j["deviation"];
    EXPECT_EQ(d["max"].get<double>(), 0.25);
    EXPECT_DOUBLE_EQ(d["rms"].get<double>(), 0.05);  // one of 25
    EXPECT_NEAR(d["hausdorff"].get<double>(), 0.25, 1e-15);
    EXPECT_DOUBLE_EQ(d["diagonal"].get<double>(), std::sqrt(2.0));
    EXPECT_NEAR(d["max_percent"].get<double>(), 25.0 / std::sqrt(2.0), 1e-12);

    r = run_meshedit({"compare", files.a, files.b, "--tolerance", "0.25"});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("vertex distance:       max 0.25 (17.6777%), RMS 0.05 (3.53553%)"),
              std::string::npos)
        << r.out;

    const std::string field = (files.dir / "deviation.ply").string();
    r = run_meshedit({"compare", files.a, files.b, "--field", field});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    const Mesh m = read_mesh(field).mesh;
    const auto deviation = m.get_property<Vertex, double>("v:ply:deviation");
    ASSERT_TRUE(deviation);
    for (const Vertex v : m.vertices()) {
        EXPECT_EQ(deviation[v], m.position(v) == kMiddle ? 0.25 : 0.0) << v.idx();
    }
    // The field file is a field: info --stats sums it up, render draws it with its legend,
    // and a wrong name lists it among the fields.
    r = run_meshedit({"info", field, "--stats", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json stats = Json::parse(r.out)["stats"]["fields"]["deviation"];
    EXPECT_EQ(stats["count"].get<int>(), 25);
    EXPECT_EQ(stats["max"].get<double>(), 0.25);
    EXPECT_DOUBLE_EQ(stats["mean"].get<double>(), 0.01);
    const std::string png = (files.dir / "deviation.png").string();
    r = run_meshedit({"render", field, "-o", png, "--field", "deviation", "--size", "160x100"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(png));
    r = run_meshedit({"render", field, "-o", png, "--field", "deviance"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no field called 'deviance' (the fields: gauss mean"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find(" distance deviation)"), std::string::npos) << r.err;
}

TEST(CliCompare, AFlippedEdgeIsNamed) {
    const Pair files([](Mesh& m) {
        const Vertex c = vertex_at(m, kMiddle);
        ASSERT_TRUE(flip(m, m.find_edge(c, vertex_at(m, {0.75, 0.75, 0}))).ok());
    });
    RunResult r = run_meshedit({"compare", files.a, files.b, "--json"});
    ASSERT_EQ(r.exit_code, 1) << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_FALSE(j["isomorphic"].get<bool>());
    EXPECT_FALSE(j["same"].get<bool>());
    EXPECT_NE(j["difference"].get<std::string>().find(" of B"), std::string::npos);
    const std::string first = j["first_difference"]["a"].get<std::string>();
    EXPECT_TRUE(first.starts_with("vertex ") || first.starts_with("face ") ||
                first.starts_with("halfedge "))
        << first;
    EXPECT_EQ(j["deviation"]["by"], "closest_points");
    EXPECT_EQ(j["deviation"]["max"].get<double>(), 0.0);  // still the same flat square

    r = run_meshedit({"compare", files.a, files.b});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.out.find("topology:              different: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("first difference:      " + first + " of A, "), std::string::npos)
        << r.out;
}

TEST(CliCompare, OtherCountsDiffer) {
    const TempDir dir;
    const std::string a = (dir / "a.off").string(), b = (dir / "b.off").string();
    write_mesh(shapes::grid(4, 4), a);
    write_mesh(shapes::grid(4, 5), b);
    const RunResult r = run_meshedit({"compare", a, b, "--json"});
    ASSERT_EQ(r.exit_code, 1) << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_EQ(j["difference"], "the vertex counts differ: 25 in A, 30 in B");
    EXPECT_TRUE(j["first_difference"].is_null());
    EXPECT_EQ(j["b"]["vertices"].get<int>(), 30);
    EXPECT_EQ(j["b"]["edges"].get<int>(), 69);
}

// What the meshes carry is compared too: assimp's duck through OBJ keeps everything (the
// same), through PLY loses its material (different, said by name).
TEST(CliCompare, AttributesAreCompared) {
    const std::string duck = "/usr/share/assimp/models/Collada/duck.dae";
    if (!std::filesystem::exists(duck)) {
        GTEST_SKIP() << "install assimp-testmodels (scripts/install-deps.sh does)";
    }
    TempDir tmp;
    for (const char* name : {"duck.obj", "duck.ply"}) {
        ASSERT_EQ(run_meshedit({"convert", duck, (tmp / name).string()}).exit_code, 0);
    }
    const RunResult obj = run_meshedit({"compare", duck, (tmp / "duck.obj").string()});
    EXPECT_EQ(obj.exit_code, 0) << obj.out << obj.err;
    EXPECT_NE(obj.out.find("texture coordinates:"), std::string::npos) << obj.out;
    EXPECT_NE(obj.out.find("the same (8500 corners)"), std::string::npos) << obj.out;
    const RunResult ply = run_meshedit({"compare", duck, (tmp / "duck.ply").string(), "--json"});
    EXPECT_EQ(ply.exit_code, 1) << ply.out << ply.err;
    const Json j = Json::parse(ply.out);
    EXPECT_EQ(j["isomorphic"], true);
    bool materials = false;
    for (const Json& a : j["attributes"]) {
        if (a["name"] == "materials") {
            materials = true;
            EXPECT_EQ(a["in_a"], true);
            EXPECT_EQ(a["in_b"], false);
        }
    }
    EXPECT_TRUE(materials) << ply.out;
}

TEST(CliCompare, BadInputExitsTwo) {
    const Pair files([](Mesh&) {});
    const std::string missing = (files.dir / "missing.obj").string();
    RunResult r = run_meshedit({"compare", files.a, missing});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err, "meshedit: " + missing + ": no such file\n");
    EXPECT_TRUE(r.out.empty()) << r.out;

    r = run_meshedit({"compare", files.a, files.b, "--field", (files.dir / "f.obj").string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--field writes a .ply file"), std::string::npos) << r.err;

    r = run_meshedit({"compare", files.a});
    EXPECT_EQ(r.exit_code, 2);
}

}  // namespace
}  // namespace meshedit::test
