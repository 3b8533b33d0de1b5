/// \file
/// meshedit-render's backends (docs/rendering.md, "Backends"): --version lists them, EGL and
/// OSMesa draw the same bytes (both llvmpipe here), auto falls back to OSMesa when EGL has no
/// driver, and every way of getting no context is one line and exit 2.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "cli/run.h"

namespace meshedit::test {
namespace {

namespace fs = std::filesystem;

std::string render_exe() {
    const char* env = std::getenv("MESHEDIT_RENDER_EXE");
    return env != nullptr && *env != '\0' ? env : MESHEDIT_RENDER_EXE;
}

// Sets an environment variable for one scope (the child processes inherit it).
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) {
            old_ = old;
        }
        if (value != nullptr) {
            ::setenv(name, value, 1);
        } else {
            ::unsetenv(name);
        }
    }
    ~ScopedEnv() {
        if (old_) {
            ::setenv(name_.c_str(), old_->c_str(), 1);
        } else {
            ::unsetenv(name_.c_str());
        }
    }

private:
    std::string name_;
    std::optional<std::string> old_;
};

bool has_backend(const std::string& name) {
    const RunResult run = run_program(render_exe(), {"--version"}, 20.0);
    const std::size_t at = run.out.find("backends:");
    return at != std::string::npos && run.out.find(" " + name, at) != std::string::npos;
}

std::string file_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

class Backends : public ::testing::Test {
protected:
    TempDir dir;
    std::string cube = (fs::path(MESHEDIT_SOURCE_DIR) / "dae/cube.dae").string();
    std::string out(const std::string& name) const { return (dir.path() / name).string(); }
};

TEST_F(Backends, VersionListsTheCompiledBackends) {
    const RunResult run = run_program(render_exe(), {"--version"}, 20.0);
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_NE(run.out.find("meshedit-render "), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("backends: "), std::string::npos) << run.out;
}

TEST_F(Backends, EglAndOsMesaDrawTheSameBytes) {
    if (!has_backend("egl") || !has_backend("osmesa")) {
        GTEST_SKIP() << "needs both backends";
    }
    const std::vector<std::string> look = {"--flat", "--wireframe", "--select", "e:0-6"};
    for (const char* backend : {"egl", "osmesa"}) {
        std::vector<std::string> args = {cube,        "-o",    out(std::string(backend) + ".png"),
                                         "--backend", backend, "--verbose"};
        args.insert(args.end(), look.begin(), look.end());
        const RunResult run = run_program(render_exe(), args, 60.0);
        ASSERT_EQ(run.exit_code, 0) << run.err;
        EXPECT_NE(run.err.find(std::string("backend ") + backend), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("GL renderer "), std::string::npos) << run.err;
    }
    EXPECT_EQ(file_bytes(out("egl.png")), file_bytes(out("osmesa.png")));
}

TEST_F(Backends, AutoFallsBackToOsMesaWhenEglHasNoDriver) {
    if (!has_backend("osmesa")) {
        GTEST_SKIP() << "needs OSMesa";
    }
    const ScopedEnv no_backend("MESHEDIT_RENDER_BACKEND", nullptr);
    // glvnd's libEGL with no vendor library: as on a machine without Mesa's EGL.
    const ScopedEnv no_vendor("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json");
    const RunResult run =
        run_program(render_exe(), {cube, "-o", out("auto.png"), "--verbose"}, 60.0);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("backend osmesa"), std::string::npos) << run.err;
}

TEST_F(Backends, NoContextIsOneLineAndExitTwo) {
    const ScopedEnv no_vendor("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json");
    const auto expect_refused = [&](const std::vector<std::string>& extra, const char* says) {
        std::vector<std::string> args = {cube, "-o", out("x.png")};
        args.insert(args.end(), extra.begin(), extra.end());
        const RunResult run = run_program(render_exe(), args, 60.0);
        EXPECT_EQ(run.exit_code, 2) << run.err;
        EXPECT_EQ(run.err.rfind("meshedit-render: ", 0), 0u) << run.err;
        EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "one line: " << run.err;
        EXPECT_NE(run.err.find(says), std::string::npos) << run.err;
        EXPECT_FALSE(fs::exists(out("x.png")));
    };
    if (has_backend("egl")) {
        expect_refused({"--backend", "egl"}, "install ");
    }
    expect_refused({"--backend", "osmesa", "--device", "0"}, "--backend osmesa has none");
}

TEST_F(Backends, DeviceOutOfRangeIsRefused) {
    if (!has_backend("egl")) {
        GTEST_SKIP() << "needs EGL";
    }
    const RunResult run =
        run_program(render_exe(), {cube, "-o", out("x.png"), "--device", "99"}, 60.0);
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_NE(run.err.find("--device 99 is out of range"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace meshedit::test
