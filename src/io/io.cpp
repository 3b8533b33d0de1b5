// The front door of meshedit_io: dispatch by extension, read_mesh(), and the atomic write
// every writer goes through.

#include "meshedit/io/io.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <system_error>

#include "io_detail.h"
#include "meshedit/core/attributes.h"
#include "meshedit/io/collada.h"
#include "meshedit/io/gltf.h"
#include "meshedit/io/obj.h"

namespace fs = std::filesystem;

namespace meshedit {

// ----------------------------------------------------------------- shared helpers

namespace io_detail {

std::string lower_extension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::string read_file(const fs::path& path) {
    const std::string name = display_name(path);
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) {
        throw IoError(name, "", "no such file");
    }
    if (fs::is_directory(status)) {
        throw IoError(name, "", "is a folder, not a file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw IoError(name, "", std::string("cannot open: ") + std::strerror(errno));
    }
    std::string bytes;
    // Size from the stream rather than the file system: /proc-style files report 0.
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);
    if (size > 0) {
        bytes.resize(static_cast<std::size_t>(size));
        in.read(bytes.data(), size);
    }
    if (in.bad() || (size > 0 && in.gcount() != size)) {
        throw IoError(name, "", "read error");
    }
    return bytes;
}

void write_file(const fs::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) {
        throw std::runtime_error(std::string("cannot open for writing: ") + std::strerror(errno));
    }
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
        throw std::runtime_error("write failed (disk full?)");
    }
}

std::string format_double(double value) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    return ec == std::errc() ? std::string(buf, end) : std::string("nan");
}

const Mesh& compacted(const Mesh& mesh, std::optional<Mesh>& storage) {
    if (!mesh.has_garbage()) {
        return mesh;
    }
    storage.emplace(mesh);
    storage->garbage_collection();
    return *storage;
}

}  // namespace io_detail

using io_detail::display_name;
using io_detail::lower_extension;

// ----------------------------------------------------------------- reading

bool is_mesh_extension(const std::string& extension) {
    return extension == ".dae" || extension == ".gltf" || extension == ".glb" ||
           extension == ".obj";
}

MeshSoup read_soup(const fs::path& path) {
    const std::string ext = lower_extension(path);
    if (ext == ".bez" || ext == ".bzc") {
        throw IoError(display_name(path), "",
                      "a Bezier " + std::string(ext == ".bez" ? "patch" : "curve") +
                          " file, not a mesh (load it as Bezier data)");
    }
    if (!is_mesh_extension(ext)) {
        throw IoError(display_name(path), "",
                      ext.empty()
                          ? "no file extension; expected .dae, .gltf, .glb or .obj"
                          : "unknown extension '" + ext + "'; expected .dae, .gltf, .glb or .obj");
    }
    // Checked here once so that every reader reports a missing file the same way.
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) {
        throw IoError(display_name(path), "", "no such file");
    }
    if (fs::is_directory(status)) {
        throw IoError(display_name(path), "", "is a folder, not a file");
    }
    if (ext == ".dae") {
        return read_collada(path);
    }
    if (ext == ".obj") {
        return read_obj(path);
    }
    return read_gltf(path);
}

LoadedMesh read_mesh(const fs::path& path) {
    MeshSoup soup = read_soup(path);
    LoadedMesh loaded;
    try {
        loaded.mesh = build_mesh(soup.soup, &loaded.repairs);
    } catch (const TopologyError& e) {
        throw IoError(display_name(path), "", e.what());
    }
    loaded.notices = std::move(soup.notices);
    loaded.unit_meter = soup.unit_meter;

    if (!soup.creases.empty()) {
        auto crease = loaded.mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
        std::size_t missing = 0;
        for (const auto& [a, b] : soup.creases) {
            // Indices are the file's (build_mesh keeps vertex i = position i); a crease
            // between vertices that share no edge cannot be marked.
            const std::size_t n = soup.soup.positions.size();
            const Edge e = (a < n && b < n) ? loaded.mesh.find_edge(Vertex(a), Vertex(b)) : Edge();
            if (e.is_valid()) {
                crease[e] = 1;
            } else {
                ++missing;
            }
        }
        if (missing > 0) {
            loaded.notices.push_back("ignored " + std::to_string(missing) +
                                     " crease(s) between vertices that share no edge");
        }
    }
    return loaded;
}

