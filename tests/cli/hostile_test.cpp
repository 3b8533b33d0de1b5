// Hostile inputs the fuzzers cannot reach (bigger than their length limit, or not bytes at all:
// FIFOs, devices, sparse files). Each is generated here and run through `meshedit info` and
// `meshedit convert` under a time and memory limit (10 s, 2 GB of address space, a memory
// budget of 1 GB): every one must end in one clear line naming the file, or in a correct mesh.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "run.h"

namespace meshedit::test {
namespace {

namespace fs = std::filesystem;

constexpr double kSeconds = 10.0;
constexpr std::size_t kAddressSpace = std::size_t{2} << 30;

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// One triangle as an embedded glTF buffer, and a glTF around it.
const char* const kTriangleBuffer =
    "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";

std::string gltf(const std::string& nodes, const std::string& roots, const std::string& uri,
                 const std::string& extras = "") {
    return R"({"asset": {"version": "2.0")" + (extras.empty() ? "" : ", \"extras\": " + extras) +
           R"(}, "scene": 0, "scenes": [{"nodes": )" + roots + R"(}], "nodes": )" + nodes +
           R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "buffers": [{"byteLength": 36, "uri": ")" +
           uri + R"("}]})";
}

// A unit grid of n×n quads cut into 2n² triangles as a COLLADA <geometry> body.
std::string collada_grid(int n) {
    std::string positions, indices;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            positions += std::to_string(i) + " " + std::to_string(j) + " 0 ";
        }
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i;
            indices += std::to_string(a) + " " + std::to_string(a + 1) + " " +
                       std::to_string(a + n + 2) + " " + std::to_string(a) + " " +
                       std::to_string(a + n + 2) + " " + std::to_string(a + n + 1) + " ";
        }
    }
    const int nv = (n + 1) * (n + 1);
    return R"(<geometry id="g"><mesh><source id="p"><float_array id="pa" count=")" +
           std::to_string(3 * nv) + "\">" + positions +
           R"(</float_array><technique_common><accessor source="#pa" count=")" +
           std::to_string(nv) +
           R"(" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source><vertices id="v"><input semantic="POSITION" source="#p"/></vertices><triangles count=")" +
           std::to_string(2 * n * n) + R"("><input semantic="VERTEX" source="#v" offset="0"/><p>)" +
           indices + "</p></triangles></mesh></geometry>";
}

struct Case {
    std::string name;
    std::function<fs::path(const fs::path& dir)> make;
    std::vector<std::string> args;  // after the command and the file; "info" if empty
    int exit_code;                  // 0: loads; 1 or 2: refused
    std::string expect;             // in stdout (0) or in the one stderr line (1, 2)
};

void PrintTo(const Case& c, std::ostream* os) {
    *os << c.name;
}

