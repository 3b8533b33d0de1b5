// Mesh drawing, wireframe and the ID pass (mesh_renderer.h).

#include "meshedit/render/mesh_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "gl.h"
#include "mesh_gpu.h"
#include "meshedit/core/display_fan.h"
#include "meshedit/core/normals.h"
#include "meshedit/render/user_shaders.h"

namespace meshedit {
namespace {

void set_camera(const ShaderProgram& shader, const Camera& camera, float aspect) {
    const glm::mat4 view = camera.view();
    const glm::mat4 projection = camera.projection(aspect);
    shader.set_mat4("u_view", glm::value_ptr(view));
    shader.set_mat4("u_projection", glm::value_ptr(projection));
}

}  // namespace

MeshRenderer::~MeshRenderer() {
    // Deleting 0 is a no-op in GL, so a renderer that never uploaded needs no context.
    if (vao_ != 0) {
        glDeleteVertexArrays(1, &vao_);
        glDeleteBuffers(1, &vbo_);
        glDeleteBuffers(1, &color_vbo_);
        glDeleteBuffers(1, &side_color_vbo_);
        glDeleteBuffers(1, &surface_vbo_);
        glDeleteTextures(1, &texture_array_);
        glDeleteTextures(1, &env_texture_);
        glDeleteTextures(1, &env_cube_);
        glDeleteBuffers(1, &pick_tbo_buffer_);
        glDeleteTextures(1, &pick_tbo_texture_);
    }
}

void MeshRenderer::ensure_gl_objects() {
    if (vao_ != 0) {
        return;
    }
    pick_shader_ = ShaderProgram("pick.vert", "pick.frag");
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    constexpr GLsizei stride = sizeof(MeshGpuVertex);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offsetof(MeshGpuVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_INT_2_10_10_10_REV, GL_TRUE, stride,
                          reinterpret_cast<const void*>(offsetof(MeshGpuVertex, smooth_normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_INT_2_10_10_10_REV, GL_TRUE, stride,
                          reinterpret_cast<const void*>(offsetof(MeshGpuVertex, flat_normal)));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                          reinterpret_cast<const void*>(offsetof(MeshGpuVertex, corner)));
    // The field colours: their own buffer, bound only while a field is shown.
    glGenBuffers(1, &color_vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, color_vbo_);
    glVertexAttribPointer(4, 4, GL_UNSIGNED_BYTE, GL_TRUE, 4, nullptr);
    // An edge field's three side colours per corner.
    glGenBuffers(1, &side_color_vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, side_color_vbo_);
    for (GLuint k = 0; k < 3; ++k) {
        glVertexAttribPointer(5 + k, 4, GL_UNSIGNED_BYTE, GL_TRUE, 12,
                              reinterpret_cast<const void*>(static_cast<std::uintptr_t>(4 * k)));
    }
    // Texture coordinates, colours, material colour and texture layer: bound when the mesh
    // has any (mesh_surface.cpp).
    glGenBuffers(1, &surface_vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, surface_vbo_);
    constexpr GLsizei surface_stride = sizeof(SurfaceCorner);
    glVertexAttribPointer(8, 2, GL_FLOAT, GL_FALSE, surface_stride,
                          reinterpret_cast<const void*>(offsetof(SurfaceCorner, uv)));
    glVertexAttribPointer(9, 4, GL_UNSIGNED_BYTE, GL_TRUE, surface_stride,
                          reinterpret_cast<const void*>(offsetof(SurfaceCorner, colour)));
    glVertexAttribPointer(10, 4, GL_UNSIGNED_BYTE, GL_TRUE, surface_stride,
                          reinterpret_cast<const void*>(offsetof(SurfaceCorner, material)));
    glVertexAttribPointer(11, 1, GL_FLOAT, GL_FALSE, surface_stride,
                          reinterpret_cast<const void*>(offsetof(SurfaceCorner, layer)));
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBindVertexArray(0);

    glGenBuffers(1, &pick_tbo_buffer_);
    glGenTextures(1, &pick_tbo_texture_);
    check_gl("MeshRenderer setup");
}

void MeshRenderer::upload(const Mesh& mesh) {
    ensure_gl_objects();
    has_field_ = has_edge_field_ = false;

    // Fan-triangulate every face: (c0, ci, ci+1). A triangle side is a real mesh edge only
    // for the first and last fan triangle's outer sides; the rest are diagonals, which the
    // wireframe must not draw and picking must not report.
    triangle_corners_.clear();
    corner_halfedges_.clear();
    triangle_faces_.clear();
    pick_table_.clear();
    face_first_.assign(mesh.faces_size(), 0);
    face_slots_.assign(mesh.faces_size(), 0);
    for (Face f : mesh.faces()) {
        face_first_[f.idx()] = static_cast<std::uint32_t>(triangle_faces_.size());
        face_slots_[f.idx()] = static_cast<std::uint32_t>(mesh.valence(f) - 2);
        append_fan(mesh, f);
    }
    triangle_count_ = live_triangles_ = triangle_faces_.size();
    fill_geometry(mesh);
    fill_surface(mesh);

    glBindBuffer(GL_TEXTURE_BUFFER, pick_tbo_buffer_);
    upload_buffer(GL_TEXTURE_BUFFER, pick_capacity_, pick_table_.data(),
                  pick_table_.size() * sizeof(std::uint32_t));
    glBindTexture(GL_TEXTURE_BUFFER, pick_tbo_texture_);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32UI, pick_tbo_buffer_);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    check_gl("MeshRenderer::upload");
}

void MeshRenderer::update_geometry(const Mesh& mesh) {
    ensure_gl_objects();
    fill_geometry(mesh);
    check_gl("MeshRenderer::update_geometry");
}

void MeshRenderer::fill_geometry(const Mesh& mesh) {
    // Room for the vertices edits add (as the GPU buffers have, mesh_gpu.h): growing this
    // array after loading 10M faces copied it whole on the first split.
    vertex_normals_.reserve(mesh.vertices_size() + mesh.vertices_size() / 16);
    face_normals_.reserve(mesh.faces_size() + mesh.faces_size() / 16);
    compute_vertex_normals(mesh, vertex_normals_);
    normals_sizes_ = {mesh.vertices_size(), mesh.faces_size()};
    compute_face_normals(mesh, face_normals_);
    split_normals_ = compute_corner_normals(mesh, normal_split_, vertex_normals_, corner_normals_);
    vertices_.resize(3 * triangle_count_);
    bounds_ = {};
    for (Vertex v : mesh.vertices()) {
        bounds_.add(mesh.position(v));
    }
    closed_and_outward_ = is_closed_and_outward(mesh);
    for (std::size_t t = 0; t < triangle_count_; ++t) {
        write_gpu_triangle(mesh, t);
    }
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    upload_buffer(GL_ARRAY_BUFFER, vbo_capacity_, vertices_.data(),
                  vertices_.size() * sizeof(MeshGpuVertex));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void MeshRenderer::write_gpu_triangle(const Mesh& mesh, std::size_t t) {
    const bool split = split_normals_;
    {
        const std::uint32_t face = triangle_faces_[t];  // invalid in an emptied slot
        const std::uint32_t flat =
            face < face_normals_.size() ? pack_normal(face_normals_[face]) : 0u;
        // Mask bit k: the side opposite corner k is a real edge. Side c1->c2 is opposite
        // corner 0, c2->c0 opposite 1, c0->c1 opposite 2.
        const std::uint32_t* sides = &pick_table_[8 * t + 4];
        const std::uint8_t mask = static_cast<std::uint8_t>((sides[1] != kInvalidIndex ? 1 : 0) |
                                                            (sides[2] != kInvalidIndex ? 2 : 0) |
                                                            (sides[0] != kInvalidIndex ? 4 : 0));
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = triangle_corners_[3 * t + static_cast<std::size_t>(k)];
            const Vec3& p = mesh.position(Vertex(v));
            MeshGpuVertex& out = vertices_[3 * t + static_cast<std::size_t>(k)];
            out.position[0] = static_cast<float>(p.x);
            out.position[1] = static_cast<float>(p.y);
            out.position[2] = static_cast<float>(p.z);
            out.smooth_normal = pack_normal(
                split ? corner_normals_[corner_halfedges_[3 * t + static_cast<std::size_t>(k)]]
                      : vertex_normals_[v]);
            out.flat_normal = flat;
            out.corner[0] = k == 0 ? 255 : 0;
            out.corner[1] = k == 1 ? 255 : 0;
            out.corner[2] = k == 2 ? 255 : 0;
            out.corner[3] = mask;
        }
    }
}

void MeshRenderer::draw(const Camera& camera, float aspect, const RenderOptions& options) {
    if (triangle_count_ == 0) {
        return;
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    set_culling(camera);  // open meshes show their back side (shaded two-sided)
    const ShaderProgram& shader = shaded_program(options.shading, options.wireframe);
    shader.use();
    set_camera(shader, camera, aspect);
    shader.set_int("u_smooth", options.smooth ? 1 : 0);
    shader.set_vec3("u_base_color", options.base_color.data());
    shader.set_int("u_field", has_field_ ? 1 : 0);
    if (options.shading >= 7) {
        if (env_texture_ == 0) {
            set_environment(default_environment());
        }
        glActiveTexture(GL_TEXTURE1);  // unit 1, as in the CS184 skeleton (user shaders)
        glBindTexture(GL_TEXTURE_2D, env_texture_);
        glActiveTexture(GL_TEXTURE2);  // mode 7's cube
        glBindTexture(GL_TEXTURE_CUBE_MAP, env_cube_);
        glActiveTexture(GL_TEXTURE0);
        shader.set_int("u_envmap", 1);
        shader.set_int("u_envcube", 2);
        shader.set_float("u_exposure", options.exposure);
    }
    shader.set_float("u_time", options.time_s);
    shader.set_int("u_has_selection", options.has_selection ? 1 : 0);
    shader.set_vec3("u_selection", options.selection.data());
    shader.set_int("u_edge_field", has_edge_field_ ? 1 : 0);
    shader.set_float("u_wire_width", options.wire_width_px);
    shader.set_vec4("u_wire_color", options.wire_color.data());
    shader.set_float("u_ambient", options.phong.ambient);
    shader.set_float("u_diffuse", options.phong.diffuse);
    shader.set_float("u_specular", options.phong.specular);
    shader.set_float("u_shininess", options.phong.shininess);
    shader.set_vec3("u_light_dir", options.phong.light_dir.data());
    shader.set_vec3("u_light_color", options.phong.light_color.data());
    // Depth mode: the scene sphere's near and far view distances.
    const float d = glm::length(camera.eye() - camera.target);
    shader.set_vec2("u_depth_range", std::max(d - camera.scene_radius, 0.0f),
                    d + camera.scene_radius);
    glBindVertexArray(vao_);
    for (GLuint k = 4; k < 8; ++k) {
        const bool on = k == 4 ? has_field_ : has_edge_field_;
        if (on) {
            glEnableVertexAttribArray(k);
        } else {
            glDisableVertexAttribArray(k);
        }
    }
    bind_surface(shader, options.color);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * triangle_count_));
    glBindVertexArray(0);
    glDisable(GL_CULL_FACE);
}

