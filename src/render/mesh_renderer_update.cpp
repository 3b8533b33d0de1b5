// The mesh renderer's staging of face fans, and its update after a local edit (mesh_renderer.h):
// what a flip on a million faces sends to the GPU is the few triangles around it.

#include <algorithm>
#include <utility>
#include <vector>

#include "gl.h"
#include "mesh_gpu.h"
#include "meshedit/core/display_fan.h"
#include "meshedit/core/normals.h"
#include "meshedit/render/mesh_renderer.h"

namespace meshedit {

void MeshRenderer::append_fan(const Mesh& mesh, Face f) {
    // Fan-triangulate: (c0, ci, ci+1). A triangle side is a real mesh edge only for the first
    // and last fan triangle's outer sides; the rest are diagonals, which the wireframe must not
    // draw and picking must not report.
    const Halfedge h0 = mesh.halfedge(f);
    const std::size_t n = mesh.valence(f);
    for_each_fan_triangle(mesh, f, [&](std::size_t i, Vertex c0, Halfedge h) {
        triangle_corners_.insert(triangle_corners_.end(),
                                 {c0.idx(), mesh.from_vertex(h).idx(), mesh.to_vertex(h).idx()});
        corner_halfedges_.insert(corner_halfedges_.end(),
                                 {mesh.prev(h0).idx(), mesh.prev(h).idx(), h.idx()});
        triangle_faces_.push_back(f.idx());
        // Halfedges c0->c1, c1->c2, c2->c0 of this fan triangle.
        const std::uint32_t side0 = i == 1 ? h0.idx() : kInvalidIndex;
        const std::uint32_t side1 = h.idx();
        const std::uint32_t side2 = i + 2 == n ? mesh.next(h).idx() : kInvalidIndex;
        pick_table_.insert(pick_table_.end(), {f.idx(), c0.idx(), mesh.from_vertex(h).idx(),
                                               mesh.to_vertex(h).idx(), side0, side1, side2, 0u});
    });
}

void MeshRenderer::write_fan(const Mesh& mesh, Face f, std::size_t first, std::size_t slots) {
    // Built where append_fan() builds it, then copied into the slot.
    const std::size_t end = triangle_faces_.size();
    const bool live = f.idx() < mesh.faces_size() && !mesh.is_deleted(f);
    if (live) {
        append_fan(mesh, f);
    }
    const std::size_t made = triangle_faces_.size() - end;
    for (std::size_t i = 0; i < slots; ++i) {
        const std::size_t t = first + i;
        if (i < made) {
            const std::size_t s = end + i;
            std::copy_n(&triangle_corners_[3 * s], 3, &triangle_corners_[3 * t]);
            std::copy_n(&corner_halfedges_[3 * s], 3, &corner_halfedges_[3 * t]);
            triangle_faces_[t] = triangle_faces_[s];
            std::copy_n(&pick_table_[8 * s], 8, &pick_table_[8 * t]);
        } else {
            // Degenerate: one corner three times draws nothing and is never picked.
            const std::uint32_t c = made > 0 ? triangle_corners_[3 * end] : 0;
            std::fill_n(&triangle_corners_[3 * t], 3, c);
            std::fill_n(&corner_halfedges_[3 * t], 3, 0u);
            const std::uint32_t row[8] = {f.idx(),       c, c, c, kInvalidIndex, kInvalidIndex,
                                          kInvalidIndex, 0u};
            std::copy_n(row, 8, &pick_table_[8 * t]);
            triangle_faces_[t] = f.idx();
        }
    }
    triangle_corners_.resize(3 * end);
    corner_halfedges_.resize(3 * end);
    triangle_faces_.resize(end);
    pick_table_.resize(8 * end);
}

namespace {

// Sends triangles [first, last) of a staging array (`per` elements of T each) to `buffer`.
template <class T>
void send(GLenum target, unsigned buffer, const memory::PodArray<T>& data, std::size_t per,
          std::size_t first, std::size_t last) {
    glBindBuffer(target, buffer);
    glBufferSubData(target, static_cast<GLintptr>(first * per * sizeof(T)),
                    static_cast<GLsizeiptr>((last - first) * per * sizeof(T)),
                    data.data() + first * per);
    glBindBuffer(target, 0);
}

}  // namespace

bool MeshRenderer::update(const Mesh& mesh, std::span<const Face> faces,
                          std::span<const Vertex> vertices) {
    if (vao_ == 0 || split_normals_ || mesh.vertices_size() == 0) {
        upload(mesh);
        return false;
    }
    has_field_ = has_edge_field_ = false;

    // Normals: around the region, and the faces to redraw: the region's and those around
    // every vertex whose normal was summed again.
    std::vector<Vertex> recomputed;
    update_vertex_normals(mesh, faces, vertices, normals_sizes_.first, normals_sizes_.second,
                          vertex_normals_, recomputed);
    normals_sizes_ = {mesh.vertices_size(), mesh.faces_size()};
    std::vector<Face> redraw(faces.begin(), faces.end());
    bool near_boundary = !closed_and_outward_;
    for (const Vertex v : recomputed) {
        if (!mesh.is_deleted(v) && !mesh.is_isolated(v)) {
            near_boundary = near_boundary || mesh.is_boundary(v);
            bounds_.add(mesh.position(v));
            for (const Face f : mesh.faces(v)) {
                redraw.push_back(f);
            }
        }
    }
    std::sort(redraw.begin(), redraw.end());
    redraw.erase(std::unique(redraw.begin(), redraw.end()), redraw.end());
    face_normals_.resize(mesh.faces_size());

    // Slots: in place where the fan still fits, at the end where it grew or is new; a face
    // gone (deleted, or undone past its creation) leaves its slot degenerate.
    face_first_.resize(std::max(face_first_.size(), mesh.faces_size()), 0);
    face_slots_.resize(face_first_.size(), 0);
    std::vector<std::pair<std::size_t, std::size_t>> written;  // triangle ranges
    for (const Face f : redraw) {
        if (f.idx() >= face_first_.size()) {
            continue;
        }
        const bool live = f.idx() < mesh.faces_size() && !mesh.is_deleted(f);
        const std::size_t need = live ? mesh.valence(f) - 2 : 0;
        if (live) {
            face_normals_[f.idx()] = face_normal(mesh, f);
        }
        std::size_t first = face_first_[f.idx()];
        std::size_t slots = face_slots_[f.idx()];
        for (std::size_t t = first; t < first + slots; ++t) {  // live before: not degenerate
            const std::uint32_t* c = &triangle_corners_[3 * t];
            live_triangles_ -= c[0] != c[1] || c[1] != c[2] ? 1 : 0;
        }
        live_triangles_ += need;
        if (need > slots) {
            if (slots > 0) {
                write_fan(mesh, Face(kInvalidIndex), first, slots);  // the old slot: nothing
                written.emplace_back(first, first + slots);
            }
            first = triangle_count_;
            slots = need;
            triangle_count_ += need;
            triangle_corners_.resize(3 * triangle_count_);
            corner_halfedges_.resize(3 * triangle_count_);
            triangle_faces_.resize(triangle_count_);
            pick_table_.resize(8 * triangle_count_);
            face_first_[f.idx()] = static_cast<std::uint32_t>(first);
            face_slots_[f.idx()] = static_cast<std::uint32_t>(slots);
        }
        if (slots > 0) {
            write_fan(mesh, f, first, slots);
            written.emplace_back(first, first + slots);
        }
    }
    face_first_.resize(mesh.faces_size());
    face_slots_.resize(mesh.faces_size());
    vertices_.resize(3 * triangle_count_);
    const bool surface = !surface_.empty();
    const SurfaceSources sources = surface ? surface_sources(mesh) : SurfaceSources{};
    surface_.resize(surface ? 3 * triangle_count_ : 0);
    for (const auto& [first, last] : written) {
        for (std::size_t t = first; t < last; ++t) {
            write_gpu_triangle(mesh, t);
            if (surface) {
                write_surface_triangle(mesh, sources, t);
            }
        }
    }
    if (near_boundary) {
        // An open mesh may have closed, a closed one opened: O(mesh), only then.
        closed_and_outward_ = is_closed_and_outward(mesh);
    }

    // To the GPU: everything when the buffers had to grow, else the ranges written.
    const std::size_t vertex_bytes = vertices_.size() * sizeof(MeshGpuVertex);
    const std::size_t pick_bytes = pick_table_.size() * sizeof(std::uint32_t);
    const std::size_t surface_bytes = surface_.size() * sizeof(SurfaceCorner);
    if (vertex_bytes > vbo_capacity_ || pick_bytes > pick_capacity_ ||
        surface_bytes > surface_capacity_) {
        glBindBuffer(GL_ARRAY_BUFFER, vbo_);
        upload_buffer(GL_ARRAY_BUFFER, vbo_capacity_, vertices_.data(), vertex_bytes);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glBindBuffer(GL_TEXTURE_BUFFER, pick_tbo_buffer_);
        upload_buffer(GL_TEXTURE_BUFFER, pick_capacity_, pick_table_.data(), pick_bytes);
        glBindTexture(GL_TEXTURE_BUFFER, pick_tbo_texture_);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32UI, pick_tbo_buffer_);
        glBindTexture(GL_TEXTURE_BUFFER, 0);
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
        if (surface) {
            glBindBuffer(GL_ARRAY_BUFFER, surface_vbo_);
            upload_buffer(GL_ARRAY_BUFFER, surface_capacity_, surface_.data(), surface_bytes);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
        }
    } else {
        std::sort(written.begin(), written.end());
        for (std::size_t i = 0; i < written.size();) {
            std::size_t j = i + 1;
            std::size_t last = written[i].second;
            while (j < written.size() && written[j].first <= last) {  // merge touching ranges
                last = std::max(last, written[j].second);
                ++j;
            }
            send(GL_ARRAY_BUFFER, vbo_, vertices_, 3, written[i].first, last);
            send(GL_TEXTURE_BUFFER, pick_tbo_buffer_, pick_table_, 8, written[i].first, last);
            if (surface) {
                send(GL_ARRAY_BUFFER, surface_vbo_, surface_, 3, written[i].first, last);
            }
            i = j;
        }
    }
    check_gl("MeshRenderer::update");
    return true;
}

}  // namespace meshedit
