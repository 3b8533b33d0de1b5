// glTF 2.0 through tinygltf (its implementation is compiled in tinygltf_impl.cpp).
//
// Reading walks the default scene's node tree, applies each node's transform, and turns every
// triangle primitive (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN) into soup faces. Every accessor
// read is bounds-checked here rather than trusted to the loader, since a hostile file may
// point anywhere. COLOR_0 is kept per vertex, TEXCOORD_0 and NORMAL per corner, materials
// per face (their name, base colour and base-colour texture path). Writing: gltf_write.cpp.

#include "meshedit/io/gltf.h"

#include <tiny_gltf.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

#include "gltf_guard.h"
#include "gltf_images.h"
#include "gltf_meshopt.h"
#include "io_util.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/normals.h"

namespace meshedit {
namespace {

/// External buffer files larger than this are refused (tinygltf reads them whole).
constexpr std::size_t kMaxBufferFileBytes = std::size_t{1} << 32;

/// Column-major 4×4 matrix, as glTF stores them.
using Mat4 = std::array<double, 16>;

constexpr Mat4 kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Mat4 multiply(const Mat4& a, const Mat4& b) {
    Mat4 r{};
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) {
            double s = 0.0;
            for (int k = 0; k < 4; ++k) {
                s += a[k * 4 + row] * b[col * 4 + k];
            }
            r[col * 4 + row] = s;
        }
    }
    return r;
}

Vec3 transform_point(const Mat4& m, const Vec3& p) {
    return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12],
            m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
            m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
}

Vec3 column(const Mat4& m, int c) {
    return {m[c * 4], m[c * 4 + 1], m[c * 4 + 2]};
}

double determinant3(const Mat4& m) {
    return dot(column(m, 0), cross(column(m, 1), column(m, 2)));
}

/// Normals transform by the inverse transpose of the linear part; its rows are the cross
/// products of the columns (the cofactor matrix, a positive multiple for det > 0).
Vec3 transform_normal(const Mat4& m, const Vec3& n) {
    const Vec3 c0 = column(m, 0), c1 = column(m, 1), c2 = column(m, 2);
    const Vec3 r0 = cross(c1, c2), r1 = cross(c2, c0), r2 = cross(c0, c1);
    const Vec3 t = r0 * n.x + r1 * n.y + r2 * n.z;
    return normalize(determinant3(m) < 0 ? -t : t);
}

Mat4 local_matrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        Mat4 m;
        std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
        return m;
    }
    Mat4 t = kIdentity, r = kIdentity, s = kIdentity;
    if (node.translation.size() == 3) {
        t[12] = node.translation[0];
        t[13] = node.translation[1];
        t[14] = node.translation[2];
    }
    if (node.rotation.size() == 4) {
        const double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2],
                     w = node.rotation[3];
        r = {1 - 2 * (y * y + z * z),
             2 * (x * y + z * w),
             2 * (x * z - y * w),
             0,
             2 * (x * y - z * w),
             1 - 2 * (x * x + z * z),
             2 * (y * z + x * w),
             0,
             2 * (x * z + y * w),
             2 * (y * z - x * w),
             1 - 2 * (x * x + y * y),
             0,
             0,
             0,
             0,
             1};
    }
    if (node.scale.size() == 3) {
        s[0] = node.scale[0];
        s[5] = node.scale[1];
        s[10] = node.scale[2];
    }
    return multiply(t, multiply(r, s));  // glTF: T * R * S
}

class GltfReader {
public:
    GltfReader(const tinygltf::Model& model, std::string file, std::filesystem::path folder,
               gltf_images::Embedded embedded)
        : model_(model),
          file_(std::move(file)),
          folder_(std::move(folder)),
          embedded_(std::move(embedded)) {}

