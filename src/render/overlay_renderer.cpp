// Overlay and background drawing (overlay_renderer.h).

#include "meshedit/render/overlay_renderer.h"

#include <algorithm>
#include <iterator>

#include <glm/gtc/type_ptr.hpp>

#include "gl.h"

namespace meshedit {
namespace {

// Floats per instance or vertex in the staging arrays.
constexpr int kPointFloats = 3 + 4 + 1;
constexpr int kLineFloats = 3 + 3 + 4 + 1;
constexpr int kTriangleVertexFloats = 3 + 4;
constexpr int kArrowheadFloats = 3 + 3 + 3 + 4 + 2;

void grow_and_upload(unsigned vbo, std::size_t& capacity, const std::vector<float>& data) {
    const std::size_t bytes = data.size() * sizeof(float);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    if (bytes > capacity) {
        capacity = std::max(bytes, 2 * capacity);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity), nullptr, GL_DYNAMIC_DRAW);
    }
    if (bytes > 0) {
        glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data.data());
    }
}

// Declares float attribute `index` with `size` components at float offset `offset`.
void attribute(GLuint index, int size, int stride_floats, int offset, bool per_instance) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE,
                          static_cast<GLsizei>(stride_floats * sizeof(float)),
                          reinterpret_cast<const void*>(offset * sizeof(float)));
    glVertexAttribDivisor(index, per_instance ? 1 : 0);
}

void push(std::vector<float>& out, const Vec3& p) {
    out.push_back(static_cast<float>(p.x));
    out.push_back(static_cast<float>(p.y));
    out.push_back(static_cast<float>(p.z));
}

void push(std::vector<float>& out, const Color& c) {
    out.insert(out.end(), c.begin(), c.end());
}

}  // namespace

OverlayRenderer::~OverlayRenderer() {
    if (point_vao_ != 0) {
        const GLuint vaos[4] = {point_vao_, line_vao_, tri_vao_, arrow_vao_};
        const GLuint vbos[4] = {point_vbo_, line_vbo_, tri_vbo_, arrow_vbo_};
        glDeleteVertexArrays(4, vaos);
        glDeleteBuffers(4, vbos);
    }
}

void OverlayRenderer::ensure_gl_objects() {
    if (point_vao_ != 0) {
        return;
    }
    point_shader_ = ShaderProgram("overlay_point.vert", "overlay_point.frag");
    line_shader_ = ShaderProgram("overlay_line.vert", "overlay_line.frag");
    tri_shader_ = ShaderProgram("overlay_tri.vert", "overlay_tri.frag");
    arrow_shader_ = ShaderProgram("overlay_arrow.vert", "overlay_tri.frag");
    GLuint vaos[4];
    GLuint vbos[4];
    glGenVertexArrays(4, vaos);
    glGenBuffers(4, vbos);
    point_vao_ = vaos[0];
    line_vao_ = vaos[1];
    tri_vao_ = vaos[2];
    arrow_vao_ = vaos[3];
    point_vbo_ = vbos[0];
    line_vbo_ = vbos[1];
    tri_vbo_ = vbos[2];
    arrow_vbo_ = vbos[3];

    glBindVertexArray(point_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, point_vbo_);
    attribute(0, 3, kPointFloats, 0, true);
    attribute(1, 4, kPointFloats, 3, true);
    attribute(2, 1, kPointFloats, 7, true);

    glBindVertexArray(line_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, line_vbo_);
    attribute(0, 3, kLineFloats, 0, true);
    attribute(1, 3, kLineFloats, 3, true);
    attribute(2, 4, kLineFloats, 6, true);
    attribute(3, 1, kLineFloats, 10, true);

    glBindVertexArray(tri_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, tri_vbo_);
    attribute(0, 3, kTriangleVertexFloats, 0, false);
    attribute(1, 4, kTriangleVertexFloats, 3, false);

    glBindVertexArray(arrow_vao_);
    glBindBuffer(GL_ARRAY_BUFFER, arrow_vbo_);
    attribute(0, 3, kArrowheadFloats, 0, true);
    attribute(1, 3, kArrowheadFloats, 3, true);
    attribute(2, 3, kArrowheadFloats, 6, true);
    attribute(3, 4, kArrowheadFloats, 9, true);
    attribute(4, 2, kArrowheadFloats, 13, true);

    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    check_gl("OverlayRenderer setup");
}

void OverlayRenderer::upload(const OverlayBatch& batch) {
    const auto is_xray = [](const auto& item) { return item.xray; };
    if (std::none_of(batch.points.begin(), batch.points.end(), is_xray) &&
        std::none_of(batch.lines.begin(), batch.lines.end(), is_xray)) {
        upload_layer(batch);
        if (xray_) {
            xray_->upload_layer({});
        }
        return;
    }
    OverlayBatch surface = batch;
    OverlayBatch xray;
    std::erase_if(surface.points, is_xray);
    std::erase_if(surface.lines, is_xray);
    std::copy_if(batch.points.begin(), batch.points.end(), std::back_inserter(xray.points),
                 is_xray);
    std::copy_if(batch.lines.begin(), batch.lines.end(), std::back_inserter(xray.lines), is_xray);
    upload_layer(surface);
    if (!xray_) {
        xray_ = std::make_unique<OverlayRenderer>();
        xray_->depth_tested_ = false;
    }
    xray_->upload_layer(xray);
}

