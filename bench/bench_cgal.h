#pragma once
/// \file
/// CGAL's Surface_mesh as the benchmarks build it from a Surface (bench_quality.h) and read
/// its result back, the same for every CGAL anchor.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstdint>
#include <vector>

#include "bench_quality.h"

namespace meshedit::bench {

using CgalKernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

inline CgalMesh cgal_mesh(const Surface& s) {
    CgalMesh mesh;
    using Size = CgalMesh::size_type;
    mesh.reserve(static_cast<Size>(s.points.size()), static_cast<Size>(3 * s.triangles.size() / 2),
                 static_cast<Size>(s.triangles.size()));
    std::vector<CgalMesh::Vertex_index> vh;
    vh.reserve(s.points.size());
    for (const Vec3& p : s.points) {
        vh.push_back(mesh.add_vertex(CgalKernel::Point_3(p.x, p.y, p.z)));
    }
    for (const auto& t : s.triangles) {
        mesh.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
    }
    return mesh;
}

/// The triangles of a CGAL result (its garbage collected first).
inline Surface surface_of(CgalMesh& mesh) {
    mesh.collect_garbage();
    Surface out;
    for (auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        out.points.push_back({p.x(), p.y(), p.z()});
    }
    for (auto f : mesh.faces()) {
        std::array<std::uint32_t, 3> t{};
        int i = 0;
        for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
            if (i < 3) {
                t[i++] = static_cast<std::uint32_t>(v.idx());
            }
        }
        out.triangles.push_back(t);
    }
    return out;
}

}  // namespace meshedit::bench
