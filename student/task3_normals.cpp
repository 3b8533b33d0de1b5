// Task 3: area-weighted vertex normals.
//
// Return the unit normal at v: the sum, over the faces around v, of each face's normal
// weighted by its area, normalized. The cross product of two edges of a triangle is a
// vector along its normal whose length is twice its area, so summing those cross products
// weights by area for free.
//
// Hints: walk the halfedges leaving v with h = h->twin()->next() until you are back at
// v->halfedge(). Skip halfedges whose face is a boundary loop (h->face()->isBoundary()):
// a boundary loop is not a face. Faces are counter-clockwise seen from outside, so for the
// corner v, a = h->next()->vertex(), b = h->next()->next()->vertex():
// cross(a - v, b - v) points outwards. Normalize at the end (.unit()).

#include "meshedit/student/student.h"

namespace meshedit::student {

Vector3D vertex_normal(VertexCIter v) {
    (void)v;
    return Vector3D();  // TODO
}

}  // namespace meshedit::student
