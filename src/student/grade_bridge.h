#pragma once
/// \file
/// `meshedit grade`'s bridge between a Mesh and the student API's HalfedgeMesh
/// (meshedit/student/student.h): a copy in, a write back through the Mesh's setters (so
/// validate() and a recorder see an ordinary edit), and the flip and split a student's
/// upsample() calls.

#include <string>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"
#include "meshedit/student/student.h"

namespace meshedit::cli::grade {

namespace st = meshedit::student;

/// A broken rule of the course's structure that keeps the student's mesh from being written
/// back (a twin that is not mutual, an unset next, a deleted face still used).
struct BridgeError {
    std::string invariant;  ///< "twin", "next", "vertex", "edge", "face"
    std::string message;
    /// The element whose rule is broken, in the student's numbering (none when fine).
    ElementRef element;
};

/// Copies `mesh` (no deleted elements) into `out`: halfedge, vertex, edge and face i of the
/// mesh are element i of `out`; each boundary loop becomes one more face, marked boundary.
/// Keeps the scratch fields (isNew, newPosition) of the elements `out` already has.
void copy_in(const Mesh& mesh, st::HalfedgeMesh& out);

/// Writes `in` back into `mesh`, which must hold what copy_in() copied (elements past its
/// sizes are appended, deleted ones tombstoned). Boundary vertices are re-anchored at their
/// boundary halfedge (MeshEdit's rule; the course has none). \return the first broken rule
/// that makes the structure impossible to write, or an empty invariant; validate() checks
/// the rest.
BridgeError copy_out(st::HalfedgeMesh& in, Mesh& mesh);

/// Binds `student`'s flipEdge()/splitEdge() to MeshEdit's flip() and split() on `mesh`, which
/// copy_in() copied into `student`: each call runs the operation on `mesh` (a split at the
/// midpoint of the positions the student sees) and copies what it touched into `student`, so
/// the two stay in step through upsample(), at O(1) a call. Other connectivity the student
/// changes reaches `mesh` only through the final copy_out(). `ops` must outlive the calls.
void bind_operations(st::HalfedgeMesh& student, Mesh& mesh, st::HalfedgeMesh::Operations& ops);

}  // namespace meshedit::cli::grade
