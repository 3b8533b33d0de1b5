#include "meshedit/render/user_shaders.h"

#include <cstdlib>
#include <string>
#include <system_error>

#include "meshedit/files/io_error.h"
#include "meshedit/render/shader_program.h"

namespace meshedit {

std::filesystem::path default_user_shader_dir() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg != nullptr && *xdg != '\0') {
        return std::filesystem::path(xdg) / "meshedit" / "shaders";
    }
    if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
        return std::filesystem::path(home) / ".config" / "meshedit" / "shaders";
    }
    return {};
}

std::filesystem::path user_shader_path(const std::filesystem::path& dir, int mode) {
    return dir / ("mesh" + std::to_string(mode) + ".frag");
}

std::filesystem::path starter_shader_dir() {
    return shader_directory() / "user";
}

std::vector<std::filesystem::path> install_starter_shaders(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        throw IoError(dir.string(), "", "cannot create the shader folder: " + ec.message());
    }
    std::vector<std::filesystem::path> written;
    for (const int mode : {8, 9}) {
        const std::filesystem::path path = user_shader_path(dir, mode);
        if (!std::filesystem::exists(path)) {
            std::filesystem::copy_file(user_shader_path(starter_shader_dir(), mode), path, ec);
            if (ec) {
                throw IoError(path.string(), "",
                              "cannot write the starter shader: " + ec.message());
            }
            written.push_back(path);
        }
    }
    return written;
}

}  // namespace meshedit
