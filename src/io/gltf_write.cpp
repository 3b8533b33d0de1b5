// Writing glTF 2.0 (gltf.h) through tinygltf: one mesh, one indexed TRIANGLES primitive per
// material. A vertex is written once per distinct combination of its corners' texture
// coordinates (TEXCOORD_0 and TEXCOORD_1) and normal (glTF's attributes are per vertex), so
// seams stay seams; its colour is COLOR_0; polygons
// are fanned from their first corner. A .glb embeds the materials' texture images; a .gltf
// names them by a path relative to itself.

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

#include "gltf_images.h"
#include "io_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/normals.h"
#include "meshedit/io/gltf.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

/// Appends the little-endian values of `T` to `buffer`.
template <class T>
void append(std::vector<unsigned char>& buffer, const std::vector<T>& values) {
    const std::size_t at = buffer.size();
    buffer.resize(at + values.size() * sizeof(T));
    if (!values.empty()) {
        std::memcpy(buffer.data() + at, values.data(), values.size() * sizeof(T));
    }
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);  // every view starts 4-byte aligned
}

// `s` with every byte that is not part of valid UTF-8 replaced by '?': glTF is JSON, and
// material names from OBJ libraries are often Latin-1.
std::string utf8(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        const std::size_t n = c < 0x80         ? 1
                              : (c >> 5) == 6  ? 2
                              : (c >> 4) == 14 ? 3
                              : (c >> 3) == 30 ? 4
                                               : 0;
        bool ok = n > 0 && i + n <= s.size();
        for (std::size_t k = 1; ok && k < n; ++k) {
            ok = (static_cast<unsigned char>(s[i + k]) >> 6) == 2;
        }
        out += ok ? s.substr(i, n) : "?";
        i += ok ? n : 1;
    }
    return out;
}

class GltfWriter {
public:
    GltfWriter(const Mesh& mesh, const fs::path& path, const IoFlags& flags)
        : mesh_(mesh), path_(path), flags_(flags), binary_(file_extension(path) == ".glb") {}

