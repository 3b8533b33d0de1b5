// The reference solution of task 3 in the student API (BUG_*: one typical mistake).

#include "meshedit/student/student.h"

namespace meshedit::student {

Vector3D vertex_normal(VertexCIter v) {
    Vector3D sum;
    HalfedgeCIter h = v->halfedge();
    do {
#if !defined(BUG_NORMALS_BOUNDARY_FACE_USED)
        if (!h->isBoundary())
#endif
        {
            [[maybe_unused]] const Vector3D p = v->position;
            [[maybe_unused]] const Vector3D a = h->next()->vertex()->position;
            [[maybe_unused]] const Vector3D b = h->next()->next()->vertex()->position;
#if defined(BUG_NORMALS_NOT_AREA_WEIGHTED)
            sum += h->face()->normal();
#elif defined(BUG_NORMALS_REVERSED)
            sum += cross(b - p, a - p);
#else
            sum += cross(a - p, b - p);
#endif
        }
        h = h->twin()->next();
    } while (h != v->halfedge());
#if defined(BUG_NORMALS_NOT_NORMALIZED)
    return sum;
#else
    return sum.unit();
#endif
}

}  // namespace meshedit::student
