// MeshRenderer::update() after recorded local edits, and after their undo, draws exactly what a
// fresh upload() of the same mesh draws: same pixels, smooth and flat, wireframe on, on
// triangle meshes, an open grid and polygons (EGL or OSMesa, one sample, so no resolve differs).

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/core/shapes.h"
#include "meshedit/render/image.h"
#include "meshedit/render/mesh_renderer.h"
#include "meshedit/render/overlay_renderer.h"
#include "meshedit/render/render_target.h"
#include "support/fixtures.h"
#include "test_context.h"

namespace meshedit {
namespace {

constexpr int kSize = 160;

Image draw(BackgroundRenderer& background, MeshRenderer& renderer, const Camera& camera,
           bool smooth, SurfaceColor color) {
    const float black[3] = {0, 0, 0};  // the background clears colour and depth
    background.draw(black, black);
    RenderOptions options;
    options.smooth = smooth;
    options.wireframe = true;
    options.color = color;
    renderer.draw(camera, 1.0f, options);
    return read_framebuffer(kSize, kSize);
}

// Random flips, splits, collapses, dissolves and pokes; after each, and after undoing it,
// the updated renderer and a fresh one must draw the same picture.
void check(Mesh mesh, unsigned seed, int edits, SurfaceColor color = SurfaceColor::Single) {
    const auto context = test::make_test_context(kSize, kSize);
    RenderTarget target(kSize, kSize, 1);
    target.bind();
    Camera camera;
    camera.frame_mesh(mesh, 1.0f);
    BackgroundRenderer background;
    MeshRenderer updated;
    updated.upload(mesh);
    std::mt19937 rng(seed);
    int incremental = 0, compared = 0;
    for (int i = 0; i < edits; ++i) {
        const Edge e(static_cast<std::uint32_t>(rng() % mesh.edges_size()));
        const Face f(static_cast<std::uint32_t>(rng() % mesh.faces_size()));
        const int op = static_cast<int>(rng() % 5);
        MeshRecorder recorder(mesh);
        bool ok = false;
        if (op < 4 && !mesh.is_deleted(e)) {
            ok = op == 0   ? flip(mesh, e).ok()
                 : op == 1 ? split(mesh, e).ok()
                 : op == 2 ? collapse(mesh, e).ok()
                           : dissolve_edge(mesh, e).ok();
        } else if (op == 4 && !mesh.is_deleted(f)) {
            ok = poke(mesh, f).ok();
        }
        MeshChange change = recorder.finish();
        if (!ok) {
            continue;
        }
        const MeshChange::Region region = change.region();
        for (const bool undo : {false, true}) {
            if (undo && rng() % 3 != 0) {
                break;  // undo a third of them; the rest stay and the mesh evolves
            }
            if (undo) {
                change.undo(mesh);
            }
            incremental += updated.update(mesh, region.faces, region.vertices) ? 1 : 0;
            MeshRenderer fresh;
            fresh.upload(mesh);
            ASSERT_EQ(updated.triangle_count(), fresh.triangle_count());
            for (const bool smooth : {true, false}) {
                const Image a = draw(background, updated, camera, smooth, color);
                const Image b = draw(background, fresh, camera, smooth, color);
                ASSERT_TRUE(a.rgba == b.rgba)
                    << "edit " << i << (undo ? " undone" : "") << (smooth ? ", smooth" : ", flat");
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, edits / 2);
    EXPECT_EQ(incremental * 2, compared);  // every update was incremental
}

TEST(RendererUpdate, TriangleMeshDrawsAsAFreshUpload) {
    check(shapes::torus(16, 10), 1, 60);
}

TEST(RendererUpdate, OpenGridDrawsAsAFreshUpload) {
    check(shapes::grid(8, 6), 2, 60);
}

// The surface colours follow the edits too: texture coordinates (drawn as the UV checker,
// seams from a chart per face side) and vertex colours.
Mesh with_surface(Mesh mesh) {
    auto uv = mesh.property<Halfedge, Vec2>(kTexCoordProperty);
    auto colour = mesh.property<Vertex, Vec4>(kColorProperty);
    for (const Halfedge h : mesh.halfedges()) {
        if (!mesh.is_boundary(h)) {
            const Vec3 p = mesh.position(mesh.to_vertex(h));
            uv[h] = Vec2{0.7 * p.x + 0.1 * (mesh.face(h).idx() % 3), 0.7 * p.y + 0.3 * p.z};
        }
    }
    for (const Vertex v : mesh.vertices()) {
        const Vec3 p = mesh.position(v);
        colour[v] = Vec4{0.5 + 0.4 * p.x, 0.5 + 0.4 * p.y, 0.5 + 0.4 * p.z, 1.0};
    }
    return mesh;
}

TEST(RendererUpdate, TextureCoordinatesDrawAsAFreshUpload) {
    check(with_surface(shapes::torus(16, 10)), 4, 60, SurfaceColor::Checker);
}

TEST(RendererUpdate, VertexColoursDrawAsAFreshUpload) {
    check(with_surface(shapes::quad_sphere(3)), 5, 60, SurfaceColor::Vertex);
}

TEST(RendererUpdate, PolygonsDrawAsAFreshUpload) {
    check(shapes::quad_sphere(3), 3, 60);
}

}  // namespace
}  // namespace meshedit