void MeshRenderer::set_environment(const EnvironmentImage& image) {
    if (env_texture_ == 0) {
        glGenTextures(1, &env_texture_);
    }
    glBindTexture(GL_TEXTURE_2D, env_texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16F, image.width, image.height, 0, GL_RGB, GL_FLOAT,
                 image.rgb.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);  // around in θ
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    // Mode 7 samples a cube map made from it (environment.h), filtered across the faces.
    if (env_cube_ == 0) {
        glGenTextures(1, &env_cube_);
    }
    const int size = std::clamp(image.width / 4, 16, 2048);
    const std::vector<std::vector<float>> faces = cube_faces(image, size);
    glBindTexture(GL_TEXTURE_CUBE_MAP, env_cube_);
    for (GLenum face = 0; face < 6; ++face) {
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGB16F, size, size, 0, GL_RGB,
                     GL_FLOAT, faces[face].data());
    }
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    check_gl("MeshRenderer::set_environment");
}

void MeshRenderer::set_field(FieldSite site, std::span<const double> values,
                             const FieldColoring& coloring) {
    ensure_gl_objects();
    const auto pack = [](const Color& c) {
        const auto byte = [](float x) {
            return static_cast<std::uint32_t>(std::lround(255.0f * std::clamp(x, 0.0f, 1.0f)));
        };
        return byte(c[0]) | byte(c[1]) << 8 | byte(c[2]) << 16 | 255u << 24;
    };
    const std::uint32_t neutral = pack({0.78f, 0.78f, 0.8f, 1.0f});
    corner_colors_.assign(3 * triangle_count_, neutral);
    for (std::size_t t = 0; t < triangle_count_; ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            if (site == FieldSite::Vertex) {
                const std::uint32_t v = triangle_corners_[3 * t + k];
                corner_colors_[3 * t + k] =
                    pack(coloring.color_of(v < values.size() ? values[v] : NAN));
            } else if (site == FieldSite::Face) {
                const std::uint32_t f = triangle_faces_[t];
                corner_colors_[3 * t + k] =
                    pack(coloring.color_of(f < values.size() ? values[f] : NAN));
            }
        }
    }
    glBindBuffer(GL_ARRAY_BUFFER, color_vbo_);
    upload_buffer(GL_ARRAY_BUFFER, color_capacity_, corner_colors_.data(),
                  corner_colors_.size() * sizeof(std::uint32_t));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    has_field_ = true;
    has_edge_field_ = site == FieldSite::Edge;
    if (has_edge_field_) {
        // Side k is opposite corner k: c1->c2 (pick table slot 1), c2->c0 (2), c0->c1 (0).
        side_colors_.assign(9 * triangle_count_, neutral);
        for (std::size_t t = 0; t < triangle_count_; ++t) {
            const std::uint32_t* sides = &pick_table_[8 * t + 4];
            const std::uint32_t opposite[3] = {sides[1], sides[2], sides[0]};
            for (std::size_t k = 0; k < 3; ++k) {
                if (opposite[k] == kInvalidIndex) {
                    continue;
                }
                const std::uint32_t e = opposite[k] >> 1;
                const std::uint32_t color =
                    pack(coloring.color_of(e < values.size() ? values[e] : NAN));
                for (std::size_t corner = 0; corner < 3; ++corner) {
                    side_colors_[9 * t + 3 * corner + k] = color;
                }
            }
        }
        glBindBuffer(GL_ARRAY_BUFFER, side_color_vbo_);
        upload_buffer(GL_ARRAY_BUFFER, side_color_capacity_, side_colors_.data(),
                      side_colors_.size() * sizeof(std::uint32_t));
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }
    check_gl("MeshRenderer::set_field");
}