    MeshSoup read() {
        const auto& scenes = model_.scenes;
        if (!scenes.empty()) {
            const std::size_t s =
                model_.defaultScene >= 0 &&
                        static_cast<std::size_t>(model_.defaultScene) < scenes.size()
                    ? static_cast<std::size_t>(model_.defaultScene)
                    : 0;
            visit_scene(scenes[s]);
        } else {
            // A file with no scene shows nothing by the letter of the spec; loading its meshes
            // as they are is more useful, and said.
            for (std::size_t m = 0; m < model_.meshes.size(); ++m) {
                add_mesh(static_cast<int>(m), kIdentity);
            }
            out_.notices.push_back("the file has no scene; loaded every mesh untransformed");
        }
        if (skipped_primitives_ > 0) {
            out_.notices.push_back("ignored " + std::to_string(skipped_primitives_) +
                                   " point or line primitive(s)");
        }
        if (!all_have_normals_) {
            out_.normals.clear();
        }
        // TEXCOORD_0 and TEXCOORD_1, each kept when every primitive has it.
        std::vector<Vec2>* corner_sets[kTexcoordSets] = {&out_.corner_texcoords,
                                                         &out_.corner_texcoords1};
        bool texcoords = false;
        for (std::size_t set = 0; set < kTexcoordSets; ++set) {
            if (all_have_texcoords_[set] && texcoords_[set].size() == out_.soup.positions.size()) {
                texcoords = true;
                corner_sets[set]->reserve(out_.soup.indices.size());
                for (const std::uint32_t v : out_.soup.indices) {
                    corner_sets[set]->push_back(texcoords_[set][v]);
                }
            }
        }
        if (all_have_colours_ && colours_.size() == out_.soup.positions.size()) {
            out_.colors = std::move(colours_);
        }
        weld_seams(texcoords);
        keep_materials();
        return std::move(out_);
    }

private:
    // Depth-first, children in order (the order decides vertex numbers), with an explicit
    // stack: a chain of 20,000 nodes must not overflow the call stack. The spec requires the
    // node graph to be a set of trees, so a node reached twice (two parents, a cycle, a root
    // listed twice) is refused; that also bounds the walk to one visit per node, where a
    // graph listing the same child twice at every level would otherwise expand to 2^depth.
    void visit_scene(const tinygltf::Scene& scene) {
        std::vector<bool> reached(model_.nodes.size(), false);
        std::vector<std::pair<int, Mat4>> stack;
        for (auto root = scene.nodes.rbegin(); root != scene.nodes.rend(); ++root) {
            stack.emplace_back(*root, kIdentity);
        }
        while (!stack.empty()) {
            const auto [index, parent] = stack.back();
            stack.pop_back();
            if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size()) {
                throw IoError(file_, "",
                              "a scene or node refers to node " + std::to_string(index) +
                                  ", which does not exist");
            }
            if (reached[static_cast<std::size_t>(index)]) {
                throw IoError(file_, "node " + std::to_string(index),
                              "the node is reached twice from the scene (two parents or a "
                              "cycle); glTF node graphs must be trees");
            }
            reached[static_cast<std::size_t>(index)] = true;
            const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
            const Mat4 world = multiply(parent, local_matrix(node));
            if (node.mesh >= 0) {
                add_mesh(node.mesh, world);
            }
            for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
                stack.emplace_back(*child, world);
            }
        }
    }

    void add_mesh(int mesh_index, const Mat4& world) {
        if (static_cast<std::size_t>(mesh_index) >= model_.meshes.size()) {
            throw IoError(
                file_, "",
                "a node refers to mesh " + std::to_string(mesh_index) + ", which does not exist");
        }
        // Primitives of one mesh instance that share a POSITION accessor share vertices
        // (common in multi-material meshes); each instance gets its own copy.
        std::map<int, std::uint32_t> base_of_accessor;
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(mesh_index)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = mesh.primitives[p];
            const std::string where =
                "mesh " + std::to_string(mesh_index) + ", primitive " + std::to_string(p);
            if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
                prim.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
                ++skipped_primitives_;
                continue;
            }
            const auto pos_it = prim.attributes.find("POSITION");
            if (pos_it == prim.attributes.end()) {
                throw IoError(file_, where, "no POSITION attribute");
            }
            const int pos_accessor = pos_it->second;
            plan(prim, pos_accessor, where);
            std::uint32_t base = 0;
            std::size_t n_vertices = 0;
            if (auto found = base_of_accessor.find(pos_accessor); found != base_of_accessor.end()) {
                base = found->second;
                n_vertices = model_.accessors[static_cast<std::size_t>(pos_accessor)].count;
            } else {
                const std::vector<Vec3> positions = read_vec3(pos_accessor, where, "POSITION");
                base = static_cast<std::uint32_t>(out_.soup.positions.size());
                n_vertices = positions.size();
                for (std::size_t i = 0; i < positions.size(); ++i) {
                    const Vec3 q = transform_point(world, positions[i]);
                    if (!is_finite(q)) {
                        throw IoError(file_, where,
                                      "position " + std::to_string(i) + " is not finite");
                    }
                    out_.soup.positions.push_back(q);
                }
                add_normals(prim, world, where, n_vertices);
                add_texcoords(prim, where, n_vertices);
                add_colours(prim, where, n_vertices);
                add_origins(prim, where, base, n_vertices);
                base_of_accessor.emplace(pos_accessor, base);
            }
            const std::size_t faces_before = out_.soup.n_faces();
            add_faces(prim, where, base, n_vertices, determinant3(world) < 0);
            face_material_.resize(out_.soup.n_faces(), -1);
            std::fill(face_material_.begin() + static_cast<std::ptrdiff_t>(faces_before),
                      face_material_.end(), prim.material);
        }
    }

    // Many nodes may instance one mesh: the budget decides before anything is copied, from
    // the accessors' counts (checked against their buffers when they are read).
    void plan(const tinygltf::Primitive& prim, int pos_accessor, const std::string& where) {
        const auto count = [&](int accessor) {
            return accessor >= 0 && static_cast<std::size_t>(accessor) < model_.accessors.size()
                       ? static_cast<double>(model_.accessors[accessor].count)
                       : 0.0;
        };
        const double vertices = count(pos_accessor);
        const double corners = prim.indices >= 0 ? count(prim.indices) : vertices;
        planned_bytes_ += build_bytes(vertices, corners, corners / 3.0);
        if (const auto over = over_budget(planned_bytes_)) {
            throw IoError(file_, where, "the scene's mesh instances " + *over);
        }
    }

    void add_normals(const tinygltf::Primitive& prim, const Mat4& world, const std::string& where,
                     std::size_t n_vertices) {
        const auto it = prim.attributes.find("NORMAL");
        if (!all_have_normals_ || it == prim.attributes.end()) {
            all_have_normals_ = false;
            return;
        }
        const std::vector<Vec3> normals = read_vec3(it->second, where, "NORMAL");
        if (normals.size() != n_vertices) {
            throw IoError(file_, where,
                          "NORMAL has " + std::to_string(normals.size()) + " elements, POSITION " +
                              std::to_string(n_vertices));
        }
        for (const Vec3& n : normals) {
            out_.normals.push_back(transform_normal(world, n));
        }
    }

    void add_texcoords(const tinygltf::Primitive& prim, const std::string& where,
                       std::size_t n_vertices) {
        if (prim.attributes.count("TEXCOORD_2") != 0 && !std::exchange(other_sets_said_, true)) {
            out_.notices.push_back(where +
                                   ": TEXCOORD_2 and later not kept (MeshEdit keeps TEXCOORD_0 "
                                   "and TEXCOORD_1)");
        }
        for (std::size_t set = 0; set < kTexcoordSets; ++set) {
            const std::string name = "TEXCOORD_" + std::to_string(set);
            const auto it = prim.attributes.find(name);
            if (!all_have_texcoords_[set] || it == prim.attributes.end()) {
                all_have_texcoords_[set] = false;
                continue;
            }
            const std::vector<double> uv =
                read_components(it->second, where, name.c_str(), TINYGLTF_TYPE_VEC2, 2);
            if (uv.size() != 2 * n_vertices) {
                throw IoError(file_, where,
                              name + " has " + std::to_string(uv.size() / 2) +
                                  " elements, POSITION " + std::to_string(n_vertices));
            }
            for (std::size_t i = 0; i < n_vertices; ++i) {
                // glTF's v runs down, MeshEdit's (OBJ's) up: exact in double for a float in
                // [0, 1].
                texcoords_[set].push_back(Vec2{uv[2 * i], 1.0 - uv[2 * i + 1]});
            }
        }
    }

    // COLOR_0: RGB or RGBA, float or normalized unsigned byte or short (alpha 1 for RGB).
    void add_colours(const tinygltf::Primitive& prim, const std::string& where, std::size_t n) {
        const auto it = prim.attributes.find("COLOR_0");
        const int a = it == prim.attributes.end() ? -1 : it->second;
        if (!all_have_colours_ || a < 0 || static_cast<std::size_t>(a) >= model_.accessors.size()) {
            all_have_colours_ = false;
            return;
        }
        const bool rgba = model_.accessors[static_cast<std::size_t>(a)].type == TINYGLTF_TYPE_VEC4;
        const std::size_t k = rgba ? 4 : 3;
        const std::vector<double> c =
            read_components(a, where, "COLOR_0", rgba ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, k);
        if (c.size() != k * n) {
            throw IoError(file_, where,
                          "COLOR_0 has " + std::to_string(c.size() / k) + " elements, POSITION " +
                              std::to_string(n));
        }
        for (std::size_t i = 0; i < n; ++i) {
            colours_.push_back({c[k * i], c[k * i + 1], c[k * i + 2], rgba ? c[k * i + 3] : 1.0});
        }
    }

    // Which mesh vertex each glTF vertex copies, from the primitive's extras when MeshEdit
    // wrote the file ("meshedit_vertex": an accessor of one index per vertex); -1 if unknown.
    void add_origins(const tinygltf::Primitive& prim, const std::string& where, std::uint32_t base,
                     std::size_t n_vertices) {
        std::vector<std::uint32_t> origin;
        if (prim.extras.Has("meshedit_vertex") && prim.extras.Get("meshedit_vertex").IsInt()) {
            origin = read_indices(prim.extras.Get("meshedit_vertex").Get<int>(), where);
        }
        for (std::size_t i = 0; i < n_vertices; ++i) {
            origin_.push_back(origin.size() == n_vertices ? std::int64_t{base} + origin[i] : -1);
        }
    }

    // glTF splits a vertex wherever its texture coordinate or normal changes; with those kept
    // per corner, the copies are welded back by exact position, so a textured surface stays
    // one surface.
    void weld_seams(bool by_position) {
        std::vector<std::uint32_t>& idx = out_.soup.indices;
        // MeshEdit's own files say which mesh vertex each glTF vertex copies (the primitive's
        // extras): those weld exactly. Others weld by exact position, when they have texture
        // coordinates (whose seams split vertices).
        const bool exact =
            std::all_of(origin_.begin(), origin_.end(), [](std::int64_t o) { return o >= 0; }) &&
            origin_.size() == out_.soup.positions.size();
        if (!exact && !by_position) {
            return;
        }
        std::map<std::tuple<double, double, double>, std::uint32_t> first;
        std::map<std::int64_t, std::uint32_t> first_origin;
        std::vector<std::uint32_t> to(out_.soup.positions.size());
        std::vector<Vec3> kept;
        std::vector<std::uint32_t> kept_from;  // the glTF vertex each kept vertex is
        for (std::size_t v = 0; v < to.size(); ++v) {
            const Vec3& p = out_.soup.positions[v];
            const auto next = static_cast<std::uint32_t>(kept.size());
            const std::uint32_t at =
                exact ? first_origin.emplace(origin_[v], next).first->second
                      : first.emplace(std::tuple{p.x, p.y, p.z}, next).first->second;
            if (at == next) {
                kept.push_back(p);
                kept_from.push_back(static_cast<std::uint32_t>(v));
            }
            to[v] = at;
        }
        if (kept.size() == to.size()) {
            return;
        }
        if (out_.normals.size() == out_.soup.positions.size()) {
            for (const std::uint32_t v : idx) {
                out_.corner_normals.push_back(out_.normals[v]);
            }
            out_.normals.clear();
        }
        // A face two of whose corners would weld together keeps its own copies (coincident
        // vertices that the file meant apart): no face is lost to the weld.
        std::map<std::uint32_t, std::uint32_t> own;
        const std::vector<Vec3> original = out_.soup.positions;
        const std::vector<std::uint32_t>& off = out_.soup.face_offsets;
        for (std::size_t f = 0; f + 1 < off.size(); ++f) {
            std::vector<std::uint32_t> corners;
            for (std::uint32_t c = off[f]; c < off[f + 1]; ++c) {
                corners.push_back(to[idx[c]]);
            }
            std::sort(corners.begin(), corners.end());
            const bool collapses =
                std::adjacent_find(corners.begin(), corners.end()) != corners.end();
            for (std::uint32_t c = off[f]; c < off[f + 1]; ++c) {
                if (!collapses) {
                    idx[c] = to[idx[c]];
                    continue;
                }
                const auto [it, fresh] =
                    own.emplace(idx[c], static_cast<std::uint32_t>(kept.size()));
                if (fresh) {
                    kept.push_back(original[idx[c]]);
                    kept_from.push_back(idx[c]);
                }
                idx[c] = it->second;
            }
        }
        const std::size_t welded = original.size() - kept.size();
        out_.soup.positions = std::move(kept);
        if (!out_.colors.empty()) {  // a vertex has one colour: the first copy's
            std::vector<Vec4> colours(kept_from.size());
            for (std::size_t v = 0; v < kept_from.size(); ++v) {
                colours[v] = out_.colors[kept_from[v]];
            }
            out_.colors = std::move(colours);
        }
        if (welded == 0) {
            return;
        }
        out_.notices.push_back("welded " + std::to_string(welded) +
                               " vertex copies at seams by exact position (texture coordinates "
                               "and normals are kept per corner)");
    }

    // The materials the faces use, by the file's material index; faces of a primitive without
    // one get an unnamed material.
    void keep_materials() {
        const bool any =
            std::any_of(face_material_.begin(), face_material_.end(), [](int m) { return m >= 0; });
        if (!any) {
            return;
        }
        for (std::size_t m = 0; m < model_.materials.size(); ++m) {
            Material material =
                gltf_images::read_material(model_, model_.materials[m], embedded_, folder_);
            const int set = model_.materials[m].pbrMetallicRoughness.baseColorTexture.texCoord;
            if (set != 0 && set != 1) {  // only TEXCOORD_0 and _1 are kept
                out_.notices.push_back("material " + std::to_string(m) + "'s texture reads " +
                                       "texCoord " + std::to_string(set) +
                                       ", which is not kept: it is drawn with TEXCOORD_0");
            }
            out_.materials.push_back(std::move(material));
        }
        const auto none = static_cast<std::uint32_t>(out_.materials.size());
        bool used_none = false;
        for (const int m : face_material_) {
            const bool valid = m >= 0 && static_cast<std::size_t>(m) < model_.materials.size();
            used_none = used_none || !valid;
            out_.face_materials.push_back(valid ? static_cast<std::uint32_t>(m) : none);
        }
        if (used_none) {
            out_.materials.push_back(Material{});
        }
    }

    void add_faces(const tinygltf::Primitive& prim, const std::string& where, std::uint32_t base,
                   std::size_t n_vertices, bool mirrored) {
        std::vector<std::uint32_t> idx;
        if (prim.indices >= 0) {
            idx = read_indices(prim.indices, where);
            for (std::size_t i = 0; i < idx.size(); ++i) {
                if (idx[i] >= n_vertices) {
                    throw IoError(file_, where,
                                  "index " + std::to_string(idx[i]) + " (element " +
                                      std::to_string(i) + ") is out of range (" +
                                      std::to_string(n_vertices) + " positions)");
                }
            }
        } else {
            idx.resize(n_vertices);
            for (std::size_t i = 0; i < n_vertices; ++i) {
                idx[i] = static_cast<std::uint32_t>(i);
            }
        }
        auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            // A mirroring transform turns counter-clockwise into clockwise; undo that.
            if (mirrored) {
                std::swap(b, c);
            }
            out_.soup.add_face({base + a, base + b, base + c});
        };
        const std::size_t n = idx.size();
        if (prim.mode == TINYGLTF_MODE_TRIANGLES) {
            for (std::size_t i = 0; i + 2 < n; i += 3) {
                add(idx[i], idx[i + 1], idx[i + 2]);
            }
            if (n % 3 != 0) {
                out_.notices.push_back(where + ": ignored " + std::to_string(n % 3) +
                                       " index(es) left over after the last triangle");
            }
        } else if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (std::size_t i = 0; i + 2 < n; ++i) {
                // Every other strip triangle is flipped so all wind the same way.
                if (i % 2 == 0) {
                    add(idx[i], idx[i + 1], idx[i + 2]);
                } else {
                    add(idx[i + 1], idx[i], idx[i + 2]);
                }
            }
        } else {
            for (std::size_t i = 1; i + 1 < n; ++i) {
                add(idx[0], idx[i], idx[i + 1]);
            }
        }
    }

    /// The bytes of accessor `index`: element `i` starts at `data + i * stride`. Checks the
    /// accessor, its buffer view and its buffer against each other.
    const unsigned char* accessor_data(int index, const std::string& where, const char* what,
                                       int expect_type, std::size_t* stride_out) {
        if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) {
            throw IoError(file_, where,
                          std::string(what) + " refers to accessor " + std::to_string(index) +
                              ", which does not exist");
        }
        const tinygltf::Accessor& acc = model_.accessors[static_cast<std::size_t>(index)];
        const std::string w = where + ", " + what + " accessor " + std::to_string(index);
        if (acc.type != expect_type) {
            throw IoError(file_, w, "unexpected accessor type");
        }
        if (acc.sparse.isSparse) {
            throw IoError(file_, w, "sparse accessors are not supported");
        }
        if (acc.bufferView < 0 ||
            static_cast<std::size_t>(acc.bufferView) >= model_.bufferViews.size()) {
            throw IoError(file_, w, "no valid bufferView");
        }
        const tinygltf::BufferView& view =
            model_.bufferViews[static_cast<std::size_t>(acc.bufferView)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size()) {
            throw IoError(file_, w, "its bufferView has no valid buffer");
        }
        const std::vector<unsigned char>& data =
            model_.buffers[static_cast<std::size_t>(view.buffer)].data;
        const int stride = acc.ByteStride(view);
        const int comp =
            tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(acc.componentType));
        const int n_comp = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(acc.type));
        if (stride <= 0 || comp <= 0 || n_comp <= 0) {
            throw IoError(file_, w, "invalid component type or stride");
        }
        const std::size_t element =
            static_cast<std::size_t>(comp) * static_cast<std::size_t>(n_comp);
        // All in size_t with overflow-safe ordering: count is bounded by the view's length
        // before it is multiplied.
        const std::size_t view_end = view.byteOffset + view.byteLength;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset) {
            throw IoError(file_, w, "its bufferView lies outside the buffer");
        }
        if (acc.count > 0) {
            const std::size_t s = static_cast<std::size_t>(stride);
            if (acc.byteOffset > view.byteLength || acc.count > view.byteLength / s + 1 ||
                view.byteOffset + acc.byteOffset + (acc.count - 1) * s + element > view_end) {
                throw IoError(file_, w,
                              std::to_string(acc.count) + " elements do not fit in the bufferView");
            }
        }
        *stride_out = static_cast<std::size_t>(stride);
        return data.data() + view.byteOffset + acc.byteOffset;
    }

    std::vector<Vec3> read_vec3(int index, const std::string& where, const char* what) {
        const std::vector<double> x = read_components(index, where, what, TINYGLTF_TYPE_VEC3, 3);
        std::vector<Vec3> out(x.size() / 3);
        for (std::size_t i = 0; i < out.size(); ++i) {
            out[i] = Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
        }
        return out;
    }

    // The `n` components of every element of accessor `index`, one after another.
    std::vector<double> read_components(int index, const std::string& where, const char* what,
                                        int type_expected, std::size_t n) {
        std::size_t stride = 0;
        const unsigned char* bytes = accessor_data(index, where, what, type_expected, &stride);
        const tinygltf::Accessor& acc = model_.accessors[static_cast<std::size_t>(index)];
        std::vector<double> out(acc.count * n);
        if (acc.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
            for (std::size_t i = 0; i < acc.count; ++i) {
                for (std::size_t c = 0; c < n; ++c) {
                    float f;
                    std::memcpy(&f, bytes + i * stride + 4 * c, sizeof f);  // may be unaligned
                    out[i * n + c] = f;
                }
            }
            return out;
        }
        // KHR_mesh_quantization: 8- or 16-bit integers, normalized to [-1, 1] / [0, 1] or
        // taken as they are (the node transform then scales them).
        const int type = acc.componentType;
        if (type != TINYGLTF_COMPONENT_TYPE_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            type != TINYGLTF_COMPONENT_TYPE_SHORT &&
            type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
            throw IoError(file_, where + ", " + what + " accessor " + std::to_string(index),
                          "components must be float, or 8- or 16-bit integers "
                          "(KHR_mesh_quantization)");
        }
        for (std::size_t i = 0; i < acc.count; ++i) {
            for (std::size_t c = 0; c < n; ++c) {
                out[i * n + c] = quantized(bytes + i * stride, type, c, acc.normalized);
            }
        }
        return out;
    }

    /// Component `c` of an integer vector at `e`, normalized as glTF says when asked.
    static double quantized(const unsigned char* e, int type, std::size_t c, bool normalized) {
        switch (type) {
            case TINYGLTF_COMPONENT_TYPE_BYTE: {
                const double v = static_cast<std::int8_t>(e[c]);
                return normalized ? std::max(v / 127.0, -1.0) : v;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                return normalized ? e[c] / 255.0 : e[c];
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                std::int16_t v;
                std::memcpy(&v, e + 2 * c, sizeof v);
                return normalized ? std::max(v / 32767.0, -1.0) : v;
            }
            default: {
                std::uint16_t v;
                std::memcpy(&v, e + 2 * c, sizeof v);
                return normalized ? v / 65535.0 : v;
            }
        }
    }

    std::vector<std::uint32_t> read_indices(int index, const std::string& where) {
        std::size_t stride = 0;
        const unsigned char* bytes =
            accessor_data(index, where, "indices", TINYGLTF_TYPE_SCALAR, &stride);
        const tinygltf::Accessor& acc = model_.accessors[static_cast<std::size_t>(index)];
        std::vector<std::uint32_t> out(acc.count);
        for (std::size_t i = 0; i < acc.count; ++i) {
            const unsigned char* e = bytes + i * stride;
            switch (acc.componentType) {
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    out[i] = *e;
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    std::uint16_t v;
                    std::memcpy(&v, e, sizeof v);
                    out[i] = v;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
                    std::memcpy(&out[i], e, sizeof(std::uint32_t));
                    break;
                default:
                    throw IoError(file_, where, "indices must be unsigned byte, short or int");
            }
        }
        return out;
    }

    const tinygltf::Model& model_;
    std::string file_;
    std::filesystem::path folder_;  // where texture paths start
    MeshSoup out_;
    static constexpr std::size_t kTexcoordSets = 2;  // TEXCOORD_0 and TEXCOORD_1
    // Per set, per soup vertex, while every primitive has them.
    std::array<std::vector<Vec2>, kTexcoordSets> texcoords_;
    std::vector<std::int64_t> origin_;  // per soup vertex: the mesh vertex it copies, or -1
    std::vector<int> face_material_;    // per soup face: the file's material index, or -1
    gltf_images::Embedded embedded_;    // embedded images' bytes, by image index
    std::array<bool, kTexcoordSets> all_have_texcoords_ = {true, true};
    bool other_sets_said_ = false;  // TEXCOORD_2's notice given
    std::vector<Vec4> colours_;     // COLOR_0 per soup vertex, while every primitive has it
    bool all_have_colours_ = true;
    bool all_have_normals_ = true;
    double planned_bytes_ = 0.0;
    std::size_t skipped_primitives_ = 0;
};

