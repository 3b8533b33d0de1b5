// Stanford PLY: a reader of our own (the writer is in ply_write.cpp).
//
// Read: the header (`ply`, `format`, `element`, `property`, `comment`, `obj_info`,
// `end_header`; elements in any order), then each element's records as ASCII lines or packed
// binary. Stored: vertex x y z, nx ny nz, the face list `vertex_indices` (or `vertex_index`),
// and every other scalar vertex or face property as a user property ("v:ply:quality",
// "f:ply:label"; io.h, UserProperty) that the writer writes back. Vertex colours, texture
// coordinates and face `texcoord` lists become MeshEdit's own attributes (ply_attributes.cpp);
// other list properties and other elements are read past and named in one notice each, never
// dropped without a word.
//
// Binary bodies are decoded straight from the file's bytes with memcpy (no streams): a switch
// on the property type per value, which the branch predictor learns after one record. Counts
// come from the header, so they may lie: nothing is reserved beyond what the remaining bytes
// can hold, and every list length is checked against them before it is read.

#include "meshedit/io/ply.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io_util.h"
#include "meshedit/core/mesh.h"
#include "ply_attributes.h"

namespace meshedit {
namespace {

enum class Type : std::uint8_t { I8, U8, I16, U16, I32, U32, F32, F64 };

std::size_t size_of(Type t) {
    switch (t) {
        case Type::I8:
        case Type::U8:
            return 1;
        case Type::I16:
        case Type::U16:
            return 2;
        case Type::I32:
        case Type::U32:
        case Type::F32:
            return 4;
        case Type::F64:
            return 8;
    }
    return 1;
}

bool is_integer(Type t) {
    return t != Type::F32 && t != Type::F64;
}

std::optional<Type> type_named(std::string_view s) {
    struct Name {
        const char* name;
        Type type;
    };
    static constexpr Name kNames[] = {
        {"char", Type::I8},   {"int8", Type::I8},     {"uchar", Type::U8},   {"uint8", Type::U8},
        {"short", Type::I16}, {"int16", Type::I16},   {"ushort", Type::U16}, {"uint16", Type::U16},
        {"int", Type::I32},   {"int32", Type::I32},   {"uint", Type::U32},   {"uint32", Type::U32},
        {"float", Type::F32}, {"float32", Type::F32}, {"double", Type::F64}, {"float64", Type::F64},
    };
    for (const Name& n : kNames) {
        if (s == n.name) {
            return n.type;
        }
    }
    return std::nullopt;
}

// A value of `T` stored at `p`, byte-swapped when the file's endianness is not the host's.
template <class T>
T load(const char* p, bool swap) {
    using U = std::conditional_t<
        sizeof(T) == 1, std::uint8_t,
        std::conditional_t<sizeof(T) == 2, std::uint16_t,
                           std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
    U u;
    std::memcpy(&u, p, sizeof u);
    if (swap) {
        if constexpr (sizeof(T) == 2) {
            u = __builtin_bswap16(u);
        } else if constexpr (sizeof(T) == 4) {
            u = __builtin_bswap32(u);
        } else if constexpr (sizeof(T) == 8) {
            u = __builtin_bswap64(u);
        }
    }
    return std::bit_cast<T>(u);
}

double value_at(const char* p, Type t, bool swap) {
    switch (t) {
        case Type::I8:
            return load<std::int8_t>(p, swap);
        case Type::U8:
            return load<std::uint8_t>(p, swap);
        case Type::I16:
            return load<std::int16_t>(p, swap);
        case Type::U16:
            return load<std::uint16_t>(p, swap);
        case Type::I32:
            return load<std::int32_t>(p, swap);
        case Type::U32:
            return load<std::uint32_t>(p, swap);
        case Type::F32:
            return load<float>(p, swap);
        case Type::F64:
            return load<double>(p, swap);
    }
    return 0.0;
}

// Whether `x` is a value of type `t` (integers in range; floats: finite or not, all fit).
bool fits(Type t, double x) {
    static constexpr double kLow[] = {-128, 0, -32768, 0, -2147483648.0, 0};
    static constexpr double kHigh[] = {127, 255, 32767, 65535, 2147483647.0, 4294967295.0};
    const auto k = static_cast<std::size_t>(t);
    return !is_integer(t) || (x >= kLow[k] && x <= kHigh[k]);
}

// Counts and indices: integer types only (checked in the header), which a double holds exactly.
std::int64_t whole_at(const char* p, Type t, bool swap) {
    return static_cast<std::int64_t>(value_at(p, t, swap));
}

struct Property {
    std::string name;
    Type type = Type::F32;  // of the value, or of a list's items
    bool list = false;
    Type count_type = Type::U8;
};

struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
};

enum class Format { Ascii, BinaryLittle, BinaryBig };

// What each vertex property is for.
enum class Role : std::uint8_t { X, Y, Z, NX, NY, NZ, Colour, Uv, Other };

Role role_of(std::string_view name) {
    struct Name {
        const char* name;
        Role role;
    };
    // clang-format off
    static constexpr Name kNames[] = {
        {"x", Role::X}, {"y", Role::Y}, {"z", Role::Z},
        {"nx", Role::NX}, {"ny", Role::NY}, {"nz", Role::NZ},
        {"red", Role::Colour}, {"green", Role::Colour}, {"blue", Role::Colour},
        {"alpha", Role::Colour}, {"diffuse_red", Role::Colour}, {"diffuse_green", Role::Colour},
        {"diffuse_blue", Role::Colour}, {"diffuse_alpha", Role::Colour},
        {"s", Role::Uv}, {"t", Role::Uv}, {"u", Role::Uv}, {"v", Role::Uv},
        {"texture_u", Role::Uv}, {"texture_v", Role::Uv},
        {"texture_s", Role::Uv}, {"texture_t", Role::Uv},
    };
    // clang-format on
    for (const Name& n : kNames) {
        if (name == n.name) {
            return n.role;
        }
    }
    return Role::Other;
}

class PlyReader {
public:
    PlyReader(std::string_view bytes, std::string file) : bytes_(bytes), file_(std::move(file)) {}

