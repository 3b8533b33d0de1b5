#pragma once
/// \file
/// What every reader's fuzz target does with what it read (docs/testing.md, "Fuzzing"): build
/// the mesh, validate() it, run one local operation picked by the input's own bytes behind its
/// predicate (validate again, or check the refusal changed nothing), write the mesh out and
/// read it back in memory (the same mesh), and on small meshes one whole-mesh operation (Loop,
/// simplify, remesh or Catmull–Clark, picked by the hash) within kWholeMeshBudget. Anything
/// wrong aborts,
/// which libFuzzer (or the replay driver) reports with the input that did it.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "meshedit/core/budget.h"
#include "meshedit/core/mesh.h"
#include "meshedit/io/io.h"

namespace meshedit::fuzz {

/// The memory budget of a target: a hostile size is refused, not allocated.
inline constexpr std::size_t kBudget = std::size_t{256} << 20;

/// The memory budget of a whole-mesh operation inside a target (a subdivision level,
/// simplify, remesh, the steps of an --ops list or a session): a Loop or Catmull–Clark level
/// that makes about 900 faces, a remesh to about 870 triangles. The algorithms run the same
/// code on a small mesh as on a big one (their threads start at 50,000 vertices or 100,000
/// faces), and what is bigger is refused by their budget checks, which are tested that way;
/// under the sanitizers one remesh to 2,000 triangles cost as much as a hundred small inputs.
inline constexpr std::size_t kWholeMeshBudget = std::size_t{256} << 10;

/// Sets what every target shares: the memory budget kBudget. Nothing is written to disk.
/// Call once, from the target.
void set_up();

/// While it lives the memory budget is kWholeMeshBudget (below the 64 MiB floor), then
/// kBudget again.
class WholeMeshBudget {
public:
    WholeMeshBudget() { set_memory_budget_without_floor(kWholeMeshBudget); }
    ~WholeMeshBudget() { set_memory_budget(kBudget); }
    WholeMeshBudget(const WholeMeshBudget&) = delete;
    WholeMeshBudget& operator=(const WholeMeshBudget&) = delete;
};

/// Aborts with `what` on stderr when `condition` is false (kept in release builds).
void check(bool condition, std::string_view what);

/// A stable 64-bit hash of the input, to pick operations from.
std::uint64_t hash(const std::uint8_t* data, std::size_t size);

/// build_mesh() on the soup (an invalid soup is the reader's business: a TopologyError is a
/// clean refusal), then everything the file comment lists.
void exercise(const MeshSoup& soup, std::uint64_t seed);

/// build_mesh() and validate() only (a TopologyError is a clean refusal).
void check_built(const MeshSoup& soup);

/// The same on a mesh already built (the .bez target's tessellation).
void exercise(Mesh mesh, std::uint64_t seed);

/// A mesh reader's whole target: set_up(), `parse(bytes, name)`, and exercise() what it read;
/// an IoError or BudgetError is a clean refusal. Built with MESHEDIT_FUZZ_PARSE_ONLY (the
/// fuzz_X_parse targets) it only builds and validates the mesh: many more executions a
/// second for the reader itself.
template <class Parse>
int read_and_exercise(const std::uint8_t* data, std::size_t size, Parse parse,
                      const std::string& name) {
    static const bool ready = (set_up(), true);
    (void)ready;
    MeshSoup soup;
    try {
        soup = parse(std::string_view(reinterpret_cast<const char*>(data), size), name);
    } catch (const IoError&) {
        return 0;  // a clean refusal is what bad input should get
    } catch (const BudgetError&) {
        return 0;
    }
#ifdef MESHEDIT_FUZZ_PARSE_ONLY
    check_built(soup);
#else
    exercise(soup, hash(data, size));
#endif
    return 0;
}

}  // namespace meshedit::fuzz
