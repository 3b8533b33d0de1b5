// Recorded edits (core/mesh_change.h) through every verb of the edit language that acts on an
// element: on several meshes, random steps are recorded as they run; undoing the change gives
// the mesh before bit for bit (every property, deleted elements included), redoing it the mesh
// after. A verb whose writes the recorder missed fails here by name.

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "meshedit/core/mesh_change.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/ops/ops.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

using Kind = ElementRef::Kind;

std::vector<Mesh> test_meshes() {
    std::vector<Mesh> meshes = {shapes::cube(),         shapes::torus(9, 7),    shapes::grid(5, 4),
                                shapes::icosphere(1),   shapes::cylinder(8, 3), test::quad_cube(),
                                shapes::quad_sphere(2), test::one_ring(6)};
    // Crease marks present from the start (a property the recording begins with).
    Mesh creased = shapes::torus(8, 6);
    auto crease = creased.add_property<Edge, std::uint8_t>("e:crease", 0);
    for (std::uint32_t e = 0; e < creased.edges_size(); e += 3) {
        crease[Edge(e)] = 1;
    }
    meshes.push_back(std::move(creased));
    return meshes;
}

// A random live element of the kind the verb takes first, and for a weld a second edge.
bool random_target(const Mesh& mesh, const ops::Verb& verb, std::mt19937& rng, ElementRef& a,
                   ElementRef& b) {
    const auto live = [&](Kind kind) {
        const std::size_t n = elements_size(mesh, kind);
        for (int tries = 0; tries < 100; ++tries) {
            const auto i = static_cast<std::uint32_t>(rng() % n);
            const ElementRef r{kind, i};
            if (is_live(mesh, r)) {
                return r;
            }
        }
        return ElementRef{};
    };
    if (verb.accepts(ops::Target::EdgePair)) {
        a = live(Kind::Edge);
        b = live(Kind::Edge);
        return !a.is_none() && !b.is_none() && a != b;
    }
    for (const auto& [target, kind] :
         {std::pair{ops::Target::Edge, Kind::Edge}, std::pair{ops::Target::Vertex, Kind::Vertex},
          std::pair{ops::Target::Face, Kind::Face}}) {
        if (verb.accepts(target) && (rng() % 2 == 0 || !verb.accepts(ops::Target::Face))) {
            a = live(kind);
            return !a.is_none();
        }
    }
    a = live(Kind::Face);
    return !a.is_none();
}

TEST(RecordedEdit, EveryElementVerbUndoesAndRedoesBitForBit) {
    std::size_t recorded = 0;
    for (const ops::Verb& verb : ops::verbs()) {
        if (verb.accepts(ops::Target::None) || (verb.traits & ops::kRebuildsMesh) != 0) {
            continue;  // whole-mesh verbs, and those that rebuild the mesh, are undone from a copy
        }
        std::mt19937 rng(7);
        std::size_t ran = 0;
        for (Mesh& mesh : test_meshes()) {
            for (int i = 0; i < 25; ++i) {
                ElementRef a, b;
                const double height = 0.25;
                const bool region = verb.accepts(ops::Target::Region);
                if (!region && !random_target(mesh, verb, rng, a, b)) {
                    continue;
                }
                const ops::Step step =
                    region
                        ? ops::make_region_step(verb.name, test::random_region(mesh, rng),
                                                std::span<const double>(&height, verb.min_amounts))
                        : ops::make_step(verb.name, mesh, a, {}, b);
                const Mesh before = mesh;
                ASSERT_TRUE(test::is_valid(before)) << verb.name << " before";
                MeshRecorder recorder(mesh);
                bool done = false;
                try {
                    ops::run_step(mesh, step);
                    done = true;
                } catch (const ops::OpError&) {
                }
                MeshChange change = recorder.finish();
                std::string why;
                if (!done) {
                    ASSERT_TRUE(bitwise_equal(mesh, before, &why)) << step.text << ": " << why;
                    continue;
                }
                ++ran;
                ASSERT_TRUE(test::is_valid(mesh))
                    << verb.name << " [" << step.text << "] on mesh with " << before.n_faces()
                    << " faces";
                const Mesh after = mesh;
                change.undo(mesh);
                ASSERT_TRUE(bitwise_equal(mesh, before, &why)) << step.text << " undone: " << why;
                change.redo(mesh);
                ASSERT_TRUE(bitwise_equal(mesh, after, &why)) << step.text << " redone: " << why;
            }
        }
        EXPECT_GT(ran, 0u) << verb.name << " never ran";
        recorded += ran;
    }
    EXPECT_GT(recorded, 200u);
}

