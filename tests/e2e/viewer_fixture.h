#pragma once
/// \file
/// What the end-to-end tests of the viewer share: settings, the private X server (one
/// Xvfb for the program, registered by viewer_fixture.cpp), the viewer's opening camera,
/// mesh comparisons, and the ViewerE2E fixture that starts `meshedit FILE` and takes its
/// screenshots.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cli/run.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/normals.h"
#include "meshedit/io/io.h"
#include "meshedit/overlay/camera.h"
#include "session.h"
#include "support/image_compare.h"
#include "support/mesh_compare.h"

namespace meshedit::test::e2e {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// ------------------------------------------------------------------------------ settings

inline fs::path source_dir() {
    return MESHEDIT_SOURCE_DIR;
}
inline fs::path e2e_golden_dir() {
    return source_dir() / "tests" / "e2e" / "golden";
}
inline fs::path headless_golden_dir() {
    return source_dir() / "tests" / "golden";
}
inline fs::path out_dir() {
    return fs::path(MESHEDIT_BUILD_DIR) / "e2e_out";
}
inline bool update_mode() {
    const char* env = std::getenv("MESHEDIT_UPDATE_GOLDEN");
    return env != nullptr && std::string(env) == "1";
}

inline const std::string kCubeTitle = "MeshEdit — cube.dae — V 8 E 18 F 12";

// -------------------------------------------------------------------- the X environment

/// One Xvfb for the whole program, DISPLAY pointing at it for every child.
class XEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        std::string missing;
        for (const char* tool : {"Xvfb", "xdotool", "import"}) {
            if (find_program(tool).empty()) {
                missing += std::string(missing.empty() ? "" : ", ") + tool;
            }
        }
        if (!missing.empty()) {
            problem() = "the end-to-end tests need " + missing +
                        " (Debian packages xvfb, xdotool, imagemagick); `make test` installs "
                        "them through scripts/install-deps.sh";
            return;  // each test fails with this message (a failure here would skip them)
        }
        try {
            server_ = std::make_unique<Xvfb>(find_program("Xvfb"));
        } catch (const std::exception& e) {
            problem() = std::string("cannot start Xvfb: ") + e.what();
            return;
        }
        if (const char* old = std::getenv("DISPLAY")) {
            old_display_ = old;
        }
        ::setenv("DISPLAY", server_->display().c_str(), 1);
        ready() = true;
    }

    void TearDown() override {
        server_.reset();
        if (!ready()) {
            return;
        }
        if (old_display_) {
            ::setenv("DISPLAY", old_display_->c_str(), 1);
        } else {
            ::unsetenv("DISPLAY");
        }
        ready() = false;
    }

    static bool& ready() {
        static bool value = false;
        return value;
    }
    static std::string& problem() {
        static std::string value;
        return value;
    }

private:
    std::unique_ptr<Xvfb> server_;
    std::optional<std::string> old_display_;
};

// ----------------------------------------------------------------------------- geometry

/// Where a world point lands in a W×H window under `camera`: pixel coordinates with the
/// origin at the top left, as the viewer computes them.
inline glm::vec2 project(const Camera& camera, float aspect, const Vec3& p, int width, int height) {
    const glm::vec4 clip =
        camera.projection(aspect) * camera.view() *
        glm::vec4(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z), 1.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * static_cast<float>(width),
            (0.5f - ndc.y * 0.5f) * static_cast<float>(height)};
}

/// Window pixels the info panel covers on the left at the viewer's start (no HiDPI under
/// Xvfb): its margin and fixed width, Panels::kInfoMargin + Panels::kInfoWidth, at most half
/// the window.
inline int info_panel_pixels(int width) {
    return std::min(10 + 300, width / 2);
}

/// The viewer's opening camera for a mesh in a W×H window (App::reset_camera): `meshedit
/// render`'s framing of the part the info panel leaves free, shifted to its centre.
inline Camera opening_camera(const Mesh& mesh, int width, int height) {
    const int covered = info_panel_pixels(width);
    Camera camera;
    camera.azimuth_deg = 30.0f;
    camera.elevation_deg = 20.0f;
    camera.lens_shift_x = static_cast<float>(covered) / static_cast<float>(width);
    camera.frame_mesh(mesh, static_cast<float>(width - covered) / static_cast<float>(height));
    return camera;
}

/// An edge to click and flip: both faces beside it face the camera, flipping is allowed,
/// and its midpoint's pixel is clear of every projected vertex and of the panels.
struct EdgeTarget {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    int x = 0;
    int y = 0;
    std::string ops() const { return "flip:" + std::to_string(a) + "-" + std::to_string(b); }
};

