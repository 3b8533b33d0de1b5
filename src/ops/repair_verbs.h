#pragma once
// Private to meshedit_ops: the functions of the repair verbs (repair, merge_by_distance,
// stitch, remove_degenerate, orient, remove_small, fill_holes, fill_holes_fair, fill_fair), whose
// rows are in verbs.cpp's table.

#include "meshedit/ops/ops.h"

namespace meshedit::ops {

OpStatus check_repair(const Mesh& mesh, const Step& step);
StepResult run_repair(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_merge_by_distance(const Mesh& mesh, const Step& step);
StepResult run_merge_by_distance(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_stitch(const Mesh& mesh, const Step& step);
StepResult run_stitch(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_remove_degenerate(const Mesh& mesh, const Step& step);
StepResult run_remove_degenerate(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_orient(const Mesh& mesh, const Step& step);
StepResult run_orient(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_remove_small(const Mesh& mesh, const Step& step);
StepResult run_remove_small(Mesh& mesh, const Step& step, const RunOptions& options);
OpStatus check_fill_holes(const Mesh& mesh, const Step& step);
StepResult run_fill_holes(Mesh& mesh, const Step& step, const RunOptions& options);
StepResult run_fill_holes_fair(Mesh& mesh, const Step& step, const RunOptions& options);
// The hole an edge names (fill, fill_fair): its boundary halfedge is the one without a face.
Halfedge hole_side(const Mesh& mesh, Edge e);
// "cannot fill: the edge is not on a hole …", or ok.
OpStatus check_on_a_hole(const Mesh& mesh, Edge e);
OpStatus check_fill_fair(const Mesh& mesh, const Step& step);
StepResult run_fill_fair(Mesh& mesh, const Step& step, const RunOptions& options);

}  // namespace meshedit::ops
