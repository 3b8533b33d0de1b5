// COLLADA reader, part 2: one <geometry>/<mesh> (sources, accessors, <vertices>, primitive
// blocks, MeshEdit's crease <extra>) into a local polygon soup indexed by position.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>

#include "collada_detail.h"
#include "meshedit/core/memory.h"

namespace meshedit::collada {
namespace {

// Offsets beyond this are certainly broken files; it also bounds the tuple stride.
constexpr std::uint64_t kMaxInputOffset = 1u << 16;

std::string str(std::uint64_t n) {
    return std::to_string(n);
}

// A source's accessor: `count` tuples of `stride` numbers starting at `offset`, of which
// `components` (positions of the named <param>s) are used.
struct Accessor {
    pugi::xml_node node;
    std::uint64_t count = 0;
    std::uint64_t stride = 1;
    std::uint64_t offset = 0;
    std::vector<std::uint64_t> components;
};

Accessor read_accessor(const Document& doc, pugi::xml_node source) {
    if (std::strcmp(source.name(), "source") != 0) {
        doc.fail(source, std::string("expected a <source>, found <") + source.name() + ">");
    }
    Accessor a;
    a.node = source.child("technique_common").child("accessor");
    if (!a.node) {
        doc.fail(source, "missing <technique_common>/<accessor>");
    }
    if (!a.node.attribute("count")) {
        doc.fail(a.node, "missing count attribute");
    }
    a.count = count_attribute(doc, a.node, "count", 0);
    a.stride = count_attribute(doc, a.node, "stride", 1);
    a.offset = count_attribute(doc, a.node, "offset", 0);
    if (a.stride == 0) {
        doc.fail(a.node, "stride=\"0\"");
    }
    // A <param> without a name is a slot the reader skips (COLLADA 1.4.1 §5 "accessor").
    std::uint64_t slot = 0;
    bool any_param = false;
    for (pugi::xml_node param : a.node.children("param")) {
        any_param = true;
        if (*param.attribute("name").value() != '\0') {
            a.components.push_back(slot);
        }
        ++slot;
    }
    if (!any_param) {
        for (std::uint64_t i = 0; i < std::min<std::uint64_t>(a.stride, 4); ++i) {
            a.components.push_back(i);
        }
    }
    if (slot > a.stride) {
        doc.fail(a.node, "has " + str(slot) + " <param>s but stride=\"" + str(a.stride) + "\"");
    }
    return a;
}

// A source's accessor and its <float_array>'s numbers, checked to hold `count` tuples of at
// least `need` named components.
struct Checked {
    Accessor a;
    std::vector<double> values;
};

Checked checked_source(const Document& doc, pugi::xml_node source, const char* what,
                       std::size_t need, const char* names) {
    Checked c{read_accessor(doc, source), {}};
    const Accessor& a = c.a;
    if (a.components.size() < need) {
        doc.fail(a.node, std::string(what) + " need " + str(need) + " components (" + names +
                             "); the accessor has " + str(a.components.size()));
    }
    const pugi::xml_attribute url = a.node.attribute("source");
    const pugi::xml_node array =
        url ? doc.resolve(url.value(), a.node) : source.child("float_array");
    if (!array || std::strcmp(array.name(), "float_array") != 0) {
        doc.fail(a.node, std::string("the accessor's source is not a <float_array>"));
    }
    c.values = parse_doubles(doc, array);
    const std::uint64_t size = c.values.size();
    if (array.attribute("count") && count_attribute(doc, array, "count", 0) != size) {
        doc.fail(array, "count=\"" + std::string(array.attribute("count").value()) +
                            "\" but it holds " + str(size) + " numbers");
    }
    // Checked before allocating, so a huge count attribute cannot cost memory.
    const std::uint64_t last_component = a.components.back();
    const bool fits =
        a.count == 0 || (a.offset + last_component < size &&
                         (a.count - 1) <= (size - 1 - a.offset - last_component) / a.stride);
    if (!fits) {
        doc.fail(a.node, "reads " + str(a.count) + " tuples of stride " + str(a.stride) +
                             " from offset " + str(a.offset) + ", past the end of its " +
                             "<float_array> (" + str(size) + " numbers)");
    }
    return c;
}

// The tuples of a 3-component source (positions, normals), checked against its array.
std::vector<Vec3> read_vec3_source(const Document& doc, pugi::xml_node source, const char* what) {
    const Checked c = checked_source(doc, source, what, 3, "X, Y, Z");
    const Accessor& a = c.a;
    const std::vector<double>& values = c.values;
    std::vector<Vec3> tuples;
    tuples.reserve(a.count);
    memory::advise_huge_pages(tuples.data(), a.count * sizeof(Vec3));
    tuples.resize(a.count);
    for (std::uint64_t i = 0; i < a.count; ++i) {
        const std::uint64_t base = a.offset + i * a.stride;
        tuples[i] = {values[base + a.components[0]], values[base + a.components[1]],
                     values[base + a.components[2]]};
    }
    return tuples;
}

// The first `width` components of each tuple of a source (texture coordinates: 2, colours:
// 4), NaN where the accessor names fewer (an RGB colour's alpha).
std::vector<double> read_tuples(const Document& doc, pugi::xml_node source, const char* what,
                                std::size_t need, std::size_t width, const char* names) {
    const Checked c = checked_source(doc, source, what, need, names);
    std::vector<double> out(c.a.count * width, std::numeric_limits<double>::quiet_NaN());
    const std::size_t k = std::min(width, c.a.components.size());
    for (std::uint64_t i = 0; i < c.a.count; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
            out[i * width + j] = c.values[c.a.offset + i * c.a.stride + c.a.components[j]];
        }
    }
    return out;
}

void check_finite_positions(const Document& doc, pugi::xml_node source,
                            const std::vector<Vec3>& positions) {
    for (std::size_t i = 0; i < positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            if (!std::isfinite(positions[i][k])) {
                const pugi::xml_node array = source.child("float_array");
                doc.fail(array ? array : source,
                         "position " + str(i) + " has a non-finite coordinate (" +
                             (std::isnan(positions[i][k]) ? "NaN" : "infinity") + ")");
            }
        }
    }
}