inline std::optional<EdgeTarget> flip_target(const Mesh& mesh, int width, int height,
                                             std::string& report) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const Camera camera = opening_camera(mesh, width, height);
    const glm::vec3 e = camera.eye();
    const Vec3 eye{e.x, e.y, e.z};
    std::vector<glm::vec2> corners;
    for (Vertex v : mesh.vertices()) {
        corners.push_back(project(camera, aspect, mesh.position(v), width, height));
    }
    std::optional<EdgeTarget> best;
    double best_score = -1.0;
    std::ostringstream log;
    for (Edge edge : mesh.edges()) {
        const Vertex va = mesh.vertex(edge, 0);
        const Vertex vb = mesh.vertex(edge, 1);
        EdgeTarget t;
        t.a = std::min(va.idx(), vb.idx());
        t.b = std::max(va.idx(), vb.idx());
        if (mesh.is_boundary(edge) || !is_flip_ok(mesh, edge)) {
            continue;
        }
        // How squarely each face looks at the camera (cosine between normal and view ray).
        double facing = 1.0;
        for (unsigned i = 0; i < 2; ++i) {
            const Face f = mesh.face(edge, i);
            Vec3 centre{0, 0, 0};
            int n = 0;
            for (Vertex v : mesh.vertices(f)) {
                centre = centre + mesh.position(v);
                ++n;
            }
            centre = centre * (1.0 / n);
            const Vec3 to_eye = eye - centre;
            facing = std::min(facing, dot(face_normal(mesh, f), to_eye) / norm(to_eye));
        }
        if (facing < 0.25) {
            continue;  // back-facing or grazing
        }
        const Vec3 mid = (mesh.position(va) + mesh.position(vb)) * 0.5;
        const glm::vec2 p = project(camera, aspect, mid, width, height);
        float clearance = 1e9f;
        for (const glm::vec2& c : corners) {
            clearance = std::min(clearance, glm::length(c - p));
        }
        t.x = static_cast<int>(std::floor(p.x));
        t.y = static_cast<int>(std::floor(p.y));
        log << "  edge " << t.a << "-" << t.b << ": facing " << facing << ", pixel (" << t.x << ", "
            << t.y << "), " << clearance << " px from the nearest vertex\n";
        const bool in_window = t.x >= 10 && t.y >= 10 && t.x < width - 10 && t.y < height - 10;
        // The info panel (top left) and the status line (bottom).
        const bool under_panel = t.x < info_panel_pixels(width) + 20 || t.y > height - 60;
        if (clearance < 10.0f || !in_window || under_panel) {
            continue;
        }
        const bool preferred = t.a == 0 && t.b == 6;  // dae/cube/flip.dae's edge
        const double score = preferred ? 2.0 : facing;
        if (score > best_score) {
            best_score = score;
            best = t;
        }
    }
    report = log.str();
    return best;
}

// ------------------------------------------------------------------------------- meshes

inline Mesh load(const fs::path& path) {
    return read_mesh(path).mesh;
}

/// Same faces by vertex index (canonical cycles) and the same positions, bit for bit.
inline ::testing::AssertionResult same_mesh(const Mesh& actual, const Mesh& expected) {
    const auto fa = canonical_faces(actual);
    const auto fe = canonical_faces(expected);
    if (fa != fe) {
        auto text = [](const std::vector<std::vector<std::uint32_t>>& faces) {
            std::ostringstream out;
            for (const auto& f : faces) {
                out << "(";
                for (std::size_t i = 0; i < f.size(); ++i) {
                    out << (i ? " " : "") << f[i];
                }
                out << ")";
            }
            return out.str();
        };
        return ::testing::AssertionFailure()
               << "faces differ:\n  actual   " << text(fa) << "\n  expected " << text(fe);
    }
    std::vector<Vec3> pa, pe;
    for (Vertex v : actual.vertices()) {
        pa.push_back(actual.position(v));
    }
    for (Vertex v : expected.vertices()) {
        pe.push_back(expected.position(v));
    }
    if (pa.size() != pe.size()) {
        return ::testing::AssertionFailure()
               << "vertex counts differ: " << pa.size() << " vs " << pe.size();
    }
    for (std::size_t i = 0; i < pa.size(); ++i) {
        const double a[3] = {pa[i].x, pa[i].y, pa[i].z};
        const double b[3] = {pe[i].x, pe[i].y, pe[i].z};
        for (int c = 0; c < 3; ++c) {
            if (std::bit_cast<std::uint64_t>(a[c]) != std::bit_cast<std::uint64_t>(b[c])) {
                return ::testing::AssertionFailure()
                       << "vertex " << i << " differs: (" << pa[i].x << ", " << pa[i].y << ", "
                       << pa[i].z << ") vs (" << pe[i].x << ", " << pe[i].y << ", " << pe[i].z
                       << ")";
            }
        }
    }
    return ::testing::AssertionSuccess();
}

