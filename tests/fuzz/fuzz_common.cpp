// The shared body of the reader fuzz targets (fuzz_common.h).

#include "fuzz_common.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "meshedit/core/budget.h"
#include "meshedit/core/build.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/simplify.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/validate.h"
#include "meshedit/io/obj.h"
#include "meshedit/ops/ops.h"

namespace meshedit::fuzz {
namespace {

// Meshes up to this many faces get the write → read round trip.
constexpr std::size_t kSmallFaces = 4000;
// Meshes up to this many faces get a whole-mesh operation, within kWholeMeshBudget (whose
// comment says why): simplify and a remesh at the mean length cost in proportion to the mesh
// they start from, which the budget does not bound.
constexpr std::size_t kWholeMeshFaces = 1000;

// The canonical face list of a mesh: each face's corners from its smallest index, the faces
// sorted. Flat (per face its corner count, then its corners): no allocation per face.
std::vector<std::uint32_t> faces_of(const Mesh& mesh) {
    std::vector<std::uint32_t> corners;
    std::vector<std::size_t> starts;
    for (const Face f : mesh.faces()) {
        starts.push_back(corners.size());
        corners.push_back(0);
        const auto first = static_cast<std::ptrdiff_t>(corners.size());
        for (const Vertex v : mesh.vertices(f)) {
            corners.push_back(v.idx());
        }
        corners[starts.back()] = static_cast<std::uint32_t>(corners.size() - starts.back() - 1);
        std::rotate(corners.begin() + first,
                    std::min_element(corners.begin() + first, corners.end()), corners.end());
    }
    const auto run = [&](std::size_t start) {
        return std::span<const std::uint32_t>(corners.data() + start, corners[start] + 1);
    };
    std::sort(starts.begin(), starts.end(), [&](std::size_t a, std::size_t b) {
        const auto x = run(a);
        const auto y = run(b);
        return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end());
    });
    std::vector<std::uint32_t> out;
    out.reserve(corners.size());
    for (const std::size_t start : starts) {
        const auto r = run(start);
        out.insert(out.end(), r.begin(), r.end());
    }
    return out;
}

void check_valid(const Mesh& mesh, const char* after) {
    if (const auto error = validate(mesh)) {
        std::fprintf(stderr, "fuzz: invalid mesh after %s: %s [%s]\n", after,
                     error->message.c_str(), error->invariant.c_str());
        std::abort();
    }
}

// A random live element of `kind`, or none (deleted slots are skipped, not retried: the
// fuzzer varies the seed).
ElementRef random_element(const Mesh& mesh, ElementRef::Kind kind, std::uint64_t seed) {
    using Kind = ElementRef::Kind;
    const std::size_t size = kind == Kind::Vertex ? mesh.vertices_size()
                             : kind == Kind::Edge ? mesh.edges_size()
                                                  : mesh.faces_size();
    if (size == 0) {
        return {};
    }
    const ElementRef e{kind, static_cast<std::uint32_t>(seed % size)};
    return is_live(mesh, e) ? e : ElementRef{};
}

// One verb of the edit language, chosen from the whole table, on a random element of a kind
// it accepts, with random amounts (some absurd): a refusal must leave the mesh as it was, a
// step that runs must leave it valid.
void one_local_op(Mesh& mesh, std::uint64_t seed) {
    using Kind = ElementRef::Kind;
    const auto all = ops::verbs();
    const ops::Verb& verb = all[seed % all.size()];
    if (verb.plan != nullptr || verb.name == "simplify" || verb.name == "remesh") {
        return;  // whole-mesh algorithms: run below, on small meshes, with sane amounts
    }
    seed >>= 5;
    std::vector<Kind> kinds;
    if ((verb.takes & ops::kVertexArg) != 0) {
        kinds.push_back(Kind::Vertex);
    }
    if ((verb.takes & (ops::kEdgeArg | ops::kEdgePair)) != 0) {
        kinds.push_back(Kind::Edge);
    }
    if ((verb.takes & ops::kFaceArg) != 0) {
        kinds.push_back(Kind::Face);
    }
    ElementRef target;
    ElementRef second;
    if (!verb.accepts(ops::Target::None) || (seed & 1) != 0) {
        if (kinds.empty()) {
            return;
        }
        target = random_element(mesh, kinds[(seed >> 1) % kinds.size()], seed >> 3);
        if (target.is_none()) {
            return;
        }
        if ((verb.takes & ops::kEdgePair) != 0) {
            second = random_element(mesh, Kind::Edge, seed >> 23);
            if (second.is_none() || second == target) {
                return;
            }
        }
    }
    // Amounts in [-0.5, 1.5): below 0, inside and beyond the ranges the ops accept.
    const std::vector<double> amounts{static_cast<double>((seed >> 33) % 200) / 100.0 - 0.5,
                                      static_cast<double>((seed >> 41) % 200) / 100.0 - 0.5,
                                      static_cast<double>((seed >> 49) % 200) / 100.0 - 0.5};
    static_assert(ops::kMaxAmounts == 3, "one amount per slot a verb may take");
    const ops::Step step = ops::make_step(
        verb.name, mesh, target, std::span<const double>(amounts.data(), verb.max_amounts), second);
    const Mesh before = mesh;
    try {
        ops::run_step(mesh, step);
    } catch (const ops::OpError& e) {
        check(e.refused(), "a live element was reported missing");
        check(faces_of(mesh) == faces_of(before) &&
                  mesh.position_vector() == before.position_vector(),
              "a refused op changed the mesh");
        return;
    }
    check_valid(mesh, std::string(verb.name).c_str());
}

void round_trip(const Mesh& mesh) {
    // OBJ keeps doubles exactly; garbage is collected by the writer, so compare with a
    // collected copy (made only when there is garbage). In memory: the text write_obj()
    // writes, read back by the OBJ parser (a file per execution cost more than the parse
    // itself).
    std::optional<Mesh> collected;
    if (mesh.has_garbage()) {
        collected.emplace(mesh);
        collected->garbage_collection();
    }
    const Mesh& dense = collected ? *collected : mesh;
    if (dense.n_faces() == 0) {
        return;  // nothing to read back: readers refuse a file without faces
    }
    const std::string text = obj_text(dense);
    Mesh again;
    BuildReport repairs;
    try {
        again = build_mesh(parse_obj(text, "round_trip.obj").soup, &repairs);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz: a written mesh did not read back: %s\n", e.what());
        std::abort();
    }
    check(!repairs.repaired(), "a written mesh needed repairs when read back");
    check(again.position_vector().size() == dense.position_vector().size() &&
              faces_of(again) == faces_of(dense),
          "a written mesh read back as another mesh");
    for (std::size_t i = 0; i < dense.position_vector().size(); ++i) {
        check(again.position_vector()[i] == dense.position_vector()[i],
              "a position changed in a write and read");
    }
}

}  // namespace