    MeshSoup read() {
        read_header();
        plan();
        if (format_ == Format::Ascii) {
            read_ascii();
        } else {
            read_binary();
        }
        check_indices();
        say_what_was_not_kept();
        ply_attributes::take(out_, face_uvs_);
        return std::move(out_);
    }

private:
    [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
        throw IoError(file_, where, problem);
    }
    std::string line_of(std::size_t line) const { return "line " + std::to_string(line); }
    // Where a record is: its line in ASCII; binary has no lines (the problem names the record).
    std::string record_where(const Element& /*e*/, std::size_t /*i*/) const {
        return format_ == Format::Ascii ? line_of(line_) : std::string();
    }

    // ------------------------------------------------------------- header

    void read_header() {
        if (bytes_.empty()) {
            fail("", "empty file: no PLY header");
        }
        std::size_t pos = 0;
        bool ended = false;
        bool has_format = false;
        while (pos < bytes_.size()) {
            std::size_t end = bytes_.find('\n', pos);
            const bool last = end == std::string_view::npos;
            end = last ? bytes_.size() : end;
            std::string_view l = bytes_.substr(pos, end - pos);
            pos = last ? end : end + 1;
            ++line_;
            if (line_ == 1) {
                std::string_view probe = l;
                if (io_util::next_token(probe) != "ply" || !io_util::next_token(probe).empty()) {
                    fail("", "not a PLY file: it should start with the line 'ply'");
                }
                continue;
            }
            std::string_view rest = l;
            const std::string_view key = io_util::next_token(rest);
            if (key == "end_header") {
                ended = true;
                break;
            }
            if (key.empty() || key == "comment" || key == "obj_info") {
                continue;
            }
            if (key == "format") {
                read_format(rest);
                has_format = true;
            } else if (key == "element") {
                read_element(rest);
            } else if (key == "property") {
                read_property(rest);
            } else {
                // Blender 2.4 wrote a bare "Created by …" line; nothing needs it.
                if (unknown_lines_++ == 0) {
                    first_unknown_ = line_of(line_) + ": '" + std::string(l.substr(0, 40)) + "'";
                }
            }
        }
        if (!ended) {
            fail("", "the header has no 'end_header' line (a truncated file, or not PLY)");
        }
        if (!has_format) {
            fail("", "the header has no 'format' line");
        }
        body_ = pos;
    }

