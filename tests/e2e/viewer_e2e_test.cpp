/// \file
/// End-to-end tests of the interactive viewer: the real `meshedit FILE` (which execs
/// meshedit-view) in a private Xvfb, driven like a person drives it — pointer and keys
/// through xdotool, the window title read back to synchronise, screenshots (P) compared with
/// golden images and with the headless renderer, saved files read back and compared face by
/// face.
///
/// MESHEDIT_UPDATE_GOLDEN=1 rewrites tests/e2e/golden/ instead of comparing (look at every
/// rewritten PNG before committing it). The headless goldens of tests/golden/ are only read.

#include <gtest/gtest.h>
#include <sys/stat.h>

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
#include "meshedit/render/camera.h"
#include "session.h"
#include "support/image_compare.h"
#include "support/mesh_compare.h"

namespace meshedit::test::e2e {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// ------------------------------------------------------------------------------ settings

fs::path source_dir() {
    return MESHEDIT_SOURCE_DIR;
}
fs::path e2e_golden_dir() {
    return source_dir() / "tests" / "e2e" / "golden";
}
fs::path headless_golden_dir() {
    return source_dir() / "tests" / "golden";
}
fs::path out_dir() {
    return fs::path(MESHEDIT_BUILD_DIR) / "e2e_out";
}
bool update_mode() {
    const char* env = std::getenv("MESHEDIT_UPDATE_GOLDEN");
    return env != nullptr && std::string(env) == "1";
}

const std::string kCubeTitle = "MeshEdit — cube.dae — V 8 E 18 F 12";

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

[[maybe_unused]] ::testing::Environment* const g_x_environment =
    ::testing::AddGlobalTestEnvironment(new XEnvironment);

// ----------------------------------------------------------------------------- geometry

/// Where a world point lands in a W×H window under `camera`: pixel coordinates with the
/// origin at the top left, as the viewer computes them.
glm::vec2 project(const Camera& camera, float aspect, const Vec3& p, int width, int height) {
    const glm::vec4 clip =
        camera.projection(aspect) * camera.view() *
        glm::vec4(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z), 1.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * static_cast<float>(width),
            (0.5f - ndc.y * 0.5f) * static_cast<float>(height)};
}