void set_up() {
    set_memory_budget(kBudget);
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

void check_built(const MeshSoup& soup) {
    try {
        check_valid(build_mesh(soup.soup), "building");
    } catch (const TopologyError&) {
    }
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
    // One whole-mesh operation per input, picked by its hash (all four took three quarters of
    // an execution; a mutation changes the hash, so the corpus reaches every one), within the
    // small budget: a bigger result is refused by the operation's own check (remesh's
    // estimate, or its guard as the mesh grows: a BudgetError that leaves the mesh as it was).
    if (mesh.n_faces() > kWholeMeshFaces) {
        return;
    }
    const WholeMeshBudget small;
    const std::uint64_t whole = (seed * 0x9E3779B97F4A7C15ull) >> 62;  // 0 … 3
    if (whole == 0 && is_loop_ok(mesh) && plan_loop(mesh).ok()) {
        Mesh loop = mesh;
        loop_subdivide(loop);
        check_valid(loop, "Loop");
    }
    SimplifyOptions half;
    half.target_faces = std::max<std::size_t>(1, mesh.n_faces() / 2);
    if (whole == 1 && check_simplify(mesh, half)) {
        Mesh simplified = mesh;
        simplify(simplified, half);
        check_valid(simplified, "simplify");
    }
    // Remeshing at the mean length, one round.
    RemeshOptions once;
    once.iterations = 1;
    if (whole == 2 && check_remesh(mesh, once)) {
        Mesh remeshed = mesh;
        try {
            remesh(remeshed, once);
        } catch (const BudgetError&) {
            check(faces_of(remeshed) == faces_of(mesh) &&
                      remeshed.position_vector() == mesh.position_vector(),
                  "a remesh stopped by the budget changed the mesh");
        }
        check_valid(remeshed, "remesh");
    }
    if (whole == 3 && plan_quad_subdivision(mesh).ok()) {
        quad_subdivide(mesh);
        check_valid(mesh, "Catmull-Clark");
    }
}

}  // namespace meshedit::fuzz
