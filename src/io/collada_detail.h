#pragma once
/// \file
/// Private parts of the COLLADA reader: loading and decoding the XML, error messages with
/// element paths and lines, number lists, and one `<geometry>` as a local polygon soup.

#include <pugixml.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "meshedit/core/math.h"
#include "meshedit/files/io_error.h"

namespace meshedit::collada {

/// The parsed document plus what error messages need: the file name and the UTF-8 text the
/// node offsets refer to.
class Document {
public:
    /// Decodes (UTF-8 with or without BOM, UTF-16 LE/BE) and parses a file's `bytes`; `name`
    /// names the file in errors. \throws IoError for an empty, binary or malformed file.
    Document(std::string bytes, const std::string& name);
    // pugixml's strings point into text_.
    Document(const Document&) = delete;
    Document& operator=(const Document&) = delete;

    const pugi::xml_node root() const { return doc_.document_element(); }
    const std::string& file() const { return file_; }

    /// The element with that `id` (first one wins), or a null node.
    pugi::xml_node find_id(std::string_view id) const;
    /// Resolves a local URL `#id`. \throws IoError naming `at` for an external or unknown URL.
    pugi::xml_node resolve(std::string_view url, pugi::xml_node at) const;

    /// "line 12, <geometry id="box">/<mesh>/<p>" for `node`.
    std::string where(pugi::xml_node node) const;
    /// An IoError placed at `node`.
    [[noreturn]] void fail(pugi::xml_node node, const std::string& problem) const;
    /// Some list of numbers was written with decimal commas ("0,5": an exporter's locale) and
    /// read as points (parse_doubles()); the reader says so once.
    bool decimal_commas() const { return decimal_commas_; }
    void note_decimal_commas() const { decimal_commas_ = true; }

private:
    std::size_t line_of(std::ptrdiff_t offset) const;

    std::string file_;
    std::string text_;                   // UTF-8, BOM removed; pugixml offsets index into it
    bool in_place_ = false;              // pugixml parsed (and changed) text_ in place
    std::vector<std::size_t> newlines_;  // offsets of text_'s newlines, when in_place_
    mutable bool decimal_commas_ = false;
    pugi::xml_document doc_;
    std::unordered_map<std::string_view, pugi::xml_node> ids_;
};

/// Whitespace-separated doubles of `node`'s text. \throws IoError for a non-number. Never
/// reserves more than the text can hold.
std::vector<double> parse_doubles(const Document& doc, pugi::xml_node node);
/// Whitespace-separated unsigned integers (each < 2^32) of `node`'s text. \throws IoError.
std::vector<std::uint32_t> parse_indices(const Document& doc, pugi::xml_node node);
/// A non-negative integer attribute, `fallback` when absent. \throws IoError if malformed.
std::uint64_t count_attribute(const Document& doc, pugi::xml_node node, const char* name,
                              std::uint64_t fallback);

/// One `<geometry>` as its file holds it (local coordinates, local position indices).
struct GeometryData {
    std::vector<Vec3> positions;
    std::vector<std::uint32_t> indices;  // CSR polygons over `positions`
    std::vector<std::uint32_t> face_offsets{0};
    /// Per-position normals, only when every corner of each position agreed (else empty).
    std::vector<Vec3> normals;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> creases;
    std::vector<std::string> notices;
    /// Per corner (as `indices`), when every primitive has the input (else empty): the
    /// (S, T) of the lowest TEXCOORD set and of the next (MeshEdit's second set), the NORMAL
    /// input's normal.
    std::vector<Vec2> corner_texcoords[2];
    std::vector<Vec3> corner_normals;
    /// Per position, when every primitive has a COLOR input (else empty): a position's first
    /// corner's colour (RGB, alpha 1; or RGBA).
    std::vector<Vec4> colors;
    /// Per face, its primitive's material symbol (an index into `symbols`; "" for none).
    std::vector<std::uint32_t> face_symbols;
    std::vector<std::string> symbols;
    /// The `set` number of the input that is MeshEdit's second texture coordinate set (the
    /// first primitive's that has one): a material bound to it draws with that set.
    std::optional<std::uint64_t> second_texcoord_set;
};

/// Reads `<geometry>` `geometry`. \throws IoError naming the element.
GeometryData read_geometry(const Document& doc, pugi::xml_node geometry);

}  // namespace meshedit::collada
