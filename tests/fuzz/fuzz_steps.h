#pragma once
// The check the edit-language fuzz targets share (fuzz_ops, fuzz_session): parsed steps run
// on two small meshes, refusals and budget stops allowed, and the mesh must stay valid.

#include <string_view>
#include <vector>

#include "fuzz_common.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/validate.h"
#include "meshedit/ops/ops.h"

namespace meshedit::fuzz {

inline void run_steps_on_two_meshes(const std::vector<ops::Step>& steps, std::string_view what) {
    for (Mesh mesh : {shapes::icosahedron(), shapes::grid(3, 2)}) {
        try {
            ops::apply_steps(mesh, steps);
        } catch (const ops::OpError&) {
        } catch (const BudgetError&) {
        }
        check(!validate(mesh), what);
    }
}

}  // namespace meshedit::fuzz