// MeshEdit's two texture coordinate sets, as messages name them.
constexpr const char* kSetNames[2] = {"texture coordinates", "second texture coordinate set"};

class GeometryReader {
public:
    GeometryReader(const Document& doc, pugi::xml_node geometry) : doc_(doc), geometry_(geometry) {}

    GeometryData read();

private:
    struct Input {
        pugi::xml_node node;
        std::string_view semantic;
        std::uint64_t offset = 0;
        std::uint64_t limit = 0;                      // number of tuples an index may address
        const std::vector<Vec3>* vec = nullptr;       // normals, for NORMAL
        const std::vector<double>* tuples = nullptr;  // TEXCOORD: 2 a tuple, COLOR: 4
        std::uint64_t set = 0;
    };
    struct Inputs {
        std::uint64_t stride = 0;  // max offset + 1
        std::uint64_t vertex_offset = 0;
        std::vector<Input> all;
        const Input* normal() const { return first("NORMAL"); }
        // The first of the lowest set: a file's main texture coordinates or colours.
        const Input* first(std::string_view semantic) const {
            return lowest(semantic, std::nullopt);
        }
        // The first input of the lowest set (of any set, or only of those above `above`).
        const Input* lowest(std::string_view semantic, std::optional<std::uint64_t> above) const {
            const Input* found = nullptr;
            for (const Input& input : all) {
                if (input.semantic == semantic && (!above || input.set > *above) &&
                    (!found || input.set < found->set)) {
                    found = &input;
                }
            }
            return found;
        }
        // MeshEdit's texture coordinate set k (0, 1): the lowest TEXCOORD set, and the next.
        const Input* texcoord(std::size_t k) const {
            const Input* first_set = first("TEXCOORD");
            return k == 0 || !first_set ? first_set : lowest("TEXCOORD", first_set->set);
        }
    };

