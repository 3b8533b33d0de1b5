// `meshedit-view` (also `meshedit FILE` and `meshedit view FILE`): the interactive viewer.

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

#include "app.h"

namespace {

constexpr const char* kUsage =
    "usage: meshedit [view] [FILE] [--size WxH] [--no-vsync]\n"
    "       (the meshedit-view executable; 'meshedit FILE' and 'meshedit view FILE' run it)\n"
    "\n"
    "Opens FILE (.dae .gltf .glb .obj mesh, .bez Bezier patches, .bzc Bezier curve) in the\n"
    "interactive editor. Press ? or F1 in the window for every key and mouse action.\n"
    "  --size WxH     window size in screen coordinates (default 1280x800)\n"
    "  --no-vsync     draw without waiting for the display's refresh\n"
    "Without a display, use 'meshedit render FILE -o out.png' to render headless.\n";

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
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "-h" || a == "--help") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (a == "--size" && i + 1 < argc) {
            if (!parse_size(argv[++i], options.width, options.height)) {
                std::fprintf(stderr, "meshedit: --size wants WxH (64..16384), got '%s'\n", argv[i]);
                return 2;
            }
        } else if (a == "--no-vsync") {
            options.vsync = false;
        } else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "meshedit: unknown option '%s' (see --help)\n", argv[i]);
            return 2;
        } else if (options.file.empty()) {
            options.file = argv[i];
        } else {
            std::fprintf(stderr, "meshedit: the viewer opens one file, got a second: '%s'\n",
                         argv[i]);
            return 2;
        }
    }
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
        meshedit::viewer::App app(options);
        return app.run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "meshedit: %s\n", e.what());
        return 1;
    }
}
