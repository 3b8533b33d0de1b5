// The reference solution of task 5 in the student API (BUG_*: one typical mistake).
//
//        a                a
//       / \              /|\          h0: b->c becomes b->m, t0: c->b becomes m->b;
//      b---c    ->      b-m-c         new edges m-c (n1), m-a (n2), m-d (n3);
//       \ /              \|/          f0 = (b m a), f2 = (m c a), f1 = (m b d), f3 = (c m d)
//        d                d
//
// On a boundary edge the side without a face (t0's) only gains m in its loop.

#include "meshedit/student/student.h"

namespace meshedit::student {

VertexIter split_edge(HalfedgeMesh& mesh, EdgeIter e) {
    HalfedgeIter h0 = e->halfedge();
#if !defined(BUG_SPLIT_BOUNDARY_FACE_USED)
    if (h0->isBoundary()) {
        h0 = h0->twin();  // h0 is the side with a face
    }
#endif
    HalfedgeIter h1 = h0->next(), h2 = h1->next(), t0 = h0->twin();
    VertexIter b = h0->vertex(), c = t0->vertex(), a = h2->vertex();
    FaceIter f0 = h0->face();

    if (!t0->isBoundary() && t0->next()->next()->vertex() == a) {
        return VertexIter();  // both faces are b, c, a: the new edges m-a would coincide
    }

    VertexIter m = mesh.newVertex();
#if defined(BUG_SPLIT_MIDPOINT)
    m->position = b->position + c->position / 2;
#else
    m->position = (b->position + c->position) / 2;
#endif
    EdgeIter e1 = mesh.newEdge(), e2 = mesh.newEdge();
    HalfedgeIter n1 = mesh.newHalfedge(), n1t = mesh.newHalfedge();
    HalfedgeIter n2 = mesh.newHalfedge(), n2t = mesh.newHalfedge();
    FaceIter f2 = mesh.newFace();

    h0->setNeighbors(n2, t0, b, e, f0);
    n2->setNeighbors(h2, n2t, m, e2, f0);
    n1->setNeighbors(h1, n1t, m, e1, f2);
#if defined(BUG_SPLIT_FACE_NOT_UPDATED)
    h1->next() = n2t;  // h1 keeps face f0
#else
    h1->setNeighbors(n2t, h1->twin(), c, h1->edge(), f2);
#endif
    n2t->setNeighbors(n1, n2, a, e2, f2);
    e->halfedge() = h0;
#if !defined(BUG_SPLIT_EDGE_HALFEDGE_UNSET)
    e1->halfedge() = n1;
#endif
    e2->halfedge() = n2;
    f0->halfedge() = h0;
    f2->halfedge() = n1;
    if (c->halfedge() == t0) {
        c->halfedge() = n1t;  // t0 now leaves m
    }

    if (t0->isBoundary()) {
        // The boundary loop ... -> p -> t0 -> ... becomes ... -> p -> n1t -> t0 -> ...
        HalfedgeIter p = t0;
        while (p->next() != t0) {
            p = p->next();
        }
        p->next() = n1t;
        n1t->setNeighbors(t0, n1, c, e1, t0->face());
        t0->vertex() = m;
        m->halfedge() = t0;
        return m;
    }

    HalfedgeIter t1 = t0->next(), t2 = t1->next();
    VertexIter d = t2->vertex();
    FaceIter f1 = t0->face();
    EdgeIter e3 = mesh.newEdge();
    HalfedgeIter n3 = mesh.newHalfedge(), n3t = mesh.newHalfedge();
    FaceIter f3 = mesh.newFace();
#if defined(BUG_SPLIT_TWIN_NOT_SET)
    t0->setNeighbors(t1, h0, m, e, f1);
    t1->next() = n3t;
    n3t->setNeighbors(t0, HalfedgeIter(), d, e3, f1);  // its twin forgotten
#else
    t0->setNeighbors(t1, h0, m, e, f1);
    t1->next() = n3t;
    n3t->setNeighbors(t0, n3, d, e3, f1);
#endif
    n1t->setNeighbors(n3, n1, c, e1, f3);
    n3->setNeighbors(t2, n3t, m, e3, f3);
    t2->setNeighbors(n1t, t2->twin(), d, t2->edge(), f3);
    e3->halfedge() = n3;
    f1->halfedge() = t0;
    f3->halfedge() = n1t;
    m->halfedge() = n1;
#if defined(BUG_SPLIT_RETURNS_OLD_VERTEX)
    return b;
#else
    return m;
#endif
}

}  // namespace meshedit::student
