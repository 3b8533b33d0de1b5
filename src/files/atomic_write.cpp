// The atomic write every writer goes through (files.h): a temporary file beside the target,
// flushed, then renamed over it.

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <system_error>

#include "meshedit/files/files.h"

namespace fs = std::filesystem;

namespace meshedit {

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
    const std::string name = target.string();
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