    Inputs read_inputs(pugi::xml_node primitive);
    void read_triangles(pugi::xml_node primitive, const Inputs& inputs);
    void read_polylist(pugi::xml_node primitive, const Inputs& inputs);
    void read_polygons(pugi::xml_node primitive, const Inputs& inputs);
    void read_strips(pugi::xml_node primitive, const Inputs& inputs, bool fan);
    std::vector<std::uint32_t> read_p(pugi::xml_node primitive, pugi::xml_node p,
                                      std::uint64_t count);
    // `sizes` holds the corner count of each of `n_polygons` polygons; null means triangles.
    void add_polygons(pugi::xml_node p, std::vector<std::uint32_t>&& indices, const Inputs& inputs,
                      std::size_t n_polygons, const std::uint32_t* sizes);
    void track_normals();
    void read_creases(pugi::xml_node mesh);
    void add_corner_attributes(pugi::xml_node p, const Inputs& inputs, const std::uint32_t* corner);
    void finish_attributes();
    void drop_out_of_range(pugi::xml_node p, const Inputs& inputs, const Input& input,
                           std::uint32_t index);
    const std::vector<Vec3>& vec3_source(pugi::xml_node source, const char* what);

    const Document& doc_;
    pugi::xml_node geometry_;
    pugi::xml_node vertices_;
    GeometryData g_;
    std::unordered_map<const void*, std::vector<Vec3>> cache_;
    std::unordered_map<const void*, std::vector<double>> tuple_cache_;
    // Per texture coordinate set (MeshEdit's two): every corner so far has one; some
    // primitive had the input.
    bool texcoords_ok_[2] = {true, true}, any_uv_[2] = {false, false};
    bool corner_normals_ok_ = true, colors_ok_ = true;
    bool other_sets_said_ = false;  // a third texture coordinate set's notice given
    // MeshEdit's <extra> says the file's one set is the mesh's second (a mesh without a first).
    bool second_set_only_ = false;
    std::optional<std::uint64_t> first_set_;  // the first primitive's lowest TEXCOORD set
    std::vector<std::uint8_t> colour_seen_;
    std::size_t colour_seams_ = 0;  // positions whose corners' colours differ
    std::string attribute_problem_;
    bool any_colour_ = false;  // some primitive had the input
    // Per-position normal agreement across corners: 0 unseen, 1 set.
    std::vector<std::uint8_t> normal_seen_;
    std::vector<Vec3> corner_normals_;
    bool normals_ok_ = true;
    bool vertex_normals_ = false;  // normals given per position in <vertices>
};

const std::vector<Vec3>& GeometryReader::vec3_source(pugi::xml_node source, const char* what) {
    const auto it = cache_.find(source.internal_object());
    if (it != cache_.end()) {
        return it->second;
    }
    return cache_.emplace(source.internal_object(), read_vec3_source(doc_, source, what))
        .first->second;
}

GeometryData GeometryReader::read() {
    const pugi::xml_node mesh = geometry_.child("mesh");
    if (!mesh) {
        g_.notices.push_back("ignored " + doc_.where(geometry_) +
                             ": only <mesh> geometry is supported");
        return std::move(g_);
    }
    vertices_ = mesh.child("vertices");
    if (!vertices_) {
        doc_.fail(mesh, "missing <vertices>");
    }
    pugi::xml_node position_input =
        vertices_.find_child_by_attribute("input", "semantic", "POSITION");
    if (!position_input) {
        doc_.fail(vertices_, "no <input semantic=\"POSITION\">");
    }
    const pugi::xml_node position_source =
        doc_.resolve(position_input.attribute("source").value(), position_input);
    // Not through the cache: the positions are moved into the result, never copied. A file
    // that also uses this source for normals parses it twice.
    g_.positions = read_vec3_source(doc_, position_source, "positions");
    check_finite_positions(doc_, position_source, g_.positions);

    if (pugi::xml_node n = vertices_.find_child_by_attribute("input", "semantic", "NORMAL")) {
        const auto& normals =
            vec3_source(doc_.resolve(n.attribute("source").value(), n), "normals");
        vertex_normals_ = normals.size() == g_.positions.size();
        normals_ok_ = vertex_normals_;
        if (vertex_normals_) {
            corner_normals_ = normals;
        }
    }

    std::map<std::string, int> ignored;
    bool any_primitive = false;
    for (pugi::xml_node child : mesh.children()) {
        const std::string_view name = child.name();
        if (name == "triangles" || name == "polylist" || name == "polygons" || name == "trifans" ||
            name == "tristrips") {
            any_primitive = true;
            const Inputs inputs = read_inputs(child);
            if (name == "triangles") {
                read_triangles(child, inputs);
            } else if (name == "polylist") {
                read_polylist(child, inputs);
            } else if (name == "polygons") {
                read_polygons(child, inputs);
            } else {
                read_strips(child, inputs, name == "trifans");
            }
        } else if (name == "lines" || name == "linestrips") {
            ++ignored[std::string(name)];
        }
    }
    for (const auto& [name, n] : ignored) {
        g_.notices.push_back("ignored " + str(static_cast<std::uint64_t>(n)) + " <" + name +
                             "> block" + (n > 1 ? "s" : "") + " in " + doc_.where(geometry_) +
                             " (unsupported primitive)");
    }
    read_creases(mesh);
    finish_attributes();
    if (second_set_only_ && g_.corner_texcoords[1].empty()) {
        std::swap(g_.corner_texcoords[0], g_.corner_texcoords[1]);
        g_.second_texcoord_set = first_set_;
    }

    if (!any_primitive) {
        normals_ok_ = vertex_normals_;
    }
    if (normals_ok_ && !g_.positions.empty()) {
        track_normals();  // no corner had a normal input: the normals stay zero
        for (const Vec3& n : corner_normals_) {
            normals_ok_ = normals_ok_ && is_finite(n);
        }
    }
    if (normals_ok_ && !g_.positions.empty()) {
        g_.normals = std::move(corner_normals_);
    }
    return std::move(g_);
}

