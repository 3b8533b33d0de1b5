#pragma once
// Private to meshedit_core: the geometric guard of the algorithms that collapse edges to a
// chosen point (QEM simplification, remeshing): collapse() checks the topology, this checks
// that no triangle that stays turns over.

#include "meshedit/core/mesh.h"
#include "meshedit/core/normals.h"

namespace meshedit {

/// Whether moving both ends of triangle-mesh edge e to p turns a face that stays (any but
/// the triangles beside e) so that its normal leaves the cone of cos_limit around the old
/// one, or makes it degenerate.
inline bool collapse_turns_a_face(const Mesh& mesh, Edge e, const Vec3& p, double cos_limit) {
    const Vertex a = mesh.vertex(e, 0), b = mesh.vertex(e, 1);
    for (const Vertex v : {a, b}) {
        for (Face f : mesh.faces(v)) {
            Vec3 corner[3];
            int i = 0;
            bool has_both = false;
            for (Vertex c : mesh.vertices(f)) {
                if (i < 3) {
                    corner[i++] = (c == a || c == b) ? p : mesh.position(c);
                }
                has_both = has_both || (c == (v == a ? b : a));
            }
            if (has_both) {
                continue;  // one of the triangles beside e: it goes
            }
            const Vec3 before = face_area_vector(mesh, f);
            const Vec3 after = cross(corner[1] - corner[0], corner[2] - corner[0]);
            const double scale = norm(before) * norm(after);
            if (!(scale > 0.0) || dot(before, after) < cos_limit * scale) {
                return true;
            }
        }
    }
    return false;
}

/// Whether v is a corner of the feature lines whose edges `is_feature(Edge)` names: the end of
/// one (a single feature edge), three or more feature edges, or two that turn by more than
/// 30 degrees. The collapses of remeshing and simplification never move a corner.
template <class IsFeature>
bool is_feature_corner(const Mesh& mesh, Vertex v, IsFeature is_feature) {
    Vec3 dir[2];
    int n = 0;
    for (Halfedge h : mesh.halfedges(v)) {
        if (is_feature(Mesh::edge(h))) {
            if (n < 2) {
                dir[n] = normalize(mesh.position(mesh.to_vertex(h)) - mesh.position(v));
            }
            ++n;
        }
    }
    return n == 1 || n >= 3 || (n == 2 && dot(dir[0], dir[1]) > -0.866);
}

}  // namespace meshedit