std::vector<Case> cases() {
    std::vector<Case> out;
    // glTF: a 20,000-node chain loads (the walk has its own stack); a DAG, deep JSON, a buffer
    // outside the folder or a FIFO are refused; instancing beyond the budget is refused.
    out.push_back({"gltf node chain",
                   [](const fs::path& d) {
                       std::string nodes = "[";
                       for (int i = 0; i < 20000; ++i) {
                           nodes +=
                               (i ? "," : "") + std::string(R"({"translation": [1, 0, 0])") +
                               (i + 1 < 20000 ? R"(, "children": [)" + std::to_string(i + 1) + "]}"
                                              : R"(, "mesh": 0})");
                       }
                       write_text(d / "chain.gltf", gltf(nodes + "]", "[0]", kTriangleBuffer));
                       return d / "chain.gltf";
                   },
                   {},
                   0,
                   "vertices:              3"});
    out.push_back({"gltf node DAG",
                   [](const fs::path& d) {
                       std::string nodes = "[";
                       for (int i = 0; i < 40; ++i) {
                           nodes += R"({"children": [)" + std::to_string(i + 1) + "," +
                                    std::to_string(i + 1) + "]},";
                       }
                       write_text(d / "dag.gltf",
                                  gltf(nodes + R"({"mesh": 0}])", "[0]", kTriangleBuffer));
                       return d / "dag.gltf";
                   },
                   {},
                   2,
                   "reached twice"});
    out.push_back({"gltf deep JSON",
                   [](const fs::path& d) {
                       write_text(d / "deep.gltf",
                                  gltf(R"([{"mesh": 0}])", "[0]", kTriangleBuffer,
                                       std::string(16000, '[') + std::string(16000, ']')));
                       return d / "deep.gltf";
                   },
                   {},
                   2,
                   "JSON nested deeper than 512 levels"});
    out.push_back({"gltf buffer outside",
                   [](const fs::path& d) {
                       fs::create_directories(d / "model");
                       write_text(d / "secret.bin", std::string(36, 'x'));
                       write_text(d / "model" / "up.gltf",
                                  gltf(R"([{"mesh": 0}])", "[0]", "../secret.bin"));
                       return d / "model" / "up.gltf";
                   },
                   {},
                   2,
                   "lies outside the model's folder"});
    out.push_back({"gltf FIFO buffer",
                   [](const fs::path& d) {
                       ::mkfifo((d / "pipe.bin").c_str(), 0600);
                       write_text(d / "fifo.gltf", gltf(R"([{"mesh": 0}])", "[0]", "pipe.bin"));
                       return d / "fifo.gltf";
                   },
                   {},
                   2,
                   "is not a regular file"});
    out.push_back({"gltf instancing",
                   [](const fs::path& d) {
                       // A 3,000-triangle mesh (108 KB of buffer) in 100,000 root nodes.
                       std::string nodes = "[", roots = "[";
                       for (int i = 0; i < 100000; ++i) {
                           nodes += std::string(i ? "," : "") + R"({"mesh": 0})";
                           roots += (i ? "," : "") + std::to_string(i);
                       }
                       write_text(d / "data.bin", std::string(108000, '\0'));
                       write_text(
                           d / "instances.gltf",
                           R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": )" +
                               roots + R"(]}], "nodes": )" + nodes +
                               R"(], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 9000, "type": "VEC3",
                "min": [0, 0, 0], "max": [0, 0, 0]}],
 "bufferViews": [{"buffer": 0, "byteLength": 108000}],
 "buffers": [{"byteLength": 108000, "uri": "data.bin"}]})");
                       return d / "instances.gltf";
                   },
                   {},
                   2,
                   "would need about"});
    // COLLADA: one 800-triangle geometry instanced 42,000 times.
    out.push_back(
        {"collada instancing",
         [](const fs::path& d) {
             std::string scene;
             for (int i = 0; i < 42000; ++i) {
                 scene += R"(<node><instance_geometry url="#g"/></node>)";
             }
             write_text(
                 d / "instances.dae",
                 R"(<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1"><library_geometries>)" +
                     collada_grid(20) +
                     R"(</library_geometries><library_visual_scenes><visual_scene id="s">)" +
                     scene +
                     R"(</visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>)");
             return d / "instances.dae";
         },
         {},
         2,
         "would need about"});
    // OBJ: a million-triangle fan around vertex 1 and a million-corner polygon load in
    // O(n log n) (they took 333 s and 208 s).
    out.push_back({"obj fan around the first vertex",
                   [](const fs::path& d) {
                       std::string t = "v 0 0 0\n";
                       constexpr int n = 1000000;
                       char line[64];
                       for (int i = 0; i < n; ++i) {
                           std::snprintf(line, sizeof line, "v %.7f %.7f 0\n",
                                         std::cos(i * 6.283185307 / n),
                                         std::sin(i * 6.283185307 / n));
                           t += line;
                       }
                       for (int i = 0; i < n; ++i) {
                           std::snprintf(line, sizeof line, "f 1 %d %d\n", i + 2, (i + 1) % n + 2);
                           t += line;
                       }
                       write_text(d / "fan.obj", t);
                       return d / "fan.obj";
                   },
                   {},
                   0,
                   "faces:                 1000000 (all triangles)"});
    out.push_back({"obj million-corner polygon",
                   [](const fs::path& d) {
                       std::string t;
                       constexpr int n = 1000000;
                       char line[64];
                       for (int i = 0; i < n; ++i) {
                           std::snprintf(line, sizeof line, "v %.7f %.7f 0\n",
                                         std::cos(i * 6.283185307 / n),
                                         std::sin(i * 6.283185307 / n));
                           t += line;
                       }
                       t += "f";
                       for (int i = 1; i <= n; ++i) {
                           t += ' ';
                           t += std::to_string(i);
                       }
                       write_text(d / "polygon.obj", t + "\n");
                       return d / "polygon.obj";
                   },
                   {},
                   0,
                   "faces:                 1 (polygons)"});
    // Bytes that are no text: zeros (a sparse file), one bigger than the budget, UTF-16.
    out.push_back({"obj of zeros",
                   [](const fs::path& d) {
                       const fs::path f = d / "zeros.obj";
                       write_text(f, "");
                       fs::resize_file(f, std::size_t{200} << 20);
                       return f;
                   },
                   {},
                   2,
                   "binary data (a NUL byte)"});
    out.push_back({"obj bigger than the budget",
                   [](const fs::path& d) {
                       const fs::path f = d / "huge.obj";
                       write_text(f, "");
                       fs::resize_file(f, std::size_t{4} << 30);
                       return f;
                   },
                   {},
                   2,
                   "more than the memory budget"});
    out.push_back({"obj UTF-16",
                   [](const fs::path& d) {
                       write_text(d / "wide.obj", std::string("\xFF\xFEv\0 \0"
                                                              "0\0",
                                                              9));
                       return d / "wide.obj";
                   },
                   {},
                   2,
                   "UTF-16"});
    out.push_back({"obj byte-order mark",
                   [](const fs::path& d) {
                       write_text(d / "bom.obj",
                                  "\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
                       return d / "bom.obj";
                   },
                   {},
                   0,
                   "vertices:              3"});
    out.push_back({"obj empty",
                   [](const fs::path& d) {
                       write_text(d / "empty.obj", "");
                       return d / "empty.obj";
                   },
                   {},
                   2,
                   "holds no faces to load"});
    out.push_back({"obj whose only face is degenerate",
                   [](const fs::path& d) {
                       write_text(d / "degenerate.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 2\n");
                       return d / "degenerate.obj";
                   },
                   {},
                   2,
                   "holds no faces to load: its only face was dropped as degenerate"});
    out.push_back({"obj that is prose",
                   [](const fs::path& d) {
                       write_text(d / "prose.obj", "This is not a mesh.\nNor is this line.\n");
                       return d / "prose.obj";
                   },
                   {},
                   2,
                   "holds no faces to load"});
    out.push_back({"obj index overflow",
                   [](const fs::path& d) {
                       write_text(d / "index.obj",
                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n");
                       return d / "index.obj";
                   },
                   {},
                   2,
                   "line 4: face 1: vertex index 99999999999999999999 is out of range"});
    out.push_back({"obj huge coordinates",
                   [](const fs::path& d) {
                       write_text(d / "far.obj",
                                  "v 0 0 0\nv 1e200 0 0\nv 0 1e200 0\nv 0 0 1e200\n"
                                  "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
                       return d / "far.obj";
                   },
                   {},
                   0,
                   "faces:                 4"});
    // Not regular files.
    out.push_back({"dae FIFO",
                   [](const fs::path& d) {
                       ::mkfifo((d / "pipe.dae").c_str(), 0600);
                       return d / "pipe.dae";
                   },
                   {},
                   2,
                   "is not a regular file"});
    out.push_back({"dae that is /dev/zero",
                   [](const fs::path& d) {
                       fs::create_symlink("/dev/zero", d / "zero.dae");
                       return d / "zero.dae";
                   },
                   {},
                   2,
                   "is not a regular file"});
    // Bezier: a patch far away keeps the teapot, a density beyond the budget is refused, every
    // de Casteljau level of a 30,000-point curve is refused.
    out.push_back({"bez far patch",
                   [](const fs::path& d) {
                       std::ifstream in(repo_root() / "bez/teapot.bez");
                       std::string header, rest;
                       std::getline(in, header);
                       while (header.empty() || header[0] == '#') {
                           std::getline(in, header);
                       }
                       rest.assign(std::istreambuf_iterator<char>(in), {});
                       std::string far = std::to_string(std::stoi(header) + 1) + "\n" + rest;
                       for (int k = 0; k < 16; ++k) {
                           far +=
                               "1e10 " + std::to_string(k % 4) + " " + std::to_string(k / 4) + "\n";
                       }
                       write_text(d / "far.bez", far);
                       return d / "far.bez";
                   },
                   {},
                   0,
                   "faces:                 4160 (all triangles)"});
    out.push_back({"bez density beyond the budget",
                   [](const fs::path&) { return repo_root() / "bez/teapot.bez"; },
                   {"--density", "256"},
                   2,
                   "would need about"});
    out.push_back({"bzc of 30,000 points",
                   [](const fs::path& d) {
                       std::string t = "30000\n";
                       for (int i = 0; i < 30000; ++i) {
                           t += std::to_string(i / 30000.0) + " 0.5\n";
                       }
                       write_text(d / "long.bzc", t);
                       return d / "long.bzc";
                   },
                   {"eval", "--t", "0.5", "--levels"},
                   1,
                   "would need about"});
    return out;
}

class Hostile : public ::testing::TestWithParam<Case> {
protected:
    void SetUp() override {
        const char* old = std::getenv("MESHEDIT_MEMORY_BUDGET");
        saved_ = old ? old : "";
        had_ = old != nullptr;
        ::setenv("MESHEDIT_MEMORY_BUDGET", "1G", 1);
    }
    void TearDown() override {
        if (had_) {
            ::setenv("MESHEDIT_MEMORY_BUDGET", saved_.c_str(), 1);
        } else {
            ::unsetenv("MESHEDIT_MEMORY_BUDGET");
        }
    }
    std::string saved_;
    bool had_ = false;
};

TEST_P(Hostile, ClearMessageOrCorrectMesh) {
    const Case& c = GetParam();
    TempDir dir;
    const fs::path file = c.make(dir.path());
    std::vector<std::string> args;
    if (!c.args.empty() && c.args[0] == "eval") {
        args = {"eval", file.string()};
        args.insert(args.end(), c.args.begin() + 1, c.args.end());
    } else {
        args = {"info", file.string()};
        args.insert(args.end(), c.args.begin(), c.args.end());
    }
    RunResult r = run_meshedit(args, kSeconds, kAddressSpace);
    ASSERT_FALSE(r.timed_out) << "took more than " << kSeconds << " s";
    ASSERT_EQ(r.signal, 0) << "killed by signal " << r.signal << ": " << r.err;
    EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
    if (c.exit_code == 0) {
        EXPECT_NE(r.out.find(c.expect), std::string::npos) << r.out;
        if (args[0] != "info") {
            return;
        }
        // What loads converts, and what is written reads back.
        const fs::path out = dir / "out.obj";
        std::vector<std::string> convert = {"convert", file.string(), out.string()};
        convert.insert(convert.end(), c.args.begin(), c.args.end());
        r = run_meshedit(convert, kSeconds, kAddressSpace);
        ASSERT_FALSE(r.timed_out);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        r = run_meshedit({"check", out.string()}, kSeconds, kAddressSpace);
        EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    } else {
        EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
        EXPECT_NE(r.err.find(file.filename().string()), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    }
}

INSTANTIATE_TEST_SUITE_P(Inputs, Hostile, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& param) {
                             std::string name;
                             for (char ch : param.param.name) {
                                 name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                             }
                             return name;
                         });

}  // namespace
}  // namespace meshedit::test