    std::string write() {
        number_vertices();
        model_.asset.version = "2.0";
        model_.asset.generator = "MeshEdit";
        model_.buffers.emplace_back();
        tinygltf::Mesh gmesh;
        const std::map<std::string, int> attributes = add_attributes();
        // Which mesh vertex each glTF vertex copies, when seams made copies: MeshEdit's reader
        // welds them back exactly (other readers ignore extras).
        int origins = -1;
        if (vertices_.size() > mesh_.vertices_size()) {
            std::vector<std::uint32_t> origin;
            for (const Corner& c : vertices_) {
                origin.push_back(c.vertex.idx());
            }
            origins = add_accessor(add_view(origin, 0), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                   TINYGLTF_TYPE_SCALAR, origin.size());
        }
        for (const auto& [material, triangles] : triangles_by_material()) {
            tinygltf::Primitive prim;
            prim.mode = TINYGLTF_MODE_TRIANGLES;
            prim.attributes = attributes;
            prim.indices = add_accessor(add_view(triangles, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                        triangles.size());
            prim.material = material;
            if (origins >= 0) {
                prim.extras = tinygltf::Value(
                    tinygltf::Value::Object{{"meshedit_vertex", tinygltf::Value(origins)}});
            }
            gmesh.primitives.push_back(std::move(prim));
        }
        model_.meshes.push_back(std::move(gmesh));
        tinygltf::Node node;
        node.mesh = 0;
        model_.nodes.push_back(std::move(node));
        tinygltf::Scene scene;
        scene.nodes.push_back(0);
        model_.scenes.push_back(std::move(scene));
        model_.defaultScene = 0;
        // Serialised in memory (the buffer as base64 in a .gltf, as the BIN chunk of a .glb).
        std::ostringstream stream;
        tinygltf::TinyGLTF writer;
        if (!writer.WriteGltfSceneToStream(&model_, stream, !binary_, binary_) || !stream) {
            throw IoError(path_.string(), "", "cannot serialise the glTF model");
        }
        return std::move(stream).str();
    }

private:
    // glTF vertex of each corner (the head of each face halfedge): one per distinct
    // (vertex, texture coordinate, normal). Vertex v keeps number v (its first corner's
    // values), so a mesh without seams is written vertex for vertex; copies at seams follow.
    void number_vertices() {
        for (std::size_t set = 0; set < kSets; ++set) {
            uv_[set] = mesh_.get_property<Halfedge, Vec2>(kTexCoordSets[set]);
        }
        normal_ = mesh_.get_property<Halfedge, Vec3>(kCornerNormalProperty);
        using Key =
            std::tuple<std::uint32_t, double, double, double, double, double, double, double>;
        std::map<Key, std::uint32_t> seen;
        const std::size_t nv = mesh_.vertices_size();
        vertices_.resize(nv);
        std::vector<bool> claimed(nv, false);
        for (std::uint32_t v = 0; v < nv; ++v) {
            vertices_[v].vertex = Vertex(v);
        }
        corner_vertex_.assign(mesh_.halfedges_size(), 0);
        for (const Face f : mesh_.faces()) {
            for (const Halfedge h : mesh_.halfedges(f)) {
                const Corner c{mesh_.to_vertex(h),
                               {uv_[0] ? uv_[0][h] : Vec2{}, uv_[1] ? uv_[1][h] : Vec2{}},
                               normal_ ? normal_[h] : Vec3{}};
                const Key key{c.vertex.idx(), c.uv[0].x,  c.uv[0].y,  c.uv[1].x,
                              c.uv[1].y,      c.normal.x, c.normal.y, c.normal.z};
                std::uint32_t index = c.vertex.idx();
                if (!claimed[index]) {
                    claimed[index] = true;
                    vertices_[index] = c;
                    seen.emplace(key, index);
                } else {
                    const auto [it, fresh] =
                        seen.emplace(key, static_cast<std::uint32_t>(vertices_.size()));
                    if (fresh) {
                        vertices_.push_back(c);
                    }
                    index = it->second;
                }
                corner_vertex_[h.idx()] = index;
            }
        }
        if (mesh_.n_faces() == 0) {
            throw IoError(path_.string(), "", "the mesh has no faces; glTF stores triangles only");
        }
    }

    std::map<std::string, int> add_attributes() {
        std::map<std::string, int> attributes;
        // glTF stores 32-bit floats; min/max are required on POSITION.
        std::vector<float> positions;
        std::vector<double> lo(3, std::numeric_limits<double>::infinity());
        std::vector<double> hi(3, -std::numeric_limits<double>::infinity());
        for (const Corner& c : vertices_) {
            const Vec3& p = mesh_.position(c.vertex);
            for (int i = 0; i < 3; ++i) {
                if (!(std::abs(p[i]) <= FLT_MAX)) {
                    throw IoError(path_.string(), "",
                                  "a coordinate does not fit in a 32-bit float");
                }
                const auto f = static_cast<float>(p[i]);
                positions.push_back(f);
                const auto k = static_cast<std::size_t>(i);
                lo[k] = std::min(lo[k], double{f});
                hi[k] = std::max(hi[k], double{f});
            }
        }
        attributes["POSITION"] =
            add_accessor(add_view(positions, TINYGLTF_TARGET_ARRAY_BUFFER),
                         TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertices_.size());
        model_.accessors.back().minValues = lo;
        model_.accessors.back().maxValues = hi;
        for (std::size_t set = 0; set < kSets; ++set) {
            if (!uv_[set]) {
                continue;
            }
            std::vector<float> uv;
            for (const Corner& c : vertices_) {
                uv.insert(uv.end(), {static_cast<float>(c.uv[set].x),
                                     static_cast<float>(1.0 - c.uv[set].y)});  // v down
            }
            attributes["TEXCOORD_" + std::to_string(set)] =
                add_accessor(add_view(uv, TINYGLTF_TARGET_ARRAY_BUFFER),
                             TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, vertices_.size());
        }
        if (const auto colour = mesh_.get_property<Vertex, Vec4>(kColorProperty)) {
            attributes["COLOR_0"] = add_colours(colour);
        }
        if (normal_ || flags_.write_normals) {
            std::vector<Vec3> computed;
            if (!normal_) {
                compute_vertex_normals(mesh_, computed);
            }
            std::vector<float> packed;
            for (const Corner& c : vertices_) {
                Vec3 n = normal_ ? c.normal : computed[c.vertex.idx()];
                // glTF requires unit normals; isolated or degenerate vertices have none.
                const double length = norm(n);
                n = length > 0 && std::isfinite(length) ? n / length : Vec3(0, 1, 0);
                packed.insert(packed.end(), {static_cast<float>(n.x), static_cast<float>(n.y),
                                             static_cast<float>(n.z)});
            }
            attributes["NORMAL"] =
                add_accessor(add_view(packed, TINYGLTF_TARGET_ARRAY_BUFFER),
                             TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, vertices_.size());
        }
        return attributes;
    }

    // Triangles (fans from each face's first corner) per glTF material index (-1: none).
    std::map<int, std::vector<std::uint32_t>> triangles_by_material() {
        const auto material = mesh_.get_property<Face, std::uint32_t>(kMaterialProperty);
        std::vector<int> gltf_material(mesh_.materials().size(), -1);
        std::map<int, std::vector<std::uint32_t>> out;
        for (const Face f : mesh_.faces()) {
            int m = -1;
            if (material && material[f] < mesh_.materials().size()) {
                int& made = gltf_material[material[f]];
                if (made < 0 && !mesh_.materials()[material[f]].name.empty()) {
                    made = add_material(mesh_.materials()[material[f]]);
                }
                m = made;
            }
            std::vector<std::uint32_t>& tri = out[m];
            const Halfedge first = mesh_.prev(mesh_.halfedge(f));  // arrives at corner 0
            for (Halfedge h = mesh_.next(first); mesh_.next(h) != first; h = mesh_.next(h)) {
                tri.insert(tri.end(), {corner_vertex_[first.idx()], corner_vertex_[h.idx()],
                                       corner_vertex_[mesh_.next(h).idx()]});
            }
        }
        return out;
    }

    int add_material(const Material& m) {
        tinygltf::Material g;
        g.name = utf8(m.name);
        g.pbrMetallicRoughness.baseColorFactor = {m.base_colour.x, m.base_colour.y, m.base_colour.z,
                                                  m.opacity};
        if (m.opacity < 1.0) {
            g.alphaMode = "BLEND";
        }
        if (const int image = add_image(m.base_colour_texture, m.base_colour_texture_bytes);
            image >= 0) {
            tinygltf::Texture texture;
            texture.source = image;
            model_.textures.push_back(texture);
            g.pbrMetallicRoughness.baseColorTexture.index =
                static_cast<int>(model_.textures.size() - 1);
            g.pbrMetallicRoughness.baseColorTexture.texCoord =
                static_cast<int>(m.base_colour_texcoord);
        }
        model_.materials.push_back(std::move(g));
        return static_cast<int>(model_.materials.size() - 1);
    }

    // A .glb carries the image's bytes; a .gltf names it relative to itself, or holds it as a
    // data: URI when the mesh has it as bytes (an image another glTF embedded).
    int add_image(const std::string& path, const std::string& embedded) {
        const std::string mime = gltf_images::mime_of(embedded);
        if (path.empty() || (!embedded.empty() && mime.empty())) {
            return -1;  // an embedded image glTF cannot hold: unkept_by_format() says so
        }
        tinygltf::Image image;
        if (!embedded.empty()) {
            image.name = utf8(fs::path(path).stem().string());
            image.mimeType = mime;
            if (binary_) {
                image.bufferView =
                    add_view(std::vector<unsigned char>(embedded.begin(), embedded.end()), 0);
            } else {
                image.uri = "data:" + mime + ";base64," + gltf_images::base64(embedded);
            }
            model_.images.push_back(std::move(image));
            return static_cast<int>(model_.images.size() - 1);
        }
        std::error_code ec;
        const fs::path file(path);
        const fs::path folder = path_.parent_path().empty() ? fs::path(".") : path_.parent_path();
        const std::string ext = file_extension(file);
        // glTF holds PNG and JPEG images; another kind is named, not embedded.
        if (binary_ && (ext == ".png" || ext == ".jpg" || ext == ".jpeg") &&
            fs::is_regular_file(file, ec)) {
            const std::string bytes = read_file(file);
            image.bufferView = add_view(std::vector<unsigned char>(bytes.begin(), bytes.end()), 0);
            image.mimeType = ext == ".png" ? "image/png" : "image/jpeg";
        } else {
            image.uri = utf8(io_util::texture_relative_to(path, folder));
        }
        model_.images.push_back(std::move(image));
        return static_cast<int>(model_.images.size() - 1);
    }

    template <class T>
    int add_view(const std::vector<T>& values, int target) {
        std::vector<unsigned char>& data = model_.buffers[0].data;
        const std::size_t offset = data.size();
        append(data, values);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = offset;
        view.byteLength = values.size() * sizeof(T);
        view.target = target;
        model_.bufferViews.push_back(view);
        return static_cast<int>(model_.bufferViews.size() - 1);
    }

    // COLOR_0 in the narrowest form that gives every value back exactly when read: normalized
    // unsigned bytes when each is k/255, shorts when k/65535, else floats (glTF has no
    // doubles, as for positions). Integers are RGBA (their elements must be 4-byte aligned);
    // floats are RGB when every alpha is 1.
    int add_colours(const VertexProperty<Vec4>& colour) {
        std::vector<double> values;
        bool alpha = false;
        for (const Corner& c : vertices_) {
            const Vec4& x = colour[c.vertex];
            values.insert(values.end(), {x.x, x.y, x.z, x.w});
            alpha = alpha || x.w != 1.0;
        }
        const auto fits = [&](double scale) {
            return std::all_of(values.begin(), values.end(), [&](double v) {
                const double k = std::nearbyint(v * scale);
                return k >= 0 && k <= scale && k / scale == v;
            });
        };
        const std::size_t n = vertices_.size();
        int accessor = -1;
        if (fits(255.0)) {
            std::vector<std::uint8_t> bytes;
            for (const double v : values) {
                bytes.push_back(static_cast<std::uint8_t>(std::nearbyint(v * 255.0)));
            }
            accessor = add_accessor(add_view(bytes, TINYGLTF_TARGET_ARRAY_BUFFER),
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4, n);
        } else if (fits(65535.0)) {
            std::vector<std::uint16_t> shorts;
            for (const double v : values) {
                shorts.push_back(static_cast<std::uint16_t>(std::nearbyint(v * 65535.0)));
            }
            accessor = add_accessor(add_view(shorts, TINYGLTF_TARGET_ARRAY_BUFFER),
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4, n);
        } else {
            std::vector<float> floats;
            for (std::size_t i = 0; i < values.size(); ++i) {
                if (alpha || i % 4 != 3) {
                    floats.push_back(static_cast<float>(values[i]));
                }
            }
            return add_accessor(add_view(floats, TINYGLTF_TARGET_ARRAY_BUFFER),
                                TINYGLTF_COMPONENT_TYPE_FLOAT,
                                alpha ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, n);
        }
        model_.accessors.back().normalized = true;
        return accessor;
    }

    int add_accessor(int view, int component, int type, std::size_t count) {
        tinygltf::Accessor acc;
        acc.bufferView = view;
        acc.byteOffset = 0;
        acc.componentType = component;
        acc.type = type;
        acc.count = count;
        model_.accessors.push_back(acc);
        return static_cast<int>(model_.accessors.size() - 1);
    }

    const Mesh& mesh_;
    fs::path path_;
    IoFlags flags_;
    bool binary_;
    static constexpr std::size_t kSets = std::size(kTexCoordSets);  // TEXCOORD_0, TEXCOORD_1
    std::array<HalfedgeProperty<Vec2>, kSets> uv_;
    HalfedgeProperty<Vec3> normal_;
    struct Corner {
        Vertex vertex;
        std::array<Vec2, kSets> uv;
        Vec3 normal;
    };
    std::vector<Corner> vertices_;              // per glTF vertex
    std::vector<std::uint32_t> corner_vertex_;  // per halfedge: its glTF vertex
    tinygltf::Model model_;
};

}  // namespace

void write_gltf(const Mesh& mesh, const std::filesystem::path& path, const IoFlags& flags) {
    std::optional<Mesh> storage;
    const Mesh& dense = io_util::compacted(mesh, storage);
    const std::string bytes = GltfWriter(dense, path, flags).write();
    write_atomically(path, [&](const std::filesystem::path& tmp) { write_file(tmp, bytes); });
}

}  // namespace meshedit