TEST(RecordedEdit, ChainsUndoInReverseOrder) {
    Mesh mesh = shapes::torus(10, 8);
    std::vector<Mesh> states = {mesh};
    std::vector<MeshChange> changes;
    std::mt19937 rng(3);
    const char* names[] = {"flip", "split", "collapse", "crease"};
    while (changes.size() < 60) {
        const ops::Verb& verb = *ops::find_verb(names[rng() % 4]);
        ElementRef a, b;
        ASSERT_TRUE(random_target(mesh, verb, rng, a, b));
        MeshRecorder recorder(mesh);
        try {
            ops::run_step(mesh, ops::make_step(verb.name, mesh, a));
        } catch (const ops::OpError&) {
            continue;  // the recorder is dropped with nothing recorded
        }
        changes.push_back(recorder.finish());
        states.push_back(mesh);
    }
    std::string why;
    for (std::size_t i = changes.size(); i-- > 0;) {
        changes[i].undo(mesh);
        ASSERT_TRUE(bitwise_equal(mesh, states[i], &why)) << "undo " << i << ": " << why;
    }
    for (std::size_t i = 0; i < changes.size(); ++i) {
        changes[i].redo(mesh);
        ASSERT_TRUE(bitwise_equal(mesh, states[i + 1], &why)) << "redo " << i << ": " << why;
    }
}

TEST(RecordedEdit, AFlipCostsTheSameAtAnySize) {
    // The change holds what the flip touched: its size does not grow with the mesh.
    std::vector<std::size_t> bytes;
    for (const int n : {10, 100, 400}) {
        Mesh mesh = shapes::torus(2 * n, n);
        MeshRecorder recorder(mesh);
        ASSERT_TRUE(flip(mesh, Edge(static_cast<std::uint32_t>(mesh.edges_size() / 2))));
        bytes.push_back(recorder.finish().bytes());
    }
    EXPECT_EQ(bytes[0], bytes[1]);
    EXPECT_EQ(bytes[1], bytes[2]);
    EXPECT_LE(bytes[2], 1024u);
}

TEST(RecordedEdit, WholeMeshWritesCannotBeRecorded) {
    Mesh mesh = shapes::cube();
    {
        MeshRecorder recorder(mesh);
        loop_subdivide(mesh);
        EXPECT_THROW(recorder.finish(), std::logic_error);
    }
    {
        MeshRecorder recorder(mesh);
        collapse(mesh, Edge(0));
        mesh.garbage_collection();
        EXPECT_THROW(recorder.finish(), std::logic_error);
    }
    {
        MeshRecorder recorder(mesh);
        EXPECT_THROW(MeshRecorder second(mesh), std::logic_error);
        mesh = shapes::tetrahedron();
        EXPECT_THROW(recorder.finish(), std::logic_error);
    }
}

TEST(RecordedEdit, RollBackRestoresAHalfDoneEdit) {
    Mesh mesh = shapes::torus(6, 5);
    const Mesh before = mesh;
    MeshRecorder recorder(mesh);
    ASSERT_TRUE(split(mesh, Edge(3)));
    ASSERT_TRUE(flip(mesh, Edge(8)));
    recorder.roll_back();
    std::string why;
    EXPECT_TRUE(bitwise_equal(mesh, before, &why)) << why;
}

// An op that writes a property through its handle without touch(): the recording misses the
// write, so its undo would not give the mesh back. In Debug and sanitizer builds the recorder
// catches it at finish(); every test that records checks the contract this way.
TEST(RecordedEdit, SelfCheckCatchesAWriteTheRecorderWasNotToldAbout) {
    if (!MeshRecorder::kSelfCheck) {
        GTEST_SKIP() << "the recorder checks itself in Debug and sanitizer builds";
    }
    Mesh mesh = shapes::torus(6, 5);
    auto weight = mesh.add_property<Vertex, double>("v:weight", 1.0);
    {
        MeshRecorder recorder(mesh);
        ASSERT_TRUE(split(mesh, Edge(3)));  // recorded through the setters
        weight[Vertex(7)] = 2.0;            // an existing element, written through the handle
        try {
            recorder.finish();
            ADD_FAILURE() << "the self-check did not notice the untold write";
        } catch (const std::logic_error& e) {
            EXPECT_NE(std::string(e.what()).find("self-check"), std::string::npos) << e.what();
        }
    }
    {
        // The same op with touch() records completely and passes.
        Mesh fixed = shapes::torus(6, 5);
        auto w = fixed.add_property<Vertex, double>("v:weight", 1.0);
        MeshRecorder recorder(fixed);
        ASSERT_TRUE(split(fixed, Edge(3)));
        fixed.touch(Vertex(7));
        w[Vertex(7)] = 2.0;
        const MeshChange change = recorder.finish();
        change.undo(fixed);
        EXPECT_EQ(w[Vertex(7)], 1.0);
    }
}

}  // namespace
}  // namespace meshedit