    void read_format(std::string_view rest) {
        const std::string_view f = io_util::next_token(rest);
        if (f == "ascii") {
            format_ = Format::Ascii;
        } else if (f == "binary_little_endian") {
            format_ = Format::BinaryLittle;
        } else if (f == "binary_big_endian") {
            format_ = Format::BinaryBig;
        } else {
            fail(line_of(line_), "unknown format '" + std::string(f.substr(0, 32)) +
                                     "' (expected ascii, binary_little_endian or "
                                     "binary_big_endian)");
        }
        swap_ = (format_ == Format::BinaryBig) != (std::endian::native == std::endian::big);
    }

    void read_element(std::string_view rest) {
        Element e;
        e.name = std::string(io_util::next_token(rest));
        const std::string_view n = io_util::next_token(rest);
        std::uint64_t count = 0;
        const auto [ptr, ec] = std::from_chars(n.data(), n.data() + n.size(), count);
        if (e.name.empty() || n.empty() || ec != std::errc() || ptr != n.data() + n.size() ||
            count >= kInvalidIndex) {
            fail(line_of(line_),
                 "an element line should be 'element NAME COUNT' with a whole "
                 "count below 4,294,967,295");
        }
        e.count = static_cast<std::size_t>(count);
        elements_.push_back(std::move(e));
    }

    Type type_of(std::string_view name) const {
        const std::optional<Type> t = type_named(name);
        if (!t) {
            fail(line_of(line_), "unknown property type '" + std::string(name.substr(0, 32)) + "'");
        }
        return *t;
    }

    void read_property(std::string_view rest) {
        if (elements_.empty()) {
            fail(line_of(line_), "a property before any element");
        }
        Property p;
        std::string_view t = io_util::next_token(rest);
        if (t == "list") {
            p.list = true;
            p.count_type = type_of(io_util::next_token(rest));
            if (!is_integer(p.count_type)) {
                fail(line_of(line_), "a list's count type must be an integer type");
            }
            t = io_util::next_token(rest);
        }
        p.type = type_of(t);
        p.name = std::string(io_util::next_token(rest));
        if (p.name.empty()) {
            fail(line_of(line_), "a property without a name");
        }
        elements_.back().properties.push_back(std::move(p));
    }

