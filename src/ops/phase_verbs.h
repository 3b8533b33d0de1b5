#pragma once
// Private to meshedit_ops: the phased subdivisions' shared check and the functions of the
// cc_step verb (a phased Catmull-Clark, core/cc_steps.h), whose row is in verbs.cpp's table.

#include "meshedit/ops/ops.h"

namespace meshedit::ops {

/// Four phases make a level: asking for more than remain is refused, naming `scheme`.
OpStatus check_phases_left(const char* scheme, int asked, int next);

/// Refuses a whole-mesh `verb` (subdivide, simplify, remesh) while a phased Loop is under way.
OpStatus phased_loop_refusal(const Mesh& mesh, const char* verb = "subdivide");

OpStatus check_cc_step_verb(const Mesh& mesh, const Step& step);
StepResult run_cc_step(Mesh& mesh, const Step& step, const RunOptions& options);

}  // namespace meshedit::ops