namespace {

std::string defines_of(int mode, bool wireframe) {
    return "#define MESHEDIT_MODE " + std::to_string(mode) + "\n#define MESHEDIT_WIREFRAME " +
           (wireframe ? "1" : "0") + "\n";
}

}  // namespace

// The program of slot (mode, wireframe), built from disk: the user's file for 8 and 9.
ShaderProgram MeshRenderer::build_program(int mode, bool wireframe) const {
    if (mode >= 8) {
        return ShaderProgram::from_files(shader_directory() / "mesh.vert",
                                         user_shader_path(user_shader_dir_, mode),
                                         defines_of(mode, wireframe));
    }
    return ShaderProgram("mesh.vert", "mesh.frag", defines_of(mode, wireframe));
}

const ShaderProgram& MeshRenderer::shaded_program(int mode, bool wireframe) {
    mode = std::clamp(mode, 0, static_cast<int>(kShadingModes.size()) - 1);
    if (mode >= 8 && user_shader_dir_.empty()) {
        mode = 1;  // no user folder: 8 and 9 draw as 1
    }
    ShaderProgram& program = shaded_programs_[static_cast<std::size_t>(2 * mode + wireframe)];
    if (!program.is_valid()) {
        if (mode < 8) {
            program = build_program(mode, wireframe);
        } else {
            try {
                program = build_program(mode, wireframe);
                user_shader_error_.clear();
            } catch (const GlError& e) {
                user_shader_error_ = e.what();  // drawn as mode 1 until it compiles
                return shaded_program(1, wireframe);
            }
        }
    }
    return program;
}

