#pragma once
// The check the edit-language fuzz targets share (fuzz_ops, fuzz_session): parsed steps run
// on two small meshes, refusals and budget stops allowed, and the mesh must stay valid.

#include <cmath>
#include <cstddef>
#include <string_view>
#include <vector>

#include "fuzz_common.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/validate.h"
#include "meshedit/ops/ops.h"

namespace meshedit::fuzz {

/// Whole-mesh passes a list may run (a subdivision step, simplify, flip_orientation, … one
/// each; a remesh one per round): the list stops before the step that would go beyond. More
/// repeat what four reach, each at the cost of a pass over the mesh (`loop:2,remesh:0,100`
/// took 455 ms under the sanitizers, and `loop:2,remesh:0.01` 72 s within the 256 MB budget;
/// with eight passes remeshing still took half of fuzz_session's time).
inline constexpr int kMaxWholeMeshPasses = 4;

/// What `step` costs of kMaxWholeMeshPasses. Subdivision levels count one: the budget bounds
/// what all the levels of a list make together.
inline int whole_mesh_passes(const ops::Step& step) {
    if (step.target != ops::Target::None) {
        return 0;
    }
    if (step.verb->name == "remesh") {
        const double rounds = step.amounts[1];
        // Rounds it would refuse cost nothing but the refusal.
        return rounds >= 1 && rounds <= 100 && rounds == std::floor(rounds)
                   ? static_cast<int>(rounds)
                   : 1;
    }
    return 1;
}

inline void run_steps_on_two_meshes(const std::vector<ops::Step>& steps, std::string_view what) {
    std::size_t end = 0;
    for (int passes = 0; end < steps.size(); ++end) {
        passes += whole_mesh_passes(steps[end]);
        if (passes > kMaxWholeMeshPasses) {
            break;
        }
    }
    const std::vector<ops::Step> run(steps.begin(), steps.begin() + static_cast<long>(end));
    // Within the small budget: a level, simplification or remesh beyond it is refused by its
    // own check (a BudgetError or an OpError), and the list stops there.
    const WholeMeshBudget small;
    for (Mesh mesh : {shapes::icosahedron(), shapes::grid(3, 2)}) {
        try {
            ops::apply_steps(mesh, run);
        } catch (const ops::OpError&) {
        } catch (const BudgetError&) {
        }
        check(!validate(mesh), what);
    }
}

}  // namespace meshedit::fuzz
