#pragma once
/// \file
/// Real scanned meshes for golden images and benchmarks: CGAL's demo data set (the Debian
/// package libcgal-demo ships it as one tarball), unpacked on first use into a folder of the
/// build, never committed to the repository.

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace meshedit::test {

inline const char* const kDemoDataTarball = "/usr/share/doc/libcgal-dev/data.tar.gz";

/// The path of data/meshes/`stem`.off (say "bunny00", "armadillo"), extracted into
/// `data_dir` if it is not there yet. \throws std::runtime_error naming the package to install.
inline std::filesystem::path demo_mesh(const std::string& stem,
                                       const std::filesystem::path& data_dir) {
    const std::string member = "data/meshes/" + stem + ".off";
    const std::filesystem::path path = data_dir / member;
    if (!std::filesystem::exists(path)) {
        std::filesystem::create_directories(data_dir);
        const std::string cmd = "tar xzf " + std::string(kDemoDataTarball) + " -C '" +
                                data_dir.string() + "' " + member;
        if (std::system(cmd.c_str()) != 0 || !std::filesystem::exists(path)) {
            throw std::runtime_error("could not extract " + member + " from " + kDemoDataTarball +
                                     " (install libcgal-demo: scripts/install-deps.sh does)");
        }
    }
    return path;
}

}  // namespace meshedit::test
