#pragma once
/// \file
/// OFF's colours and texture coordinates (Geomview's C and ST prefixes, a face's colour after
/// its indices), read and written (private to meshedit_io; off.cpp).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/io/io.h"

namespace meshedit::off_attributes {

/// Collects what follows a vertex's position and normal, and a face's indices, then gives it
/// to the soup. A bad value drops that attribute only, with one notice naming the line.
class Reader {
public:
    bool vertex_colours = false;  ///< the header has C
    bool texcoords = false;       ///< the header has ST

    /// The rest of vertex `v`'s line (on line `line`), after its position and normal.
    void read_vertex(std::string_view rest, std::size_t v, std::size_t line);
    /// The rest of face `f`'s line, after its indices: nothing, a colour map index, or an
    /// RGB or RGBA colour.
    void read_face(std::string_view rest, std::size_t f, std::size_t line);
    /// Colours (integers 0–255 when any value is above 1 and none has a fraction, else 0–1)
    /// and texture coordinates (on every corner of their vertex) into `soup`; the notices.
    void finish(MeshSoup& soup);

private:
    struct Colours {
        std::vector<double> values;  // four per element; alpha NaN where the file had none
        bool whole = true;           // every value written without a fraction or exponent
        std::string problem;         // the first bad one, which drops them all
        void add(const std::vector<std::string_view>& tokens, const std::string& where);
        std::vector<Vec4> scaled() const;
    };
    Colours vertex_, face_;
    std::vector<Vec2> uv_;
    std::string uv_problem_;
    std::size_t colour_map_faces_ = 0;
    std::size_t faces_ = 0;
};

/// What the writer puts after each vertex's position and each face's indices for `mesh`:
/// normals (N) and texture coordinates (ST) when one per vertex holds them, vertex colours
/// (C), face colours; integers 0–255 when every colour is k/255, else exact decimals.
class Columns {
public:
    explicit Columns(const Mesh& mesh);
    std::string keyword() const;  ///< "OFF", "NOFF", "STCNOFF" …
    void put_vertex(std::string& out, std::size_t v) const;
    void put_face(std::string& out, std::size_t f) const;

private:
    std::vector<Vec3> normals_;
    std::vector<Vec4> colours_, face_colours_;
    std::vector<Vec2> uvs_;
    bool whole_colours_ = false, whole_face_colours_ = false;
};

}  // namespace meshedit::off_attributes
