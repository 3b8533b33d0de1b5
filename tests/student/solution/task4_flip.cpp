// The reference solution of task 4 in the student API (BUG_*: one typical mistake).
//
//        a                a
//       / \              /|\   (a, d: the corners opposite e)
//      b---c    ->      b | c      h0: b->c becomes a->d, t0: c->b becomes d->a
//       \ /              \|/       f0 = (b c a) becomes (a d c), f1 = (c b d) becomes (d a b)
//        d                d

#include "meshedit/student/student.h"

namespace meshedit::student {

EdgeIter flip_edge(HalfedgeMesh& mesh, EdgeIter e) {
    (void)mesh;
#if !defined(BUG_FLIP_BOUNDARY_NOT_REFUSED)
    if (e->isBoundary()) {
        return e;
    }
#endif
    HalfedgeIter h0 = e->halfedge(), h1 = h0->next(), h2 = h1->next();
    HalfedgeIter t0 = h0->twin(), t1 = t0->next(), t2 = t1->next();
    VertexIter b = h0->vertex(), c = t0->vertex(), a = h2->vertex(), d = t2->vertex();
    FaceIter f0 = h0->face(), f1 = t0->face();
#if !defined(BUG_FLIP_EXISTING_EDGE_NOT_REFUSED)
    if (a == d) {
        return e;
    }
    HalfedgeIter h = a->halfedge();
    do {
        if (h->twin()->vertex() == d) {
            return e;  // a-d exists already
        }
        h = h->twin()->next();
    } while (h != a->halfedge());
#endif
#if defined(BUG_FLIP_CRASH)
    // A raw pointer cached for later and used before it was set.
    Face* volatile cached = nullptr;
    if (f0->degree() > 3) {
        cached = &*f0;
    }
    cached->halfedge() = h0;
#endif
    h0->setNeighbors(t2, t0, a, e, f0);
    t2->setNeighbors(h1, t2->twin(), d, t2->edge(), f0);
    h1->setNeighbors(h0, h1->twin(), c, h1->edge(), f0);
    t0->setNeighbors(h2, h0, d, e, f1);
    h2->setNeighbors(t1, h2->twin(), a, h2->edge(), f1);
    t1->setNeighbors(t0, t1->twin(), b, t1->edge(), f1);
#if !defined(BUG_FLIP_VERTEX_ANCHOR)
    b->halfedge() = t1;  // h0 no longer leaves b
    c->halfedge() = h1;  // nor t0 c
#endif
    a->halfedge() = h0;
    d->halfedge() = t0;
#if defined(BUG_FLIP_FACE_ANCHOR)
    f0->halfedge() = h2;  // h2 has moved to f1
    f1->halfedge() = t2;
#else
    f0->halfedge() = h0;
    f1->halfedge() = t0;
#endif
    e->halfedge() = h0;
    return e;
}

}  // namespace meshedit::student
