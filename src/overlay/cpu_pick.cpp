// Picking on the CPU by pick.frag's rules (cpu_pick.h).

#include "meshedit/overlay/cpu_pick.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace meshedit {
namespace {

/// The line through a window sample from the near plane (t = 0) to the far plane (t = 1).
struct Unprojector {
    glm::dmat4 inverse;
    double width, height;

    FaceBvh::Ray ray(double x, double y) const {
        const double nx = 2.0 * x / width - 1.0;
        const double ny = 1.0 - 2.0 * y / height;
        const auto at = [&](double nz) {
            const glm::dvec4 p = inverse * glm::dvec4(nx, ny, nz, 1.0);
            return Vec3{p.x / p.w, p.y / p.w, p.z / p.w};
        };
        const Vec3 near = at(-1.0);
        return {near, at(1.0) - near, 0.0, 1.0};
    }
};

/// pick.frag's decision, in the same order and with the same ties.
ElementRef classify(const FaceBvh::Hit& hit, const std::array<double, 3>& fwidth,
                    const PickRadii& radii) {
    const std::array<double, 3>& b = hit.barycentric;
    std::array<double, 3> w{};
    for (std::size_t k = 0; k < 3; ++k) {
        w[k] = std::max(fwidth[k], 1e-7);
    }
    const std::size_t k = b[0] > b[1] ? (b[0] > b[2] ? 0 : 2) : (b[1] > b[2] ? 1 : 2);
    if ((1.0 - b[k]) / w[k] < radii.vertex_px) {
        return ElementRef::vertex(hit.corners[k]);
    }
    // Side c_s -> c_(s+1) lies opposite corner s+2: its barycentric is 0 on the side.
    std::size_t j = 3;
    double best = 1e9;
    for (std::size_t s = 0; s < 3; ++s) {
        const double bs = b[(s + 2) % 3];
        if (hit.sides[s].is_valid() && bs < best) {
            best = bs;
            j = s;
        }
    }
    if (j < 3) {
        const double pixels = best / w[(j + 2) % 3];
        if (pixels < radii.edge_px) {
            return ElementRef::edge(Mesh::edge(hit.sides[j]));
        }
        if (best < radii.halfedge_band || pixels < 2.5 * radii.edge_px) {
            return ElementRef::halfedge(hit.sides[j]);
        }
    }
    return ElementRef::face(hit.face);
}

}  // namespace

PickDetail pick_sample(const FaceBvh& bvh, const Mesh& mesh, const Camera& camera, int width,
                       int height, double x, double y, bool cull_back_faces,
                       const PickRadii& radii) {
    PickDetail out;
    if (width <= 0 || height <= 0) {
        return out;
    }
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const Unprojector unproject{
        glm::inverse(glm::dmat4(camera.projection(aspect)) * glm::dmat4(camera.view())),
        static_cast<double>(width), static_cast<double>(height)};
    const FaceBvh::Ray ray = unproject.ray(x, y);
    out.hit = bvh.intersect(mesh, ray,
                            cull_back_faces ? FaceBvh::Sides::FrontOnly : FaceBvh::Sides::Both);
    if (!out.hit) {
        return out;
    }
    // fwidth(): the barycentrics extrapolated over the hit triangle's plane to the other
    // pixel of the 2×2 quad in the same row, and in the same column, as the GPU's helper
    // lanes compute them.
    const Vec3& a = mesh.position(out.hit->corners[0]);
    const Vec3& b = mesh.position(out.hit->corners[1]);
    const Vec3& c = mesh.position(out.hit->corners[2]);
    const auto column = static_cast<long>(std::floor(x));
    const auto row = static_cast<long>(std::floor(y));
    const double dx = (column % 2 == 0) ? 1.0 : -1.0;
    const double dy = (row % 2 == 0) ? 1.0 : -1.0;
    for (const auto& [sx, sy] : {std::pair{x + dx, y}, std::pair{x, y + dy}}) {
        const FaceBvh::Ray other = unproject.ray(sx, sy);
        const auto line = FaceBvh::line_plane(a, b, c, other.origin, other.direction);
        for (std::size_t k = 0; k < 3; ++k) {
            out.fwidth[k] += line ? std::abs((*line)[k + 1] - out.hit->barycentric[k]) : INFINITY;
        }
    }
    out.element = classify(*out.hit, out.fwidth, radii);
    return out;
}

ElementRef cpu_pick(const FaceBvh& bvh, const Mesh& mesh, const Camera& camera, int width,
                    int height, int x, int y, bool cull_back_faces, float vertex_radius_px,
                    float edge_radius_px) {
    if (x < 0 || y < 0 || x >= width || y >= height) {
        return {};
    }
    return pick_sample(bvh, mesh, camera, width, height, x + 0.5, y + 0.5, cull_back_faces,
                       {vertex_radius_px, edge_radius_px, 0.15f})
        .element;
}

}  // namespace meshedit
