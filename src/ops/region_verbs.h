#pragma once
// Private to meshedit_ops: the functions of the region verbs (extrude_region, dissolve_region,
// subdivide_region) and of the selection verbs (select, select_loop, …), whose rows are in
// verbs.cpp's table.

#include <string>
#include <utility>

#include "meshedit/ops/ops.h"

namespace meshedit::ops {

/// The result of a step: the element it documents and a sentence.
inline StepResult local(ElementRef selected, std::string message, bool topology = true) {
    StepResult result;
    result.selected = selected;
    result.message = std::move(message);
    result.topology = topology;
    return result;
}

OpStatus check_extrude_region(const Mesh& mesh, const Step& step);
StepResult run_extrude_region(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_inset_region(const Mesh& mesh, const Step& step);
StepResult run_inset_region(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_simplify_region(const Mesh& mesh, const Step& step);
StepResult run_simplify_region(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_dissolve_region(const Mesh& mesh, const Step& step);
StepResult run_dissolve_region(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_loop_region(const Mesh& mesh, const Step& step);
StepResult run_loop_region(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_catmull_clark_region(const Mesh& mesh, const Step& step);
StepResult run_catmull_clark_region(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_subdivide_region(const Mesh& mesh, const Step& step);
StepResult run_subdivide_region(Mesh& mesh, const Step& step, const RunOptions& options);

/// Every selection verb: check() names what the step names (an error for a missing element),
/// run() leaves the mesh alone, select() makes the selection.
OpStatus check_select(const Mesh& mesh, const Step& step);
StepResult run_select(Mesh& mesh, const Step& step, const RunOptions& options);
Selection select_listed(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_none(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_loop(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_ring(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_linked(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_more(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_less(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_invert(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_boundary(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_creases(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_valence(const Mesh& mesh, const Step& step, const Selection& now);
Selection select_degree(const Mesh& mesh, const Step& step, const Selection& now);

}  // namespace meshedit::ops
