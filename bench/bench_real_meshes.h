#pragma once
/// \file
/// Real meshes for the benchmarks: CGAL's demo data (tests/support/demo_meshes.h), read with
/// MeshEdit's OFF reader.

#include <filesystem>
#include <stdexcept>
#include <string>

#include "meshedit/core/build.h"
#include "meshedit/io/off.h"
#include "support/demo_meshes.h"

namespace meshedit::bench {

/// The triangles of the demo mesh `name` ("bunny" is data/meshes/bunny00.off), unpacked into
/// `data_dir` on first use. \throws std::runtime_error unless every face is a triangle (the
/// anchors' loaders are given triangles).
inline PolygonSoup real_mesh(const std::string& name, const std::filesystem::path& data_dir) {
    const std::filesystem::path path =
        test::demo_mesh(name == "bunny" ? "bunny00" : name, data_dir);
    PolygonSoup soup = read_off(path).soup;
    for (std::size_t f = 0; f < soup.n_faces(); ++f) {
        if (soup.face_offsets[f + 1] - soup.face_offsets[f] != 3) {
            throw std::runtime_error(path.string() + ": face " + std::to_string(f) +
                                     " is not a triangle");
        }
    }
    return soup;
}

}  // namespace meshedit::bench
