// smooth_targets() (region_targets.h): Loop's and Catmull-Clark's rules on the region's inside.
//
//   Loop (triangles), edge a-b between (a, b, c) and (b, a, d):  3/8 (a + b) + 1/8 (c + d)
//       an inner vertex v of valence n:  (1 - n u) v + u (sum of its neighbours),
//       u = 3/16 at n = 3, else 3/(8 n) (Warren's, loop_subdivide()'s default)
//   Catmull-Clark, edge a-b between faces f0 and f1:  (a + b + F0 + F1) / 4, F the centroids
//       an inner vertex v of valence n:  (Q + 2 R + (n - 3) v) / n, Q the mean of the
//       centroids of its faces, R the mean of its edges' midpoints

#include "region_targets.h"

#include "meshedit/core/attributes.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/smoothing.h"

namespace meshedit::region_detail {

RegionTargets smooth_targets(const Mesh& mesh, const FaceSet& region,
                             const std::vector<Edge>& edges, RegionScheme scheme) {
    RegionTargets out;
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    const auto creased = [&](Edge e) { return crease && crease[e] != 0; };
    const auto inside = [&](Edge e) {
        const Face f0 = mesh.face(e, 0), f1 = mesh.face(e, 1);
        return f0.is_valid() && f1.is_valid() && region.contains(f0) && region.contains(f1) &&
               !creased(e);
    };
    const bool loop = scheme == RegionScheme::Loop;
    for (const Edge e : edges) {
        if (!inside(e)) {
            out.edge_points.emplace_back(false, Vec3{});
            continue;
        }
        const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
        const Vec3 a = mesh.position(mesh.from_vertex(h));
        const Vec3 b = mesh.position(mesh.to_vertex(h));
        if (loop) {
            const Vec3 c = mesh.position(mesh.to_vertex(mesh.next(h)));
            const Vec3 d = mesh.position(mesh.to_vertex(mesh.next(t)));
            out.edge_points.emplace_back(true, (a + b) * (3.0 / 8.0) + (c + d) * (1.0 / 8.0));
        } else {
            const Vec3 f0 = face_centroid(mesh, mesh.face(h));
            const Vec3 f1 = face_centroid(mesh, mesh.face(t));
            out.edge_points.emplace_back(true, (a + b + f0 + f1) * 0.25);
        }
    }
    std::vector<Face> faces = region.elements();
    for (const Vertex v : region_inner_vertices(mesh, faces)) {
        bool on_crease = false;
        for (const Edge e : mesh.edges(v)) {
            on_crease = on_crease || creased(e);
        }
        if (on_crease) {
            continue;
        }
        const Vec3 p = mesh.position(v);
        const double n = static_cast<double>(mesh.valence(v));
        Vec3 ring{0, 0, 0};
        for (const Vertex w : mesh.vertices(v)) {
            ring += mesh.position(w);
        }
        if (loop) {
            const double u = n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
            out.vertices.emplace_back(v, p * (1.0 - n * u) + ring * u);
            continue;
        }
        Vec3 q{0, 0, 0};
        for (const Face f : mesh.faces(v)) {
            q += face_centroid(mesh, f);
        }
        const Vec3 r = (p * n + ring) * (0.5 / n);  // the mean of the edges' midpoints
        out.vertices.emplace_back(v, (q * (1.0 / n) + r * 2.0 + p * (n - 3.0)) * (1.0 / n));
    }
    return out;
}

}  // namespace meshedit::region_detail
