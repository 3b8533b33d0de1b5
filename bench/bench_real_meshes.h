#pragma once
/// \file
/// Real meshes for the benchmarks: CGAL's demo data (libcgal-demo's data.tar.gz), unpacked at
/// run time, never committed, and a small OFF reader.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshedit/core/build.h"

namespace meshedit::bench {

namespace fs = std::filesystem;

inline const char* const kDataTarball = "/usr/share/doc/libcgal-dev/data.tar.gz";

/// The triangles of an OFF file (polygons cut into fans).
inline PolygonSoup read_off(const fs::path& path) {
    std::ifstream file(path);
    if (!file) {
        throw std::runtime_error("cannot open " + path.string());
    }
    // Strip comments, then read whitespace-separated tokens.
    std::stringstream text;
    std::string line;
    while (std::getline(file, line)) {
        text << line.substr(0, line.find('#')) << '\n';
    }
    std::string header;
    text >> header;
    if (header != "OFF") {
        throw std::runtime_error(path.string() + ": not an OFF file");
    }
    std::size_t nv = 0;
    std::size_t nf = 0;
    std::size_t ne = 0;
    text >> nv >> nf >> ne;
    PolygonSoup soup;
    soup.positions.resize(nv);
    for (auto& p : soup.positions) {
        text >> p.x >> p.y >> p.z;
    }
    std::vector<std::uint32_t> corners;
    for (std::size_t f = 0; f < nf; ++f) {
        std::size_t n = 0;
        text >> n;
        corners.resize(n);
        for (auto& c : corners) {
            text >> c;
        }
        // Fan-triangulate polygons (the CGAL demo meshes are all triangles).
        for (std::size_t i = 1; i + 1 < n; ++i) {
            soup.add_face({corners[0], corners[i], corners[i + 1]});
        }
    }
    if (!text) {
        throw std::runtime_error(path.string() + ": truncated");
    }
    return soup;
}

/// The .off of `name`, extracted from the CGAL demo tarball into `data_dir` on first use.
inline fs::path real_mesh_path(const std::string& name, const fs::path& data_dir) {
    const std::string member =
        "data/meshes/" + std::string(name == "bunny" ? "bunny00" : name) + ".off";
    const fs::path path = data_dir / member;
    if (!fs::exists(path)) {
        fs::create_directories(data_dir);
        const std::string cmd =
            "tar xzf " + std::string(kDataTarball) + " -C '" + data_dir.string() + "' " + member;
        if (std::system(cmd.c_str()) != 0 || !fs::exists(path)) {
            throw std::runtime_error("could not extract " + member + " from " + kDataTarball +
                                     " (install libcgal-demo)");
        }
    }
    return path;
}

}  // namespace meshedit::bench
