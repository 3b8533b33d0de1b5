// The shared body of the reader fuzz targets (fuzz_common.h).

#include "fuzz_common.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "meshedit/core/budget.h"
#include "meshedit/core/build.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/validate.h"

namespace meshedit::fuzz {
namespace {

std::filesystem::path g_scratch;

// Meshes up to this many faces get the write → read round trip and a Loop level.
constexpr std::size_t kSmallFaces = 4000;

// The canonical face list of a mesh: each face's corners from its smallest index.
std::vector<std::vector<std::uint32_t>> faces_of(const Mesh& mesh) {
    std::vector<std::vector<std::uint32_t>> out;
    for (const Face f : mesh.faces()) {
        std::vector<std::uint32_t> c;
        for (const Vertex v : mesh.vertices(f)) {
            c.push_back(v.idx());
        }
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        out.push_back(std::move(c));
    }
    std::sort(out.begin(), out.end());
    return out;
}

void check_valid(const Mesh& mesh, const char* after) {
    if (const auto error = validate(mesh)) {
        std::fprintf(stderr, "fuzz: invalid mesh after %s: %s [%s]\n", after,
                     error->message.c_str(), error->invariant.c_str());
        std::abort();
    }
}

void one_local_op(Mesh& mesh, std::uint64_t seed) {
    if (mesh.n_edges() == 0) {
        return;
    }
    const Edge e(static_cast<std::uint32_t>((seed >> 8) % mesh.edges_size()));
    if (mesh.is_deleted(e)) {
        return;
    }
    const Mesh before = mesh;
    const int op = static_cast<int>(seed % 3);
    const OpStatus ok = op == 0   ? is_flip_ok(mesh, e)
                        : op == 1 ? is_split_ok(mesh, e)
                                  : is_collapse_ok(mesh, e);
    const bool done = op == 0   ? flip(mesh, e).ok()
                      : op == 1 ? split(mesh, e).ok()
                                : collapse(mesh, e).ok();
    check(done == static_cast<bool>(ok), "an op disagrees with its predicate");
    if (!done) {
        check(faces_of(mesh) == faces_of(before) &&
                  mesh.position_vector().size() == before.position_vector().size(),
              "a refused op changed the mesh");
        return;
    }
    check_valid(mesh, op == 0 ? "flip" : op == 1 ? "split" : "collapse");
}

void round_trip(const Mesh& mesh) {
    // OBJ keeps doubles exactly; garbage is collected by the writer, so compare with a
    // collected copy.
    Mesh dense = mesh;
    dense.garbage_collection();
    const std::filesystem::path file = g_scratch / "round_trip.obj";
    try {
        write_mesh(dense, file);
    } catch (const IoError& e) {
        std::fprintf(stderr, "fuzz: cannot write a valid mesh: %s\n", e.what());
        std::abort();
    }
    if (dense.n_faces() == 0) {
        return;  // nothing to read back: readers refuse a file without faces
    }
    const LoadedMesh again = read_mesh(file);
    check(!again.repairs.repaired(), "a written mesh needed repairs when read back");
    check(again.mesh.position_vector().size() == dense.position_vector().size() &&
              faces_of(again.mesh) == faces_of(dense),
          "a written mesh read back as another mesh");
    for (std::size_t i = 0; i < dense.position_vector().size(); ++i) {
        check(again.mesh.position_vector()[i] == dense.position_vector()[i],
              "a position changed in a write and read");
    }
}

}  // namespace

void set_up() {
    set_memory_budget(std::size_t{256} << 20);
    const char* tmp = std::getenv("TMPDIR");
    g_scratch = std::filesystem::path(tmp != nullptr && *tmp ? tmp : "/tmp") /
                ("meshedit-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(g_scratch);
}

void check(bool condition, std::string_view what) {
    if (!condition) {
        std::fprintf(stderr, "fuzz: %.*s\n", static_cast<int>(what.size()), what.data());
        std::abort();
    }
}

std::uint64_t hash(const std::uint8_t* data, std::size_t size) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a
    for (std::size_t i = 0; i < size; ++i) {
        h = (h ^ data[i]) * 1099511628211ull;
    }
    return h;
}

void exercise(const MeshSoup& soup, std::uint64_t seed) {
    Mesh mesh;
    try {
        mesh = build_mesh(soup.soup);
    } catch (const TopologyError&) {
        return;
    }
    exercise(std::move(mesh), seed);
}

void exercise(Mesh mesh, std::uint64_t seed) {
    check_valid(mesh, "building");
    one_local_op(mesh, seed);
    if (mesh.n_faces() > kSmallFaces) {
        return;
    }
    round_trip(mesh);
    if (is_loop_ok(mesh) && plan_loop(mesh).ok()) {
        loop_subdivide(mesh);
        check_valid(mesh, "Loop");
    }
}

}  // namespace meshedit::fuzz
