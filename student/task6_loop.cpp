// Task 6: Loop subdivision, one level, in place.
//
//   1. For every old vertex compute its new position into v->newPosition, from the OLD
//      positions: with n = v->degree() and u = 3/16 if n == 3, else 3/(8n),
//          (1 - n*u) * position + u * (sum of the neighbours' positions).
//   2. For every old edge a-b compute e->newPosition:
//          3/8 * (a + b) + 1/8 * (c + d), c and d the third corners of its two triangles.
//   3. Split every old edge (mesh.splitEdge(e), MeshEdit's own split, so this task is graded
//      on its own); mark the new vertex isNew and give it the edge's newPosition. Mark the
//      new edges that cross old faces isNew (not the two halves of the old edge). Loop over
//      the old edges only: splitting appends edges.
//   4. Flip every new edge that joins an old and a new vertex (mesh.flipEdge(e)).
//   5. Move every vertex to its newPosition.
//
// Sharp edges: a boundary edge (e->isBoundary()) or a crease (e->isCrease) gets the midpoint
// 1/2 * (a + b). A vertex on exactly two sharp edges gets 3/4 * position + 1/8 * (p + q), p
// and q the far ends of those two edges; on three or more it stays where it is; on none or
// one it uses the rule of step 1.

#include "meshedit/student/student.h"

namespace meshedit::student {

void upsample(HalfedgeMesh& mesh) {
    (void)mesh;  // TODO
}

}  // namespace meshedit::student