void OverlayRenderer::upload_layer(const OverlayBatch& batch) {
    ensure_gl_objects();
    points_.clear();
    lines_.clear();
    triangles_.clear();
    arrowheads_.clear();
    for (const auto& p : batch.points) {
        push(points_, p.p);
        push(points_, p.color);
        points_.push_back(p.size_px);
    }
    for (const auto& l : batch.lines) {
        push(lines_, l.a);
        push(lines_, l.b);
        push(lines_, l.color);
        lines_.push_back(l.width_px);
    }
    for (const auto& t : batch.triangles) {
        for (const Vec3* p : {&t.a, &t.b, &t.c}) {
            push(triangles_, *p);
            push(triangles_, t.color);
        }
    }
    for (const auto& a : batch.arrowheads) {
        push(arrowheads_, a.tip);
        push(arrowheads_, a.tail);
        push(arrowheads_, a.across);
        push(arrowheads_, a.color);
        arrowheads_.push_back(a.length_px);
        arrowheads_.push_back(a.half_width_px);
    }
    n_points_ = batch.points.size();
    n_lines_ = batch.lines.size();
    n_triangles_ = batch.triangles.size();
    n_arrowheads_ = batch.arrowheads.size();
    grow_and_upload(point_vbo_, point_capacity_, points_);
    grow_and_upload(line_vbo_, line_capacity_, lines_);
    grow_and_upload(tri_vbo_, tri_capacity_, triangles_);
    grow_and_upload(arrow_vbo_, arrow_capacity_, arrowheads_);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    check_gl("OverlayRenderer::upload");
}

void OverlayRenderer::draw(const Camera& camera, int width, int height, float depth_bias) {
    draw_layer(camera, width, height, depth_bias);
    if (xray_) {
        xray_->draw_layer(camera, width, height, depth_bias);
    }
}

void OverlayRenderer::draw_layer(const Camera& camera, int width, int height, float depth_bias) {
    if (n_points_ + n_lines_ + n_triangles_ + n_arrowheads_ == 0) {
        return;
    }
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const glm::mat4 view_projection = camera.projection(aspect) * camera.view();
    const float* vp = glm::value_ptr(view_projection);
    const float w = static_cast<float>(width);
    const float h = static_cast<float>(height);

    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    // Translucent overlays must not hide each other through the depth buffer.
    glDepthMask(GL_FALSE);

    // Every overlay shader takes the same uniforms (the triangles' ignores the viewport and
    // the alpha).
    float alpha = 1.0f;
    const auto use = [&](const ShaderProgram& shader, unsigned vao) {
        shader.use();
        shader.set_mat4("u_view_projection", vp);
        shader.set_vec2("u_viewport", w, h);
        shader.set_float("u_depth_bias", depth_bias);
        shader.set_float("u_alpha", alpha);
        glBindVertexArray(vao);
    };
    // The x-ray layer draws twice: where the surface does not hide it, then faded where it
    // does (as Blender shows hidden marks).
    glDepthFunc(GL_LEQUAL);
    draw_primitives(use);
    if (!depth_tested_) {
        glDepthFunc(GL_GREATER);
        alpha = kHiddenAlpha;
        draw_primitives(use);
    }
    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDepthFunc(GL_LESS);
}

template <typename Use>
void OverlayRenderer::draw_primitives(const Use& use) {
    // Order: face tints, then lines, arrowheads over their shafts, then discs on top.
    if (n_triangles_ > 0) {
        use(tri_shader_, tri_vao_);
        glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * n_triangles_));
    }
    if (n_lines_ > 0) {
        use(line_shader_, line_vao_);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(n_lines_));
    }
    if (n_arrowheads_ > 0) {
        use(arrow_shader_, arrow_vao_);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, static_cast<GLsizei>(n_arrowheads_));
    }
    if (n_points_ > 0) {
        use(point_shader_, point_vao_);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(n_points_));
    }
}

BackgroundRenderer::~BackgroundRenderer() {
    if (vao_ != 0) {
        glDeleteVertexArrays(1, &vao_);
    }
}

void BackgroundRenderer::draw(const float top[3], const float bottom[3]) {
    if (vao_ == 0) {
        shader_ = ShaderProgram("background.vert", "background.frag");
        glGenVertexArrays(1, &vao_);  // core profile draws need a bound VAO, even empty
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    shader_.use();
    shader_.set_vec3("u_top", top);
    shader_.set_vec3("u_bottom", bottom);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace meshedit
