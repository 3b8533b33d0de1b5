// Face and vertex normals. Vertex normals take one pass over the faces, scattering each face's
// area vector to its corners: no per-vertex circulation, and the work is O(halfedges). On
// large meshes chunks of faces run on several threads (see compute_vertex_normals).

#include "meshedit/core/normals.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>

#include "mesh/mesh_arrays.h"
#include "mesh/parallel.h"
#include "mesh/unit_scale.h"
#include "meshedit/core/assert.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/number_text.h"
#include "meshedit/core/topology.h"

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

namespace {

// A power of two that brings the largest coordinate of `mesh` near 1: scaling by it is exact,
// so normals computed from scaled positions have the same directions, without the overflow
// that cross products of coordinates above ~1e154 run into.
double unit_scale(const Mesh& mesh) {
    double largest = 0.0;
    for (const Vertex v : mesh.vertices()) {
        const Vec3& p = mesh.position(v);
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    int exponent = 0;
    std::frexp(largest, &exponent);
    return largest > 0.0 ? std::ldexp(1.0, -exponent) : 1.0;
}

}  // namespace

Vec3 face_centroid(const Mesh& mesh, Face f) {
    Vec3 sum{0, 0, 0};
    std::size_t n = 0;
    for (const Vertex v : mesh.vertices(f)) {
        sum += mesh.position(v);
        ++n;
    }
    return n > 0 ? sum / static_cast<double>(n) : sum;
}

Vec3 face_normal(const Mesh& mesh, Face f) {
    const Vec3 area = face_area_vector(mesh, f);
    if (is_finite(area) && norm(area) > 1e-250) {
        return normalize(area);
    }
    // Overflowed, or underflowed (corners near 1e-200; or a degenerate face): the same
    // directions from the face's corners scaled near 1.
    double largest = 0.0;
    for (const Vertex v : mesh.vertices(f)) {
        const Vec3& p = mesh.position(v);
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    int exponent = 0;
    if (largest > 0.0 && std::isfinite(largest)) {
        std::frexp(largest, &exponent);
    }
    const double s = std::ldexp(1.0, -exponent);
    const Halfedge h0 = mesh.halfedge(f);
    const Vec3 p0 = s * mesh.position(mesh.from_vertex(h0));
    Vec3 sum;
    Vec3 d1 = s * mesh.position(mesh.to_vertex(h0)) - p0;
    for (Halfedge h = mesh.next(h0); mesh.to_vertex(h) != mesh.from_vertex(h0); h = mesh.next(h)) {
        const Vec3 d2 = s * mesh.position(mesh.to_vertex(h)) - p0;
        sum += cross(d1, d2);
        d1 = d2;
    }
    return normalize(sum);
}

namespace {

// The signed volume of the mesh scaled by 2^exponent (exactly: a power of two).
double scaled_volume(const Mesh& mesh, int exponent) {
    const auto at = [&](Vertex v) { return scaled_point(mesh.position(v), exponent); };
    Vec3 origin;
    for (Vertex v : mesh.vertices()) {
        origin = at(v);
        break;
    }
    // Each fan triangle with the origin spans a tetrahedron of volume (p0 · (d1 × d2)) / 6;
    // Σ d1 × d2 over a face is its area vector (face_area_vector's sum).
    double sum = 0;
    for (Face f : mesh.faces()) {
        const Halfedge h0 = mesh.halfedge(f);
        const Vec3 p0 = at(mesh.from_vertex(h0));
        Vec3 area;
        Vec3 d1 = at(mesh.to_vertex(h0)) - p0;
        for (Halfedge h = mesh.next(h0); mesh.to_vertex(h) != mesh.from_vertex(h0);
             h = mesh.next(h)) {
            const Vec3 d2 = at(mesh.to_vertex(h)) - p0;
            area += cross(d1, d2);
            d1 = d2;
        }
        sum += dot(p0 - origin, area);
    }
    return sum / 6.0;
}

}  // namespace

double signed_volume(const Mesh& mesh) {
    const double volume = scaled_volume(mesh, 0);
    if (std::isfinite(volume)) {
        return volume;
    }
    // Overflowed (coordinates past ~1e100): computed at unit scale, scaled back (inf only
    // when the volume itself is past 1.8e308, never NaN).
    const int exponent = unit_exponent(mesh);
    return std::ldexp(scaled_volume(mesh, -exponent), 3 * exponent);
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

// The arrays the scatter reads, as plain pointers: the compiler keeps them in registers
// through the loop, where every Mesh accessor would reload its array after each call.
struct FaceArrays {
    explicit FaceArrays(const Mesh& mesh)
        : next(MeshArrays::next(mesh).data()),
          to(MeshArrays::to_vertex(mesh).data()),
          face_halfedge(MeshArrays::face_halfedge(mesh).data()),
          face_deleted(MeshArrays::face_deleted(mesh).data()),
          position(mesh.position_vector().data()) {}

    const Halfedge* next;
    const Vertex* to;
    const Halfedge* face_halfedge;
    const std::uint8_t* face_deleted;
    const Vec3* position;
};

// A live face's corners and area vector. For triangles, the common case, the same cross
// product face_area_vector() forms, without walking the face twice.
struct FaceCorners {
    Vertex v[3];
    Vec3 area;
    bool triangle;
};

FaceCorners face_corners(const Mesh& mesh, const FaceArrays& m, std::size_t i) {
    const Halfedge h0 = m.face_halfedge[i];
    const Halfedge h1 = m.next[h0.idx()];
    const Halfedge h2 = m.next[h1.idx()];
    FaceCorners c{{m.to[h2.idx()], m.to[h0.idx()], m.to[h1.idx()]}, {}, m.next[h2.idx()] == h0};
    if (c.triangle) {
        const Vec3& p0 = m.position[c.v[0].idx()];
        c.area = cross(m.position[c.v[1].idx()] - p0, m.position[c.v[2].idx()] - p0);
    } else {
        c.area = face_area_vector(mesh, Face(static_cast<std::uint32_t>(i)));
    }
    return c;
}

// One chunk's share of the sums: the vertices [lo, hi) are its own, to write at will.
struct OwnedRange {
    Vec3* sums;
    std::size_t lo;
    std::size_t hi;

    bool owns(Vertex v) const { return v.idx() >= lo && v.idx() < hi; }
    // Adds `c` to the corners this range owns (owned == true) or to the others; returns
    // whether any corner was of the other kind.
    bool add(const Mesh& mesh, std::size_t i, const FaceCorners& c, bool owned) const {
        bool skipped = false;
        auto visit = [&](Vertex v) {
            if (owns(v) == owned) {
                sums[v.idx()] += c.area;
            } else {
                skipped = true;
            }
        };
        if (c.triangle) {
            visit(c.v[0]);
            visit(c.v[1]);
            visit(c.v[2]);
        } else {
            for (Vertex v : mesh.vertices(Face(static_cast<std::uint32_t>(i)))) {
                visit(v);
            }
        }
        return skipped;
    }
};

// Adds the area vectors of the live faces [begin, end) to the corners `out` owns, and lists
// the faces with a corner it does not own in `unfinished`.
void scatter_faces(const Mesh& mesh, const FaceArrays& m, std::size_t begin, std::size_t end,
                   const OwnedRange& out, std::vector<std::uint32_t>& unfinished) {
    for (std::size_t i = begin; i < end; ++i) {
        if (m.face_deleted[i] != 0) {
            continue;
        }
        const Halfedge h0 = m.face_halfedge[i];
        const Halfedge h1 = m.next[h0.idx()];
        const Halfedge h2 = m.next[h1.idx()];
        const Vertex v0 = m.to[h2.idx()];
        const Vertex v1 = m.to[h0.idx()];
        const Vertex v2 = m.to[h1.idx()];
        if (m.next[h2.idx()] == h0 && out.owns(v0) && out.owns(v1) && out.owns(v2)) {
            // The common case, kept free of calls: the cross product face_corners() forms.
            const Vec3& p0 = m.position[v0.idx()];
            const Vec3 a = cross(m.position[v1.idx()] - p0, m.position[v2.idx()] - p0);
            out.sums[v0.idx()] += a;
            out.sums[v1.idx()] += a;
            out.sums[v2.idx()] += a;
        } else if (out.add(mesh, i, face_corners(mesh, m, i), true)) {
            unfinished.push_back(static_cast<std::uint32_t>(i));
        }
    }
}

}  // namespace

// Faces are cut into chunks of kChunk; the chunk of faces [b, e) owns the vertices
// [b·V/F, e·V/F). Each chunk (on any thread) zeroes its own vertices and adds its faces' area
// vectors to them in face order; a face with a corner owned by another chunk goes on the
// chunk's list of unfinished faces. Then, chunk by chunk in order, the listed faces are added
// to the corners their chunk skipped, and the sums normalised. On a mesh whose vertex order
// follows its face order (builders, subdivision) the lists are short. Every sum
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
    // Faces a chunk left unfinished: 4 bytes each, where a list of (vertex, area vector)
    // pairs took 32 per corner and, allocated afresh per call, most of the time on a 6.4M-face
    // mesh in page faults. Their area vectors are formed again below, the same bits.
    std::vector<std::vector<std::uint32_t>> unfinished(n_chunks);
    const unsigned threads = parallel::thread_count(mesh.n_faces(), kParallelFaces, max_threads);
    const FaceArrays arrays(mesh);
    auto range = [&](std::size_t c) {
        return OwnedRange{out.data(), first_owned(c), first_owned(c + 1)};
    };
    parallel::for_chunks(nf, kChunk, threads, [&](std::size_t begin, std::size_t end) {
        const std::size_t c = begin / kChunk;
        const OwnedRange own = range(c);
        std::fill(own.sums + own.lo, own.sums + own.hi, Vec3{});
        scatter_faces(mesh, arrays, begin, end, own, unfinished[c]);
    });
    for (std::size_t c = 0; c < n_chunks; ++c) {
        const OwnedRange own = range(c);
        for (const std::uint32_t i : unfinished[c]) {
            own.add(mesh, i, face_corners(mesh, arrays, i), false);
        }
    }
    // A sum that overflowed (coordinates above ~1e154) is noticed here, in the pass that
    // touches every normal anyway, so ordinary meshes pay one comparison per vertex for it.
    std::vector<std::uint8_t> overflowed((nv + kChunk - 1) / kChunk, 0);
    parallel::for_chunks(nv, kChunk, threads, [&](std::size_t begin, std::size_t end) {
        bool bad = false;
        for (std::size_t i = begin; i < end; ++i) {
            bad |= !is_finite(out[i]);
            out[i] = normalize(out[i]);
        }
        overflowed[begin / kChunk] = bad ? 1 : 0;
    });
    if (std::find(overflowed.begin(), overflowed.end(), 1) != overflowed.end()) {
        Mesh scaled = mesh;
        const double s = unit_scale(mesh);
        for (const Vertex v : scaled.vertices()) {
            scaled.position(v) *= s;
        }
        compute_vertex_normals(scaled, out, max_threads);
    }
}

void compute_vertex_normals(const Mesh& mesh, std::vector<Vec3>& out) {
    compute_vertex_normals(mesh, out, 0);
}

namespace {

// The full pass's vertex ranges for given sizes: chunk c of faces owns the vertices
// [first(c), first(c + 1)).
struct Ownership {
    std::size_t nv, nf;
    std::size_t chunks() const { return nf == 0 ? 0 : (nf + kChunk - 1) / kChunk; }
    std::size_t first(std::size_t c) const {
        const std::size_t x = std::min(c * kChunk, nf);
        return nv / nf * x + nv % nf * x / nf;
    }
    std::size_t owner(std::size_t v) const {  // the last chunk whose range starts at or before v
        std::size_t lo = 0, hi = chunks();
        while (hi - lo > 1) {
            const std::size_t mid = (lo + hi) / 2;
            (first(mid) <= v ? lo : hi) = mid;
        }
        return lo;
    }
};

// v's normal summed as compute_vertex_normals() sums it: its faces in the chunk that owns it
// in face order, then its faces in the other chunks in face order (the unfinished lists).
Vec3 vertex_normal_in_pass_order(const Mesh& mesh, Vertex v, const Ownership& own,
                                 std::vector<std::uint32_t>& faces) {
    faces.clear();
    if (!mesh.is_isolated(v)) {
        for (const Face f : mesh.faces(v)) {
            faces.push_back(f.idx());
        }
    }
    std::sort(faces.begin(), faces.end());
    const std::size_t mine = own.owner(v.idx());
    const FaceArrays arrays(mesh);
    Vec3 sum{};
    for (const bool own_chunk : {true, false}) {
        for (const std::uint32_t f : faces) {
            if ((f / kChunk == mine) == own_chunk) {
                sum += face_corners(mesh, arrays, f).area;
            }
        }
    }
    return normalize(sum);
}

}  // namespace

void update_vertex_normals(const Mesh& mesh, std::span<const Face> faces,
                           std::span<const Vertex> vertices, std::size_t old_vertices,
                           std::size_t old_faces, std::vector<Vec3>& out,
                           std::vector<Vertex>& recomputed) {
    const Ownership now{mesh.vertices_size(), mesh.faces_size()};
    const Ownership before{old_vertices, old_faces};
    out.resize(now.nv);
    std::vector<Vertex> todo;
    const auto add_corners = [&](Face f) {
        if (f.idx() < now.nf && !mesh.is_deleted(f)) {
            for (const Vertex c : mesh.vertices(f)) {
                todo.push_back(c);
            }
        }
    };
    for (const Face f : faces) {
        add_corners(f);
    }
    for (const Vertex v : vertices) {
        todo.push_back(v);
        if (v.idx() < now.nv && !mesh.is_deleted(v) && !mesh.is_isolated(v)) {
            for (const Face f : mesh.faces(v)) {  // a moved vertex changes its faces' areas
                add_corners(f);
            }
        }
    }
    // Where a chunk's range starts moved, the vertices in between changed owner.
    if (now.nf != 0) {
        for (std::size_t c = 1; c <= std::max(now.chunks(), before.chunks()); ++c) {
            const std::size_t a = now.first(std::min(c, now.chunks()));
            const std::size_t b = before.nf == 0 ? 0 : before.first(std::min(c, before.chunks()));
            for (std::size_t v = std::min(a, b); v < std::max(a, b) && v < now.nv; ++v) {
                todo.push_back(Vertex(static_cast<std::uint32_t>(v)));
            }
        }
    }
    // Vertices appended since: zero unless recomputed (as the full pass gives an isolated one).
    for (std::size_t v = std::min(old_vertices, now.nv); v < now.nv; ++v) {
        todo.push_back(Vertex(static_cast<std::uint32_t>(v)));
    }
    std::sort(todo.begin(), todo.end());
    todo.erase(std::unique(todo.begin(), todo.end()), todo.end());
    std::vector<std::uint32_t> scratch;
    for (const Vertex v : todo) {
        if (v.idx() >= now.nv) {
            continue;
        }
        Vec3 n{};
        if (!mesh.is_deleted(v) && now.nf != 0) {
            n = vertex_normal_in_pass_order(mesh, v, now, scratch);
            if (!is_finite(n)) {  // an overflowing sum: the full pass rescales the mesh
                compute_vertex_normals(mesh, out);
                recomputed.clear();
                for (const Vertex w : mesh.vertices()) {
                    recomputed.push_back(w);
                }
                return;
            }
        }
        out[v.idx()] = n;
        recomputed.push_back(v);
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

double dihedral_angle_deg(const Mesh& mesh, Edge e) {
    if (mesh.is_boundary(e)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    const Vec3 a = face_normal(mesh, mesh.face(e, 0)), b = face_normal(mesh, mesh.face(e, 1));
    if (sqrnorm(a) == 0.0 || sqrnorm(b) == 0.0) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    // atan2 rather than acos of the dot: exact near 0 and 180, where acos loses half the digits.
    return std::atan2(norm(cross(a, b)), dot(a, b)) * 180.0 / std::numbers::pi;
}

OpStatus check_crease_by_angle(double degrees) {
    if (!(degrees >= 0.0 && degrees <= 180.0)) {
        return OpStatus::composed(
            "cannot mark creases by angle: the angle must be from 0 to 180 degrees, not " +
            number_text(degrees));
    }
    return OpStatus::ok();
}

std::size_t crease_by_angle(Mesh& mesh, double degrees) {
    MESHEDIT_ASSERT(check_crease_by_angle(degrees));
    auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    std::size_t marked = 0;
    for (Edge e : mesh.edges()) {
        if (crease && crease[e] != 0) {
            continue;
        }
        // NaN (boundary, degenerate face) compares false: never marked.
        if (!(dihedral_angle_deg(mesh, e) > degrees)) {
            continue;
        }
        if (!crease) {
            crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
        }
        mesh.touch(e);  // a write through the property's handle: tell a recorded edit
        crease[e] = 1;
        ++marked;
    }
    return marked;
}

// Around v, clockwise from a sharp (or boundary) edge: the faces up to the next sharp edge
// form a wedge. Corners are named by their incoming halfedge (to_vertex = v, in the face).
bool compute_corner_normals(const Mesh& mesh, const NormalSplit& split,
                            const std::vector<Vec3>& vertex_normals, std::vector<Vec3>& out) {
    // The crease flags looked up once (by name), and nothing at all to do, the usual case
    // during a drag, when there are none and no Auto Smooth.
    const auto crease = split.creases ? mesh.get_property<Edge, std::uint8_t>(kCreaseProperty)
                                      : EdgeProperty<std::uint8_t>();
    if (!crease && !split.auto_smooth_deg) {
        return false;
    }
    std::vector<std::uint8_t> sharp(mesh.edges_size(), 0);
    bool any = false;
    const double cos_limit =
        split.auto_smooth_deg ? std::cos(*split.auto_smooth_deg * M_PI / 180.0) : -2.0;
    for (Edge e : mesh.edges()) {
        if (mesh.is_boundary(e)) {
            continue;
        }
        const bool flagged = crease && crease[e] != 0;
        const bool turned =
            split.auto_smooth_deg &&
            dot(face_normal(mesh, mesh.face(e, 0)), face_normal(mesh, mesh.face(e, 1))) < cos_limit;
        if (flagged || turned) {
            sharp[e.idx()] = 1;
            any = true;
        }
    }
    if (!any) {
        return false;
    }
    out.assign(mesh.halfedges_size(), Vec3{});
    for (Vertex v : mesh.vertices()) {
        const Halfedge start = mesh.halfedge(v);
        if (!start.is_valid()) {
            continue;
        }
        // Faces around v, clockwise: face(h) for each outgoing h, the next one sharing
        // edge(h) with it. A cut: an outgoing halfedge whose edge is sharp or boundary.
        const auto is_cut = [&](Halfedge g) {
            return sharp[Mesh::edge(g).idx()] != 0 || mesh.is_boundary(Mesh::edge(g));
        };
        Halfedge cut = start;
        bool has_sharp = false;
        Halfedge h = start;
        do {
            if (sharp[Mesh::edge(h).idx()] != 0) {
                cut = h;
                has_sharp = true;
                break;
            }
            h = mesh.cw_rotated(h);
        } while (h != start);
        if (!has_sharp) {
            // No sharp edge at v (a hole's rim alone does not split): its vertex normal for
            // every corner, bit for bit what shading without splits gives.
            h = start;
            do {
                if (!mesh.is_boundary(h)) {
                    out[mesh.prev(h).idx()] = vertex_normals[v.idx()];
                }
                h = mesh.cw_rotated(h);
            } while (h != start);
            continue;
        }
        // From just after a cut, once around: the corner of face(h) at v is entered by
        // prev(h); a cut edge(h) closes the wedge.
        std::vector<Halfedge> wedge;
        Vec3 sum;
        const Halfedge begin = mesh.cw_rotated(cut);
        h = begin;
        do {
            if (!mesh.is_boundary(h)) {
                wedge.push_back(mesh.prev(h));
                sum += face_area_vector(mesh, mesh.face(h));
            }
            if (is_cut(h)) {
                const Vec3 n = normalize(sum);
                for (Halfedge corner : wedge) {
                    out[corner.idx()] = n;
                }
                wedge.clear();
                sum = Vec3{};
            }
            h = mesh.cw_rotated(h);
        } while (h != begin);
    }
    return true;
}

}  // namespace meshedit
