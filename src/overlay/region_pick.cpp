// Box selection (region_pick.h).

#include "meshedit/overlay/region_pick.h"

#include <algorithm>
#include <optional>

#include "meshedit/core/normals.h"

namespace meshedit {

namespace {

// The camera's projection of points into pixels, its matrices taken once.
class Projector {
public:
    Projector(const Camera& camera, int width, int height)
        : w_(static_cast<float>(std::max(width, 1))),
          h_(static_cast<float>(std::max(height, 1))),
          matrix_(camera.projection(w_ / h_) * camera.view()) {}

    std::optional<glm::vec2> operator()(const Vec3& p) const {
        const glm::vec4 clip = matrix_ * glm::vec4(static_cast<float>(p.x), static_cast<float>(p.y),
                                                   static_cast<float>(p.z), 1.0f);
        if (clip.w <= 0.0f || clip.z < -clip.w || clip.z > clip.w) {
            return std::nullopt;
        }
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        return glm::vec2((ndc.x + 1.0f) * 0.5f * w_, (1.0f - ndc.y) * 0.5f * h_);
    }

private:
    float w_, h_;
    glm::mat4 matrix_;
};

// Whether the view shows `p`: a ray from the eye (along the view direction when orthographic)
// meets no face before it. Faces through `p` itself meet it at t = 1, past the bound.
bool shows(const FaceBvh& tree, const Mesh& mesh, const Camera& camera, const Vec3& p) {
    const glm::vec3 eye = camera.eye();
    FaceBvh::Ray ray;
    if (camera.orthographic) {
        const glm::vec3 forward = glm::normalize(camera.target - eye);
        const Vec3 back{forward.x, forward.y, forward.z};
        const double reach = 4.0 * static_cast<double>(camera.far_plane());
        ray.origin = p - back * reach;
        ray.direction = back * reach;
    } else {
        ray.origin = Vec3{eye.x, eye.y, eye.z};
        ray.direction = p - ray.origin;
    }
    ray.t_max = 1.0 - 1e-6;
    return !tree.intersect(mesh, ray).has_value();
}

// What a region selects: `in_region(pixel)` says whether a projected point lies inside.
template <class InRegion>
std::vector<ElementRef> elements_inside(const Mesh& mesh, const Camera& camera, int width,
                                        int height, ElementRef::Kind kind, const FaceBvh* visible,
                                        const InRegion& in_region) {
    const Projector project(camera, width, height);
    const auto inside = [&](const Vec3& p) {
        const std::optional<glm::vec2> q = project(p);
        return q && in_region(*q) && (visible == nullptr || shows(*visible, mesh, camera, p));
    };
    std::vector<ElementRef> out;
    if (kind == ElementRef::Kind::Face) {
        for (const Face f : mesh.faces()) {
            if (inside(face_centroid(mesh, f))) {
                out.push_back(ElementRef::face(f));
            }
        }
        return out;
    }
    std::vector<bool> in(mesh.vertices_size(), false);
    for (const Vertex v : mesh.vertices()) {
        in[v.idx()] = inside(mesh.position(v));
        if (in[v.idx()] && kind == ElementRef::Kind::Vertex) {
            out.push_back(ElementRef::vertex(v));
        }
    }
    if (kind == ElementRef::Kind::Edge || kind == ElementRef::Kind::Halfedge) {
        for (const Edge e : mesh.edges()) {
            if (in[mesh.vertex(e, 0).idx()] && in[mesh.vertex(e, 1).idx()]) {
                out.push_back(ElementRef::edge(e));
            }
        }
    }
    return out;
}

}  // namespace

std::vector<ElementRef> elements_in_box(const Mesh& mesh, const Camera& camera,
                                        const ScreenBox& box, ElementRef::Kind kind,
                                        const FaceBvh* visible) {
    const glm::vec2 lo = glm::min(box.a, box.b), hi = glm::max(box.a, box.b);
    return elements_inside(mesh, camera, box.width, box.height, kind, visible,
                           [&](const glm::vec2& q) {
                               return q.x >= lo.x && q.x <= hi.x && q.y >= lo.y && q.y <= hi.y;
                           });
}

std::vector<ElementRef> elements_in_lasso(const Mesh& mesh, const Camera& camera,
                                          const std::vector<glm::vec2>& outline, int width,
                                          int height, ElementRef::Kind kind,
                                          const FaceBvh* visible) {
    if (outline.size() < 3) {
        return {};
    }
    glm::vec2 lo = outline[0], hi = outline[0];
    for (const glm::vec2& p : outline) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // Even-odd: a ray to the right of q crosses the outline an odd number of times.
    const auto in_outline = [&](const glm::vec2& q) {
        if (q.x < lo.x || q.x > hi.x || q.y < lo.y || q.y > hi.y) {
            return false;
        }
        bool odd = false;
        for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
            const glm::vec2 &a = outline[i], &b = outline[j];
            if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
                odd = !odd;
            }
        }
        return odd;
    };
    return elements_inside(mesh, camera, width, height, kind, visible, in_outline);
}

}  // namespace meshedit
