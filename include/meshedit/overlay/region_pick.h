#pragma once
/// \file
/// Box and lasso selection (Blender's B and Ctrl+right-drag): what a region of the screen selects,
/// as Blender does it — in vertex mode the vertices that land inside, in edge mode the edges both
/// of whose ends do, in face mode the faces whose centre does. GL-free: points are projected with
/// the camera's own matrices (project_to_pixels()'s arithmetic), and what the view hides is found
/// with a depth buffer of the region, drawn on the CPU (a triangle per pixel of a million-face
/// mesh costs what the GPU's ID pass would, without a round trip through the driver).

#include <vector>

#include <glm/glm.hpp>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"
#include "meshedit/overlay/camera.h"

namespace meshedit {

struct ScreenBox {
    glm::vec2 a, b;             ///< two opposite corners, pixels from the top-left of the image
    int width = 1, height = 1;  ///< the image
};

/// Whether a region takes only what the view shows or also what is hidden (Blender's X-ray).
/// VisibleFrontOnly is Visible where the renderer culls back faces (MeshRenderer::
/// culls_back_faces(), back_faces_hidden() in camera.h: a closed, outward mesh seen from
/// outside): a face turned away is neither drawn into the depth buffer nor selected.
enum class Reach { Visible, VisibleFrontOnly, Through };

/// The elements of `kind` (Vertex, Edge, Face; a Halfedge counts as Edge) that `box` selects,
/// in increasing index order. Visible: an element's point (a vertex, a face's centre) counts
/// when the depth buffer of the faces at its pixel is not nearer than the point by more than
/// the element's own depth change across a pixel; Through: everything inside counts.
std::vector<ElementRef> elements_in_box(const Mesh& mesh, const Camera& camera,
                                        const ScreenBox& box, ElementRef::Kind kind,
                                        Reach reach = Reach::Through);

/// The same for a lasso: a closed outline in pixels of a `width` × `height` image (the last
/// point joins the first); a point is inside by the even-odd rule.
std::vector<ElementRef> elements_in_lasso(const Mesh& mesh, const Camera& camera,
                                          const std::vector<glm::vec2>& outline, int width,
                                          int height, ElementRef::Kind kind,
                                          Reach reach = Reach::Through);

/// The same for a circle of `radius` pixels around `centre` (Blender's circle select, the
/// viewer's brush).
std::vector<ElementRef> elements_in_circle(const Mesh& mesh, const Camera& camera, glm::vec2 centre,
                                           float radius, int width, int height,
                                           ElementRef::Kind kind, Reach reach = Reach::Through);

}  // namespace meshedit
