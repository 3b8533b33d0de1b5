// The atomic write every writer goes through (files.h): a temporary file beside the real
// target (through symbolic links, as editors do), flushed, given the old file's mode and owner,
// then renamed over it. Temporary files that a killed process left behind are recognised by
// their name (they carry the target's name and the writer's pid) and removed by the next write
// of the same target by the same user.

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
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

// ".NAME.tmp-PID-COUNTER-NONCE": the pid if `name` is one of our temporary files, else 0.
long temporary_pid(const std::string& name) {
    if (name.empty() || name[0] != '.') {
        return 0;
    }
    const std::size_t at = name.rfind(".tmp-");
    if (at == std::string::npos) {
        return 0;
    }
    long fields[3] = {0, 0, 0};
    std::size_t pos = at + 5;
    for (int i = 0; i < 3; ++i) {
        const char* first = name.data() + pos;
        const char* last = name.data() + name.size();
        const auto [end, ec] = std::from_chars(first, last, fields[i]);
        if (ec != std::errc() || end == first ||
            (i < 2 ? (end == last || *end != '-') : end != last)) {
            return 0;
        }
        pos = static_cast<std::size_t>(end - name.data()) + 1;
    }
    return fields[0];
}

// Removes the temporary files of writers of the same target that are gone (killed
// mid-write: SIGKILL, power loss). Only ours: the same output name, owned by the running user
// (a shared folder holds other users' and other programs' files); a live pid keeps its files,
// even if it is another program's now: never remove what might be in use.
void remove_stale_temporaries(const fs::path& folder, const fs::path& target) {
    // Appended piecewise: `"." + string` trips a GCC 12 -Wrestrict false positive.
    std::string prefix(1, '.');
    prefix += target.filename().string();
    prefix += ".tmp-";
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.compare(0, prefix.size(), prefix) != 0) {
            continue;
        }
        const long pid = temporary_pid(name);
        struct stat info {};
        if (pid > 0 && pid != ::getpid() && ::lstat(it->path().c_str(), &info) == 0 &&
            S_ISREG(info.st_mode) && info.st_uid == ::geteuid() &&
            ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
            std::error_code ignored;
            fs::remove(it->path(), ignored);
        }
    }
}

// Why a write must not go through the symbolic link `link`, or empty. A link is followed only
// when it and its folder belong to the running user or to root: a link another user planted
// (in the system temporary folder, say) would otherwise make us replace whatever it names —
// as root, any file. The kernel's fs.protected_symlinks does not help: the link is never
// opened, only read.
std::string untrusted_link(const fs::path& link) {
    const uid_t me = ::geteuid();
    struct stat info {};
    if (::lstat(link.c_str(), &info) != 0) {
        return "cannot inspect the symbolic link '" + link.string() + "': " + std::strerror(errno);
    }
    if (info.st_uid != me && info.st_uid != 0) {
        return "will not write through the symbolic link '" + link.string() +
               "': it belongs to another user (uid " + std::to_string(info.st_uid) + ")";
    }
    const fs::path folder = link.has_parent_path() ? link.parent_path() : fs::path(".");
    struct stat dir {};
    if (::stat(folder.c_str(), &dir) != 0) {
        return "cannot inspect the folder '" + folder.string() + "': " + std::strerror(errno);
    }
    if (dir.st_uid != me && dir.st_uid != 0) {
        return "will not write through the symbolic link '" + link.string() +
               "': its folder belongs to another user (uid " + std::to_string(dir.st_uid) + ")";
    }
    // A world-writable sticky folder not ours (the system temporary folder, as a normal user):
    // only links we made ourselves.
    if ((dir.st_mode & S_IWOTH) != 0 && dir.st_uid != me && info.st_uid != me) {
        return "will not write through the symbolic link '" + link.string() +
               "': it lies in a folder everyone may write to and is not yours";
    }
    return {};
}

// The file a write to `target` must replace: `target` itself, or the file its chain of
// symbolic links ends at (which need not exist yet), so that the links survive the write.
// \throws IoError when a link on the way is not to be trusted (untrusted_link()).
fs::path real_target(const fs::path& target) {
    fs::path real = target;
    std::error_code ec;
    for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(real, ec)); ++hops) {
        if (std::string why = untrusted_link(real); !why.empty()) {
            throw IoError(target.string(), "", why);
        }
        const fs::path link = fs::read_symlink(real, ec);
        if (ec) {
            break;
        }
        real = link.is_absolute() ? link : real.parent_path() / link;
    }
    return real;
}

}  // namespace

void write_atomically(const fs::path& target,
                      const std::function<void(const fs::path& tmp)>& write) {
    const std::string name = target.string();
    if (target.filename().empty()) {
        throw IoError(name, "", "not a file name");
    }
    const fs::path real = real_target(target);
    const fs::path folder = real.has_parent_path() ? real.parent_path() : fs::path(".");
    std::error_code ec;
    const fs::file_status folder_status = fs::status(folder, ec);
    if (!fs::exists(folder_status)) {
        throw IoError(name, "", "the folder '" + folder.string() + "' does not exist");
    }
    if (!fs::is_directory(folder_status)) {
        throw IoError(name, "", "'" + folder.string() + "' is not a folder");
    }
    if (fs::is_directory(fs::status(real, ec))) {
        throw IoError(name, "", "is a folder");
    }
    remove_stale_temporaries(folder, real);

    // Create the temporary file exclusively ("x"): this claims the name and proves the folder
    // is writable before any work is done.
    const fs::path tmp = temporary_name(folder, real);
    std::FILE* claim = std::fopen(tmp.c_str(), "wx");
    if (claim == nullptr) {
        throw IoError(name, "",
                      "cannot create a file in '" + folder.string() + "': " + std::strerror(errno));
    }
    std::fclose(claim);

    try {
        write(tmp);
        sync_file(tmp);
        // Keep the mode of the file being replaced (a 0600 file stays private) and, where the
        // process may (root), its owner and group.
        struct stat old {};
        if (::stat(real.c_str(), &old) == 0) {
            ::chmod(tmp.c_str(), old.st_mode & 07777);
            if (old.st_uid != ::geteuid() || old.st_gid != ::getegid()) {
                [[maybe_unused]] const int ignored = ::chown(tmp.c_str(), old.st_uid, old.st_gid);
            }
        }
        fs::rename(tmp, real);
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