void MeshRenderer::set_user_shader_dir(const std::filesystem::path& dir) {
    user_shader_dir_ = dir;
    user_shader_error_.clear();
    for (const int mode : {8, 9}) {
        for (const int wire : {0, 1}) {
            shaded_programs_[static_cast<std::size_t>(2 * mode + wire)] = ShaderProgram();
        }
    }
}

std::string MeshRenderer::reload_shaders() {
    std::string errors;
    for (int mode = 0; mode < static_cast<int>(kShadingModes.size()); ++mode) {
        for (const bool wire : {false, true}) {
            ShaderProgram& program = shaded_programs_[static_cast<std::size_t>(2 * mode + wire)];
            const bool user = mode >= 8 && !user_shader_dir_.empty();
            if (!program.is_valid() && !user) {
                continue;  // never used: compiled when first drawn
            }
            if (user && wire) {
                continue;  // the same file as without the wireframe: one message is enough
            }
            try {
                program = build_program(mode, wire);
                if (user) {
                    shaded_programs_[static_cast<std::size_t>(2 * mode + 1)] = ShaderProgram();
                }
            } catch (const GlError& e) {
                errors += std::string(errors.empty() ? "" : "\n") + e.what();
            }
        }
    }
    user_shader_error_.clear();
    return errors;
}