/// The viewer's opening camera for a mesh (App::reset_camera = `meshedit render`'s framing).
Camera opening_camera(const Mesh& mesh, float aspect) {
    Camera camera;
    camera.azimuth_deg = 30.0f;
    camera.elevation_deg = 20.0f;
    camera.frame_mesh(mesh, aspect);
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

std::optional<EdgeTarget> flip_target(const Mesh& mesh, int width, int height,
                                      std::string& report) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const Camera camera = opening_camera(mesh, aspect);
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
        // The info panel (top left, ≤ 420 px wide) and the status line (bottom).
        const bool under_panel = (t.x < 440 && t.y < 230) || t.y > height - 60;
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

Mesh load(const fs::path& path) {
    return read_mesh(path).mesh;
}

/// Same faces by vertex index (canonical cycles) and the same positions, bit for bit.
::testing::AssertionResult same_mesh(const Mesh& actual, const Mesh& expected) {
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
std::pair<ino_t, long long> file_stamp(const fs::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        return {0, 0};
    }
    return {st.st_ino,
            static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec};
}

std::size_t count_of(const std::string& text, const std::string& what) {
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

    /// `meshedit FILE --size WxH` with the work folder as its current directory.
    std::unique_ptr<BackgroundProcess> start_viewer(const fs::path& file, const std::string& size) {
        viewer_stem_ = file.stem().string();
        return std::make_unique<BackgroundProcess>(
            MESHEDIT_EXE, std::vector<std::string>{file.string(), "--size", size}, work_.path(),
            logs_.path());
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
        EXPECT_TRUE(fs::equivalent(path.parent_path(), work_.path(), ec))
            << "screenshot " << path << " not in the current directory " << work_.path();
        EXPECT_TRUE(fs::exists(path)) << path;
        return path;
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
::testing::AssertionResult looks_rendered(const fs::path& png, int width, int height) {
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

// Click an edge, flip it, save; Loop twice and screenshot (golden + headless render); undo
// back through the flip to the input, saving on the way; quit.
TEST_F(ViewerE2E, CubeFlipSaveLoopUndo) {
    const fs::path original = source_dir() / "dae" / "cube.dae";
    const fs::path doc = work_ / "cube.dae";
    fs::copy_file(original, doc);
    const Mesh input = load(doc);

    std::string candidates;
    const std::optional<EdgeTarget> target = flip_target(input, 800, 600, candidates);
    ASSERT_TRUE(target) << "no visible flippable edge to click; candidates:\n" << candidates;
    std::cout << "clicking edge " << target->a << "-" << target->b << " at (" << target->x << ", "
              << target->y << ")\n";

    // The expected flip, through the CLI's own op path.
    const fs::path expected_file = logs_ / "expected.dae";
    const RunResult convert = run_meshedit(
        {"convert", original.string(), expected_file.string(), "--ops", target->ops()});
    ASSERT_EQ(convert.exit_code, 0) << convert.err;
    const Mesh expected = load(expected_file);

    auto viewer = start_viewer(doc, "800x600");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title(kCubeTitle, false, 20s, &title)) << title;

    // Select the edge and flip it: the title gets its '*'.
    window.click(target->x, target->y);
    window.key("f");
    ASSERT_TRUE(window.wait_title(" *", false, 20s, &title))
        << "no unsaved change after clicking edge " << target->a << "-" << target->b
        << " and pressing F; title '" << title << "'\nstderr:\n"
        << viewer->err();
    EXPECT_EQ(title, kCubeTitle + " *");

    // Ctrl+S writes the flip to the opened file.
    window.key("ctrl+s");
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;
    EXPECT_TRUE(same_mesh(load(doc), expected)) << "saved after the flip of " << target->ops();
    if (target->a == 0 && target->b == 6) {
        EXPECT_TRUE(same_mesh(load(doc), load(source_dir() / "dae" / "cube" / "flip.dae")));
    }

    // Loop twice; P writes the 3D view without panels.
    window.keys({"l", "l"});
    ASSERT_TRUE(window.wait_title("V 98 E 288 F 192 *", false, 60s, &title)) << title;
    const fs::path shot = screenshot(*viewer, window, 1);
    ASSERT_FALSE(shot.empty());
    EXPECT_TRUE(looks_rendered(shot, 800, 600));
    const fs::path golden = e2e_golden_dir() / "cube_flip_loop2.png";
    if (update_mode()) {
        fs::create_directories(golden.parent_path());
        if (!same_file_bytes(shot, golden)) {
            fs::copy_file(shot, golden, fs::copy_options::overwrite_existing);
            std::cout << "golden: rewrote " << golden.string() << "\n";
        }
    } else {
        ASSERT_TRUE(fs::exists(golden))
            << "no reference image " << golden << "; create it with MESHEDIT_UPDATE_GOLDEN=1 "
            << "and look at it before committing it";
        EXPECT_TRUE(images_match(shot, golden, out_dir(), "cube_flip_loop2"));
    }

    // The headless renderer draws the same picture. The viewer keeps its camera through
    // edits while `meshedit render` frames the final mesh, so Space (reset camera: the same
    // framing) first; the viewer shows the wireframe by default, `render` on --wireframe.
    window.key("space");
    const fs::path framed = screenshot(*viewer, window, 2);
    ASSERT_FALSE(framed.empty());
    const fs::path headless = logs_ / "headless.png";
    const RunResult render =
        run_meshedit({"render", original.string(), "-o", headless.string(), "--size", "800x600",
                      "--ops", target->ops() + ",loop:2", "--wireframe"},
                     120.0);
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_TRUE(images_match(framed, headless, out_dir(), "cube_flip_loop2_vs_headless"));

    // Undo both Loops, redo them (both redo keys), undo again: the flipped cube, which is
    // what is on disk (clean).
    window.keys({"ctrl+z", "ctrl+z"});
    ASSERT_TRUE(window.wait_title("V 8 E 18 F 12", false, 20s, &title)) << title;
    window.key("ctrl+y");
    ASSERT_TRUE(window.wait_title("V 26 E 72 F 48 *", false, 20s, &title)) << title;
    window.key("ctrl+shift+z");
    ASSERT_TRUE(window.wait_title("V 98 E 288 F 192 *", false, 20s, &title)) << title;
    window.keys({"ctrl+z", "ctrl+z"});
    ASSERT_TRUE(window.wait_title("V 8 E 18 F 12", false, 20s, &title)) << title;
    EXPECT_EQ(window.title(), kCubeTitle);
    const auto before_save = file_stamp(doc);
    window.key("ctrl+s");
    ASSERT_TRUE(wait_until([&] { return file_stamp(doc) != before_save; }, 20s))
        << "Ctrl+S did not rewrite " << doc;
    EXPECT_TRUE(same_mesh(load(doc), expected)) << "saved after undoing both Loops";

    // Undo the flip: the input cube, unsaved; save it.
    window.key("ctrl+z");
    ASSERT_TRUE(window.wait_title(" *", false, 20s, &title)) << title;
    window.key("ctrl+s");
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;
    EXPECT_TRUE(same_mesh(load(doc), input)) << "saved after undoing the flip";

    // Saved, so Ctrl+Q quits at once.
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

// A curve: every de Casteljau level (E) matches the headless golden of that level.
TEST_F(ViewerE2E, CurveLevels) {
    const fs::path doc = work_ / "curve6.bzc";
    fs::copy_file(source_dir() / "bez" / "curve6.bzc", doc);
    const BezierCurve curve = read_bzc(doc);
    const int width = 384;
    const int height = 288;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    Camera camera;
    camera.frame_2d({0.0f, 0.0f}, {1.0f, 1.0f}, aspect);

    // The pointer rests on the paper corner farthest from every control point.
    glm::vec2 rest{0.0f};
    float rest_clearance = -1.0f;
    for (const Vec3& corner : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}}) {
        const glm::vec2 p = project(camera, aspect, corner, width, height);
        float clearance = 1e9f;
        for (const Vec3& c : curve.control_points) {
            clearance =
                std::min(clearance, glm::length(project(camera, aspect, c, width, height) - p));
        }
        if (clearance > rest_clearance) {
            rest_clearance = clearance;
            rest = p;
        }
    }
    ASSERT_GT(rest_clearance, 12.0f) << "every paper corner is within picking distance";

    auto viewer = start_viewer(doc, "384x288");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title("curve6.bzc — curve, 6 points", false, 20s, &title)) << title;
    window.move_to(static_cast<int>(rest.x), static_cast<int>(rest.y));

    for (int k = 0; k <= 5; ++k) {
        const fs::path shot = screenshot(*viewer, window, static_cast<std::size_t>(k) + 1);
        ASSERT_FALSE(shot.empty());
        const std::string name = "curve6_level" + std::to_string(k);
        EXPECT_TRUE(images_match(shot, headless_golden_dir() / (name + ".png"), out_dir(),
                                 "viewer_" + name))
            << "level " << k;
        window.key("e");
    }
    // The last E went past the last level: refused, said on stderr; once more for luck.
    const std::string refusal = "already at the last level";
    ASSERT_TRUE(wait_until([&] { return count_of(viewer->err(), refusal) >= 1; }, 20s))
        << viewer->err();
    window.key("e");
    ASSERT_TRUE(wait_until([&] { return count_of(viewer->err(), refusal) >= 2; }, 20s))
        << viewer->err();
    EXPECT_TRUE(viewer->running());
    EXPECT_EQ(window.title(), "MeshEdit — curve6.bzc — curve, 6 points");

    // Nothing selected, nothing changed: Esc quits.
    window.key("Escape");
    expect_exit(*viewer, 0);
}

// A file that fails to open, through Ctrl+O and on the command line: an error, no crash.
TEST_F(ViewerE2E, BrokenFile) {
    const fs::path doc = work_ / "cube.dae";
    fs::copy_file(source_dir() / "dae" / "cube.dae", doc);
    const fs::path broken = work_ / "broken.dae";
    {
        std::ifstream in(doc, std::ios::binary);
        std::string text(700, '\0');
        in.read(text.data(), static_cast<std::streamsize>(text.size()));
        std::ofstream(broken, std::ios::binary) << text << "<<garbage";
    }

    {
        auto viewer = start_viewer(doc, "800x600");
        const ViewerWindow window(*viewer);
        ASSERT_TRUE(window.ok());
        std::string title;
        ASSERT_TRUE(window.wait_title(kCubeTitle, false, 20s, &title)) << title;
        window.move_to(780, 20);  // background: no hover highlight changes the picture

        // Ctrl+O opens the prompt; wait until it shows before typing into it.
        const fs::path before = logs_ / "before_open.png";
        ASSERT_TRUE(window.capture(before));
        window.key("ctrl+o");
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
        ASSERT_TRUE(prompt_shown) << "no Open prompt after Ctrl+O";
        sleep_for(300ms);  // the text field takes the focus one frame after the prompt shows
        window.key("ctrl+a");
        window.type(broken.string());
        window.key("Return");
        ASSERT_TRUE(wait_until(
            [&] { return viewer->err().find(broken.string()) != std::string::npos; }, 20s))
            << "no error naming " << broken << " on stderr:\n"
            << viewer->err();
        sleep_for(1s);
        EXPECT_TRUE(viewer->running()) << "the viewer died opening a broken file:\n"
                                       << viewer->err();
        EXPECT_EQ(window.title(), kCubeTitle) << "the cube must stay open";
        window.key("ctrl+q");
        expect_exit(*viewer, 0);
        EXPECT_NE(viewer->err().find("broken.dae"), std::string::npos) << viewer->err();
        EXPECT_NE(viewer->err().find("cube.dae stays open"), std::string::npos) << viewer->err();
    }

    // On the command line: the window opens with an empty document and the error.
    auto viewer = start_viewer(broken, "800x600");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    EXPECT_TRUE(window.wait_title("V 0 E 0 F 0", false, 20s, &title)) << title;
    ASSERT_TRUE(
        wait_until([&] { return viewer->err().find("broken.dae") != std::string::npos; }, 20s))
        << viewer->err();
    sleep_for(500ms);
    EXPECT_TRUE(viewer->running()) << viewer->err();
    // Nothing was open, so the message does not claim a document stays open.
    EXPECT_EQ(viewer->err().find("stays open"), std::string::npos) << viewer->err();
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

// Unsaved changes: the first Ctrl+Q is refused, the second quits without saving.
TEST_F(ViewerE2E, QuitProtection) {
    const fs::path original = source_dir() / "dae" / "cube.dae";
    const fs::path doc = work_ / "cube.dae";
    fs::copy_file(original, doc);
    std::string candidates;
    const std::optional<EdgeTarget> target = flip_target(load(doc), 800, 600, candidates);
    ASSERT_TRUE(target) << candidates;

    auto viewer = start_viewer(doc, "800x600");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title(kCubeTitle, false, 20s, &title)) << title;
    window.click(target->x, target->y);
    window.key("f");
    ASSERT_TRUE(window.wait_title(" *", false, 20s, &title)) << title << "\n" << viewer->err();

    window.key("ctrl+q");
    ASSERT_TRUE(
        wait_until([&] { return viewer->err().find("unsaved changes") != std::string::npos; }, 20s))
        << "no refusal on stderr:\n"
        << viewer->err();
    sleep_for(300ms);
    EXPECT_TRUE(viewer->running()) << "quit with unsaved changes on the first Ctrl+Q";
    EXPECT_EQ(window.title(), kCubeTitle + " *");

    window.key("ctrl+q");
    expect_exit(*viewer, 0);
    EXPECT_TRUE(same_file_bytes(doc, original)) << "the file on disk changed";
    EXPECT_EQ(work_.entries(), std::vector<std::string>{"cube.dae"}) << "files left behind";
}

// The window as a person sees it: the render with the panels over it.
TEST_F(ViewerE2E, RealWindowShowsRenderAndPanels) {
    const fs::path doc = work_ / "cube.dae";
    fs::copy_file(source_dir() / "dae" / "cube.dae", doc);
    auto viewer = start_viewer(doc, "800x600");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title(kCubeTitle, false, 20s, &title)) << title;
    window.move_to(780, 20);  // background, away from the mesh: no hover highlight

    const fs::path png = logs_ / "window.png";
    RgbImage seen;
    const bool drawn = wait_until(
        [&] {
            if (!window.capture(png)) {
                return false;
            }
            seen = read_rgb(png);
            return seen.width == 800 && seen.height == 600 && distinct_colours(seen) >= 1000;
        },
        20s, 100ms);
    ASSERT_TRUE(drawn) << "the window shows " << seen.width << "x" << seen.height << " with "
                       << distinct_colours(seen) << " colours";
    // The cube covers the centre; the right edge at the same height is background.
    EXPECT_GT(channel_difference(seen, 400, 300, seen, 795, 300), 30)
        << "the centre of the window looks like the background";

    // Compared with P (same view, no panels): the info panel darkens the top left, and the
    // cube looks the same where no panel covers it.
    const fs::path shot = screenshot(*viewer, window, 1);
    ASSERT_FALSE(shot.empty());
    const RgbImage clean = read_rgb(shot);
    ASSERT_EQ(clean.width, 800);
    const double panel_seen = mean_brightness(seen, 15, 40, 250, 120);
    const double panel_clean = mean_brightness(clean, 15, 40, 250, 120);
    EXPECT_LT(panel_seen + 60.0, panel_clean)
        << "no info panel in the window's top left (brightness " << panel_seen << " vs "
        << panel_clean << " without panels)";
    EXPECT_LE(channel_difference(seen, 400, 300, clean, 400, 300), 8)
        << "the window's centre differs from the screenshot's";
    EXPECT_LE(channel_difference(seen, 600, 330, clean, 600, 330), 8);

    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

}  // namespace
}  // namespace meshedit::test::e2e
