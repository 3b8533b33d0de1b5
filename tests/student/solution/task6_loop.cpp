// The reference solution of task 6 in the student API (BUG_*: one typical mistake).

#include <cmath>

#include "meshedit/student/student.h"

namespace meshedit::student {
namespace {

bool sharp(EdgeIter e) {
#if defined(BUG_LOOP_BOUNDARY_IGNORED)
    return e->isCrease;
#elif defined(BUG_LOOP_CREASE_IGNORED)
    return e->isBoundary();
#else
    return e->isBoundary() || e->isCrease;
#endif
}

Vector3D vertex_rule(VertexIter v) {
    const int n = v->degree();
    Vector3D neighbours, ends;
    int n_sharp = 0;
    HalfedgeIter h = v->halfedge();
    do {
        const Vector3D& q = h->twin()->vertex()->position;
        neighbours += q;
        if (sharp(h->edge())) {
            ++n_sharp;
            ends += q;
        }
        h = h->twin()->next();
    } while (h != v->halfedge());
    if (n_sharp == 2) {
        return 0.75 * v->position + 0.125 * ends;
    }
    if (n_sharp > 2) {
        return v->position;
    }
#if defined(BUG_LOOP_VALENCE3_WEIGHT)
    const double u = 3.0 / (8.0 * n);
#else
    const double u = n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
#endif
    return (1.0 - n * u) * v->position + u * neighbours;
}

Vector3D edge_rule(EdgeIter e) {
    HalfedgeIter h = e->halfedge();
    const Vector3D& a = h->vertex()->position;
    const Vector3D& b = h->twin()->vertex()->position;
    if (sharp(e)) {
        return 0.5 * (a + b);
    }
    const Vector3D& c = h->next()->next()->vertex()->position;
    const Vector3D& d = h->twin()->next()->next()->vertex()->position;
#if defined(BUG_LOOP_EDGE_WEIGHTS_SWAPPED)
    return 0.125 * (a + b) + 0.375 * (c + d);
#else
    return 0.375 * (a + b) + 0.125 * (c + d);
#endif
}

}  // namespace

void upsample(HalfedgeMesh& mesh) {
    for (VertexIter v = mesh.verticesBegin(); v != mesh.verticesEnd(); ++v) {
        v->isNew = false;
#if defined(BUG_LOOP_UPDATED_POSITIONS)
        v->position = vertex_rule(v);  // later vertices see moved neighbours
        v->newPosition = v->position;
#else
        v->newPosition = vertex_rule(v);
#endif
    }
    for (EdgeIter e = mesh.edgesBegin(); e != mesh.edgesEnd(); ++e) {
        e->isNew = false;
        e->newPosition = edge_rule(e);
    }
#if defined(BUG_LOOP_ENDLESS)
    for (EdgeIter e = mesh.edgesBegin(); e != mesh.edgesEnd();) {
        VertexIter b = e->halfedge()->vertex(), c = e->halfedge()->twin()->vertex();
        if (b->isNew || c->isNew) {
            continue;  // skips the ++e at the bottom: stays on this edge for ever
        }
#else
    for (EdgeIter e = mesh.edgesBegin(); e != mesh.edgesEnd(); ++e) {
        VertexIter b = e->halfedge()->vertex(), c = e->halfedge()->twin()->vertex();
        if (b->isNew || c->isNew) {
            continue;  // a half of an edge split already, or a new edge
        }
#endif
        const Vector3D p = e->newPosition;
        VertexIter m = mesh.splitEdge(e);
        m->isNew = true;
        m->newPosition = p;
        HalfedgeIter h = m->halfedge();
        do {
            VertexIter w = h->twin()->vertex();
            h->edge()->isNew = w != b && w != c;  // across an old face, not a half of e
            h = h->twin()->next();
        } while (h != m->halfedge());
#if defined(BUG_LOOP_ENDLESS)
        ++e;
#endif
    }
    for (EdgeIter e = mesh.edgesBegin(); e != mesh.edgesEnd(); ++e) {
        const bool b_new = e->halfedge()->vertex()->isNew;
        const bool c_new = e->halfedge()->twin()->vertex()->isNew;
#if defined(BUG_LOOP_EDGES_NOT_MARKED_NEW)
        if (b_new != c_new) {  // the halves of old edges join old and new too
#else
        if (e->isNew && b_new != c_new) {
#endif
            mesh.flipEdge(e);
        }
    }
    for (VertexIter v = mesh.verticesBegin(); v != mesh.verticesEnd(); ++v) {
        v->position = v->newPosition;
    }
}

}  // namespace meshedit::student