    // Finds the vertex and face elements and what each of their properties is for.
    void plan() {
        for (std::size_t i = 0; i < elements_.size(); ++i) {
            const Element& e = elements_[i];
            if (e.name == "vertex" || e.name == "face") {
                std::size_t& slot = e.name == "vertex" ? vertex_ : face_;
                if (slot != kNone) {
                    fail("", "two '" + e.name + "' elements");
                }
                slot = i;
            } else {
                skipped_elements_ += std::string(skipped_elements_.empty() ? "" : ", ") + "'" +
                                     e.name + "' (" + std::to_string(e.count) + ")";
            }
        }
        if (vertex_ != kNone) {
            const Element& v = elements_[vertex_];
            int found[6] = {-1, -1, -1, -1, -1, -1};
            for (std::size_t k = 0; k < v.properties.size(); ++k) {
                const Property& p = v.properties[k];
                Role r = p.list ? Role::Other : role_of(p.name);
                if (r <= Role::NZ) {
                    if (found[static_cast<int>(r)] >= 0) {
                        fail("", "the vertex property '" + p.name + "' is declared twice");
                    }
                    found[static_cast<int>(r)] = static_cast<int>(k);
                }
                roles_.push_back(r);
            }
            if (found[0] < 0 || found[1] < 0 || found[2] < 0) {
                fail("", "the 'vertex' element has no x, y and z properties");
            }
            for (int c = 0; c < 3; ++c) {
                position_[c] = static_cast<std::size_t>(found[c]);
            }
            has_normals_ = found[3] >= 0 && found[4] >= 0 && found[5] >= 0;
            for (int c = 0; c < 3; ++c) {
                if (has_normals_) {
                    normal_[c] = static_cast<std::size_t>(found[3 + c]);
                } else if (found[3 + c] >= 0) {
                    roles_[static_cast<std::size_t>(found[3 + c])] = Role::Other;
                }
            }
            // Colours and texture coordinates are kept under their own names (v:ply:red) until
            // MeshEdit has attributes of its own for them; writing PLY puts them back.
            for (std::size_t k = 0; k < roles_.size(); ++k) {
                if (roles_[k] == Role::Other || roles_[k] == Role::Colour ||
                    roles_[k] == Role::Uv) {
                    keep_or_ignore(v.properties[k], "v", kept_vertex_, out_.vertex_properties);
                }
            }
        }
        if (face_ != kNone) {
            const Element& f = elements_[face_];
            for (std::size_t k = 0; k < f.properties.size(); ++k) {
                const Property& p = f.properties[k];
                if (p.list && (p.name == "vertex_indices" || p.name == "vertex_index") &&
                    indices_ == kNone) {
                    if (!is_integer(p.type)) {
                        fail("", "the face list '" + p.name + "' holds " +
                                     (p.type == Type::F32 ? "float" : "double") +
                                     " values; vertex indices must be integers");
                    }
                    indices_ = k;
                } else if (p.list && p.name == "texcoord" && texcoord_ == kNone) {
                    texcoord_ = k;
                } else {
                    keep_or_ignore(p, "f", kept_face_, out_.face_properties);
                }
            }
            if (indices_ == kNone) {
                out_.notices.push_back(
                    "the 'face' element has no vertex_indices list: no faces read");
            }
        }
    }

    // A scalar property MeshEdit has no meaning for becomes a user property ("v:ply:quality");
    // a list, or a second property of the same name, is read past with a notice.
    void keep_or_ignore(const Property& p, const char* kind, std::vector<std::size_t>& kept,
                        std::vector<UserProperty>& props) {
        const std::string name = std::string(kind) + ":ply:" + p.name;
        const bool taken = std::any_of(props.begin(), props.end(),
                                       [&](const UserProperty& u) { return u.name == name; });
        if (p.list || taken) {
            note_ignored(kind[0] == 'v' ? "vertex" : "face", p.name);
            return;
        }
        const auto& element = elements_[kind[0] == 'v' ? vertex_ : face_];
        kept.push_back(static_cast<std::size_t>(&p - element.properties.data()));
        props.push_back({name, static_cast<UserProperty::Type>(p.type), {}});
    }

    // Appends record `i`'s values of the kept properties; integers must fit their type.
    void store_kept(const Element& e, std::size_t i, const double* values,
                    const std::vector<std::size_t>& kept, std::vector<UserProperty>& props) {
        for (std::size_t j = 0; j < kept.size(); ++j) {
            const Property& p = e.properties[kept[j]];
            const double x = values[kept[j]];
            if (!fits(p.type, x)) {
                fail(record_where(e, i), e.name + " " + std::to_string(i) + ": '" + p.name +
                                             "' is out of range for its type");
            }
            props[j].values.push_back(p.type == Type::F32 ? double{static_cast<float>(x)} : x);
        }
    }

    void note_ignored(const std::string& element, const std::string& property) {
        ignored_ += std::string(ignored_.empty() ? "" : ", ") + element + "." + property;
    }

    void say_what_was_not_kept() {
        std::vector<std::string>& n = out_.notices;
        if (!ignored_.empty()) {
            n.push_back("ignored properties " + ignored_ + " (MeshEdit has no place for them)");
        }
        if (!skipped_elements_.empty()) {
            n.push_back("skipped elements " + skipped_elements_ +
                        " (MeshEdit reads vertex and face)");
        }
        if (unknown_lines_ > 0) {
            n.push_back("ignored " + std::to_string(unknown_lines_) + " unknown header line" +
                        (unknown_lines_ == 1 ? "" : "s") + " (" + first_unknown_ + ")");
        }
        if (extra_ > 0) {
            n.push_back("ignored " + std::to_string(extra_) + " byte" + (extra_ == 1 ? "" : "s") +
                        " after the last element");
        }
    }