GeometryReader::Inputs GeometryReader::read_inputs(pugi::xml_node primitive) {
    Inputs inputs;
    bool has_vertex = false;
    for (pugi::xml_node node : primitive.children("input")) {
        Input input;
        input.node = node;
        input.semantic = node.attribute("semantic").value();
        input.offset = count_attribute(doc_, node, "offset", 0);
        if (input.offset >= kMaxInputOffset) {
            doc_.fail(node, "offset=\"" + str(input.offset) + "\" is too large");
        }
        inputs.stride = std::max(inputs.stride, input.offset + 1);
        if (input.semantic == "VERTEX") {
            const pugi::xml_node target = doc_.resolve(node.attribute("source").value(), node);
            if (target != vertices_) {
                doc_.fail(node, "the VERTEX input must name this mesh's <vertices>");
            }
            if (!has_vertex) {
                inputs.vertex_offset = input.offset;
            }
            has_vertex = true;
            input.limit = g_.positions.size();
        } else if (input.semantic == "NORMAL" || input.semantic == "TEXCOORD" ||
                   input.semantic == "COLOR") {
            const pugi::xml_node source = doc_.resolve(node.attribute("source").value(), node);
            input.set = count_attribute(doc_, node, "set", 0);
            if (input.semantic == "NORMAL") {
                input.vec = &vec3_source(source, "normals");
                input.limit = input.vec->size();
            } else {
                const bool uv = input.semantic == "TEXCOORD";
                auto it = tuple_cache_.find(source.internal_object());
                if (it == tuple_cache_.end()) {
                    it = tuple_cache_
                             .emplace(
                                 source.internal_object(),
                                 uv ? read_tuples(doc_, source, "texture coordinates", 2, 2, "S, T")
                                    : read_tuples(doc_, source, "colours", 3, 4, "R, G, B"))
                             .first;
                }
                input.tuples = &it->second;
                input.limit = it->second.size() / (uv ? 2 : 4);
            }
        } else {
            continue;  // other semantics only take part in the stride
        }
        inputs.all.push_back(input);
    }
    if (!has_vertex) {
        doc_.fail(primitive, "no <input semantic=\"VERTEX\">");
    }
    // Two texture coordinate sets are kept: the others are said, once per geometry.
    const Input* kept[2] = {inputs.texcoord(0), inputs.texcoord(1)};
    if (kept[1] && !g_.second_texcoord_set) {
        g_.second_texcoord_set = kept[1]->set;
    }
    if (kept[0] && !first_set_) {
        first_set_ = kept[0]->set;
    }
    for (const Input& input : inputs.all) {
        if (input.semantic == "TEXCOORD" && &input != kept[0] && &input != kept[1] &&
            !other_sets_said_) {
            g_.notices.push_back("texture coordinate set " + str(input.set) + " of " +
                                 doc_.where(geometry_) + " not kept (MeshEdit keeps two sets, " +
                                 str(kept[0]->set) +
                                 (kept[1] ? " and " + str(kept[1]->set) : std::string()) + ")");
            other_sets_said_ = true;
        }
    }
    return inputs;
}

