// Catmull-Clark and linear subdivision, classic reference (the shape of Scotty3D's
// catmark_subdivide and most course code): compute every new point with circulators, then
// build a new mesh from the list of quads. Public mesh API and build_mesh() only, so it is
// slow but easy to trust; the tests hold the fast path (quad_subdivision.cpp) to it.

#include <cstdint>
#include <vector>

#include "algorithms/catmark_rules.h"
#include "algorithms/loop_rules.h"
#include "meshedit/core/build.h"
#include "meshedit/core/quad_subdivision.h"

namespace meshedit {

void quad_subdivide_classic(Mesh& mesh, const QuadSubdivisionOptions& options) {
    loop_rules::Progress progress(options.progress);
    progress(0.0);
    if (mesh.has_garbage()) {
        mesh.garbage_collection();
    }
    const auto nv = static_cast<std::uint32_t>(mesh.vertices_size());
    const auto ne = static_cast<std::uint32_t>(mesh.edges_size());
    const EdgeProperty<std::uint8_t> crease = loop_rules::crease_property(mesh);
    const auto sharp = [&](Edge e) {
        return loop_rules::is_sharp(mesh.is_boundary(e), crease ? crease[e] : 0);
    };

    // The points, numbered as the result numbers its vertices: old v, then V + e, V + E + f.
    PolygonSoup soup;
    soup.positions.resize(nv + ne + mesh.faces_size());
    const auto face_point = [&](Face f) -> const Vec3& {
        return soup.positions[nv + ne + f.idx()];
    };
    for (Face f : mesh.faces()) {
        Vec3 sum;
        std::size_t k = 0;
        for (Vertex c : mesh.vertices(f)) {
            sum += mesh.position(c);
            ++k;
        }
        soup.positions[nv + ne + f.idx()] = catmark_rules::face_point(sum, k);
    }
    for (Edge e : mesh.edges()) {
        const Vec3& a = mesh.position(mesh.vertex(e, 1));
        const Vec3& b = mesh.position(mesh.vertex(e, 0));
        soup.positions[nv + e.idx()] =
            sharp(e) ? catmark_rules::edge_point(options.scheme, true, a, b, a, b)
                     : catmark_rules::edge_point(options.scheme, false, a, b,
                                                 face_point(mesh.face(e, 0)),
                                                 face_point(mesh.face(e, 1)));
    }
    progress(0.3);
    for (Vertex v : mesh.vertices()) {
        catmark_rules::Ring ring;
        for (Halfedge h : mesh.halfedges(v)) {
            const Vec3& q = mesh.position(mesh.to_vertex(h));
            ring.neighbour_sum += q;
            ++ring.valence;
            if (const Face f = mesh.face(h); f.is_valid()) {
                ring.face_point_sum += face_point(f);
            }
            if (sharp(Mesh::edge(h))) {
                ring.sharp_sum += q;
                ++ring.n_sharp;
            }
        }
        soup.positions[v.idx()] =
            catmark_rules::vertex_point(options.scheme, mesh.position(v), ring);
    }
    progress(0.5);

    // One quad per corner to(h) of each face, from halfedge(f) on: (to(h), m of next(h),
    // face point, m of h).
    for (Face f : mesh.faces()) {
        for (Halfedge h : mesh.halfedges(f)) {
            const Halfedge n = mesh.next(h);
            soup.add_face({mesh.to_vertex(h).idx(), nv + Mesh::edge(n).idx(), nv + ne + f.idx(),
                           nv + Mesh::edge(h).idx()});
        }
    }
    // Crease edges stay creases in both halves.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> crease_halves;
    if (crease) {
        for (Edge e : mesh.edges()) {
            if (crease[e] != 0) {
                crease_halves.emplace_back(mesh.vertex(e, 0).idx(), nv + e.idx());
                crease_halves.emplace_back(mesh.vertex(e, 1).idx(), nv + e.idx());
            }
        }
    }
    Mesh result = build_mesh(soup);
    progress(0.9);
    if (crease) {
        EdgeProperty<std::uint8_t> flags =
            result.add_property<Edge, std::uint8_t>(kCreaseProperty, 0);
        for (const auto& [a, b] : crease_halves) {
            flags[result.find_edge(Vertex(a), Vertex(b))] = 1;
        }
    }
    mesh = std::move(result);
    progress(1.0);
}

}  // namespace meshedit
