// Face and vertex normals. Vertex normals take one pass over the faces, scattering each face's
// area vector to its corners: no per-vertex circulation, and the work is O(halfedges). On
// large meshes chunks of faces run on several threads (see compute_vertex_normals).

#include "meshedit/core/normals.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "meshedit/core/topology.h"
#include "parallel.h"

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

double signed_volume(const Mesh& mesh) {
    Vec3 origin;
    for (Vertex v : mesh.vertices()) {
        origin = mesh.position(v);
        break;
    }
    // Each fan triangle with the origin spans a tetrahedron of volume (p0 · (d1 × d2)) / 6,
    // and face_area_vector is the sum of those d1 × d2.
    double sum = 0;
    for (Face f : mesh.faces()) {
        const Vec3 p0 = mesh.position(mesh.from_vertex(mesh.halfedge(f))) - origin;
        sum += dot(p0, face_area_vector(mesh, f));
    }
    return sum / 6.0;
}

bool is_closed_and_outward(const Mesh& mesh) {
    if (!is_closed(mesh)) {
        return false;
    }
    // Six times each component's volume, indexed by its root vertex and taken about it.
    const std::vector<std::uint32_t> roots = component_roots(mesh);
    std::vector<double> six_volume(roots.size(), 0.0);
    for (Face f : mesh.faces()) {
        const Vertex v0 = mesh.from_vertex(mesh.halfedge(f));
        const std::uint32_t root = roots[v0.idx()];
        const Vec3 p0 = mesh.position(v0) - mesh.position(Vertex(root));
        six_volume[root] += dot(p0, face_area_vector(mesh, f));
    }
    for (Vertex v : mesh.vertices()) {
        if (roots[v.idx()] == v.idx() && !mesh.is_isolated(v) && !(six_volume[v.idx()] > 0)) {
            return false;
        }
    }
    return true;
}

void compute_face_normals(const Mesh& mesh, std::vector<Vec3>& out) {
    out.assign(mesh.faces_size(), Vec3{});
    for (Face f : mesh.faces()) {
        out[f.idx()] = face_normal(mesh, f);
    }
}

namespace {

// Below this many faces the normals are computed on the calling thread.
constexpr std::size_t kParallelFaces = 100'000;
// Faces per chunk of the scatter, vertices per chunk of the normalisation.
constexpr std::size_t kChunk = 1 << 16;

// A face's area vector bound for a vertex another chunk owns.
struct Contribution {
    Vertex vertex;
    Vec3 area;
};

// The arrays the scatter reads, as plain pointers: the compiler keeps them in registers
// through the loop, where every Mesh accessor would reload its array after each call.
struct FaceArrays {
    explicit FaceArrays(const Mesh& mesh)
        : next(mesh.get_property<Halfedge, Halfedge>("h:next").vector().data()),
          to(mesh.get_property<Halfedge, Vertex>("h:vertex").vector().data()),
          face_halfedge(mesh.get_property<Face, Halfedge>("f:halfedge").vector().data()),
          face_deleted(mesh.get_property<Face, std::uint8_t>("f:deleted").vector().data()),
          position(mesh.position_vector().data()) {}

    const Halfedge* next;
    const Vertex* to;
    const Halfedge* face_halfedge;
    const std::uint8_t* face_deleted;
    const Vec3* position;
};

// The sums of one chunk of faces: its own vertices [lo, hi) in `sums`, the rest in `others`.
struct ChunkSums {
    Vec3* sums;
    std::size_t lo;
    std::size_t hi;
    std::vector<Contribution>* others;