bool MeshRenderer::culls_back_faces(const Camera& camera) const {
    return back_faces_hidden(camera, closed_and_outward_, bounds_);
}

void MeshRenderer::set_culling(const Camera& camera) const {
    if (culls_back_faces(camera)) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(GL_CCW);
    } else {
        glDisable(GL_CULL_FACE);
    }
}

void MeshRenderer::draw_bare(const Camera& camera, float aspect, bool cull_back_faces) {
    if (triangle_count_ == 0) {
        return;
    }
    if (!bare_shader_.is_valid()) {
        bare_shader_ = ShaderProgram("bare.vert", "bare.frag");
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    if (cull_back_faces) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(GL_CCW);
    } else {
        glDisable(GL_CULL_FACE);
    }
    bare_shader_.use();
    set_camera(bare_shader_, camera, aspect);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * triangle_count_));
    glBindVertexArray(0);
    glDisable(GL_CULL_FACE);
}

void MeshRenderer::draw_ids(const Camera& camera, float aspect, float vertex_radius_px,
                            float edge_radius_px) {
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (triangle_count_ == 0) {
        return;
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    set_culling(camera);
    pick_shader_.use();
    set_camera(pick_shader_, camera, aspect);
    pick_shader_.set_float("u_vertex_radius", vertex_radius_px);
    pick_shader_.set_float("u_edge_radius", edge_radius_px);
    pick_shader_.set_float("u_halfedge_band", 0.15f);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_BUFFER, pick_tbo_texture_);
    pick_shader_.set_int("u_table", 0);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * triangle_count_));
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glDisable(GL_CULL_FACE);
}

ElementRef MeshRenderer::decode_id(const std::uint8_t* rgba) {
    const std::uint32_t index =
        (std::uint32_t{rgba[0]} << 16) | (std::uint32_t{rgba[1]} << 8) | std::uint32_t{rgba[2]};
    switch (rgba[3]) {
        case 1:
            return ElementRef::vertex(Vertex(index));
        case 2:
            return ElementRef::edge(Edge(index));
        case 3:
            return ElementRef::halfedge(Halfedge(index));
        case 4:
            return ElementRef::face(Face(index));
        default:
            return {};
    }
}

ElementRef MeshRenderer::pick(const Camera& camera, int width, int height, int x, int y,
                              float vertex_radius_px, float edge_radius_px) {
    if (x < 0 || y < 0 || x >= width || y >= height) {
        return {};
    }
    // Only the pixel under the cursor is shaded (scissor): on a million triangles the pass
    // costs the vertex work alone.
    const int row = height - 1 - y;
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, row, 1, 1);
    draw_ids(camera, static_cast<float>(width) / static_cast<float>(height), vertex_radius_px,
             edge_radius_px);
    glDisable(GL_SCISSOR_TEST);
    std::uint8_t rgba[4] = {0, 0, 0, 0};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, row, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    check_gl("MeshRenderer::pick");
    return decode_id(rgba);
}

}  // namespace meshedit