std::vector<std::uint32_t> GeometryReader::read_p(pugi::xml_node primitive, pugi::xml_node p,
                                                  std::uint64_t count) {
    if (!p) {
        if (count == 0) {
            return {};
        }
        doc_.fail(primitive, "missing <p> (count=\"" + str(count) + "\")");
    }
    return parse_indices(doc_, p);
}

void GeometryReader::read_triangles(pugi::xml_node primitive, const Inputs& inputs) {
    const pugi::xml_node p = primitive.child("p");
    if (!primitive.attribute("count")) {
        doc_.fail(primitive, "missing count attribute");
    }
    const std::uint64_t count = count_attribute(doc_, primitive, "count", 0);
    std::vector<std::uint32_t> indices = read_p(primitive, p, count);
    const std::uint64_t per_triangle = 3 * inputs.stride;
    if (indices.size() / per_triangle != count || indices.size() % per_triangle != 0) {
        doc_.fail(p, "holds " + str(indices.size()) + " indices, but count=\"" + str(count) +
                         "\" triangles with " + str(inputs.stride) + " index" +
                         (inputs.stride > 1 ? "es" : "") + " per corner need " +
                         (count <= indices.size() ? str(count * per_triangle)
                                                  : "more than the element holds"));
    }
    add_polygons(p, std::move(indices), inputs, count, nullptr);
}

void GeometryReader::read_polylist(pugi::xml_node primitive, const Inputs& inputs) {
    const pugi::xml_node p = primitive.child("p");
    const pugi::xml_node vcount_node = primitive.child("vcount");
    const std::uint64_t count = count_attribute(doc_, primitive, "count", 0);
    if (!vcount_node && count > 0) {
        doc_.fail(primitive, "missing <vcount> (count=\"" + str(count) + "\")");
    }
    const std::vector<std::uint32_t> vcount =
        vcount_node ? parse_indices(doc_, vcount_node) : std::vector<std::uint32_t>{};
    if (primitive.attribute("count") && vcount.size() != count) {
        doc_.fail(vcount_node, "holds " + str(vcount.size()) + " polygon sizes, but count=\"" +
                                   str(count) + "\"");
    }
    std::uint64_t corners = 0;
    for (std::uint32_t n : vcount) {
        corners += n;
    }
    std::vector<std::uint32_t> indices = read_p(primitive, p, corners);
    if (indices.size() / inputs.stride != corners || indices.size() % inputs.stride != 0) {
        doc_.fail(p, "holds " + str(indices.size()) + " indices, but <vcount> lists " +
                         str(corners) + " corners with " + str(inputs.stride) +
                         " index(es) each (" + str(corners * inputs.stride) + ")");
    }
    add_polygons(p, std::move(indices), inputs, vcount.size(), vcount.data());
}

void GeometryReader::read_polygons(pugi::xml_node primitive, const Inputs& inputs) {
    if (const pugi::xml_node ph = primitive.child("ph")) {
        doc_.fail(ph, "polygons with holes (<ph>) are not supported");
    }
    std::uint64_t n_polygons = 0;
    for (pugi::xml_node p : primitive.children("p")) {
        std::vector<std::uint32_t> indices = parse_indices(doc_, p);
        if (indices.size() % inputs.stride != 0) {
            doc_.fail(p, "holds " + str(indices.size()) + " indices, not a multiple of the " +
                             str(inputs.stride) + " indices per corner");
        }
        const auto corners = static_cast<std::uint32_t>(indices.size() / inputs.stride);
        add_polygons(p, std::move(indices), inputs, 1, &corners);
        ++n_polygons;
    }
    if (primitive.attribute("count") &&
        count_attribute(doc_, primitive, "count", 0) != n_polygons) {
        doc_.fail(primitive, "count=\"" + std::string(primitive.attribute("count").value()) +
                                 "\" but it holds " + str(n_polygons) + " <p> elements");
    }
    if (n_polygons == 0 && count_attribute(doc_, primitive, "count", 0) > 0) {
        doc_.fail(primitive, "missing <p>");
    }
}

