// meshedit-make-samples: regenerates the sample meshes in dae/ (docs/samples.md).
//
//   meshedit-make-samples [REPO_ROOT]      (default: the source tree it was built from)
//
// Every sample is built by the project's own code (shapes.h, tessellate()) and written with
// write_mesh(). The reference pairs dae/<shape>/{input,flip,split,collapse}.dae are made the
// way `meshedit convert input.dae out.dae --ops <op>` makes them: input.dae is written, read
// back, the op applied through the CLI's ops library, and the result written. So the CLI
// tests can check that the command reproduces each file exactly.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/build.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/topology.h"
#include "meshedit/core/validate.h"
#include "meshedit/io/io.h"
#include "meshedit/ops/ops.h"

namespace fs = std::filesystem;
using namespace meshedit;

namespace {

constexpr double kPi = std::numbers::pi;

// Reverses every face whose normal points towards the origin. The generated shapes are
// star-shaped about the origin, so this orients them outward without bookkeeping per
// ring and cap.
void orient_outward(PolygonSoup& soup) {
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        auto* first = &soup.indices[soup.face_offsets[f]];
        auto* last = &soup.indices[soup.face_offsets[f + 1]];
        const Vec3 a = soup.positions[first[0]];
        const Vec3 b = soup.positions[first[1]];
        const Vec3 c = soup.positions[first[2]];
        if (dot(cross(b - a, c - a), a + b + c) < 0.0) {
            std::reverse(first, last);
        }
    }
}

/// An open bowl: the lower unit hemisphere (Y-up), a pole vertex 0 at (0,-1,0) and `rings`
/// rings of `segments` vertices up to the rim at y = 0, which stays open (one boundary).
Mesh bowl(int segments, int rings) {
    PolygonSoup soup;
    soup.positions.push_back({0.0, -1.0, 0.0});
    for (int k = 1; k <= rings; ++k) {
        const double theta = 0.5 * kPi * k / rings;
        for (int i = 0; i < segments; ++i) {
            const double phi = 2.0 * kPi * i / segments;
            // The rim lies exactly on y = 0 (cos(π/2) is 6e-17 in floating point).
            const double y = k == rings ? 0.0 : -std::cos(theta);
            soup.positions.push_back(
                {std::sin(theta) * std::cos(phi), y, std::sin(theta) * std::sin(phi)});
        }
    }
    auto id = [&](int k, int i) { return std::uint32_t(1 + (k - 1) * segments + i % segments); };
    for (int i = 0; i < segments; ++i) {
        soup.add_face({0, id(1, i), id(1, i + 1)});
    }
    for (int k = 1; k < rings; ++k) {
        for (int i = 0; i < segments; ++i) {
            soup.add_face({id(k, i), id(k + 1, i), id(k + 1, i + 1)});
            soup.add_face({id(k, i), id(k + 1, i + 1), id(k, i + 1)});
        }
    }
    orient_outward(soup);
    return build_mesh(soup);
}

/// A closed cylinder along y (radius 1, y in [-1, 1]) with fan caps, its two rim circles
/// marked as creases so Loop subdivision rounds the side but keeps the rims sharp. Vertex
/// (i, j) (segment i, row j from the bottom) is j·segments + i; the bottom and top cap
/// centres follow.
Mesh creased_cylinder(int segments, int rows) {
    PolygonSoup soup;
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i < segments; ++i) {
            const double phi = 2.0 * kPi * i / segments;
            soup.positions.push_back({std::cos(phi), -1.0 + 2.0 * j / rows, std::sin(phi)});
        }
    }
    const auto bottom = std::uint32_t(soup.positions.size());
    soup.positions.push_back({0.0, -1.0, 0.0});
    soup.positions.push_back({0.0, 1.0, 0.0});
    const std::uint32_t top = bottom + 1;
    auto id = [&](int i, int j) { return std::uint32_t(j * segments + i % segments); };
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < segments; ++i) {
            soup.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            soup.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    for (int i = 0; i < segments; ++i) {
        soup.add_face({bottom, id(i, 0), id(i + 1, 0)});
        soup.add_face({top, id(i, rows), id(i + 1, rows)});
    }
    orient_outward(soup);
    Mesh mesh = build_mesh(soup);
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    for (const int j : {0, rows}) {
        for (int i = 0; i < segments; ++i) {
            crease[mesh.find_edge(Vertex(id(i, j)), Vertex(id(i + 1, j)))] = 1;
        }
    }
    return mesh;
}