/// Inode and modification time: an atomic save (temporary file + rename) changes both.
inline std::pair<ino_t, long long> file_stamp(const fs::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        return {0, 0};
    }
    return {st.st_ino,
            static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec};
}

inline std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos;
         at = text.find(what, at + what.size())) {
        ++n;
    }
    return n;
}

// ------------------------------------------------------------------------------ fixture

class ViewerE2E : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(XEnvironment::ready()) << XEnvironment::problem();
        fs::create_directories(out_dir());
    }

    /// `meshedit FILE --size WxH [MORE…]` with the work folder as its current directory and as its
    /// pictures folder (XDG_PICTURES_DIR): screenshots go to work_/MeshEdit; its settings
    /// folder is work_/config.
    std::unique_ptr<BackgroundProcess> start_viewer(const fs::path& file, const std::string& size,
                                                    const std::vector<std::string>& more = {}) {
        viewer_stem_ = file.stem().string();
        ::setenv("XDG_PICTURES_DIR", work_.path().c_str(), 1);
        // The viewer's settings (the up axis remembered per file) stay in the test's folder:
        // a run must not remember a choice for the next.
        ::setenv("XDG_CONFIG_HOME", (work_ / "config").c_str(), 1);
        std::vector<std::string> args{file.string(), "--size", size};
        args.insert(args.end(), more.begin(), more.end());
        return std::make_unique<BackgroundProcess>(MESHEDIT_EXE, args, work_.path(), logs_.path());
    }

    /// Presses P and waits for the viewer to announce screenshot number `n` on stdout;
    /// returns its path (empty on failure, with the test failed).
    fs::path screenshot(BackgroundProcess& viewer, const ViewerWindow& window, std::size_t n) {
        const std::string marker = "meshedit: screenshot ";
        window.key("p");
        const bool written = wait_until(
            [&] {
                const std::string out = viewer.out();
                return count_of(out, marker) >= n && out.back() == '\n';
            },
            20s);
        EXPECT_TRUE(written) << "no screenshot " << n << " announced on stdout; stdout:\n"
                             << viewer.out() << "\nstderr:\n"
                             << viewer.err();
        if (!written) {
            return {};
        }
        std::string last;
        for (const std::string& line : split_lines(viewer.out())) {
            if (line.rfind(marker, 0) == 0) {
                last = line.substr(marker.size());
            }
        }
        const fs::path path = last;
        EXPECT_TRUE(path.is_absolute()) << "screenshot path is not absolute: " << last;
        EXPECT_EQ(path.filename().string(),
                  "meshedit-" + viewer_stem_ + "-" + std::to_string(n) + ".png");
        std::error_code ec;
        EXPECT_TRUE(fs::equivalent(path.parent_path(), work_ / "MeshEdit", ec))
            << "screenshot " << path << " not in the pictures folder " << work_ / "MeshEdit";
        EXPECT_TRUE(fs::exists(path)) << path;
        return path;
    }

    /// `shot` equals the golden image tests/e2e/golden/NAME.png (images_match()'s tolerance);
    /// with MESHEDIT_UPDATE_GOLDEN=1 it becomes the golden instead (look at it before
    /// committing it).
    void expect_golden(const fs::path& shot, const std::string& name) {
        const fs::path golden = e2e_golden_dir() / (name + ".png");
        if (update_mode()) {
            fs::create_directories(golden.parent_path());
            if (!same_file_bytes(shot, golden)) {
                fs::copy_file(shot, golden, fs::copy_options::overwrite_existing);
                std::cout << "golden: rewrote " << golden.string() << "\n";
            }
            return;
        }
        ASSERT_TRUE(fs::exists(golden))
            << "no reference image " << golden << "; create it with MESHEDIT_UPDATE_GOLDEN=1 "
            << "and look at it before committing it";
        EXPECT_TRUE(images_match(shot, golden, out_dir(), name));
    }

    /// Copies dae/cube.dae to work_/cube.dae, opens it at 800×600 in `viewer` and `window`,
    /// and flips a visible edge by a click and F: the title gets its '*'.
    void open_cube_and_flip(std::unique_ptr<BackgroundProcess>& viewer,
                            std::optional<ViewerWindow>& window) {
        const fs::path doc = work_ / "cube.dae";
        fs::copy_file(source_dir() / "dae" / "cube.dae", doc);
        std::string candidates;
        const std::optional<EdgeTarget> target = flip_target(load(doc), 800, 600, candidates);
        ASSERT_TRUE(target) << candidates;
        viewer = start_viewer(doc, "800x600");
        window.emplace(*viewer);
        ASSERT_TRUE(window->ok());
        std::string title;
        ASSERT_TRUE(window->wait_title(kCubeTitle, false, 20s, &title)) << title;
        window->click(target->x, target->y);
        window->key("f");
        ASSERT_TRUE(window->wait_title(" *", false, 20s, &title)) << title << "\n" << viewer->err();
    }

    /// Ctrl+O, then (once the chooser shows) its field replaced by `path`, and Return.
    void open_through_prompt(const ViewerWindow& window, const fs::path& path) {
        answer_prompt(window, "ctrl+o", path);
    }

    /// `key` (Ctrl+O, Ctrl+Shift+S, Ctrl+Shift+E), then (once its file chooser shows) the
    /// field's text replaced by `path` — or, without one, the name the chooser suggests kept —
    /// and Return.
    void answer_prompt(const ViewerWindow& window, const std::string& key,
                       const std::optional<fs::path>& path) {
        ASSERT_NO_FATAL_FAILURE(show_chooser(window, key));
        if (path) {
            window.key("ctrl+a");
            window.type(path->string());
        }
        window.key("Return");
    }

    /// `key`, then (once its file chooser shows) `keys` pressed at once (say End and
    /// BackSpace ×8: on a slow document they all arrive between two frames), `text` typed,
    /// and Return.
    void edit_prompt(const ViewerWindow& window, const std::string& key,
                     const std::vector<std::string>& keys, const std::string& text) {
        ASSERT_NO_FATAL_FAILURE(show_chooser(window, key));
        window.keys(keys);
        window.type(text);
        window.key("Return");
    }

    /// `key`, then waits until the file chooser covers much of the window. The chooser takes
    /// every key from then on, however slow the frames (file_chooser.h).
    void show_chooser(const ViewerWindow& window, const std::string& key) {
        const fs::path before = logs_ / "before_prompt.png";
        ASSERT_TRUE(window.capture(before));
        window.key(key);
        const RgbImage plain = read_rgb(before);
        const bool prompt_shown = wait_until(
            [&] {
                const fs::path now = logs_ / "prompt.png";
                if (!window.capture(now)) {
                    return false;
                }
                const RgbImage image = read_rgb(now);
                if (image.width != plain.width || image.height != plain.height) {
                    return false;
                }
                int changed = 0;
                for (int y = 0; y < image.height; y += 2) {
                    for (int x = 0; x < image.width; x += 2) {
                        changed += channel_difference(image, x, y, plain, x, y) > 40;
                    }
                }
                return changed > 1000;
            },
            20s, 100ms);
        ASSERT_TRUE(prompt_shown) << "no file chooser after " << key;
    }

    /// The viewer exits with `code` within a few seconds.
    void expect_exit(BackgroundProcess& viewer, int code) {
        const std::optional<int> status = viewer.wait_exit(15s);
        ASSERT_TRUE(status.has_value()) << "the viewer did not exit; stderr:\n" << viewer.err();
        EXPECT_EQ(*status, code) << "signal " << viewer.term_signal() << "; stderr:\n"
                                 << viewer.err();
    }

    TempDir work_;             // the viewer's current directory and its document
    TempDir logs_;             // its stdout/stderr and the test's own scratch files
    std::string viewer_stem_;  // the document's stem: screenshots are meshedit-STEM-N.png
};

/// A screenshot is a picture, not a black or uniform frame.
inline ::testing::AssertionResult looks_rendered(const fs::path& png, int width, int height) {
    const RgbImage image = read_rgb(png);
    if (image.width != width || image.height != height) {
        return ::testing::AssertionFailure() << png << " is " << image.width << "x" << image.height
                                             << ", wanted " << width << "x" << height;
    }
    const std::size_t colours = distinct_colours(image);
    const int centre_vs_corner =
        channel_difference(image, width / 2, height / 2, image, width - 3, height / 2);
    if (colours < 200 || centre_vs_corner < 20) {
        return ::testing::AssertionFailure()
               << png << " looks blank: " << colours << " colours, centre differs from the "
               << "background by " << centre_vs_corner << "/255";
    }
    return ::testing::AssertionSuccess();
}

// -------------------------------------------------------------------------------- tests

}  // namespace meshedit::test::e2e
