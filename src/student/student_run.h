#pragma once
/// \file
/// One student function that changes a mesh (flip_edge, split_edge, upsample), run in a forked
/// child on the viewer's mesh, its result checked there (the write-back's rules, validate(),
/// then the reference's result on the same input) and brought back: what the viewer's F, S
/// and L do under `--student` (docs/student.md). The student's result may be no valid mesh, so
/// it comes back as polygons read with bounded walks, never as a Mesh to trust.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "meshedit/core/build.h"
#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"
#include "meshedit/student/student.h"

namespace meshedit::cli::grade {

/// The tasks that change a mesh.
enum class MeshTask { FlipEdge, SplitEdge, Upsample };

/// The task called `name` ("flip_edge", "split_edge", "upsample"), or none.
std::optional<MeshTask> mesh_task(std::string_view name);

/// How a student's function did on one input.
struct MeshAttempt {
    enum class Verdict {
        Same,       ///< a valid mesh, the reference's up to renumbering and a tolerance
        Different,  ///< a broken rule, or a valid mesh that is not the reference's
        Failed,     ///< crashed, timed out, threw, or not handed in: nothing came back
    };
    Verdict verdict = Verdict::Failed;
    /// Different: what differs ("invariant twin: halfedge 7's twin is unset", "differs from
    /// the reference: …"); Failed: what happened ("crashed (SIGSEGV)").
    std::string message;
    /// Different: the broken rule's name ("twin", "next-prev"); empty when the student's
    /// result is a valid mesh that differs from the reference's.
    std::string invariant;
    /// Different: the student's result as polygons (vertex i is the result's vertex i; a face
    /// whose loop does not close is left out).
    PolygonSoup yours;
    /// The first differing element: its kind, and its corners (vertex indices, in loop order)
    /// in `yours` and in the reference's result (empty where it has none there).
    ElementRef::Kind kind = ElementRef::Kind::None;
    std::vector<std::uint32_t> yours_at, reference_at;
};

/// Runs `task` of `tasks` on a copy of `input` (flip and split on `edge`) in a child process
/// that may take `seconds`, and compares its result with `reference`: the reference
/// operation's result on `input` (`input` itself where the operation refuses).
/// \pre `input` has no deleted elements.
MeshAttempt attempt_mesh_task(const student::StudentTasks& tasks, MeshTask task, const Mesh& input,
                              Edge edge, const Mesh& reference, double seconds);

/// How a student's vertex_normal() did at every vertex of a mesh.
struct NormalsAttempt {
    MeshAttempt::Verdict verdict = MeshAttempt::Verdict::Failed;
    /// Different: the grader's message for the first wrong vertex; Failed: what happened.
    std::string message;
    /// Different: the student's normal of every vertex, by index (zero at isolated vertices;
    /// a NaN comes back as 0).
    std::vector<Vec3> normals;
};

/// Runs `tasks.vertex_normal` at every vertex of `mesh` in a child process that may take
/// `seconds`, checked as `meshedit grade` checks it (check_normals()).
NormalsAttempt attempt_normals(const student::StudentTasks& tasks, const Mesh& mesh,
                               double seconds);

/// The corners of `element` of `mesh` in loop order: a vertex's own, an edge's or halfedge's
/// two ends, a face's corners; walks are bounded and indices checked, so a broken mesh gives
/// what it can.
std::vector<std::uint32_t> corners_of(const Mesh& mesh, const ElementRef& element);

/// The element of `mesh` whose corners (see corners_of(), each plus `offset`) are `corners`,
/// or none.
ElementRef element_at(const Mesh& mesh, ElementRef::Kind kind,
                      const std::vector<std::uint32_t>& corners, std::uint32_t offset = 0);

}  // namespace meshedit::cli::grade
