// Helpers the format writers share (io_util.h).

#include "io_util.h"

#include <charconv>

namespace meshedit::io_util {

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

}  // namespace meshedit::io_util