    // ------------------------------------------------------------- records

    // Stores vertex `i` from its property values.
    void store_vertex(const Element& e, std::size_t i, const double* values) {
        const Vec3 p(values[position_[0]], values[position_[1]], values[position_[2]]);
        if (!is_finite(p)) {
            fail(record_where(e, i),
                 "vertex " + std::to_string(i) + " is not finite (NaN or infinity)");
        }
        out_.soup.positions.push_back(p);
        store_kept(e, i, values, kept_vertex_, out_.vertex_properties);
        if (has_normals_) {
            const Vec3 n(values[normal_[0]], values[normal_[1]], values[normal_[2]]);
            out_.normals.push_back(is_finite(n) ? n : Vec3());
        }
    }

    // One index of face `f`; checked now when the vertices came first (else check_indices()).
    void store_index(const Element& e, std::size_t f, std::int64_t i) {
        const bool known = vertex_ != kNone && vertex_ < face_;
        const std::size_t nv = vertex_ == kNone ? 0 : elements_[vertex_].count;
        if (i < 0 || (known && static_cast<std::uint64_t>(i) >= nv)) {
            fail(record_where(e, f), out_of_range(f, i, nv));
        }
        if (i >= static_cast<std::int64_t>(kInvalidIndex)) {
            fail(record_where(e, f), out_of_range(f, i, nv));
        }
        out_.soup.indices.push_back(static_cast<std::uint32_t>(i));
    }

    static std::string out_of_range(std::size_t f, std::int64_t i, std::size_t nv) {
        return "face " + std::to_string(f) + " refers to vertex " + std::to_string(i) +
               ", but the file has " + std::to_string(nv) + " vertices (0 to " +
               std::to_string(nv == 0 ? 0 : nv - 1) + ")";
    }

    void end_face(const Element& e, std::size_t f, const double* values) {
        if (out_.soup.indices.size() >= kInvalidIndex) {
            fail(record_where(e, f), "more than 4,294,967,294 face corners");
        }
        store_kept(e, f, values, kept_face_, out_.face_properties);
        out_.soup.face_offsets.push_back(static_cast<std::uint32_t>(out_.soup.indices.size()));
    }

    void check_indices() {
        const std::size_t nv = out_.soup.positions.size();
        const std::vector<std::uint32_t>& idx = out_.soup.indices;
        for (std::size_t c = 0; c < idx.size(); ++c) {
            if (idx[c] >= nv) {
                const auto& off = out_.soup.face_offsets;
                const std::size_t f =
                    static_cast<std::size_t>(std::upper_bound(off.begin(), off.end(), c) -
                                             off.begin()) -
                    1;
                fail("", out_of_range(f, idx[c], nv));
            }
        }
    }

    // ------------------------------------------------------------- ASCII

    // The next line with content in the body; empty at the end of the file.
    std::string_view next_line() { return io_util::next_content_line(bytes_, pos_, line_); }

    std::string_view token(std::string_view& l, const Element& e, std::size_t i,
                           const Property& p) const {
        const std::string_view t = io_util::next_token(l);
        if (t.empty()) {
            fail(line_of(line_), e.name + " " + std::to_string(i) + ": the line ends before its '" +
                                     p.name + "' value");
        }
        return t;
    }

    double ascii_value(std::string_view t, Type type, const Element& e, std::size_t i,
                       const Property& p) const {
        const std::optional<double> x = io_util::parse_double(t);
        if (!x || (is_integer(type) && std::isfinite(*x) && *x != std::floor(*x))) {
            fail(line_of(line_), e.name + " " + std::to_string(i) + ": '" + p.name +
                                     "' should be a" + (is_integer(type) ? " whole" : "") +
                                     " number, found '" + std::string(t.substr(0, 24)) + "'");
        }
        return *x;
    }

