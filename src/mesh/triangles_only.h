#pragma once
// Private to meshedit_core: the first refusal of the algorithms that work on triangles only
// (QEM simplification, remeshing), worded as Loop's is in the edit language.

#include <string>
#include <string_view>

#include "meshedit/core/mesh.h"

namespace meshedit {

/// "cannot <verb>: the mesh has no faces", "cannot <verb>: <who> needs triangles and N of the
/// F faces are polygons (triangulate them first: …)", or empty.
inline std::string refuse_unless_triangles(const Mesh& mesh, std::string_view verb,
                                           std::string_view who) {
    const std::string cannot = "cannot " + std::string(verb) + ": ";
    if (mesh.n_faces() == 0) {
        return cannot + "the mesh has no faces";
    }
    std::size_t polygons = 0;
    for (Face f : mesh.faces()) {
        polygons += mesh.valence(f) != 3;
    }
    if (polygons == 0) {
        return {};
    }
    return cannot + std::string(who) + " needs triangles and " + std::to_string(polygons) +
           " of the " + std::to_string(mesh.n_faces()) +
           " faces are polygons (triangulate them first: the `triangulate` step, Ctrl+T in the "
           "viewer)";
}

}  // namespace meshedit
