// Guards around tinygltf; see gltf_guard.h.

#include "gltf_guard.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <system_error>

#include "meshedit/files/io_error.h"

namespace fs = std::filesystem;

namespace meshedit::gltf_guard {

namespace {

std::uint32_t read_u32(std::string_view bytes, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, sizeof v);  // glb is little-endian, as is x86/arm
    return v;
}

// The JSON chunk of a .glb (header: magic, version, length; then chunk length, chunk type,
// data). A malformed header is left to tinygltf, which reports it.
std::string_view glb_json(std::string_view bytes) {
    if (bytes.size() < 20) {
        return {};
    }
    const std::size_t length = read_u32(bytes, 12);
    return bytes.substr(20, std::min(length, bytes.size() - 20));
}

}  // namespace

void check_json_depth(std::string_view bytes, bool binary, const std::string& file) {
    const std::string_view json = binary ? glb_json(bytes) : bytes;
    std::size_t depth = 0;
    std::size_t line = 1;
    bool in_string = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (c == '\n') {
            ++line;
        } else if (in_string) {
            if (c == '\\') {
                ++i;  // the escaped character cannot end the string
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) {
                throw IoError(
                    file,
                    binary ? "JSON chunk, line " + std::to_string(line)
                           : "line " + std::to_string(line),
                    "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
            }
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

ConfinedFiles::ConfinedFiles(const std::optional<fs::path>& given, std::size_t max_bytes)
    : no_files_(!given), max_bytes_(max_bytes) {
    const fs::path folder = given.value_or(fs::path());
    std::error_code ec;
    root_ =
        fs::weakly_canonical(folder.empty() ? fs::current_path(ec) : fs::absolute(folder, ec), ec);
    // The folder as tinygltf joins a URI to it (JoinPath adds a '/' unless there is one).
    prefix_ = folder.string();
    if (!prefix_.empty() && prefix_.back() != '/') {
        prefix_ += '/';
    }
}

tinygltf::FsCallbacks ConfinedFiles::callbacks() {
    return tinygltf::FsCallbacks{&file_exists, &expand_path, &read_whole_file, &write_whole_file,
                                 this};
}

void ConfinedFiles::refuse(const std::string& uri, const std::string& why) {
    if (refusal_.empty()) {
        refusal_ = "buffer URI '" + uri + "' " + why;
    }
}

bool ConfinedFiles::in_base(const std::string& path) const {
    return path.size() > prefix_.size() && path.compare(0, prefix_.size(), prefix_) == 0;
}

std::string ConfinedFiles::uri_of(const std::string& path) const {
    return path.substr(prefix_.size());
}

fs::path ConfinedFiles::admit(const std::string& path) {
    // tinygltf joins the URI to the base folder we gave it, and then also to "."; the second
    // search (the current folder) is never allowed.
    if (!in_base(path)) {
        return {};
    }
    const std::string uri = uri_of(path);
    if (no_files_) {
        refuse(uri, "names a file, but the glTF was given without a folder to read it from");
        return {};
    }
    if (fs::path(uri).is_absolute()) {
        refuse(uri, "is an absolute path; only files in the model's folder may be read");
        return {};
    }
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (ec) {
        return {};
    }
    const fs::path inside = resolved.lexically_relative(root_);
    if (inside.empty() || *inside.begin() == "..") {
        refuse(uri, "lies outside the model's folder; only files in it may be read");
        return {};
    }
    const fs::file_status status = fs::status(resolved, ec);
    if (!fs::exists(status)) {
        return {};  // tinygltf says "file not found"
    }
    if (!fs::is_regular_file(status)) {
        refuse(uri, "is not a regular file");
        return {};
    }
    return resolved;
}

bool ConfinedFiles::file_exists(const std::string& path, void* self) {
    return !static_cast<ConfinedFiles*>(self)->admit(path).empty();
}

std::string ConfinedFiles::expand_path(const std::string& path, void*) {
    return path;  // no `~` or `$VAR` expansion: a URI is a relative path, nothing more
}

bool ConfinedFiles::read_whole_file(std::vector<unsigned char>* out, std::string* err,
                                    const std::string& path, void* self_) {
    auto* self = static_cast<ConfinedFiles*>(self_);
    const fs::path resolved = self->admit(path);
    if (resolved.empty()) {
        *err = "not readable";
        return false;
    }
    // O_NONBLOCK: a FIFO swapped in after the check must not block the reader forever.
    const int fd = ::open(resolved.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) {
        *err = std::strerror(errno);
        return false;
    }
    struct stat st {};
    bool ok = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    if (!ok) {
        self->refuse(self->uri_of(path), "is not a regular file");
    } else if (static_cast<std::uint64_t>(st.st_size) > self->max_bytes_) {
        self->refuse(self->uri_of(path), "is " + std::to_string(st.st_size) +
                                             " bytes, over the limit of " +
                                             std::to_string(self->max_bytes_));
        ok = false;
    }
    if (ok) {
        out->resize(static_cast<std::size_t>(st.st_size));
        std::size_t done = 0;
        while (done < out->size()) {
            const ssize_t n = ::read(fd, out->data() + done, out->size() - done);
            if (n <= 0) {
                *err = n < 0 ? std::strerror(errno) : "the file shrank while it was read";
                ok = false;
                break;
            }
            done += static_cast<std::size_t>(n);
        }
    }
    ::close(fd);
    return ok;
}

bool ConfinedFiles::write_whole_file(std::string* err, const std::string&,
                                     const std::vector<unsigned char>&, void*) {
    *err = "MeshEdit writes glTF files itself";
    return false;
}

}  // namespace meshedit::gltf_guard