void report(const fs::path& path, const Mesh& mesh) {
    const MeshStats s = compute_stats(mesh);
    std::printf("%-32s V %6zu  E %6zu  F %6zu  (%ju bytes)\n", path.string().c_str(), s.vertices,
                s.edges, s.faces, static_cast<std::uintmax_t>(fs::file_size(path)));
}

void save(const Mesh& mesh, const fs::path& path) {
    if (const auto error = validate(mesh)) {
        throw std::runtime_error(path.string() + ": generated mesh is invalid: " + error->message);
    }
    fs::create_directories(path.parent_path());
    write_mesh(mesh, path);
    report(path, read_mesh(path).mesh);
}

/// One reference pair folder: input.dae plus one file per op, each made from input.dae
/// read back, as `meshedit convert input.dae <name>.dae --ops <op>` does.
struct Reference {
    const char* name;  // file stem
    const char* op;    // --ops text
};

void save_references(const Mesh& mesh, const fs::path& folder,
                     const std::vector<Reference>& references) {
    const fs::path input = folder / "input.dae";
    save(mesh, input);
    for (const Reference& r : references) {
        Mesh edited = read_mesh(input).mesh;
        ops::apply_steps(edited, ops::parse(r.op));
        save(edited, folder / (std::string(r.name) + ".dae"));
    }
}

}  // namespace

int main(int argc, char** argv) {
    const fs::path root = argc > 1 ? fs::path(argv[1]) : fs::path(MESHEDIT_SOURCE_DIR);
    if (argc > 2 ||
        (argc == 2 && (std::string(argv[1]) == "-h" || std::string(argv[1]) == "--help"))) {
        std::printf(
            "usage: meshedit-make-samples [REPO_ROOT]\nRegenerates REPO_ROOT/dae "
            "(docs/samples.md).\n");
        return argc > 2 ? 2 : 0;
    }
    const fs::path dae = root / "dae";
    try {
        save(shapes::cube(), dae / "cube.dae");
        save(shapes::icosahedron(), dae / "icosahedron.dae");
        save(shapes::torus(24, 12), dae / "torus.dae");
        save(shapes::quad_sphere(4), dae / "quadball.dae");
        save(shapes::quad_sphere(1), dae / "quadcube.dae");
        save(bowl(24, 6), dae / "bowl.dae");
        save(creased_cylinder(16, 2), dae / "creased.dae");
        // The default density (8 quads per patch side) keeps the file small (~0.3 MB).
        save(tessellate(read_bez(root / "bez" / "teapot.bez")), dae / "teapot.dae");

        // Interior edges named by their endpoints in the sample's own numbering; each choice
        // is explained in docs/samples.md.
        save_references(
            shapes::cube(), dae / "cube",
            {{"flip", "flip:0-6"}, {"split", "split:0-1"}, {"collapse", "collapse:1-3"}});
        save_references(
            shapes::icosahedron(), dae / "icosahedron",
            {{"flip", "flip:0-5"}, {"split", "split:0-1"}, {"collapse", "collapse:3-4"}});
        save_references(
            shapes::torus(24, 12), dae / "torus",
            {{"flip", "flip:0-13"}, {"split", "split:0-1"}, {"collapse", "collapse:0-12"}});
    } catch (const std::exception& e) {
        std::fprintf(stderr, "meshedit-make-samples: %s\n", e.what());
        return 1;
    }
    return 0;
}
