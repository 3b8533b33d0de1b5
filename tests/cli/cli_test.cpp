// The `meshedit` command run for real: info, convert --ops, subdivide, check, eval, usage.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "meshedit/files/files.h"
#include "meshedit/io/io.h"
#include "run.h"
#include "support/mesh_compare.h"

namespace meshedit::test {
namespace {

#ifdef MESHEDIT_HAS_VIEWER
constexpr bool kViewerBuilt = true;
#else
constexpr bool kViewerBuilt = false;
#endif

using Json = nlohmann::json;

Json info_json(const std::filesystem::path& file) {
    const RunResult r = run_meshedit({"info", file.string(), "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return Json::parse(r.out);
}

// --------------------------------------------------------------------------- info

struct SampleCounts {
    const char* file;
    std::size_t vertices, edges, faces, boundary_loops, components;
    long euler, genus;
    std::size_t creases;
};

// Counts follow from the generators (docs/samples.md): e.g. torus(24, 12) has 24·12
// vertices and 2·24·12 triangles; a split adds 1 vertex, 3 edges, 2 faces; a collapse of an
// interior edge removes 1 vertex, 3 edges, 2 faces.
const SampleCounts kSamples[] = {
    {"dae/cube.dae", 8, 18, 12, 0, 1, 2, 0, 0},
    {"dae/icosahedron.dae", 12, 30, 20, 0, 1, 2, 0, 0},
    {"dae/torus.dae", 288, 864, 576, 0, 1, 0, 1, 0},
    {"dae/quadball.dae", 98, 192, 96, 0, 1, 2, 0, 0},
    {"dae/quadcube.dae", 8, 12, 6, 0, 1, 2, 0, 0},
    {"dae/bowl.dae", 145, 408, 264, 1, 1, 1, 0, 0},
    {"dae/creased.dae", 50, 144, 96, 0, 1, 2, 0, 32},
    {"dae/teapot.dae", 2082, 6112, 4032, 6, 4, 2, 0, 0},
    {"dae/cube/input.dae", 8, 18, 12, 0, 1, 2, 0, 0},
    {"dae/cube/flip.dae", 8, 18, 12, 0, 1, 2, 0, 0},
    {"dae/cube/split.dae", 9, 21, 14, 0, 1, 2, 0, 0},
    {"dae/cube/collapse.dae", 7, 15, 10, 0, 1, 2, 0, 0},
    {"dae/icosahedron/input.dae", 12, 30, 20, 0, 1, 2, 0, 0},
    {"dae/icosahedron/flip.dae", 12, 30, 20, 0, 1, 2, 0, 0},
    {"dae/icosahedron/split.dae", 13, 33, 22, 0, 1, 2, 0, 0},
    {"dae/icosahedron/collapse.dae", 11, 27, 18, 0, 1, 2, 0, 0},
    {"dae/torus/input.dae", 288, 864, 576, 0, 1, 0, 1, 0},
    {"dae/torus/flip.dae", 288, 864, 576, 0, 1, 0, 1, 0},
    {"dae/torus/split.dae", 289, 867, 578, 0, 1, 0, 1, 0},
    {"dae/torus/collapse.dae", 287, 861, 574, 0, 1, 0, 1, 0},
};

TEST(CliInfo, JsonCountsOfEverySample) {
    for (const SampleCounts& s : kSamples) {
        SCOPED_TRACE(s.file);
        const Json j = info_json(repo_root() / s.file);
        EXPECT_EQ(j["kind"], "mesh");
        EXPECT_EQ(j["vertices"], s.vertices);
        EXPECT_EQ(j["edges"], s.edges);
        EXPECT_EQ(j["faces"], s.faces);
        EXPECT_EQ(j["boundary_loops"], s.boundary_loops);
        EXPECT_EQ(j["components"], s.components);
        EXPECT_EQ(j["euler_characteristic"], s.euler);
        EXPECT_EQ(j["genus"], s.genus);
        EXPECT_EQ(j["creases"], s.creases);
        EXPECT_EQ(j["manifold"], true);
        EXPECT_TRUE(j["repairs"].empty());
        EXPECT_EQ(j["unit_meter"], 1.0);
        ASSERT_TRUE(j["bbox"].is_object());
        EXPECT_EQ(j["bbox"]["min"].size(), 3u);
    }
}

// The face-degree histogram: a poke turns one quad into four triangles, a dissolve merges two
// quads into a hexagon.
TEST(CliInfo, FaceDegreeHistogram) {
    TempDir tmp;
    const RunResult r =
        run_meshedit({"convert", (repo_root() / "dae/quadball.dae").string(),
                      (tmp / "out.dae").string(), "--ops", "poke:f3,dissolve:85-88"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(info_json(repo_root() / "dae/quadball.dae")["face_degrees"],
              Json::parse(R"({"4": 96})"));
    EXPECT_EQ(info_json(tmp / "out.dae")["face_degrees"],
              Json::parse(R"({"3": 4, "4": 93, "6": 1})"));
    const RunResult text = run_meshedit({"info", (tmp / "out.dae").string()});
    EXPECT_NE(text.out.find("face degrees:          3 corners: 4, 4 corners: 93, 6 corners: 1"),
              std::string::npos)
        << text.out;
}

TEST(CliInfo, BoundingBoxOfCube) {
    const Json j = info_json(repo_root() / "dae/cube.dae");
    EXPECT_EQ(j["bbox"]["min"], Json::parse("[-1, -1, -1]"));
    EXPECT_EQ(j["bbox"]["max"], Json::parse("[1, 1, 1]"));
    EXPECT_EQ(j["triangle_mesh"], true);
    EXPECT_EQ(info_json(repo_root() / "dae/quadball.dae")["triangle_mesh"], false);
}

TEST(CliInfo, RepairedInputIsNotManifold) {
    // Two triangles sharing only vertex 0: the loader splits it.
    const Json j = info_json(data_dir() / "bowtie.dae");
    EXPECT_EQ(j["manifold"], false);
    ASSERT_EQ(j["repairs"].size(), 1u);
    EXPECT_NE(j["repairs"][0].get<std::string>().find("non-manifold"), std::string::npos);
    EXPECT_EQ(j["vertices"], 6);
    EXPECT_EQ(j["components"], 2);

    const RunResult r = run_meshedit({"check", (data_dir() / "bowtie.dae").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const auto notes = split_lines(r.err);
    ASSERT_EQ(notes.size(), 1u) << r.err;
    EXPECT_NE(notes[0].find("meshedit: note: "), std::string::npos);
    EXPECT_NE(notes[0].find("repaired on load"), std::string::npos);
}

TEST(CliInfo, TextOutputNamesTheCounts) {
    const RunResult r = run_meshedit({"info", (repo_root() / "dae/torus.dae").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("vertices:              288"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("genus:                 1"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("manifold:              yes"), std::string::npos) << r.out;
    EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(CliInfo, TeapotPatchesGiveOneEntryPerPart) {
    const Json j = info_json(repo_root() / "bez/teapot.bez");
    EXPECT_EQ(j["kind"], "bezier-patches");
    EXPECT_EQ(j["patches"], 32);
    EXPECT_EQ(j["density"], 8);
    // Body (with rim and bottom), lid, handle, spout: the welded tessellation is the same
    // mesh as dae/teapot.dae (made from it by meshedit-make-samples).
    const Json dae = info_json(repo_root() / "dae/teapot.dae");
    for (const char* key : {"vertices", "edges", "faces", "boundary_loops", "components"}) {
        EXPECT_EQ(j[key], dae[key]) << key;
    }
    EXPECT_EQ(j["components"], 4);
    ASSERT_EQ(j["parts"].size(), 4u);
    std::size_t v = 0, e = 0, f = 0;
    for (const Json& part : j["parts"]) {
        v += part["vertices"].get<std::size_t>();
        e += part["edges"].get<std::size_t>();
        f += part["faces"].get<std::size_t>();
    }
    EXPECT_EQ(v, j["vertices"]);
    EXPECT_EQ(e, j["edges"]);
    EXPECT_EQ(f, j["faces"]);
    EXPECT_EQ(j["parts"][0]["faces"], 2016);

    const RunResult text = run_meshedit({"info", (repo_root() / "bez/teapot.bez").string()});
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("part 4:"), std::string::npos) << text.out;
}

TEST(CliInfo, DensityChangesTheTessellation) {
    const RunResult r = run_meshedit(
        {"info", (repo_root() / "bez/wavy_cube.bez").string(), "--json", "--density", "2"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json j = Json::parse(r.out);
    EXPECT_EQ(j["patches"], 6);
    EXPECT_EQ(j["density"], 2);
    // Six 2×2 patches welded into a closed cube: 6·4 quads = 48 triangles, 26 vertices.
    EXPECT_EQ(j["faces"], 48);
    EXPECT_EQ(j["vertices"], 26);
}

TEST(CliInfo, Curve) {
    const Json j = info_json(repo_root() / "bez/curve2.bzc");
    EXPECT_EQ(j["kind"], "bezier-curve");
    EXPECT_EQ(j["points"], 5);
    EXPECT_EQ(j["degree"], 4);
    EXPECT_EQ(j["bbox"]["min"][0], 0.05);
    EXPECT_EQ(j["bbox"]["max"][0], 0.95);
}

// --------------------------------------------------------------------------- convert --ops

// `meshedit convert input.dae out.dae --ops <op>` reproduces the reference file: same
// vertex positions by index and the same faces.
void expect_reference(const std::string& shape, const std::string& name, const std::string& op) {
    SCOPED_TRACE(shape + "/" + name + " by " + op);
    TempDir tmp;
    const auto dir = repo_root() / "dae" / shape;
    const RunResult r = run_meshedit(
        {"convert", (dir / "input.dae").string(), (tmp / "out.dae").string(), "--ops", op});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Mesh actual = read_mesh(tmp / "out.dae").mesh;
    const Mesh expected = read_mesh(dir / (name + ".dae")).mesh;
    ASSERT_EQ(actual.n_vertices(), expected.n_vertices());
    for (const Vertex v : expected.vertices()) {
        EXPECT_LE(distance(actual.position(v), expected.position(v)), 1e-12) << v.idx();
    }
    EXPECT_EQ(canonical_faces(actual), canonical_faces(expected));
    // The op did something: the reference differs from the input.
    EXPECT_NE(canonical_faces(read_mesh(dir / "input.dae").mesh), canonical_faces(expected));
}

TEST(CliConvert, OpsReproduceTheReferencePairs) {
    expect_reference("cube", "flip", "flip:0-6");
    expect_reference("cube", "split", "split:0-1");
    expect_reference("cube", "collapse", "collapse:1-3");
    expect_reference("icosahedron", "flip", "flip:0-5");
    expect_reference("icosahedron", "split", "split:0-1");
    expect_reference("icosahedron", "collapse", "collapse:3-4");
    expect_reference("torus", "flip", "flip:0-13");
    expect_reference("torus", "split", "split:0-1");
    expect_reference("torus", "collapse", "collapse:0-12");
}

TEST(CliConvert, EdgeNamesWorkInEitherOrder) {
    TempDir tmp;
    const auto in = (repo_root() / "dae/cube.dae").string();
    ASSERT_EQ(run_meshedit({"convert", in, (tmp / "a.dae").string(), "--ops=flip:0-6"}).exit_code,
              0);
    ASSERT_EQ(
        run_meshedit({"convert", in, (tmp / "b.dae").string(), "--ops", "flip:6-0"}).exit_code, 0);
    EXPECT_EQ(canonical_faces(read_mesh(tmp / "a.dae").mesh),
              canonical_faces(read_mesh(tmp / "b.dae").mesh));
}

TEST(CliConvert, OpListRunsInOrder) {
    TempDir tmp;
    // split 0-1 adds vertex 8; the next ops name it.
    const RunResult r = run_meshedit({"convert", (repo_root() / "dae/cube.dae").string(),
                                      (tmp / "out.obj").string(), "--ops",
                                      "split:0-1,flip:8-5,crease:0-8,triangulate,loop"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json j = info_json(tmp / "out.obj");
    EXPECT_EQ(j["faces"], 14 * 4);
    EXPECT_EQ(j["vertices"], 9 + 21);
}

TEST(CliConvert, CreaseTogglesAndSurvivesCollada) {
    TempDir tmp;
    const RunResult r =
        run_meshedit({"convert", (repo_root() / "dae/creased.dae").string(),
                      (tmp / "out.dae").string(), "--ops", "crease:0-1,crease:0-16,crease:0-16"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // 0-1 was a rim crease (toggled off); 0-16 toggled on and off again.
    EXPECT_EQ(info_json(tmp / "out.dae")["creases"], 31);
}

// Nothing is lost without a word: what the output format cannot keep is a note on stderr.
TEST(CliConvert, WhatTheFormatCannotKeepIsSaid) {
    TempDir tmp;
    const auto creased = (repo_root() / "dae/creased.dae").string();
    RunResult r = run_meshedit({"convert", creased, (tmp / "c.obj").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("c.obj: not kept: 32 crease marks (OBJ has no crease edges)"),
              std::string::npos)
        << r.err;
    r = run_meshedit({"convert", creased, (tmp / "c.dae").string()});
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.err.find("not kept"), std::string::npos) << r.err;
    r = run_meshedit(
        {"convert", (repo_root() / "dae/quadball.dae").string(), (tmp / "q.glb").string()});
    EXPECT_NE(r.err.find("q.glb: not kept: 96 polygons (glTF stores triangles: each is fanned)"),
              std::string::npos)
        << r.err;
}

// --strict: what would be dropped is an error, exit 1 and no file; without it a note.
TEST(CliConvert, StrictRefusesToDropAnything) {
    TempDir tmp;
    const auto creased = (repo_root() / "dae/creased.dae").string();
    const auto out = tmp / "c.obj";
    for (const char* command : {"convert", "subdivide", "simplify", "repair"}) {
        SCOPED_TRACE(command);
        std::vector<std::string> args = {command, creased, out.string(), "--strict"};
        if (std::string(command) == "simplify") {
            args.insert(args.end(), {"--ratio", "0.5"});
        } else if (std::string(command) == "subdivide") {
            args.insert(args.end(), {"-n", "1"});
        }
        const RunResult r = run_meshedit(args);
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_NE(r.err.find("c.obj: not written (--strict): the format cannot keep "),
                  std::string::npos)
            << r.err;
        EXPECT_NE(r.err.find("crease marks (OBJ has no crease edges)"), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
    // A format that keeps everything writes as without --strict.
    const RunResult kept = run_meshedit({"convert", creased, (tmp / "c.dae").string(), "--strict"});
    EXPECT_EQ(kept.exit_code, 0) << kept.err;
    EXPECT_TRUE(std::filesystem::exists(tmp / "c.dae"));
}

// info lists what a mesh carries: texture coordinates with their seams, colours, materials.
TEST(CliInfo, ListsAttributesAndMaterials) {
    TempDir tmp;
    std::ofstream(tmp / "q.mtl") << "newmtl red\nKd 1 0 0\nnewmtl wood\nmap_Kd wood.png\n";
    std::ofstream(tmp / "q.obj") << "mtllib q.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                                    "usemtl red\nf 1/1 2/2 3/3\nusemtl wood\nf 1/5 3/3 4/4\n";
    const RunResult r = run_meshedit({"info", (tmp / "q.obj").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("texture coordinates:   per corner, 1 seam edges"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("materials:             2, 1 border edges"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("material 0:            'red' colour 1 0 0"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("material 1:            'wood' texture wood.png (missing)"),
              std::string::npos)
        << r.out;
    const auto j = info_json(tmp / "q.obj")["attributes"];
    EXPECT_EQ(j["texcoords"], true);
    EXPECT_EQ(j["uv_seam_edges"], 1);
    EXPECT_EQ(j["vertex_colours"], false);
    EXPECT_EQ(j["materials"][1]["texture_found"], false);
}

TEST(CliConvert, QuadsTriangulate) {
    TempDir tmp;
    const RunResult r = run_meshedit({"convert", (repo_root() / "dae/quadball.dae").string(),
                                      (tmp / "out.dae").string(), "--ops", "triangulate"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json j = info_json(tmp / "out.dae");
    EXPECT_EQ(j["faces"], 192);
    EXPECT_EQ(j["edges"], 288);
    EXPECT_EQ(j["triangle_mesh"], true);
}

TEST(CliConvert, BezierPatchesConvertToAMesh) {
    TempDir tmp;
    const RunResult r = run_meshedit(
        {"convert", (repo_root() / "bez/teapot.bez").string(), (tmp / "teapot.dae").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Mesh a = read_mesh(tmp / "teapot.dae").mesh;
    const Mesh b = read_mesh(repo_root() / "dae/teapot.dae").mesh;
    EXPECT_TRUE(same_faces_by_position(a, b, 1e-9));
}

TEST(CliConvert, BezierFilesRewriteInTheCourseFormat) {
    TempDir tmp;
    const auto teapot = repo_root() / "bez/teapot.bez";
    RunResult r = run_meshedit({"convert", teapot.string(), (tmp / "t.bez").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto in = read_bez(teapot);
    const auto out = read_bez(tmp / "t.bez");
    ASSERT_EQ(out.size(), in.size());
    for (std::size_t p = 0; p < in.size(); ++p) {
        EXPECT_EQ(out[p].control_points, in[p].control_points);
    }
    EXPECT_EQ(read_file(tmp / "t.bez").rfind("32\n", 0), 0u) << "the count first, no header";
    r = run_meshedit({"convert", teapot.string(), (tmp / "u.bez").string(), "--ops", "loop"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("keeps the patches"), std::string::npos) << r.err;
}

TEST(CliConvert, RefusedOpExitsOneNamingOpAndReason) {
    TempDir tmp;
    // The bowl's rim (vertices 121…144) is boundary: flipping a rim edge is refused.
    const RunResult r = run_meshedit({"convert", (repo_root() / "dae/bowl.dae").string(),
                                      (tmp / "out.dae").string(), "--ops", "flip:121-122"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("meshedit: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("bowl.dae"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("flip:121-122 refused: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("boundary"), std::string::npos) << r.err;
    EXPECT_TRUE(tmp.entries().empty());
}

TEST(CliConvert, RefusedOpExitsOneWithOneLineAndWritesNothing) {
    TempDir tmp;
    const RunResult r = run_meshedit({"convert", (repo_root() / "dae/bowl.dae").string(),
                                      (tmp / "out.dae").string(), "--ops", "flip:121-122"});
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("flip:121-122 refused: cannot flip: boundary edge"), std::string::npos)
        << r.err;
    EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
    EXPECT_TRUE(tmp.entries().empty());
}

// quadball is all quads (its first face is 0-1-6-5): a flip keeps every face a quad, and a
// split of a side between two quads only adds a corner to each.
TEST(CliConvert, QuadsFlipAndSplit) {
    TempDir tmp;
    const RunResult r = run_meshedit({"convert", (repo_root() / "dae/quadball.dae").string(),
                                      (tmp / "out.obj").string(), "--ops", "flip:0-1,split:1-6"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json j = info_json(tmp / "out.obj");
    EXPECT_EQ(j["vertices"], 99);
    EXPECT_EQ(j["edges"], 193);
    EXPECT_EQ(j["faces"], 96);
}

TEST(CliConvert, MissingEdgeIsBadInputNamingIt) {
    TempDir tmp;
    const auto in = (repo_root() / "dae/cube.dae").string();
    RunResult r = run_meshedit({"convert", in, (tmp / "o.dae").string(), "--ops", "flip:0-7"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("flip:0-7: no edge joins vertices 0 and 7"), std::string::npos) << r.err;
    r = run_meshedit({"convert", in, (tmp / "o.dae").string(), "--ops", "split:0-99"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no vertex 99"), std::string::npos) << r.err;
    EXPECT_TRUE(tmp.entries().empty());
}

TEST(CliConvert, BadOpListIsBadUsage) {
    TempDir tmp;
    const auto in = (repo_root() / "dae/cube.dae").string();
    for (const char* ops : {"twist:0-1", "flip:0", "flip:a-b", "loop:0", "loop:x", "flip:0-6,,loop",
                            "", "flip:1-1"}) {
        SCOPED_TRACE(ops);
        const RunResult r = run_meshedit({"convert", in, (tmp / "o.dae").string(), "--ops", ops});
        EXPECT_EQ(r.exit_code, 2);
        EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
        EXPECT_EQ(r.err.rfind("meshedit: convert: ", 0), 0u) << r.err;
    }
    EXPECT_TRUE(tmp.entries().empty());
}

// --------------------------------------------------------------------------- subdivide

TEST(CliSubdivide, TwoLevelsGiveTheLoopCounts) {
    TempDir tmp;
    const RunResult r = run_meshedit({"subdivide", (repo_root() / "dae/cube.dae").string(),
                                      (tmp / "out.dae").string(), "-n", "2"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;  // stderr is not a terminal: no progress bar
    // Each level: V' = V + E, E' = 2E + 3F, F' = 4F. 8/18/12 → 26/72/48 → 98/288/192.
    const Json j = info_json(tmp / "out.dae");
    EXPECT_EQ(j["vertices"], 98);
    EXPECT_EQ(j["edges"], 288);
    EXPECT_EQ(j["faces"], 192);
    EXPECT_EQ(j["euler_characteristic"], 2);
}

// Loop is for triangles: quads are refused with their count and the way out, nothing is
// written; `triangulate` first makes it run.
TEST(CliSubdivide, QuadsAreRefusedUntilTriangulated) {
    TempDir tmp;
    const RunResult refused =
        run_meshedit({"subdivide", (repo_root() / "dae/quadball.dae").string(),
                      (tmp / "out.obj").string(), "-n", "2", "--weights", "loop"});
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_NE(refused.err.find("quadball.dae: loop:2 refused: cannot subdivide: Loop needs "
                               "triangles and 96 of the 96 faces are polygons (triangulate "
                               "them first"),
              std::string::npos)
        << refused.err;
    EXPECT_FALSE(std::filesystem::exists(tmp / "out.obj"));
    const RunResult r = run_meshedit({"convert", (repo_root() / "dae/quadball.dae").string(),
                                      (tmp / "out.obj").string(), "--ops", "triangulate,loop:2"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // Triangulated: 98/288/192 → 386/1152/768 → 1538/4608/3072.
    const Json j = info_json(tmp / "out.obj");
    EXPECT_EQ(j["vertices"], 1538);
    EXPECT_EQ(j["edges"], 4608);
    EXPECT_EQ(j["faces"], 3072);
}

TEST(CliSubdivide, CreasesSplitAndStayCreases) {
    TempDir tmp;
    const RunResult r = run_meshedit({"subdivide", (repo_root() / "dae/creased.dae").string(),
                                      (tmp / "out.dae").string(), "-n", "2"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json j = info_json(tmp / "out.dae");
    EXPECT_EQ(j["creases"], 32 * 4);
    // The rims stay sharp: the cylinder keeps its full height and radius 1 at the rims.
    EXPECT_NEAR(j["bbox"]["min"][1].get<double>(), -1.0, 1e-12);
    EXPECT_NEAR(j["bbox"]["max"][1].get<double>(), 1.0, 1e-12);
}

// --scheme catmull-clark takes polygons: quadball's 96 quads → 384 → 1536; the same as the
// --ops verb; linear keeps every old vertex where it was (the bounding box of a ball
// shrinks under Catmull-Clark, not under linear).
TEST(CliSubdivide, CatmullClarkAndLinearSchemes) {
    TempDir tmp;
    const std::string in = (repo_root() / "dae/quadball.dae").string();
    const RunResult cc = run_meshedit(
        {"subdivide", in, (tmp / "cc.dae").string(), "-n", "2", "--scheme", "catmull-clark"});
    ASSERT_EQ(cc.exit_code, 0) << cc.err;
    const Json j = info_json(tmp / "cc.dae");
    // 98/192/96 → 386/768/384 → 1538/3072/1536.
    EXPECT_EQ(j["vertices"], 1538);
    EXPECT_EQ(j["edges"], 3072);
    EXPECT_EQ(j["faces"], 1536);
    EXPECT_LT(j["bbox"]["max"][0].get<double>(), 0.99);
    const RunResult ops =
        run_meshedit({"convert", in, (tmp / "ops.dae").string(), "--ops", "catmull_clark:2"});
    ASSERT_EQ(ops.exit_code, 0) << ops.err;
    EXPECT_EQ(canonical_faces(read_mesh(tmp / "cc.dae").mesh),
              canonical_faces(read_mesh(tmp / "ops.dae").mesh));

    const RunResult linear = run_meshedit(
        {"subdivide", in, (tmp / "linear.dae").string(), "-n", "1", "--scheme", "linear"});
    ASSERT_EQ(linear.exit_code, 0) << linear.err;
    const Json l = info_json(tmp / "linear.dae");
    EXPECT_EQ(l["faces"], 384);
    EXPECT_EQ(l["bbox"]["max"][0].get<double>(), 1.0);
    EXPECT_EQ(l["bbox"]["min"][1].get<double>(), -1.0);

    const RunResult bad = run_meshedit(
        {"subdivide", in, (tmp / "x.dae").string(), "-n", "1", "--scheme", "butterfly"});
    EXPECT_EQ(bad.exit_code, 2);
}

TEST(CliSubdivide, WarrenAndLoopWeightsDiffer) {
    TempDir tmp;
    const auto in = (repo_root() / "dae/icosahedron.dae").string();
    ASSERT_EQ(run_meshedit({"subdivide", in, (tmp / "w.dae").string(), "-n", "1"}).exit_code, 0);
    ASSERT_EQ(run_meshedit({"subdivide", in, (tmp / "l.dae").string(), "-n1", "--weights=loop"})
                  .exit_code,
              0);
    const Mesh w = read_mesh(tmp / "w.dae").mesh;
    const Mesh l = read_mesh(tmp / "l.dae").mesh;
    EXPECT_EQ(canonical_faces(w), canonical_faces(l));
    EXPECT_GT(distance(w.position(Vertex(0)), l.position(Vertex(0))), 1e-6);
}

TEST(CliSubdivide, RefusesWhatCannotFitInMemoryBeforeStarting) {
    TempDir tmp;
    // 4032 · 4^12 triangles would need terabytes: refused at once, nothing written.
    const RunResult r = run_meshedit({"subdivide", (repo_root() / "dae/teapot.dae").string(),
                                      (tmp / "out.dae").string(), "-n", "12"},
                                     5.0);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("loop:12 refused: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("memory"), std::string::npos) << r.err;
    EXPECT_TRUE(tmp.entries().empty());
}

TEST(CliSubdivide, BadArgumentsAreBadUsage) {
    TempDir tmp;
    const auto in = (repo_root() / "dae/cube.dae").string();
    const auto out = (tmp / "o.dae").string();
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"subdivide", in, out},
          {"subdivide", in, out, "-n", "two"},
          {"subdivide", in, out, "-n", "-1"},
          {"subdivide", in, out, "-n", "99"},
          {"subdivide", in, out, "-n", "1", "--weights", "catmull"},
          {"subdivide", in, out, "-n", "1", "--uv-interpolation", "smooth"},
          {"subdivide", in, "-n", "1"},
          {"subdivide", in, out, "-n", "1", "--frobnicate"}}) {
        const RunResult r = run_meshedit(args);
        EXPECT_EQ(r.exit_code, 2) << args.back();
        EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
    }
    EXPECT_TRUE(tmp.entries().empty());
}

// --uv-interpolation names OpenSubdiv's face-varying option; a wrong name is told with the
// valid ones, and each name reaches the core: on a quad cube with a chart per face, `all`
// writes other texture coordinates than `none`, and `corners` (the default) what no flag
// writes.
TEST(CliSubdivide, UvInterpolationReachesTheCore) {
    TempDir tmp;
    const auto in = (tmp / "charts.obj").string();
    {
        std::ofstream obj(in);
        obj << "v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\n"
               "v -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n";
        for (int f = 0; f < 6; ++f) {
            obj << "vt " << f << " 0\nvt " << f + 0.5 << " 0\nvt " << f + 0.5 << " 0.5\nvt " << f
                << " 0.75\n";
        }
        const int faces[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5},
                                 {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
        for (int f = 0; f < 6; ++f) {
            obj << "f";
            for (int i = 0; i < 4; ++i) {
                obj << " " << faces[f][i] << "/" << 4 * f + i + 1;
            }
            obj << "\n";
        }
    }
    const RunResult bad = run_meshedit(
        {"subdivide", in, (tmp / "x.obj").string(), "-n", "1", "--uv-interpolation", "corners+3"});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("unknown texture-coordinate interpolation 'corners+3' (one of none, "
                           "corners, corners+1, corners+2, boundaries, all)"),
              std::string::npos)
        << bad.err;
    const auto texcoords = [&](const std::vector<std::string>& flag) {
        const auto out = (tmp / "out.obj").string();
        std::vector<std::string> args{"subdivide", in, out, "-n", "2", "--scheme", "catmull-clark"};
        args.insert(args.end(), flag.begin(), flag.end());
        const RunResult r = run_meshedit(args);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        std::ifstream file(out);
        std::string line, vt;
        while (std::getline(file, line)) {
            vt += line.rfind("vt ", 0) == 0 ? line + "\n" : "";
        }
        return vt;
    };
    const std::string none = texcoords({"--uv-interpolation", "none"});
    const std::string all = texcoords({"--uv-interpolation=all"});
    EXPECT_FALSE(none.empty());
    EXPECT_NE(none, all);
    EXPECT_EQ(texcoords({"--uv-interpolation", "corners"}), texcoords({}));
}

// --------------------------------------------------------------------------- check

TEST(CliCheck, ValidMeshesPass) {
    for (const char* file : {"dae/cube.dae", "dae/bowl.dae", "dae/teapot.dae", "bez/teapot.bez"}) {
        const RunResult r = run_meshedit({"check", (repo_root() / file).string()});
        EXPECT_EQ(r.exit_code, 0) << file << r.err;
        EXPECT_NE(r.out.find(": OK ("), std::string::npos) << r.out;
    }
}

// --------------------------------------------------------------------------- eval

// Σ C(n,i) tⁱ (1−t)ⁿ⁻ⁱ Pᵢ, written out here rather than taken from the library under test.
std::pair<double, double> bernstein(const std::vector<std::pair<double, double>>& p, double t) {
    const int n = static_cast<int>(p.size()) - 1;
    double x = 0.0, y = 0.0, binomial = 1.0;
    for (int i = 0; i <= n; ++i) {
        const double w = binomial * std::pow(t, i) * std::pow(1.0 - t, n - i);
        x += w * p[i].first;
        y += w * p[i].second;
        binomial = binomial * (n - i) / (i + 1);
    }
    return {x, y};
}

// "(x y) (x y) …" → points.
std::vector<std::pair<double, double>> parse_points(const std::string& text) {
    std::vector<std::pair<double, double>> points;
    std::istringstream in(text);
    char open = 0, close = 0;
    double x = 0, y = 0;
    while (in >> open >> x >> y >> close) {
        EXPECT_EQ(open, '(');
        EXPECT_EQ(close, ')');
        points.emplace_back(x, y);
    }
    return points;
}

TEST(CliEval, CurveLevelsAndBernsteinValue) {
    const RunResult r =
        run_meshedit({"eval", (repo_root() / "bez/curve1.bzc").string(), "--t", "0.5", "--levels"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> lines = split_lines(r.out);
    ASSERT_EQ(lines.size(), 5u) << r.out;
    const std::vector<std::pair<double, double>> control{
        {0.1, 0.2}, {0.3, 0.9}, {0.7, 0.1}, {0.9, 0.8}};
    for (std::size_t k = 0; k < 4; ++k) {
        const std::string prefix = "level " + std::to_string(k) + ": ";
        ASSERT_EQ(lines[k].rfind(prefix, 0), 0u) << lines[k];
        const auto points = parse_points(lines[k].substr(prefix.size()));
        EXPECT_EQ(points.size(), 4 - k) << lines[k];
        if (k == 0) {
            EXPECT_EQ(points, control);
        }
    }
    const auto expected = bernstein(control, 0.5);
    const auto last = parse_points(lines[3].substr(9));
    ASSERT_EQ(last.size(), 1u);
    EXPECT_NEAR(last[0].first, expected.first, 1e-12);
    EXPECT_NEAR(last[0].second, expected.second, 1e-12);
    ASSERT_EQ(lines[4].rfind("B(0.5) = ", 0), 0u) << lines[4];
    EXPECT_EQ(parse_points(lines[4].substr(9)), last);
}

TEST(CliEval, CurveAtOtherParameters) {
    const std::vector<std::pair<double, double>> control{
        {0.05, 0.3}, {0.25, 0.95}, {0.5, 0.05}, {0.75, 0.95}, {0.95, 0.3}};
    for (const double t : {0.0, 0.25, 0.8, 1.0}) {
        std::ostringstream text;
        text << t;
        const RunResult r =
            run_meshedit({"eval", (repo_root() / "bez/curve2.bzc").string(), "--t", text.str()});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const auto at = r.out.find(" = ");
        ASSERT_NE(at, std::string::npos) << r.out;
        const auto point = parse_points(r.out.substr(at + 3));
        ASSERT_EQ(point.size(), 1u) << r.out;
        const auto expected = bernstein(control, t);
        EXPECT_NEAR(point[0].first, expected.first, 1e-12) << t;
        EXPECT_NEAR(point[0].second, expected.second, 1e-12) << t;
    }
}

TEST(CliEval, PatchPositionAndNormal) {
    // wavy_cube.bez patch 0 through the library, compared with the command's output.
    const auto file = repo_root() / "bez/wavy_cube.bez";
    const PatchPoint expected = read_bez(file)[1].evaluate_with_derivatives(0.25, 0.5);
    const RunResult r = run_meshedit({"eval", file.string(), "--uv", "0.25,0.5", "--patch", "1"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto lines = split_lines(r.out);
    ASSERT_EQ(lines.size(), 3u) << r.out;
    std::istringstream pos(lines[1].substr(lines[1].find(':') + 1));
    std::istringstream nrm(lines[2].substr(lines[2].find(':') + 1));
    Vec3 p, n;
    pos >> p.x >> p.y >> p.z;
    nrm >> n.x >> n.y >> n.z;
    EXPECT_LE(distance(p, expected.position), 1e-12) << r.out;
    EXPECT_LE(distance(n, expected.normal), 1e-12) << r.out;
    EXPECT_NEAR(norm(n), 1.0, 1e-12);
}

TEST(CliEval, BadArgumentsAreBadUsage) {
    const auto curve = (repo_root() / "bez/curve1.bzc").string();
    const auto patches = (repo_root() / "bez/teapot.bez").string();
    for (const std::vector<std::string>& args : {
             std::vector<std::string>{"eval", curve},
             {"eval", curve, "--t", "half"},
             {"eval", curve, "--t", "1.5"},
             {"eval", curve, "--t", "nan"},
             {"eval", curve, "--uv", "0.5,0.5"},
             {"eval", patches, "--uv", "0.5"},
             {"eval", patches, "--uv", "0.5,0.5", "--patch", "32"},
             {"eval", patches, "--t", "0.5"},
             {"eval", (repo_root() / "dae/cube.dae").string(), "--t", "0.5"},
         }) {
        const RunResult r = run_meshedit(args);
        EXPECT_EQ(r.exit_code, 2) << args[1] << " " << args.back() << ": " << r.err;
        EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
        EXPECT_EQ(r.err.rfind("meshedit: ", 0), 0u) << r.err;
    }
}

// --------------------------------------------------------------------------- usage

TEST(CliUsage, NoArgumentsPrintsUsageAndExitsTwo) {
    const RunResult r = run_meshedit({});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("usage: meshedit"), std::string::npos);
    EXPECT_TRUE(r.out.empty());
}

TEST(CliUsage, HelpEverywhere) {
    const RunResult top = run_meshedit({"--help"});
    EXPECT_EQ(top.exit_code, 0);
    EXPECT_NE(top.out.find("usage: meshedit"), std::string::npos);
    std::vector<const char*> commands{"info", "convert", "subdivide", "repair", "check", "eval"};
    if (kViewerBuilt) {
        commands.push_back("view");  // answered by meshedit-view
    }
    for (const char* command : commands) {
        for (const char* flag : {"--help", "-h"}) {
            const RunResult r = run_meshedit({command, flag});
            EXPECT_EQ(r.exit_code, 0) << command;
            EXPECT_NE(r.out.find(std::string("meshedit ") +
                                 (std::string(command) == "view" ? "[view]" : command)),
                      std::string::npos)
                << command << ": " << r.out;
            EXPECT_TRUE(r.err.empty()) << r.err;
        }
    }
    const RunResult version = run_meshedit({"--version"});
    EXPECT_EQ(version.exit_code, 0);
    EXPECT_EQ(version.out.rfind("meshedit ", 0), 0u) << version.out;
    const RunResult help = run_meshedit({"help", "subdivide"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("-n K"), std::string::npos);
}

TEST(CliUsage, UnknownCommandAndOption) {
    RunResult r = run_meshedit({"frobnicate"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown command 'frobnicate'"), std::string::npos) << r.err;
    r = run_meshedit({"info", (repo_root() / "dae/cube.dae").string(), "--color"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown option '--color'"), std::string::npos) << r.err;
    r = run_meshedit({"info"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("missing FILE"), std::string::npos) << r.err;
}

TEST(CliUsage, ViewerWithoutDisplayPointsToRender) {
    if (!kViewerBuilt) {
        GTEST_SKIP() << "configured with MESHEDIT_BUILD_VIEWER=OFF";
    }
    // `meshedit FILE` and `meshedit view FILE` run meshedit-view; with no display it says so
    // in one line and names the headless command instead of failing obscurely.
    const char* display = std::getenv("DISPLAY");
    const std::string saved = display ? display : "";
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    const auto cube = (repo_root() / "dae/cube.dae").string();
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{cube}, std::vector<std::string>{"view", cube}}) {
        const RunResult r = run_meshedit(args);
        EXPECT_EQ(r.exit_code, 1);
        EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
        EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("meshedit render " + cube), std::string::npos) << r.err;
    }
    if (display) {
        ::setenv("DISPLAY", saved.c_str(), 1);
    }
}

}  // namespace
}  // namespace meshedit::test