    bool owns(Vertex v) const { return v.idx() >= lo && v.idx() < hi; }
    void add(Vertex v, const Vec3& a) const {
        if (owns(v)) {
            sums[v.idx()] += a;
        } else {
            others->push_back({v, a});
        }
    }
};

// A polygon, or a triangle with a corner another chunk owns: the uncommon cases, kept out of
// the loop below.
void add_face(const Mesh& mesh, Face f, const Vec3& area, const ChunkSums& out) {
    for (Vertex v : mesh.vertices(f)) {
        out.add(v, area);
    }
}

// Adds the area vectors of the live faces [begin, end) to their corners.
void scatter_faces(const Mesh& mesh, const FaceArrays& m, std::size_t begin, std::size_t end,
                   const ChunkSums& out) {
    for (std::size_t i = begin; i < end; ++i) {
        if (m.face_deleted[i] != 0) {
            continue;
        }
        const Face f(static_cast<std::uint32_t>(i));
        const Halfedge h0 = m.face_halfedge[i];
        const Halfedge h1 = m.next[h0.idx()];
        const Halfedge h2 = m.next[h1.idx()];
        if (m.next[h2.idx()] != h0) {
            add_face(mesh, f, face_area_vector(mesh, f), out);
            continue;
        }
        // Triangles, the common case: the same cross product face_area_vector() forms,
        // without walking the face twice.
        const Vertex v0 = m.to[h2.idx()];
        const Vertex v1 = m.to[h0.idx()];
        const Vertex v2 = m.to[h1.idx()];
        const Vec3& p0 = m.position[v0.idx()];
        const Vec3 a = cross(m.position[v1.idx()] - p0, m.position[v2.idx()] - p0);
        if (out.owns(v0) && out.owns(v1) && out.owns(v2)) {
            out.sums[v0.idx()] += a;
            out.sums[v1.idx()] += a;
            out.sums[v2.idx()] += a;
        } else {
            add_face(mesh, f, a, out);
        }
    }
}

}  // namespace

// Faces are cut into chunks of kChunk; the chunk of faces [b, e) owns the vertices
// [b·V/F, e·V/F). Each chunk (on any thread) zeroes its own vertices and adds its faces' area
// vectors to them in face order; a corner owned by another chunk goes to the chunk's list
// instead. Then the lists are added in chunk order, and the sums normalised. On a mesh whose
// vertex order follows its face order (builders, subdivision) the lists are short. Every sum
// is formed in an order fixed by the mesh alone, so the bits do not depend on the number of
// threads; with a single chunk (up to 65,536 faces) the order is plain face order.
void compute_vertex_normals(const Mesh& mesh, std::vector<Vec3>& out, unsigned max_threads) {
    const std::size_t nv = mesh.vertices_size();
    const std::size_t nf = mesh.faces_size();
    out.resize(nv);
    if (nf == 0) {
        std::fill(out.begin(), out.end(), Vec3{});
        return;
    }
    const std::size_t n_chunks = (nf + kChunk - 1) / kChunk;
    // ⌊nv · x / nf⌋ for the first face x of chunk c, without overflowing 64 bits.
    auto first_owned = [&](std::size_t c) {
        const std::size_t x = std::min(c * kChunk, nf);
        return nv / nf * x + nv % nf * x / nf;
    };
    std::vector<std::vector<Contribution>> foreign(n_chunks);
    const unsigned threads = parallel::thread_count(mesh.n_faces(), kParallelFaces, max_threads);
    const FaceArrays arrays(mesh);
    parallel::for_chunks(nf, kChunk, threads, [&](std::size_t begin, std::size_t end) {
        const std::size_t c = begin / kChunk;
        const ChunkSums sums{out.data(), first_owned(c), first_owned(c + 1), &foreign[c]};
        std::fill(sums.sums + sums.lo, sums.sums + sums.hi, Vec3{});
        scatter_faces(mesh, arrays, begin, end, sums);
    });
    for (const std::vector<Contribution>& list : foreign) {
        for (const Contribution& x : list) {
            out[x.vertex.idx()] += x.area;
        }
    }
    parallel::for_chunks(nv, kChunk, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            out[i] = normalize(out[i]);
        }
    });
}

void compute_vertex_normals(const Mesh& mesh, std::vector<Vec3>& out) {
    compute_vertex_normals(mesh, out, 0);
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
