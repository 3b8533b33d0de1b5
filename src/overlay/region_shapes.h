#pragma once
// What region_pick.cpp and shown_points.cpp both ask of a region: whether a point lies in a
// lasso or a circle, a lasso's bounds, and the edges between selected vertices.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"

namespace meshedit::region {

/// Even-odd: whether a ray to the right of q crosses `outline` (closed) an odd number of times.
bool in_outline(const std::vector<glm::vec2>& outline, glm::vec2 q);
bool in_circle(glm::vec2 centre, float radius, glm::vec2 q);
/// The corners of a non-empty outline's bounding box.
glm::vec2 lower(const std::vector<glm::vec2>& outline);
glm::vec2 upper(const std::vector<glm::vec2>& outline);

// The edges both of whose ends are `in` (Blender's edge mode: an edge is inside when its
// ends are), in increasing index order.
template <class In>
std::vector<ElementRef> edges_between(const Mesh& mesh, const In& in) {
    std::vector<ElementRef> out;
    for (const Edge e : mesh.edges()) {
        if (in(mesh.vertex(e, 0).idx()) && in(mesh.vertex(e, 1).idx())) {
            out.push_back(ElementRef::edge(e));
        }
    }
    return out;
}

}  // namespace meshedit::region