std::string one_line(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) {
        s.pop_back();
    }
    for (char& c : s) {
        if (c == '\n') {
            c = ';';
        }
    }
    return s;
}

}  // namespace

MeshSoup read_gltf(const std::filesystem::path& path) {
    return parse_gltf(read_file(path), path.string(), path.parent_path());
}

namespace {

// A glTF 1.0 file tinygltf could not read as 2.0: its meshes are an object keyed by name (an
// array in 2.0), or it has 1.0's techniques and shaders, or its asset says 1.x.
bool looks_like_gltf1(std::string_view text) {
    const nlohmann::json j = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
    if (!j.is_object()) {
        return false;
    }
    const auto asset = j.find("asset");
    if (asset != j.end() && asset->is_object() && asset->contains("version") &&
        (*asset)["version"].is_string()) {
        return (*asset)["version"].get<std::string>().rfind('1', 0) == 0;
    }
    const auto meshes = j.find("meshes");
    return (meshes != j.end() && meshes->is_object()) || j.contains("techniques") ||
           j.contains("shaders");
}

}  // namespace

MeshSoup parse_gltf(std::string_view bytes, const std::string& file,
                    const std::optional<std::filesystem::path>& folder) {
    if (bytes.size() > std::numeric_limits<unsigned int>::max()) {
        throw IoError(file, "", "file too large for the glTF loader (over 4 GiB)");
    }
    // The content decides, not the extension: a binary glTF always starts with "glTF".
    const bool binary = bytes.substr(0, 4) == "glTF";
    gltf_guard::check_json_depth(bytes, binary, file);
    const std::optional<std::string> rewritten =
        gltf_meshopt::replace_fallback_buffers(bytes, binary, file);
    if (rewritten) {
        bytes = *rewritten;
    }
    tinygltf::TinyGLTF loader;
    gltf_images::Embedded embedded;  // images are kept as bytes, never decoded
    loader.SetImageLoader(&gltf_images::keep_embedded, &embedded);
    const std::string base_dir = folder ? folder->string() : std::string();
    gltf_guard::ConfinedFiles files(folder, kMaxBufferFileBytes);
    loader.SetFsCallbacks(files.callbacks());
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(
                          &model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                          static_cast<unsigned int>(bytes.size()), base_dir)
                    : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                                 static_cast<unsigned int>(bytes.size()), base_dir);
    } catch (const std::exception& e) {
        throw IoError(file, "", std::string("cannot parse: ") + e.what());
    }
    if (!files.refusal().empty()) {
        throw IoError(file, "", files.refusal());
    }
    // glTF 1.0 parses as 2.0 with nothing in it: name the version (issue 40) rather than
    // "holds no faces". A binary 1.0 file says so in its header (version 1).
    const bool binary_v1 = binary && bytes.size() >= 8 &&
                           static_cast<unsigned char>(bytes[4]) == 1 && bytes[5] == 0 &&
                           bytes[6] == 0 && bytes[7] == 0;
    const bool declared_v1 = !model.asset.version.empty() && model.asset.version[0] == '1';
    if (binary_v1 || declared_v1 || (!ok && !binary && looks_like_gltf1(bytes))) {
        throw IoError(file, "",
                      "a glTF " + (declared_v1 ? model.asset.version : std::string("1.0")) +
                          " file; MeshEdit reads glTF 2.0 (convert it first, for example by "
                          "importing it into Blender and exporting glTF 2.0)");
    }
    if (!ok) {
        gltf_meshopt::check_required(model, file);
        throw IoError(file, "", err.empty() ? "cannot parse" : one_line(err));
    }
    gltf_meshopt::decode(model, file);
    MeshSoup soup =
        GltfReader(model, file, folder.value_or(std::filesystem::path()), std::move(embedded))
            .read();
    if (!warn.empty()) {
        soup.notices.push_back(one_line(warn));
    }
    return soup;
}

}  // namespace meshedit
