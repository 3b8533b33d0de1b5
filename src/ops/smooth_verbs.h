#pragma once
// Private to meshedit_ops: the functions of the smoothing verbs (smooth, smooth_cotan, taubin,
// smooth_implicit) and of fair, whose rows are in verbs.cpp's table.

#include "meshedit/ops/ops.h"

namespace meshedit::ops {

OpStatus check_smooth_uniform(const Mesh& mesh, const Step& step);
StepResult run_smooth_uniform(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_smooth_cotan(const Mesh& mesh, const Step& step);
StepResult run_smooth_cotan(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_taubin(const Mesh& mesh, const Step& step);
StepResult run_taubin(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_smooth_implicit(const Mesh& mesh, const Step& step);
StepResult run_smooth_implicit(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_smooth_region(const Mesh& mesh, const Step& step);
StepResult run_smooth_region(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_fair_step(const Mesh& mesh, const Step& step);
StepResult run_fair(Mesh& mesh, const Step& step, const RunOptions& options);

}  // namespace meshedit::ops
