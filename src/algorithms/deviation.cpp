// Positional difference between two meshes (compare.h): vertex distances under the matching,
// or to the other surface, and a sampled symmetric Hausdorff distance.

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/parallel.h"
#include "meshedit/core/closest_point.h"
#include "meshedit/core/compare.h"
#include "meshedit/core/display_fan.h"

namespace meshedit {
namespace {

constexpr std::size_t kParallelSamples = 20'000;
constexpr std::size_t kChunk = 4096;

// A mesh's surface for closest points: its display triangles and a point-triangle for each
// isolated vertex (by vertex index), with which triangles each face's fan starts at.
struct Surface {
    TriangleTree tree;
    std::vector<std::uint32_t> first_triangle;  // by face index
    std::vector<std::uint32_t> triangle_face;   // by triangle (kInvalidIndex: a lone vertex)
};

Surface surface_of(const Mesh& mesh) {
    std::vector<Vec3> points(mesh.position_vector().begin(), mesh.position_vector().end());
    std::vector<std::array<std::uint32_t, 3>> triangles;
    triangles.reserve(2 * mesh.n_faces());
    std::vector<std::uint32_t> first(mesh.faces_size(), kInvalidIndex), face;
    face.reserve(2 * mesh.n_faces());
    for (const Face f : mesh.faces()) {
        first[f.idx()] = static_cast<std::uint32_t>(triangles.size());
        for_each_fan_triangle(mesh, f, [&](std::size_t, Vertex c0, Halfedge h) {
            triangles.push_back({c0.idx(), mesh.from_vertex(h).idx(), mesh.to_vertex(h).idx()});
            face.push_back(f.idx());
        });
    }
    for (const Vertex v : mesh.vertices()) {
        if (mesh.is_isolated(v)) {
            triangles.push_back({v.idx(), v.idx(), v.idx()});
            face.push_back(kInvalidIndex);
        }
    }
    return {TriangleTree(std::move(points), std::move(triangles)), std::move(first),
            std::move(face)};
}

// Points to measure from, each with a triangle of the other surface near it (kInvalidIndex:
// none known, then the previous point's answer is the hint).
struct Samples {
    std::vector<Vec3> points;
    std::vector<std::uint32_t> hints;
};

// distance[i] = the distance from sample i to `tree`'s surface, on several threads; a good
// hint bounds the search to a few leaves.
std::vector<double> distances_to(const Samples& samples, const TriangleTree& tree) {
    std::vector<double> out(samples.points.size(), std::numeric_limits<double>::infinity());
    if (tree.empty()) {
        return out;
    }
    const unsigned threads = parallel::thread_count(out.size(), kParallelSamples);
    parallel::for_chunks(out.size(), kChunk, threads, [&](std::size_t begin, std::size_t end) {
        std::uint32_t previous = kInvalidIndex;
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t hint =
                samples.hints[i] != kInvalidIndex ? samples.hints[i] : previous;
            const TriangleTree::Hit hit = tree.closest(samples.points[i], hint);
            out[i] = std::sqrt(hit.distance_squared);
            previous = hit.triangle;
        }
    });
    return out;
}

// A face at v, or none.
Face face_at(const Mesh& mesh, Vertex v) {
    if (mesh.is_isolated(v)) {
        return Face();
    }
    const Halfedge h = mesh.halfedge(v);
    return mesh.is_boundary(h) ? mesh.face(Mesh::twin(h)) : mesh.face(h);
}

// The hint for a point at `face` of one mesh: the first triangle of the face it maps to.
std::uint32_t hint_of(Face face, const std::vector<std::uint32_t>* face_map, const Surface& other) {
    if (face_map == nullptr || !face.is_valid()) {
        return kInvalidIndex;
    }
    return other.first_triangle[(*face_map)[face.idx()]];
}

// `mesh`'s live vertices and its triangles' centroids, hinted by `face_map` (its faces to the
// other's) when the meshes match: with the vertices, what a one-sided distance samples.
Samples samples_of(const Mesh& mesh, const Surface& own, const Surface& other,
                   const std::vector<std::uint32_t>* face_map) {
    Samples s;
    const std::vector<Vec3>& p = own.tree.points();
    s.points.reserve(mesh.n_vertices() + own.tree.triangles().size());
    s.hints.reserve(s.points.capacity());
    for (const Vertex v : mesh.vertices()) {
        s.points.push_back(mesh.position(v));
        s.hints.push_back(hint_of(face_at(mesh, v), face_map, other));
    }
    for (std::size_t i = 0; i < own.tree.triangles().size(); ++i) {
        const auto& t = own.tree.triangles()[i];
        s.points.push_back((p[t[0]] + p[t[1]] + p[t[2]]) / 3.0);
        s.hints.push_back(hint_of(Face(own.triangle_face[i]), face_map, other));
    }
    return s;
}

double max_of(const std::vector<double>& values) {
    double m = 0.0;
    for (const double x : values) {
        m = std::max(m, x);  // NaN never wins: (m < NaN) is false
    }
    return m;
}

std::vector<std::uint32_t> inverse(const std::vector<std::uint32_t>& map, std::size_t size) {
    std::vector<std::uint32_t> out(size, kInvalidIndex);
    for (std::uint32_t i = 0; i < map.size(); ++i) {
        if (map[i] != kInvalidIndex) {
            out[map[i]] = i;
        }
    }
    return out;
}

}  // namespace

double percent_of(double distance, double diagonal) {
    return distance == 0.0 ? 0.0 : 100.0 * distance / diagonal;
}

Deviation measure_deviation(const Mesh& a, const Mesh& b, const TopologyMatch& match) {
    Deviation d;
    d.diagonal = a.bounds().diagonal();
    d.by_mapping = match.isomorphic;
    d.vertex.assign(a.vertices_size(), std::numeric_limits<double>::quiet_NaN());
    if (d.by_mapping) {
        for (const Vertex v : a.vertices()) {
            d.vertex[v.idx()] = distance(a.position(v), b.position(Vertex(match.vertex[v.idx()])));
        }
    }
    double squares = 0.0;
    const auto sum_up = [&] {
        for (const Vertex v : a.vertices()) {
            d.max = std::max(d.max, d.vertex[v.idx()]);
            squares += d.vertex[v.idx()] * d.vertex[v.idx()];
        }
        d.rms = a.n_vertices() == 0 ? 0.0 : std::sqrt(squares / double(a.n_vertices()));
    };
    if (d.by_mapping) {
        sum_up();
        if (d.max == 0.0) {
            return d;  // the same positions on the same faces: the same surface
        }
    }
    const Surface sa = surface_of(a), sb = surface_of(b);
    const std::vector<std::uint32_t> b_faces =
        d.by_mapping ? inverse(match.face, b.faces_size()) : std::vector<std::uint32_t>{};
    const std::vector<double> from_a =
        distances_to(samples_of(a, sa, sb, d.by_mapping ? &match.face : nullptr), sb.tree);
    if (!d.by_mapping) {
        std::size_t i = 0;  // the samples start with A's live vertices, in order
        for (const Vertex v : a.vertices()) {
            d.vertex[v.idx()] = from_a[i++];
        }
        sum_up();
    }
    d.a_to_b = max_of(from_a);
    d.b_to_a =
        max_of(distances_to(samples_of(b, sb, sa, d.by_mapping ? &b_faces : nullptr), sa.tree));
    d.hausdorff = std::max(d.a_to_b, d.b_to_a);
    return d;
}

}  // namespace meshedit
