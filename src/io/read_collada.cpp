// COLLADA reader, part 3: <asset>, the scene's node tree with its transforms, and the
// concatenation of every instanced geometry into one soup (docs/spec.md §2).

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

#include "collada_detail.h"
#include "collada_material.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/memory.h"
#include "meshedit/io/collada.h"

namespace meshedit {
namespace {

using collada::Document;

// Guards against instance_node explosions (a DAG can instance a node 2^depth times).
constexpr std::size_t kMaxNodeDepth = 256;
constexpr std::size_t kMaxNodeVisits = 1'000'000;
constexpr std::uint64_t kMaxCorners = std::uint64_t{1} << 31;

/// Affine 4×4 matrix acting on column vectors, row-major storage.
struct Mat4 {
    std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

    double operator()(int r, int c) const { return m[4 * r + c]; }
    double& operator()(int r, int c) { return m[4 * r + c]; }

    friend Mat4 operator*(const Mat4& a, const Mat4& b) {
        Mat4 out;
        for (int r = 0; r < 4; ++r) {
            for (int c = 0; c < 4; ++c) {
                double sum = 0.0;
                for (int k = 0; k < 4; ++k) {
                    sum += a(r, k) * b(k, c);
                }
                out(r, c) = sum;
            }
        }
        return out;
    }
    Vec3 point(const Vec3& p) const {
        return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3],
                m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
                m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
    }
    double det3() const {
        return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
               m[2] * (m[4] * m[9] - m[5] * m[8]);
    }
    bool is_identity() const { return *this == Mat4{}; }
    bool operator==(const Mat4&) const = default;

    // Normals transform by the inverse transpose; the cofactor matrix is that times det.
    Vec3 normal(const Vec3& n) const {
        const Vec3 c0 = cross(column(1), column(2));
        const Vec3 c1 = cross(column(2), column(0));
        const Vec3 c2 = cross(column(0), column(1));
        const Vec3 out = c0 * n.x + c1 * n.y + c2 * n.z;
        return normalize(det3() < 0 ? -out : out);
    }
    Vec3 column(int c) const { return {m[c], m[4 + c], m[8 + c]}; }
};

Mat4 translation(const Vec3& t) {
    Mat4 out;
    out(0, 3) = t.x;
    out(1, 3) = t.y;
    out(2, 3) = t.z;
    return out;
}

Mat4 with_columns(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& t) {
    Mat4 out;
    for (int r = 0; r < 3; ++r) {
        out(r, 0) = a[r];
        out(r, 1) = b[r];
        out(r, 2) = c[r];
        out(r, 3) = t[r];
    }
    return out;
}

// Rodrigues' rotation by `degrees` about `axis` (right-handed, as COLLADA's <rotate>).
Mat4 rotation(Vec3 axis, double degrees) {
    axis = normalize(axis);
    const double a = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(a);
    const double s = std::sin(a);
    const double t = 1.0 - c;
    const auto [x, y, z] = std::array{axis.x, axis.y, axis.z};
    Mat4 out;
    out.m = {t * x * x + c,
             t * x * y - s * z,
             t * x * z + s * y,
             0,
             t * x * y + s * z,
             t * y * y + c,
             t * y * z - s * x,
             0,
             t * x * z - s * y,
             t * y * z + s * x,
             t * z * z + c,
             0,
             0,
             0,
             0,
             1};
    return out;
}

class SceneReader {
public:
    explicit SceneReader(const Document& doc) : doc_(doc) {}

    MeshSoup read();

private:
    struct Instance {
        pugi::xml_node geometry;
        pugi::xml_node at;  // the instancing element, for messages
        Mat4 transform;
    };

