#pragma once
/// \file
/// Box and lasso selection (Blender's B and Ctrl+right-drag): what a region of the screen selects,
/// as Blender does it — in vertex mode the vertices that land inside, in edge mode the edges both
/// of whose ends do, in face mode the faces whose centre does. GL-free: points are projected with
/// the camera's own matrices (project_to_pixels()'s arithmetic), and what the view hides is found
/// with a depth buffer of the region, drawn on the CPU (a triangle per pixel of a million-face
/// mesh costs what the GPU's ID pass would, without a round trip through the driver).
/// ShownPoints keeps what one whole view shows, for the many regions of an interactive session.

#include <cstdint>
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

/// What one view shows, kept between regions: the points a region in that view may select
/// (face centres, or vertices for vertex and edge mode), binned into 16-pixel tiles, so that
/// each box, lasso or brush dab costs what it holds rather than a pass over the mesh. Blender
/// keeps its selection buffer the same way until the view changes. Built for one state of the
/// mesh (the caller drops it when the mesh changes), one camera, image size, kind and reach;
/// its answers equal elements_in_box(), elements_in_lasso() and elements_in_circle() exactly.
class ShownPoints {
public:
    ShownPoints(const Mesh& mesh, const Camera& camera, int width, int height,
                ElementRef::Kind kind, Reach reach);

    /// Whether it was built for this view, kind and reach (a Halfedge counts as Edge).
    bool fits(const Camera& camera, int width, int height, ElementRef::Kind kind,
              Reach reach) const;

    /// The elements a region selects, in increasing index order; `mesh` is the one built
    /// from (edges are found from their ends).
    std::vector<ElementRef> in_box(const Mesh& mesh, glm::vec2 a, glm::vec2 b) const;
    std::vector<ElementRef> in_lasso(const Mesh& mesh, const std::vector<glm::vec2>& outline) const;
    std::vector<ElementRef> in_circle(const Mesh& mesh, glm::vec2 centre, float radius) const;

    /// Points kept (what the view shows of the kind, in the image).
    std::size_t size() const { return points_.size(); }

    struct Point {
        glm::vec2 at;  ///< pixels
        std::uint32_t index;
    };

private:
    enum class Cover { Outside, Inside, Mixed };
    template <class Classify, class Inside>
    std::vector<ElementRef> select(const Mesh& mesh, glm::vec2 lo, glm::vec2 hi,
                                   const Classify& classify, const Inside& inside) const;

    static constexpr int kTile = 16;
    glm::mat4 view_projection_{1.0f};
    int width_ = 1, height_ = 1, tiles_x_ = 1, tiles_y_ = 1;
    ElementRef::Kind kind_;
    Reach reach_;
    std::size_t elements_ = 0;           ///< faces_size() or vertices_size()
    std::vector<Point> points_;          ///< by tile, row by row
    std::vector<std::uint32_t> starts_;  ///< tile t's points: [starts_[t], starts_[t + 1])
};

}  // namespace meshedit
