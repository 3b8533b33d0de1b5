// `meshedit-view` (also `meshedit FILE` and `meshedit view FILE`): the interactive viewer.

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

#include "app.h"
#include "command_line.h"
#include "meshedit/io/io.h"

namespace {

// "WxH" with both in 64..16384.
bool parse_size(std::string_view text, int& width, int& height) {
    const std::size_t x = text.find('x');
    if (x == std::string_view::npos) {
        return false;
    }
    const auto w = std::from_chars(text.data(), text.data() + x, width);
    const auto h = std::from_chars(text.data() + x + 1, text.data() + text.size(), height);
    return w.ec == std::errc() && h.ec == std::errc() && w.ptr == text.data() + x &&
           h.ptr == text.data() + text.size() && width >= 64 && height >= 64 && width <= 16384 &&
           height <= 16384;
}

}  // namespace

int main(int argc, char** argv) {
    meshedit::viewer::ViewerOptions options;
    CLI::App app("Opens FILE (" + meshedit::mesh_extension_list(" ") +
                     " mesh, .bez Bezier patches, .bzc Bezier curve) in the interactive editor. "
                     "Press ? or F1 in the window for every key and mouse action.",
                 "meshedit [view]");
    meshedit::command_line::style(app);
    std::string file;
    std::string size;
    bool no_vsync = false;
    app.add_option("FILE", file, "the file to open (none: start empty, open with Ctrl+O)");
    app.add_option("--size", size, "window size in screen coordinates (default 1280x800)")
        ->type_name("WxH");
    app.add_flag("--no-vsync", no_vsync, "draw without waiting for the display's refresh");
    std::string envmap;
    app.add_option("--envmap", envmap,
                   "shading 7's environment: an equirectangular PNG, JPEG, HDR or EXR (default: a "
                   "procedural studio); dropping an image on the window does the same")
        ->type_name("FILE");
    std::string shader_dir;
    app.add_option("--shader-dir", shader_dir,
                   "where shading 8 and 9 load mesh8.frag and mesh9.frag (default: "
                   "$XDG_CONFIG_HOME/meshedit/shaders or ~/.config/meshedit/shaders, given starter "
                   "shaders the first time)")
        ->type_name("DIR");
    std::string up = "file";
    app.add_option("--up", up,
                   "which axis is up: y, z (the CS184 course's models), or file (the file's "
                   "declared axis, +Y once read; the default); Y switches in the window")
        ->type_name("y|z|file")
        ->check(CLI::IsMember({"y", "z", "file"}));
    std::string student;
    app.add_option("--student", student,
                   "a student library built from student/ (docs/student.md): F, S, L, Q and E "
                   "call its functions in a sandbox and compare each result with MeshEdit's")
        ->type_name("LIB.so");
    const CLI::Option* threads = meshedit::command_line::add_threads_option(app);
    app.footer(
        "The meshedit-view executable; 'meshedit FILE' and 'meshedit view FILE' run it.\n"
        "Without a display, use 'meshedit render FILE -o out.png' to render headless.");
    if (const int status = meshedit::command_line::parse(app, argc, argv, "meshedit");
        status >= 0) {
        return status;
    }
    if (threads->count() == 0 && !meshedit::command_line::check_thread_environment("meshedit")) {
        return 2;
    }
    if (!size.empty() && !parse_size(size, options.width, options.height)) {
        std::fprintf(stderr, "meshedit: --size wants WxH (64..16384), got '%s'\n", size.c_str());
        return 2;
    }
    options.file = file;
    options.envmap = envmap;
    options.shader_dir = shader_dir;
    options.student = student;
    options.vsync = !no_vsync;
    options.up = up == "z" ? meshedit::UpAxis::Z : meshedit::UpAxis::Y;
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland)) {
        std::fprintf(stderr,
                     "meshedit: no display (DISPLAY is not set): the viewer needs a window. "
                     "Render headless instead: meshedit render %s -o out.png\n",
                     options.file.empty() ? "FILE" : options.file.c_str());
        return 1;
    }
    try {
        meshedit::viewer::App viewer(options);
        return viewer.run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "meshedit: %s\n", e.what());
        return 1;
    }
}
