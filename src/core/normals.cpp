// Face and vertex normals. Vertex normals take one pass over the faces, scattering each face's
// area vector to its corners: no per-vertex circulation, and the work is O(halfedges).

#include "meshedit/core/normals.h"

namespace meshedit {

Vec3 face_area_vector(const Mesh& mesh, Face f) {
    const Halfedge h0 = mesh.halfedge(f);
    const Vec3& p0 = mesh.position(mesh.from_vertex(h0));
    // Newell's sum taken relative to the first corner: the same value as the classic form,
    // but independent of where the face sits, so far-from-origin faces keep their precision.
    // For a triangle it reduces to the cross product of its two edges at p0.
    Vec3 sum;
    Halfedge h = mesh.next(h0);
    Vec3 d1 = mesh.position(mesh.to_vertex(h0)) - p0;
    for (; mesh.to_vertex(h) != mesh.from_vertex(h0); h = mesh.next(h)) {
        const Vec3 d2 = mesh.position(mesh.to_vertex(h)) - p0;
        sum += cross(d1, d2);
        d1 = d2;
    }
    return sum;
}

Vec3 face_normal(const Mesh& mesh, Face f) {
    return normalize(face_area_vector(mesh, f));
}

void compute_face_normals(const Mesh& mesh, std::vector<Vec3>& out) {
    out.assign(mesh.faces_size(), Vec3{});
    for (Face f : mesh.faces()) {
        out[f.idx()] = face_normal(mesh, f);
    }
}

void compute_vertex_normals(const Mesh& mesh, std::vector<Vec3>& out) {
    out.assign(mesh.vertices_size(), Vec3{});
    for (Face f : mesh.faces()) {
        const Halfedge h0 = mesh.halfedge(f);
        const Halfedge h1 = mesh.next(h0);
        const Halfedge h2 = mesh.next(h1);
        if (mesh.next(h2) == h0) {
            // Triangles, the common case: the same cross product face_area_vector() forms,
            // scattered to the three corners without walking the face twice.
            const Vertex v0 = mesh.to_vertex(h2);
            const Vertex v1 = mesh.to_vertex(h0);
            const Vertex v2 = mesh.to_vertex(h1);
            const Vec3& p0 = mesh.position(v0);
            const Vec3 a = cross(mesh.position(v1) - p0, mesh.position(v2) - p0);
            out[v0.idx()] += a;
            out[v1.idx()] += a;
            out[v2.idx()] += a;
            continue;
        }
        const Vec3 a = face_area_vector(mesh, f);
        for (Vertex v : mesh.vertices(f)) {
            out[v.idx()] += a;
        }
    }
    for (Vec3& n : out) {
        n = normalize(n);
    }
}

std::vector<Vec3> face_normals(const Mesh& mesh) {
    std::vector<Vec3> out;
    compute_face_normals(mesh, out);
    return out;
}

std::vector<Vec3> vertex_normals(const Mesh& mesh) {
    std::vector<Vec3> out;
    compute_vertex_normals(mesh, out);
    return out;
}

}  // namespace meshedit
