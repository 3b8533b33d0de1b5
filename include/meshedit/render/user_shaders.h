#pragma once
/// \file
/// Shading modes 8 and 9 as the user writes them: `mesh8.frag` and `mesh9.frag` in a user
/// shader folder, compiled with MeshEdit's own vertex shader (shaders/mesh.vert) and given
/// every uniform and varying the built-in modes get (docs/shaders.md). The viewer recompiles
/// every shader from disk on Ctrl+R.

#include <filesystem>
#include <string_view>
#include <vector>

namespace meshedit {

/// `$XDG_CONFIG_HOME/meshedit/shaders`, else `$HOME/.config/meshedit/shaders`; empty when
/// neither variable is set.
std::filesystem::path default_user_shader_dir();

/// The file mode `mode` (8 or 9) loads from `dir`.
std::filesystem::path user_shader_path(const std::filesystem::path& dir, int mode);

/// Where the commented starter shaders live: `user/` in the shader folder (shaders/user in
/// the source tree): mesh8.frag toon shading, mesh9.frag stripes moving with u_time; both
/// declare every input there is.
std::filesystem::path starter_shader_dir();

/// Creates `dir` and writes each starter shader whose file is missing (an existing file is
/// never overwritten). \return the files written. \throws IoError naming the folder or file.
std::vector<std::filesystem::path> install_starter_shaders(const std::filesystem::path& dir);

}  // namespace meshedit