    std::int64_t ascii_whole(std::string_view t, const Element& e, std::size_t i,
                             const Property& p) const {
        const double x = ascii_value(t, Type::I32, e, i, p);
        if (!(x >= -9.0e15 && x <= 9.0e15)) {
            fail(line_of(line_), e.name + " " + std::to_string(i) + ": '" + p.name +
                                     "' is out of range: '" + std::string(t.substr(0, 24)) + "'");
        }
        return static_cast<std::int64_t>(x);
    }

    void read_ascii() {
        pos_ = body_;
        for (std::size_t ei = 0; ei < elements_.size(); ++ei) {
            const Element& e = elements_[ei];
            // A record takes at least two bytes ("0\n"): reserve no more than the file can hold.
            if (e.properties.empty()) {
                continue;  // nothing on its lines to read
            }
            const std::size_t left = pos_ < bytes_.size() ? bytes_.size() - pos_ : 0;
            const std::size_t room = std::min(e.count, left / 2 + 1);
            if (ei == vertex_) {
                out_.soup.positions.reserve(room);
            } else if (ei == face_) {
                out_.soup.face_offsets.reserve(room + 1);
            }
            std::vector<double> values(e.properties.size(), 0.0);
            for (std::size_t i = 0; i < e.count; ++i) {
                std::string_view l = next_line();
                if (l.empty()) {
                    fail("", "the file ends after " + std::to_string(i) + " of the " +
                                 std::to_string(e.count) + " '" + e.name +
                                 "' records the header announced");
                }
                for (std::size_t k = 0; k < e.properties.size(); ++k) {
                    const Property& p = e.properties[k];
                    if (!p.list) {
                        values[k] = ascii_value(token(l, e, i, p), p.type, e, i, p);
                        continue;
                    }
                    const std::int64_t n = ascii_whole(token(l, e, i, p), e, i, p);
                    const bool uvs = ei == face_ && k == texcoord_;
                    if (n < 0 || static_cast<std::uint64_t>(n) > l.size()) {
                        fail(line_of(line_), e.name + " " + std::to_string(i) + ": list '" +
                                                 p.name + "' of " + std::to_string(n) +
                                                 " items does not fit on its line");
                    }
                    if (uvs) {
                        face_uvs_.face.push_back(static_cast<std::uint32_t>(i));
                        face_uvs_.count.push_back(static_cast<std::uint32_t>(n));
                        face_uvs_.line.push_back(line_);
                    }
                    for (std::int64_t c = 0; c < n; ++c) {
                        const std::string_view t = token(l, e, i, p);
                        if (ei == face_ && k == indices_) {
                            store_index(e, i, ascii_whole(t, e, i, p));
                        } else if (uvs) {
                            face_uvs_.values.push_back(ascii_value(t, p.type, e, i, p));
                        } else {
                            ascii_value(t, p.type, e, i, p);
                        }
                    }
                }
                if (ei == vertex_) {
                    store_vertex(e, i, values.data());
                } else if (ei == face_ && indices_ != kNone) {
                    end_face(e, i, values.data());
                }
            }
        }
        for (std::string_view rest = next_line(); !rest.empty(); rest = next_line()) {
            extra_ += rest.size();
        }
    }

    // ------------------------------------------------------------- binary

    [[noreturn]] void short_body(const Element& e, std::size_t i) const {
        fail("", "the binary body ends inside '" + e.name + "' record " + std::to_string(i) +
                     " of the " + std::to_string(e.count) + " the header announced (" +
                     std::to_string(bytes_.size()) + " bytes in the file)");
    }