void GeometryReader::read_strips(pugi::xml_node primitive, const Inputs& inputs, bool fan) {
    for (pugi::xml_node p : primitive.children("p")) {
        const std::vector<std::uint32_t> strip = parse_indices(doc_, p);
        if (strip.size() % inputs.stride != 0) {
            doc_.fail(p, "holds " + str(strip.size()) + " indices, not a multiple of the " +
                             str(inputs.stride) + " indices per corner");
        }
        const std::size_t n = strip.size() / inputs.stride;
        const auto position = [&](std::size_t t) {
            return strip[t * inputs.stride + inputs.vertex_offset];
        };
        // Re-lay the strip's corners as separate triangles; odd strip triangles swap their
        // first two corners to keep one orientation.
        std::vector<std::uint32_t> corners;
        std::size_t n_triangles = 0;
        for (std::size_t i = 0; i + 2 < n; ++i) {
            const std::array<std::size_t, 3> t =
                fan ? std::array<std::size_t, 3>{0, i + 1, i + 2}
                    : (i % 2 == 0 ? std::array<std::size_t, 3>{i, i + 1, i + 2}
                                  : std::array<std::size_t, 3>{i + 1, i, i + 2});
            // Repeated corners stitch strips together; they are not faces.
            if (position(t[0]) == position(t[1]) || position(t[1]) == position(t[2]) ||
                position(t[0]) == position(t[2])) {
                continue;
            }
            for (std::size_t k : t) {
                corners.insert(
                    corners.end(), strip.begin() + static_cast<std::ptrdiff_t>(k * inputs.stride),
                    strip.begin() + static_cast<std::ptrdiff_t>((k + 1) * inputs.stride));
            }
            ++n_triangles;
        }
        add_polygons(p, std::move(corners), inputs, n_triangles, nullptr);
    }
}

// The per-position normal agreement buffers, allocated only once some corner has a normal.
void GeometryReader::track_normals() {
    if (normal_seen_.empty() && !g_.positions.empty()) {
        normal_seen_.assign(g_.positions.size(), 0);
        if (!vertex_normals_) {
            corner_normals_.assign(g_.positions.size(), Vec3{});
        }
    }
}

void GeometryReader::add_polygons(pugi::xml_node p, std::vector<std::uint32_t>&& indices,
                                  const Inputs& inputs, std::size_t n_polygons,
                                  const std::uint32_t* sizes) {
    const Input* normal_input = vertex_normals_ ? nullptr : inputs.normal();
    if (normal_input) {
        track_normals();
    } else if (!vertex_normals_ && !indices.empty()) {  // some corner has no normal
        normals_ok_ = false;
    }
    // The callers checked that `indices` holds exactly one tuple per corner. The first block
    // packs its position indices into its own array (tuple t is read before slot t <= t *
    // stride is written), which then becomes the soup's: no second array of that size.
    const std::uint64_t stride = inputs.stride;
    const std::size_t n_tuples = indices.size() / stride;
    const bool in_place = g_.indices.empty();
    const std::size_t base = g_.indices.size();
    if (!in_place) {
        g_.indices.resize(base + n_tuples);
    }
    std::uint32_t* out = in_place ? indices.data() : g_.indices.data() + base;
    memory::reserve_more(g_.face_offsets, n_polygons);
    std::uint64_t tuple = 0;
    for (std::size_t f = 0; f < n_polygons; ++f) {
        const std::uint32_t n = sizes ? sizes[f] : 3;
        for (std::uint32_t k = 0; k < n; ++k, ++tuple) {
            const std::uint32_t* corner = indices.data() + tuple * stride;
            for (const Input& input : inputs.all) {
                const std::uint32_t index = corner[input.offset];
                if (index >= input.limit &&
                    (input.semantic == "TEXCOORD" || input.semantic == "COLOR")) {
                    drop_out_of_range(p, inputs, input, index);
                } else if (index >= input.limit) {
                    doc_.fail(p, std::string(input.semantic) + " index " + str(index) +
                                     " out of range (" + str(input.limit) +
                                     (input.semantic == "VERTEX" ? " positions)" : " entries)"));
                }
            }
            const std::uint32_t position = corner[inputs.vertex_offset];
            const std::uint32_t normal_index = normal_input ? corner[normal_input->offset] : 0;
            add_corner_attributes(p, inputs, corner);
            out[tuple] = position;
            if (!normal_input) {
                continue;
            }
            const Vec3& normal = (*normal_input->vec)[normal_index];
            // Exact comparison: shared normals repeat the same text, so they parse equal.
            if (normal_seen_[position] == 0) {
                normal_seen_[position] = 1;
                corner_normals_[position] = normal;
            } else if (!(corner_normals_[position] == normal)) {
                normals_ok_ = false;
            }
        }
        g_.face_offsets.push_back(static_cast<std::uint32_t>(base + tuple));
    }
    // The primitive's material symbol, per face.
    const pugi::xml_node primitive = std::strcmp(p.name(), "p") == 0 ? p.parent() : p;
    const std::string symbol = primitive.attribute("material").value();
    auto s = std::find(g_.symbols.begin(), g_.symbols.end(), symbol);
    if (s == g_.symbols.end()) {
        s = g_.symbols.insert(s, symbol);
    }
    g_.face_symbols.resize(g_.face_offsets.size() - 1,
                           static_cast<std::uint32_t>(s - g_.symbols.begin()));
    if (in_place) {
        indices.resize(n_tuples);
        g_.indices = std::move(indices);
    }
}