    Mat4 read_asset();
    Mat4 local_transform(pugi::xml_node node);
    void visit(pugi::xml_node node, const Mat4& parent, std::size_t depth);
    void visit_children(pugi::xml_node node, const Mat4& transform, std::size_t depth);
    void instance_controller(pugi::xml_node at, const Mat4& transform);
    void append(const Instance& instance, collada::GeometryData& g, bool last_use);
    void append_attributes(const Instance& instance, const collada::GeometryData& g, bool mirror);
    std::uint32_t material_for(pugi::xml_node at, const std::string& symbol,
                               const collada::GeometryData* g = nullptr);

    const Document& doc_;
    MeshSoup out_;
    std::vector<Instance> instances_;
    std::vector<pugi::xml_node> active_;  // nodes on the current path (cycle guard)
    std::size_t visits_ = 0;
    std::size_t appended_ = 0;
    double planned_bytes_ = 0.0;
    std::size_t skipped_transforms_ = 0;
    bool normals_ok_ = true;
    // Per texture coordinate set: every geometry so far has it; some geometry had it.
    bool texcoords_ok_[2] = {true, true}, any_uv_[2] = {false, false};
    bool corner_normals_ok_ = true, colors_ok_ = true;
    bool any_colour_ = false;                                        // some geometry had them
    std::unordered_map<const void*, std::uint32_t> material_index_;  // by <material>
    std::uint32_t no_material_ = std::numeric_limits<std::uint32_t>::max();
    bool any_material_ = false;
};

Mat4 SceneReader::read_asset() {
    const pugi::xml_node asset = doc_.root().child("asset");
    if (const pugi::xml_node unit = asset.child("unit")) {
        if (const pugi::xml_attribute meter = unit.attribute("meter")) {
            std::string text = meter.value();
            if (text.find(',') != std::string::npos && text.find('.') == std::string::npos) {
                std::replace(text.begin(), text.end(), ',', '.');  // "0,01": a decimal comma
                doc_.note_decimal_commas();
            }
            text.erase(0, text.find_first_not_of(" \t\r\n"));
            text.erase(text.find_last_not_of(" \t\r\n") + 1);
            double value = 0.0;
            const auto [stop, error] =
                std::from_chars(text.data(), text.data() + text.size(), value);
            if (error == std::errc() && stop == text.data() + text.size() && std::isfinite(value) &&
                value > 0.0) {
                out_.unit_meter = value;
            } else {
                out_.notices.push_back(std::string("ignored <unit meter=\"") + meter.value() +
                                       "\">: not a positive number");
            }
        }
    }
    const pugi::xml_node up = asset.child("up_axis");
    std::string axis = up.child_value();
    axis.erase(0, axis.find_first_not_of(" \t\r\n"));
    axis.erase(axis.find_last_not_of(" \t\r\n") + 1);
    if (axis.empty() || axis == "Y_UP") {
        return {};
    }
    // Rotations taking the file's up axis to +Y (the view is Y-up).
    if (axis == "Z_UP") {
        out_.notices.push_back("converted Z_UP to Y_UP: (x, y, z) became (x, z, -y)");
        return with_columns({1, 0, 0}, {0, 0, -1}, {0, 1, 0}, {});
    }
    if (axis == "X_UP") {
        out_.notices.push_back("converted X_UP to Y_UP: (x, y, z) became (-y, x, z)");
        return with_columns({0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {});
    }
    doc_.fail(up, "unknown up axis \"" + axis + "\" (expected X_UP, Y_UP or Z_UP)");
}

Mat4 SceneReader::local_transform(pugi::xml_node node) {
    Mat4 local;
    for (pugi::xml_node child : node.children()) {
        const std::string_view name = child.name();
        std::size_t need = 0;
        if (name == "matrix") {
            need = 16;
        } else if (name == "translate" || name == "scale") {
            need = 3;
        } else if (name == "rotate") {
            need = 4;
        } else if (name == "lookat") {
            need = 9;
        } else if (name == "skew") {
            ++skipped_transforms_;
            continue;
        } else {
            continue;
        }
        const std::vector<double> v = collada::parse_doubles(doc_, child);
        if (v.size() != need) {
            doc_.fail(child, "needs " + std::to_string(need) + " numbers, has " +
                                 std::to_string(v.size()));
        }
        for (double x : v) {
            if (!std::isfinite(x)) {
                doc_.fail(child, "holds a non-finite number");
            }
        }
        Mat4 t;
        if (name == "matrix") {
            std::copy(v.begin(), v.end(), t.m.begin());
        } else if (name == "translate") {
            t = translation({v[0], v[1], v[2]});
        } else if (name == "scale") {
            t = with_columns({v[0], 0, 0}, {0, v[1], 0}, {0, 0, v[2]}, {});
        } else if (name == "rotate") {
            if (norm(Vec3{v[0], v[1], v[2]}) == 0.0 && v[3] != 0.0) {
                doc_.fail(child, "rotation axis is zero");
            }
            if (v[3] != 0.0) {  // exporters write "0 0 0 0" for no rotation
                t = rotation({v[0], v[1], v[2]}, v[3]);
            }
        } else {
            // <lookat> eye, interest, up: places the node at `eye` looking down its -Z at
            // `interest` (the camera convention), with `up` orthogonalised.
            const Vec3 eye{v[0], v[1], v[2]};
            const Vec3 dir = normalize(Vec3{v[3], v[4], v[5]} - eye);
            const Vec3 right = normalize(cross(dir, Vec3{v[6], v[7], v[8]}));
            if (norm(dir) == 0.0 || norm(right) == 0.0) {
                doc_.fail(child,
                          "degenerate <lookat> (eye = interest, or up parallel to the "
                          "view direction)");
            }
            t = with_columns(right, cross(right, dir), -dir, eye);
        }
        local = local * t;  // document order: the first transform is outermost
    }
    return local;
}

void SceneReader::visit(pugi::xml_node node, const Mat4& parent, std::size_t depth) {
    if (depth > kMaxNodeDepth) {
        doc_.fail(node, "nodes nested more than " + std::to_string(kMaxNodeDepth) + " levels deep");
    }
    if (++visits_ > kMaxNodeVisits) {
        doc_.fail(node, "the node tree expands to more than " + std::to_string(kMaxNodeVisits) +
                            " nodes (repeated <instance_node>s)");
    }
    visit_children(node, parent * local_transform(node), depth);
}

void SceneReader::visit_children(pugi::xml_node node, const Mat4& transform, std::size_t depth) {
    for (pugi::xml_node child : node.children()) {
        const std::string_view name = child.name();
        if (name == "node") {
            visit(child, transform, depth + 1);
        } else if (name == "instance_geometry") {
            const pugi::xml_node geometry = doc_.resolve(child.attribute("url").value(), child);
            if (std::strcmp(geometry.name(), "geometry") != 0) {
                doc_.fail(child,
                          std::string("url names a <") + geometry.name() + ">, not a <geometry>");
            }
            instances_.push_back({geometry, child, transform});
        } else if (name == "instance_node") {
            const pugi::xml_node target = doc_.resolve(child.attribute("url").value(), child);
            if (std::strcmp(target.name(), "node") != 0) {
                doc_.fail(child, std::string("url names a <") + target.name() + ">, not a <node>");
            }
            if (std::find(active_.begin(), active_.end(), target) != active_.end()) {
                doc_.fail(child, std::string("cycle: instances \"") +
                                     child.attribute("url").value() +
                                     "\", which contains this element");
            }
            active_.push_back(target);
            visit(target, transform, depth + 1);
            active_.pop_back();
        } else if (name == "instance_controller") {
            instance_controller(child, transform);
        }
    }
}

// A skinned or morphed mesh: its base geometry in the bind pose.
void SceneReader::instance_controller(pugi::xml_node at, const Mat4& transform) {
    const pugi::xml_node controller = doc_.resolve(at.attribute("url").value(), at);
    const pugi::xml_node skin = controller.child("skin");
    const pugi::xml_node which = skin ? skin : controller.child("morph");
    if (which) {
        Mat4 bind;
        if (skin) {
            const std::vector<double> v =
                collada::parse_doubles(doc_, skin.child("bind_shape_matrix"));
            if (v.size() == 16) {
                std::copy(v.begin(), v.end(), bind.m.begin());
            }
        }
        // Controller chains (a skin of a morph) are rare and not followed.
        const pugi::xml_node base = doc_.resolve(which.attribute("source").value(), which);
        if (std::strcmp(base.name(), "geometry") == 0) {
            instances_.push_back({base, at, transform * bind});
            return;
        }
    }
    out_.notices.push_back("ignored " + doc_.where(at) + ": no base <geometry> found");
}

// `last_use`: no later instance needs `g`, so its arrays may be moved out.
void SceneReader::append(const Instance& instance, collada::GeometryData& g, bool last_use) {
    // Instancing multiplies what the file holds: the budget decides before anything is copied.
    ++appended_;
    planned_bytes_ +=
        build_bytes(static_cast<double>(g.positions.size()), static_cast<double>(g.indices.size()),
                    static_cast<double>(g.face_offsets.size() - 1));
    if (const auto over = over_budget(planned_bytes_)) {
        doc_.fail(instance.at, std::to_string(appended_) + " geometry instances so far " + *over);
    }
    const std::size_t base = out_.soup.positions.size();
    if (base + g.positions.size() >= std::numeric_limits<std::uint32_t>::max() ||
        out_.soup.indices.size() + g.indices.size() > kMaxCorners) {
        doc_.fail(instance.at, "the scene is too large (more than 2^31 corners)");
    }
    const Mat4& t = instance.transform;
    const bool identity = t.is_identity();
    // A mirroring transform turns faces inside out; reversing the corners keeps them outward.
    const bool mirror = t.det3() < 0.0;
    append_attributes(instance, g, mirror);
    normals_ok_ = normals_ok_ && !g.normals.empty();
    // The usual single untransformed instance takes the geometry's arrays instead of copying
    // them (its positions were checked finite when read).
    if (last_use && identity && base == 0 && out_.soup.face_offsets.size() == 1) {
        out_.soup.positions = std::move(g.positions);
        out_.soup.indices = std::move(g.indices);
        out_.soup.face_offsets = std::move(g.face_offsets);
        if (normals_ok_) {
            out_.normals = std::move(g.normals);
        }
        out_.creases = g.creases;
        return;
    }
    memory::reserve_more(out_.soup.positions, g.positions.size());
    for (const Vec3& p : g.positions) {
        out_.soup.positions.push_back(identity ? p : t.point(p));
        if (!is_finite(out_.soup.positions.back())) {
            doc_.fail(instance.at, "a transformed position is not finite");
        }
    }
    if (normals_ok_) {
        memory::reserve_more(out_.normals, g.normals.size());
        for (const Vec3& n : g.normals) {
            out_.normals.push_back(identity ? n : t.normal(n));
        }
    }
    const auto offset = static_cast<std::uint32_t>(base);
    memory::reserve_more(out_.soup.indices, g.indices.size());
    memory::reserve_more(out_.soup.face_offsets, g.face_offsets.size() - 1);
    for (std::size_t f = 0; f + 1 < g.face_offsets.size(); ++f) {
        const std::uint32_t begin = g.face_offsets[f];
        const std::uint32_t end = g.face_offsets[f + 1];
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint32_t k = (!mirror || i == begin) ? i : begin + (end - i);
            out_.soup.indices.push_back(g.indices[k] + offset);
        }
        out_.soup.face_offsets.push_back(static_cast<std::uint32_t>(out_.soup.indices.size()));
    }
    for (const auto& [a, b] : g.creases) {
        out_.creases.emplace_back(a + offset, b + offset);
    }
}

// Texture coordinates and normals per corner (in the order append() lays the corners),
// colours per position, and each face's material through the instance's <bind_material>.
void SceneReader::append_attributes(const Instance& instance, const collada::GeometryData& g,
                                    bool mirror) {
    const Mat4& t = instance.transform;
    for (std::size_t set = 0; set < 2; ++set) {
        any_uv_[set] = any_uv_[set] || !g.corner_texcoords[set].empty();
        texcoords_ok_[set] = texcoords_ok_[set] && !g.corner_texcoords[set].empty();
    }
    any_colour_ = any_colour_ || !g.colors.empty();
    corner_normals_ok_ = corner_normals_ok_ && !g.corner_normals.empty();
    colors_ok_ = colors_ok_ && !g.colors.empty();
    if (colors_ok_) {
        out_.colors.insert(out_.colors.end(), g.colors.begin(), g.colors.end());
    }
    std::vector<std::uint32_t> material(g.symbols.size());
    for (std::size_t s = 0; s < g.symbols.size(); ++s) {
        material[s] = material_for(instance.at, g.symbols[s], &g);
    }
    for (std::size_t f = 0; f + 1 < g.face_offsets.size(); ++f) {
        const std::uint32_t begin = g.face_offsets[f];
        const std::uint32_t end = g.face_offsets[f + 1];
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint32_t k = (!mirror || i == begin) ? i : begin + (end - i);
            if (texcoords_ok_[0]) {
                out_.corner_texcoords.push_back(g.corner_texcoords[0][k]);
            }
            if (texcoords_ok_[1]) {
                out_.corner_texcoords1.push_back(g.corner_texcoords[1][k]);
            }
            if (corner_normals_ok_) {
                out_.corner_normals.push_back(t.is_identity() ? g.corner_normals[k]
                                                              : t.normal(g.corner_normals[k]));
            }
        }
        out_.face_materials.push_back(f < g.face_symbols.size() ? material[g.face_symbols[f]]
                                                                : material_for({}, ""));
    }
}

