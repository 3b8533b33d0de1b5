#pragma once
/// \file
/// `meshedit grade`'s checks: each runs one student function on one input, checks the
/// result (validate(), then the reference on the same input) and returns what is wrong, or
/// an empty string when it passes. They run inside a forked child (grade_sandbox.h).

#include <string>
#include <vector>

#include "grade_bridge.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"

namespace meshedit::cli::grade {

/// One de Casteljau step of `points` (2D: z is ignored) at t.
std::string check_step(const st::StudentTasks& tasks, const std::vector<Vec3>& points, double t);
/// The patch at (u, v).
std::string check_patch(const st::StudentTasks& tasks, const BezierPatch& patch, double u,
                        double v);
/// vertex_normal() at every vertex of `mesh`.
std::string check_normals(const st::StudentTasks& tasks, const Mesh& mesh);
/// flip_edge() of `e`; where MeshEdit's flip refuses, the mesh must stay as it was.
std::string check_flip(const st::StudentTasks& tasks, const Mesh& mesh, Edge e);
/// split_edge() of `e`.
std::string check_split(const st::StudentTasks& tasks, const Mesh& mesh, Edge e);
/// upsample() of `mesh` (its flipEdge()/splitEdge() are MeshEdit's).
std::string check_loop(const st::StudentTasks& tasks, const Mesh& mesh);

/// One step of a teacher's session: flip or split of the edge joining two vertices.
struct SessionStep {
    bool split = false;
    std::uint32_t a = 0, b = 0;
};
/// The steps in order, each by the student's function and by MeshEdit's, the two meshes
/// compared after each.
std::string check_session(const st::StudentTasks& tasks, const Mesh& mesh,
                          const std::vector<SessionStep>& steps);

/// What differs between the student's mesh and the reference's, and where first: an element
/// of each (none of either when the counts already differ).
struct Difference {
    std::string text;  ///< "" when the same
    ElementRef got, expected;
};
Difference compare_results(const Mesh& got, const Mesh& expected);

/// What differs between the student's mesh and the reference's, or "" when they are the
/// same up to renumbering with the positions within a tolerance.
std::string difference(const Mesh& got, const Mesh& expected);

}  // namespace meshedit::cli::grade