// A corner's texture coordinate and normal (kept per corner) and colour (per position: a
// vertex has one colour, its first corner's). A primitive without one of the inputs drops
// that attribute for the whole geometry; a value that is not a number drops it with a notice.
void GeometryReader::add_corner_attributes(pugi::xml_node p, const Inputs& inputs,
                                           const std::uint32_t* corner) {
    const Input* normal = inputs.normal();
    const Input* colour = inputs.first("COLOR");
    const std::string where = doc_.where(p);
    for (std::size_t k = 0; k < 2; ++k) {
        const Input* uv = inputs.texcoord(k);
        if (texcoords_ok_[k] && uv) {
            const double* t = uv->tuples->data() + 2 * std::size_t{corner[uv->offset]};
            if (!std::isfinite(t[0]) || !std::isfinite(t[1])) {
                texcoords_ok_[k] = false;
                attribute_problem_ += "; " + std::string(kSetNames[k]) + " not kept: " + where +
                                      " names one that is not a number";
            }
            g_.corner_texcoords[k].push_back({t[0], t[1]});
        }
        texcoords_ok_[k] = texcoords_ok_[k] && uv;
        any_uv_[k] = any_uv_[k] || uv;
    }
    any_colour_ = any_colour_ || colour;
    if (corner_normals_ok_ && normal && !vertex_normals_) {
        g_.corner_normals.push_back((*normal->vec)[corner[normal->offset]]);
    }
    corner_normals_ok_ = corner_normals_ok_ && normal && !vertex_normals_;
    if (colors_ok_ && colour) {
        const double* c = colour->tuples->data() + 4 * std::size_t{corner[colour->offset]};
        const Vec4 rgba{c[0], c[1], c[2], std::isnan(c[3]) ? 1.0 : c[3]};
        if (!std::isfinite(rgba.x) || !std::isfinite(rgba.y) || !std::isfinite(rgba.z) ||
            !std::isfinite(rgba.w)) {
            colors_ok_ = false;
            attribute_problem_ +=
                "; vertex colours not kept: " + where + " names one " + "that is not a number";
        }
        if (colour_seen_.empty()) {
            colour_seen_.assign(g_.positions.size(), 0);
            g_.colors.assign(g_.positions.size(), Vec4{1, 1, 1, 1});
        }
        const std::uint32_t position = corner[inputs.vertex_offset];
        if (colour_seen_[position] == 0) {
            colour_seen_[position] = 1;
            g_.colors[position] = rgba;
        } else if (!(g_.colors[position] == rgba)) {
            ++colour_seams_;
        }
    }
    colors_ok_ = colors_ok_ && colour;
}