// The index in out_.materials of what `symbol` is bound to at the instancing element `at`
// (or, unbound, of the <material> whose id it is); an unnamed material for none.
std::uint32_t SceneReader::material_for(pugi::xml_node at, const std::string& symbol,
                                        const collada::GeometryData* g) {
    pugi::xml_node target, binding;
    for (pugi::xml_node bound :
         at.child("bind_material").child("technique_common").children("instance_material")) {
        const std::string_view url = bound.attribute("target").value();
        if (symbol == bound.attribute("symbol").value() && url.size() > 1 && url[0] == '#') {
            target = doc_.find_id(url.substr(1));
            binding = bound;
            break;
        }
    }
    if (!target && !symbol.empty()) {
        target = doc_.find_id(symbol);
    }
    if (!target || std::strcmp(target.name(), "material") != 0) {
        if (no_material_ == std::numeric_limits<std::uint32_t>::max()) {
            no_material_ = static_cast<std::uint32_t>(out_.materials.size());
            Material none;
            none.has_base_colour = false;
            none.has_opacity = false;
            out_.materials.push_back(none);
        }
        return no_material_;
    }
    any_material_ = true;
    const auto [it, fresh] = material_index_.emplace(
        target.internal_object(), static_cast<std::uint32_t>(out_.materials.size()));
    if (fresh) {
        Material m = collada::read_material(doc_, target);
        // The texture's texcoord names a semantic the binding maps to an input set: the
        // geometry's second set's number makes it MeshEdit's second set.
        const std::string semantic = collada::diffuse_texcoord(doc_, target);
        for (pugi::xml_node input : binding.children("bind_vertex_input")) {
            if (!semantic.empty() && semantic == input.attribute("semantic").value() && g &&
                g->second_texcoord_set &&
                input.attribute("input_set").as_ullong(~0ull) == *g->second_texcoord_set) {
                m.base_colour_texcoord = 1;
            }
        }
        out_.materials.push_back(std::move(m));
    }
    return it->second;
}