// ----------------------------------------------------------------- writing

void write_mesh(const Mesh& mesh, const fs::path& path, const IoFlags& flags) {
    const std::string ext = lower_extension(path);
    std::optional<Mesh> storage;
    const Mesh& dense = io_detail::compacted(mesh, storage);
    if (ext == ".dae") {
        write_collada(dense, path, flags);
    } else if (ext == ".gltf" || ext == ".glb") {
        write_gltf(dense, path, flags);
    } else if (ext == ".obj") {
        write_obj(dense, path, flags);
    } else {
        throw IoError(display_name(path), "",
                      ext.empty()
                          ? "no file extension; expected .dae, .gltf, .glb or .obj"
                          : "cannot write '" + ext + "' files; expected .dae, .gltf, .glb or .obj");
    }
}

namespace {

/// A name no other writer (thread or process) picks: dot-prefixed so file browsers hide it,
/// with the pid, a process-wide counter and a random nonce.
fs::path temporary_name(const fs::path& folder, const fs::path& target) {
    static std::atomic<unsigned long> counter{0};
    static const unsigned long nonce = std::random_device{}();
    // Appended piecewise: `"-" + string` trips a GCC 12 -Wrestrict false positive.
    std::string name(1, '.');
    name += target.filename().string();
    name += ".tmp-";
    name += std::to_string(::getpid());
    name += '-';
    name += std::to_string(counter.fetch_add(1));
    name += '-';
    name += std::to_string(nonce);
    return folder / name;
}

/// Flushes `path`'s data to the disk, so the rename cannot become visible before the bytes
/// (a crash would otherwise leave an empty target on some file systems).
void sync_file(const fs::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        throw std::runtime_error(std::string("cannot reopen the temporary file: ") +
                                 std::strerror(errno));
    }
    const int rc = ::fsync(fd);
    const int err = errno;
    ::close(fd);
    if (rc != 0) {
        throw std::runtime_error(std::string("cannot flush to disk: ") + std::strerror(err));
    }
}

}  // namespace

void write_atomically(const fs::path& target,
                      const std::function<void(const fs::path& tmp)>& write) {
    const std::string name = display_name(target);
    if (target.filename().empty()) {
        throw IoError(name, "", "not a file name");
    }
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    const fs::file_status folder_status = fs::status(folder, ec);
    if (!fs::exists(folder_status)) {
        throw IoError(name, "", "the folder '" + folder.string() + "' does not exist");
    }
    if (!fs::is_directory(folder_status)) {
        throw IoError(name, "", "'" + folder.string() + "' is not a folder");
    }
    if (fs::is_directory(fs::status(target, ec))) {
        throw IoError(name, "", "is a folder");
    }

    // Create the temporary file exclusively ("x"): this claims the name and proves the folder
    // is writable before any work is done.
    const fs::path tmp = temporary_name(folder, target);
    std::FILE* claim = std::fopen(tmp.c_str(), "wx");
    if (claim == nullptr) {
        throw IoError(name, "",
                      "cannot create a file in '" + folder.string() + "': " + std::strerror(errno));
    }
    std::fclose(claim);

    try {
        write(tmp);
        sync_file(tmp);
        // Keep the permissions of the file being replaced (a 0600 file stays private).
        const fs::file_status old_status = fs::status(target, ec);
        if (!ec && fs::exists(old_status)) {
            fs::permissions(tmp, old_status.permissions(), ec);
        }
        fs::rename(tmp, target);
    } catch (const IoError& e) {
        fs::remove(tmp, ec);
        throw IoError(name, e.where(), e.problem());
    } catch (const fs::filesystem_error& e) {
        fs::remove(tmp, ec);
        throw IoError(name, "", "cannot replace the file: " + e.code().message());
    } catch (const std::exception& e) {
        fs::remove(tmp, ec);
        throw IoError(name, "", e.what());
    } catch (...) {
        fs::remove(tmp, ec);
        throw IoError(name, "", "unknown error while writing");
    }

    // Make the rename itself durable; failing here loses nothing already written.
    const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
}

}  // namespace meshedit