// A texture coordinate or colour index past its source drops that attribute (the one in
// use; an unused set's is never read), with a notice: the mesh still loads.
void GeometryReader::drop_out_of_range(pugi::xml_node p, const Inputs& inputs, const Input& input,
                                       std::uint32_t index) {
    const bool uv = input.semantic == "TEXCOORD";
    const std::size_t k = uv && inputs.texcoord(1) == &input ? 1 : 0;
    bool& ok = uv ? texcoords_ok_[k] : colors_ok_;
    if (!ok || (uv ? inputs.texcoord(k) : inputs.first(input.semantic)) != &input) {
        return;
    }
    ok = false;
    attribute_problem_ += std::string("; ") + (uv ? kSetNames[k] : "vertex colours") +
                          " not kept: " + doc_.where(p) + " names " + std::string(input.semantic) +
                          " index " + str(index) + " of " + str(input.limit) + " entries";
}

void GeometryReader::finish_attributes() {
    const bool any_face = g_.face_offsets.size() > 1;
    for (std::size_t k = 0; k < 2; ++k) {
        if (!texcoords_ok_[k] || !any_face) {
            g_.corner_texcoords[k].clear();
        }
    }
    if (!corner_normals_ok_ || !any_face) {
        g_.corner_normals.clear();
    }
    if (!colors_ok_ || !any_face) {
        g_.colors.clear();
    } else if (colour_seams_ > 0) {
        g_.notices.push_back("kept one colour per vertex in " + doc_.where(geometry_) + ": " +
                             str(colour_seams_) + " corner(s) had another colour than their " +
                             "vertex's first corner");
    }
    // Some primitives with the input and some without: said, never dropped without a word.
    for (std::size_t k = 0; k < 2; ++k) {
        const std::string said = "; " + std::string(kSetNames[k]);
        if (any_uv_[k] && !texcoords_ok_[k] && attribute_problem_.find(said) == std::string::npos) {
            attribute_problem_ += said + " not kept: some primitives of " + doc_.where(geometry_) +
                                  " have no " + (k == 0 ? "TEXCOORD input" : "second TEXCOORD set");
        }
    }
    if (any_colour_ && !colors_ok_ && attribute_problem_.find("colours") == std::string::npos) {
        attribute_problem_ += "; vertex colours not kept: some primitives of " +
                              doc_.where(geometry_) + " have no COLOR input";
    }
    if (!attribute_problem_.empty()) {
        g_.notices.push_back(attribute_problem_.substr(2) + "; the mesh loads without them");
    }
}

void GeometryReader::read_creases(pugi::xml_node mesh) {
    for (pugi::xml_node extra : mesh.children("extra")) {
        const pugi::xml_node technique =
            extra.find_child_by_attribute("technique", "profile", "MeshEdit");
        second_set_only_ = second_set_only_ || technique.child("second_texcoord_set_only");
        const pugi::xml_node creases = technique.child("creases");
        if (!creases) {
            continue;
        }
        const std::vector<std::uint32_t> ends = parse_indices(doc_, creases);
        if (ends.size() % 2 != 0) {
            doc_.fail(creases, "holds an odd number of indices (" + str(ends.size()) + ")");
        }
        if (creases.attribute("count") &&
            count_attribute(doc_, creases, "count", 0) != ends.size() / 2) {
            doc_.fail(creases, "count=\"" + std::string(creases.attribute("count").value()) +
                                   "\" but it holds " + str(ends.size() / 2) + " pairs");
        }
        for (std::size_t i = 0; i < ends.size(); i += 2) {
            for (std::uint32_t end : {ends[i], ends[i + 1]}) {
                if (end >= g_.positions.size()) {
                    doc_.fail(creases, "index " + str(end) + " out of range (" +
                                           str(g_.positions.size()) + " positions)");
                }
            }
            g_.creases.emplace_back(ends[i], ends[i + 1]);
        }
    }
}

}  // namespace

GeometryData read_geometry(const Document& doc, pugi::xml_node geometry) {
    return GeometryReader(doc, geometry).read();
}

}  // namespace meshedit::collada
