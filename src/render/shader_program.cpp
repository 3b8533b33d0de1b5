// Shader loading: files from the shader folder, compile and link errors as GlError with the
// file name and the driver's log.

#include "meshedit/render/shader_program.h"
#include "meshedit/files/files.h"
#include "meshedit/overlay/shader_log.h"

#include <unistd.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "gl.h"

namespace meshedit {
namespace {

std::filesystem::path executable_directory() {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : self.parent_path();
}

// Through read_file(): a FIFO or a device named as a user shader is refused, not read
// forever; a shader is source text, so 1 MiB is plenty.
std::string read_text(const std::filesystem::path& path) {
    try {
        return read_file(path, std::size_t{1} << 20);
    } catch (const IoError& e) {
        throw GlError("cannot read shader " + std::string(e.what()));
    }
}

std::string shader_log(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

std::string program_log(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

GLuint compile(GLenum type, const std::filesystem::path& path, std::string_view defines) {
    std::string source = read_text(path);
    if (!defines.empty()) {
        // GLSL wants #version first; the defines follow it, then #line keeps the compiler's
        // line numbers those of the file.
        const std::size_t eol = source.find('\n');
        source.insert(eol == std::string::npos ? source.size() : eol + 1,
                      std::string(defines) + "#line 2\n");
    }
    const GLuint shader = glCreateShader(type);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        // Mesa writes "0:36(15): error: …": name the line and column as a reader looks
        // them up.
        const std::string log = readable_shader_log(shader_log(shader));
        glDeleteShader(shader);
        throw GlError("shader " + path.string() + " does not compile: " + log);
    }
    return shader;
}

}  // namespace

std::filesystem::path shader_directory() {
    std::vector<std::filesystem::path> candidates;
    if (const char* env = std::getenv("MESHEDIT_SHADER_DIR"); env != nullptr && *env != '\0') {
        candidates.emplace_back(env);
    }
    const std::filesystem::path exe = executable_directory();
    if (!exe.empty()) {
        candidates.push_back(exe / "shaders");
        candidates.push_back(exe.parent_path() / "share" / "meshedit" / "shaders");
    }
    for (const auto& dir : candidates) {
        std::error_code ec;
        if (std::filesystem::is_regular_file(dir / "mesh.vert", ec)) {
            return dir;
        }
    }
    throw GlError("no shader folder found (looked in $MESHEDIT_SHADER_DIR, " +
                  (exe / "shaders").string() + " and " +
                  (exe.parent_path() / "share" / "meshedit" / "shaders").string() + ")");
}

void check_gl(std::string_view what) {
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
        std::ostringstream message;
        message << "GL error 0x" << std::hex << error << " in " << what;
        while (glGetError() != GL_NO_ERROR) {
        }
        throw GlError(message.str());
    }
}

ShaderProgram::ShaderProgram(std::string_view vert_name, std::string_view frag_name,
                             std::string_view defines)
    : ShaderProgram(
          from_files(shader_directory() / vert_name, shader_directory() / frag_name, defines)) {}

ShaderProgram ShaderProgram::from_files(const std::filesystem::path& vert_path,
                                        const std::filesystem::path& frag_path,
                                        std::string_view defines) {
    const GLuint vert = compile(GL_VERTEX_SHADER, vert_path, defines);
    GLuint frag = 0;
    try {
        frag = compile(GL_FRAGMENT_SHADER, frag_path, defines);
    } catch (...) {
        glDeleteShader(vert);
        throw;
    }
    const GLuint program = glCreateProgram();
    glAttachShader(program, vert);
    glAttachShader(program, frag);
    glLinkProgram(program);
    glDeleteShader(vert);  // flagged; freed with the program
    glDeleteShader(frag);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = readable_shader_log(program_log(program));
        glDeleteProgram(program);
        throw GlError("shaders " + vert_path.string() + " + " + frag_path.string() +
                      " do not link: " + log);
    }
    ShaderProgram out;
    out.id_ = program;
    return out;
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        if (id_ != 0) {
            glDeleteProgram(id_);
        }
        id_ = std::exchange(other.id_, 0);
    }
    return *this;
}

ShaderProgram::~ShaderProgram() {
    if (id_ != 0) {
        glDeleteProgram(id_);
    }
}

void ShaderProgram::use() const {
    glUseProgram(id_);
}

int ShaderProgram::location(const char* name) const {
    return glGetUniformLocation(id_, name);
}

void ShaderProgram::set_int(const char* name, int value) const {
    glUniform1i(location(name), value);
}
void ShaderProgram::set_float(const char* name, float value) const {
    glUniform1f(location(name), value);
}
void ShaderProgram::set_vec2(const char* name, float x, float y) const {
    glUniform2f(location(name), x, y);
}
void ShaderProgram::set_vec3(const char* name, const float* xyz) const {
    glUniform3fv(location(name), 1, xyz);
}
void ShaderProgram::set_vec4(const char* name, const float* xyzw) const {
    glUniform4fv(location(name), 1, xyzw);
}
void ShaderProgram::set_mat3(const char* name, const float* m) const {
    glUniformMatrix3fv(location(name), 1, GL_FALSE, m);
}
void ShaderProgram::set_mat4(const char* name, const float* m) const {
    glUniformMatrix4fv(location(name), 1, GL_FALSE, m);
}

}  // namespace meshedit
