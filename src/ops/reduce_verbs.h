#pragma once
// Private to meshedit_ops: the functions of the verbs that reduce or rebuild a whole mesh
// (crease_by_angle, simplify, remesh and remesh_region), whose rows are in verbs.cpp's table.

#include "meshedit/ops/ops.h"

namespace meshedit::ops {

OpStatus check_crease_by_angle_step(const Mesh& mesh, const Step& step);
StepResult run_crease_by_angle(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_simplify_step(const Mesh& mesh, const Step& step);
StepResult run_simplify(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_remesh_step(const Mesh& mesh, const Step& step);
StepResult run_remesh(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_remesh_region(const Mesh& mesh, const Step& step);
StepResult run_remesh_region(Mesh& mesh, const Step& step, const RunOptions& options);

}  // namespace meshedit::ops
