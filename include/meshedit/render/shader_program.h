#pragma once
/// \file
/// GLSL 330 programs loaded at run time from the shader folder, and GlError.
///
/// Shaders live in `shaders/` as plain files so they can be edited without recompiling. The
/// folder is looked up in this order: `$MESHEDIT_SHADER_DIR`, `<exe dir>/shaders`,
/// `<exe dir>/../share/meshedit/shaders` (an installed tree; the build tree links its
/// `src/share`, `tests/share` and `share` to the source's `shaders/` for the same lookup). No
/// path is compiled in, so an installed tree can move. Needs a current GL 3.3 core context.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace meshedit {

/// A GL failure: a shader that is missing, does not compile or does not link (the message
/// names the file and carries the driver's log), or a context/framebuffer problem.
class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The folder shaders are loaded from (see the file comment for the search order).
/// \throws GlError if no candidate folder exists.
std::filesystem::path shader_directory();

/// Throws GlError naming `what` if glGetError() reports an error (clears the error flag).
void check_gl(std::string_view what);

/// A linked vertex + fragment program. Move-only; deletes the GL program on destruction.
class ShaderProgram {
public:
    ShaderProgram() = default;
    /// Loads `<shader dir>/<vert_name>` and `<shader dir>/<frag_name>`, compiles and links.
    /// `defines` (lines such as "#define MESHEDIT_MODE 1\n") go right after each file's
    /// `#version` line: one source, specialised variants.
    /// \throws GlError naming the file with the compiler or linker log.
    ShaderProgram(std::string_view vert_name, std::string_view frag_name,
                  std::string_view defines = {});
    /// The same from two paths anywhere (a user's shader folder).
    static ShaderProgram from_files(const std::filesystem::path& vert,
                                    const std::filesystem::path& frag,
                                    std::string_view defines = {});
    ShaderProgram(ShaderProgram&& other) noexcept;
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;
    ~ShaderProgram();

    bool is_valid() const { return id_ != 0; }
    unsigned id() const { return id_; }
    void use() const;

    /// Uniform location by name (-1 if the linker removed it; setting -1 is a no-op in GL).
    int location(const char* name) const;
    void set_int(const char* name, int value) const;
    void set_float(const char* name, float value) const;
    void set_vec2(const char* name, float x, float y) const;
    void set_vec3(const char* name, const float* xyz) const;
    void set_vec4(const char* name, const float* xyzw) const;
    void set_mat3(const char* name, const float* m) const;  ///< column-major
    void set_mat4(const char* name, const float* m) const;  ///< column-major

private:
    unsigned id_ = 0;
};

}  // namespace meshedit