    void read_binary() {
        const char* p = bytes_.data() + body_;
        const char* const end = bytes_.data() + bytes_.size();
        for (std::size_t ei = 0; ei < elements_.size(); ++ei) {
            const Element& e = elements_[ei];
            std::size_t fixed = 0;  // a record's bytes without its lists' items
            bool has_list = false;
            for (const Property& q : e.properties) {
                fixed += q.list ? size_of(q.count_type) : size_of(q.type);
                has_list = has_list || q.list;
            }
            const std::size_t left = static_cast<std::size_t>(end - p);
            if (fixed > 0 && e.count > left / fixed) {
                fail("", "the header announces " + std::to_string(e.count) + " '" + e.name +
                             "' records of at least " + std::to_string(fixed) +
                             " bytes, but only " + std::to_string(left) +
                             " bytes of the binary body remain");
            }
            if (fixed == 0) {
                continue;  // no properties: the records take no bytes
            }
            if (ei != vertex_ && ei != face_ && !has_list) {
                p += e.count * fixed;  // skipped whole: checked above
                continue;
            }
            if (ei == vertex_) {
                out_.soup.positions.reserve(e.count);
                if (has_normals_) {
                    out_.normals.reserve(e.count);
                }
            } else if (ei == face_) {
                out_.soup.face_offsets.reserve(e.count + 1);
            }
            std::vector<double> values(e.properties.size(), 0.0);
            for (std::size_t i = 0; i < e.count; ++i) {
                for (std::size_t k = 0; k < e.properties.size(); ++k) {
                    const Property& q = e.properties[k];
                    if (!q.list) {
                        const std::size_t s = size_of(q.type);
                        if (static_cast<std::size_t>(end - p) < s) {
                            short_body(e, i);
                        }
                        values[k] = value_at(p, q.type, swap_);
                        p += s;
                        continue;
                    }
                    const std::size_t cs = size_of(q.count_type);
                    if (static_cast<std::size_t>(end - p) < cs) {
                        short_body(e, i);
                    }
                    const std::int64_t n = whole_at(p, q.count_type, swap_);
                    p += cs;
                    const std::size_t s = size_of(q.type);
                    const std::size_t room = static_cast<std::size_t>(end - p) / s;
                    if (n < 0 || static_cast<std::uint64_t>(n) > room) {
                        fail(e.name + " " + std::to_string(i),
                             "list '" + q.name + "' claims " + std::to_string(n) +
                                 " items, but only " + std::to_string(end - p) +
                                 " bytes of the file remain");
                    }
                    if (ei == face_ && k == indices_) {
                        for (std::int64_t c = 0; c < n; ++c, p += s) {
                            store_index(e, i, whole_at(p, q.type, swap_));
                        }
                    } else if (ei == face_ && k == texcoord_) {
                        face_uvs_.face.push_back(static_cast<std::uint32_t>(i));
                        face_uvs_.count.push_back(static_cast<std::uint32_t>(n));
                        for (std::int64_t c = 0; c < n; ++c, p += s) {
                            face_uvs_.values.push_back(value_at(p, q.type, swap_));
                        }
                    } else {
                        p += static_cast<std::size_t>(n) * s;
                    }
                }
                if (ei == vertex_) {
                    store_vertex(e, i, values.data());
                } else if (ei == face_ && indices_ != kNone) {
                    end_face(e, i, values.data());
                }
            }
        }
        extra_ = static_cast<std::size_t>(end - p);
    }

    static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

    std::string_view bytes_;
    std::string file_;
    Format format_ = Format::Ascii;
    bool swap_ = false;
    std::size_t line_ = 0;
    std::size_t body_ = 0;
    std::size_t pos_ = 0;
    std::vector<Element> elements_;
    std::size_t vertex_ = kNone;
    std::size_t face_ = kNone;
    std::size_t indices_ = kNone;                       // the face list property
    std::vector<Role> roles_;                           // of the vertex properties
    std::vector<std::size_t> kept_vertex_, kept_face_;  // user properties: property numbers
    std::size_t position_[3] = {0, 0, 0};
    std::size_t normal_[3] = {0, 0, 0};
    bool has_normals_ = false;
    std::size_t texcoord_ = kNone;            // the face texcoord list property
    ply_attributes::FaceTexcoords face_uvs_;  // its values
    std::string ignored_;
    std::string skipped_elements_;
    std::size_t unknown_lines_ = 0;
    std::string first_unknown_;
    std::size_t extra_ = 0;
    MeshSoup out_;
};

}  // namespace

MeshSoup parse_ply(std::string_view bytes, const std::string& name) {
    return PlyReader(bytes, name).read();
}

MeshSoup read_ply(const std::filesystem::path& path) {
    const std::string bytes = read_file(path);
    return parse_ply(bytes, path.string());
}

}  // namespace meshedit
