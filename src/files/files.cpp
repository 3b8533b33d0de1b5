// File names and whole-file reads and writes (files.h). The atomic write is in
// atomic_write.cpp.

#include "meshedit/files/files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

#include "meshedit/core/budget.h"
#include "meshedit/core/memory.h"

namespace fs = std::filesystem;

namespace meshedit {

std::string file_extension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

void append_utf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

std::string read_file(const fs::path& path, std::size_t max_bytes) {
    const std::string name = path.string();
    if (max_bytes == 0) {
        max_bytes = memory_budget();
    }
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) {
        // A relative path names the folder it was looked for in: a program started from
        // elsewhere (a desktop launcher, an IDE) looks in a folder the user did not expect.
        std::string why = "no such file";
        if (path.is_relative()) {
            std::error_code cwd_error;
            const fs::path cwd = fs::current_path(cwd_error);
            if (!cwd_error) {
                why += " (looked for it in " + cwd.string() + ")";
            }
        }
        throw IoError(name, "", why);
    }
    if (fs::is_directory(status)) {
        throw IoError(name, "", "is a folder, not a file");
    }
    if (!fs::is_regular_file(status)) {
        throw IoError(name, "", "is not a regular file (a FIFO, a device or a socket)");
    }
    // O_NONBLOCK: should the path have become a FIFO since the check, open() must not wait
    // for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        throw IoError(name, "", std::string("cannot open: ") + std::strerror(errno));
    }
    struct Close {
        int fd;
        ~Close() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        throw IoError(name, "", "is not a regular file (a FIFO, a device or a socket)");
    }
    const auto size = static_cast<std::size_t>(st.st_size);
    if (size > max_bytes) {
        throw IoError(name, "",
                      "is " + format_bytes(static_cast<double>(size)) +
                          ", more than the memory budget of " +
                          format_bytes(static_cast<double>(max_bytes)) +
                          " (--memory-budget or MESHEDIT_MEMORY_BUDGET sets it)");
    }
    // One spare byte, so that a file read whole meets its end without growing the buffer.
    std::string bytes;
    bytes.reserve(size + 1);
    memory::advise_huge_pages(bytes.data(), bytes.capacity());
    bytes.resize(bytes.capacity());
    std::size_t used = 0;
    for (;;) {
        if (used == bytes.size()) {
            if (used > max_bytes) {
                throw IoError(name, "",
                              "is more than the memory budget of " +
                                  format_bytes(static_cast<double>(max_bytes)));
            }
            bytes.resize(std::max<std::size_t>(2 * bytes.size(), 1 << 16));
        }
        const ssize_t got = ::read(fd, bytes.data() + used, bytes.size() - used);
        if (got < 0) {
            if (errno == EINTR) {
                continue;
            }
            throw IoError(name, "", std::string("read error: ") + std::strerror(errno));
        }
        if (got == 0) {
            break;
        }
        used += static_cast<std::size_t>(got);
    }
    bytes.resize(used);
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

std::string content_hash(std::string_view bytes) {
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a, 64 bits
    for (const char c : bytes) {
        h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

}  // namespace meshedit