MeshSoup SceneReader::read() {
    const Mat4 up = read_asset();
    const pugi::xml_node root = doc_.root();
    pugi::xml_node scene;
    if (const pugi::xml_node instance = root.child("scene").child("instance_visual_scene")) {
        scene = doc_.resolve(instance.attribute("url").value(), instance);
        if (std::strcmp(scene.name(), "visual_scene") != 0) {
            doc_.fail(instance,
                      std::string("url names a <") + scene.name() + ">, not a <visual_scene>");
        }
    } else if ((scene = root.child("library_visual_scenes").child("visual_scene"))) {
        out_.notices.push_back("no <scene>: used the first <visual_scene>");
    }
    if (scene) {
        visit_children(scene, up, 0);
    } else {
        out_.notices.push_back("no <visual_scene>: loaded every <geometry> untransformed");
        for (pugi::xml_node library : root.children("library_geometries")) {
            for (pugi::xml_node geometry : library.children("geometry")) {
                instances_.push_back({geometry, geometry, up});
            }
        }
    }
    if (instances_.empty()) {
        throw IoError(doc_.file(), "", "the scene instances no <geometry>");
    }
    if (skipped_transforms_ > 0) {
        out_.notices.push_back("ignored " + std::to_string(skipped_transforms_) +
                               " <skew> transform(s)");
    }

    std::unordered_map<const void*, std::size_t> uses;
    for (const Instance& instance : instances_) {
        ++uses[instance.geometry.internal_object()];
    }
    std::unordered_map<const void*, collada::GeometryData> geometries;
    for (const Instance& instance : instances_) {
        auto it = geometries.find(instance.geometry.internal_object());
        if (it == geometries.end()) {
            it = geometries
                     .emplace(instance.geometry.internal_object(),
                              collada::read_geometry(doc_, instance.geometry))
                     .first;
            for (const std::string& notice : it->second.notices) {
                out_.notices.push_back(notice);
            }
        }
        append(instance, it->second, --uses[instance.geometry.internal_object()] == 0);
    }
    if (!normals_ok_) {
        out_.normals.clear();
    }
    // Normals one per position stay that (the seamless case); else the corners' own.
    if (normals_ok_ || !corner_normals_ok_) {
        out_.corner_normals.clear();
    }
    // Geometries with texture coordinates or colours beside some without: said in a line.
    for (const std::size_t set : {0, 1}) {
        if (!texcoords_ok_[set] && any_uv_[set]) {
            out_.notices.push_back(
                std::string(set == 0 ? "texture coordinates"
                                     : "the second texture coordinate set") +
                " not kept: some instanced geometries have none; the mesh loads without " +
                (set == 0 ? "them" : "it"));
        }
    }
    if (!colors_ok_ && any_colour_) {
        out_.notices.push_back(
            "vertex colours not kept: some instanced geometries have none; "
            "the mesh loads without them");
    }
    if (!texcoords_ok_[0]) {
        out_.corner_texcoords.clear();
    }
    if (!texcoords_ok_[1]) {
        out_.corner_texcoords1.clear();
    }
    if (!colors_ok_) {
        out_.colors.clear();
    }
    if (!any_material_) {
        out_.face_materials.clear();
        out_.materials.clear();
    }
    if (doc_.decimal_commas()) {
        out_.notices.push_back(
            "read numbers written with decimal commas (\"0,5\", the exporter's locale) as "
            "decimal points");
    }
    return std::move(out_);
}

}  // namespace

MeshSoup read_collada(const std::filesystem::path& path) {
    return parse_collada(read_file(path), path.string());
}

MeshSoup parse_collada(std::string bytes, const std::string& name) {
    const Document doc(std::move(bytes), name);
    return SceneReader(doc).read();
}

}  // namespace meshedit
