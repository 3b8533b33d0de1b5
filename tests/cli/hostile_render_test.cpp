// Hostile inputs to `meshedit render` beside the mesh: environment images and user shaders
// that are not files or lie in their headers, and a long curve drawn at a low level. Each run
// is limited to 20 s and 2 GB of address space, with a memory budget of 1 GB: it ends with
// one clear line naming the file, or with the picture.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "run.h"

namespace meshedit::test {
namespace {

namespace fs = std::filesystem;

constexpr double kSeconds = 20.0;
constexpr std::size_t kAddressSpace = std::size_t{2} << 30;

class HostileRender : public ::testing::Test {
protected:
    void SetUp() override { ::setenv("MESHEDIT_MEMORY_BUDGET", "1G", 1); }
    void TearDown() override { ::unsetenv("MESHEDIT_MEMORY_BUDGET"); }

    RunResult render(const std::vector<std::string>& extra) {
        std::vector<std::string> args = {"render", (repo_root() / "dae/cube.dae").string(),
                                         "-o",     (dir_ / "out.png").string(),
                                         "--size", "64x48"};
        args.insert(args.end(), extra.begin(), extra.end());
        RunResult r = run_meshedit(args, kSeconds, kAddressSpace);
        EXPECT_FALSE(r.timed_out) << "took more than " << kSeconds << " s";
        EXPECT_EQ(r.signal, 0) << r.err;
        return r;
    }
    void expect_one_line(const RunResult& r, const std::string& file, const std::string& what) {
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
        EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir_ / "out.png"));
    }

    TempDir dir_;
};

TEST_F(HostileRender, EnvironmentThatIsAFifoOrADeviceIsRefusedNotWaitedFor) {
    ASSERT_EQ(::mkfifo((dir_ / "pipe.hdr").c_str(), 0600), 0);
    expect_one_line(render({"--shading", "7", "--envmap", (dir_ / "pipe.hdr").string()}),
                    "pipe.hdr", "is not a regular file");
    fs::create_symlink("/dev/zero", dir_ / "zero.png");
    expect_one_line(render({"--shading", "7", "--envmap", (dir_ / "zero.png").string()}),
                    "zero.png", "is not a regular file");
}

TEST_F(HostileRender, EnvironmentWhoseHeaderPromisesMissingPixelsFailsAtItsEnd) {
    // A binary PPM header of 16384 × 8192 pixels and 100 bytes of them: 1.6 GB promised.
    std::ofstream(dir_ / "lie.ppm", std::ios::binary) << "P6\n16384 8192\n255\n"
                                                      << std::string(100, '\x80');
    const RunResult r = render({"--shading", "7", "--envmap", (dir_ / "lie.ppm").string()});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
    EXPECT_NE(r.err.find("lie.ppm"), std::string::npos) << r.err;
}

TEST_F(HostileRender, UserShaderThatIsAFifoIsRefusedNotWaitedFor) {
    fs::create_directory(dir_ / "shaders");
    ASSERT_EQ(::mkfifo((dir_ / "shaders" / "mesh8.frag").c_str(), 0600), 0);
    const RunResult r = render({"--shading", "8", "--shader-dir", (dir_ / "shaders").string()});
    EXPECT_NE(r.exit_code, 0) << r.err;
    EXPECT_EQ(split_lines(r.err).size(), 1u) << r.err;
    EXPECT_NE(r.err.find("mesh8.frag"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("is not a regular file"), std::string::npos) << r.err;
}

TEST_F(HostileRender, NumbersThatAreNotFiniteOrOutOfRangeAreBadUsage) {
    // Each drew a blank or black image with exit status 0.
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--camera", "nan,30"}, "bad azimuth 'nan': not a finite number"},
        {{"--camera", "30,inf"}, "bad elevation 'inf': not a finite number"},
        {{"--camera", "30,30,1e39"}, "bad distance '1e39'"},
        {{"--exposure", "nan"}, "'nan' is not a number from -16 to 16"},
        {{"--auto-smooth", "nan"}, "'nan' is not a number from 0 to 180"}};
    for (const auto& [bad, message] : cases) {
        const RunResult r = render(bad);
        EXPECT_EQ(r.exit_code, 2) << bad[0] << " " << bad[1] << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir_ / "out.png")) << bad[0] << " " << bad[1];
    }
    std::ofstream(dir_ / "c.bzc") << "2\n0 0\n1 1\n";
    for (const char* t : {"nan", "-0.5", "1.5"}) {
        const RunResult r = run_meshedit(
            {"render", (dir_ / "c.bzc").string(), "-o", (dir_ / "out.png").string(), "--t", t},
            kSeconds, kAddressSpace);
        EXPECT_EQ(r.exit_code, 2) << t << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir_ / "out.png")) << t;
    }
}

TEST_F(HostileRender, RunAsMeshEditRenderItsMessagesSayMeshEdit) {
    const RunResult r =
        run_meshedit({"render", (dir_ / "absent.dae").string(), "-o", (dir_ / "out.png").string()},
                     kSeconds, kAddressSpace);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("meshedit: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("absent.dae: no such file"), std::string::npos) << r.err;
    // A field that does not exist: the valid names are listed.
    const RunResult field = render({"--field", "curvy"});
    EXPECT_EQ(field.exit_code, 2) << field.err;
    EXPECT_NE(field.err.find("no field called 'curvy' (the fields: "), std::string::npos)
        << field.err;
    EXPECT_NE(field.err.find("gauss mean valence"), std::string::npos) << field.err;
}

TEST_F(HostileRender, LongCurveAtALowLevelDrawsOnlyThatLevel) {
    // 30,000 points: all levels are 450 million points (10 GB); levels 0 and 1 are 60,000.
    // (--no-curve: the curve itself is sampled by de Casteljau, n² a sample.)
    std::string text = "30000\n";
    for (int i = 0; i < 30000; ++i) {
        text += std::to_string(i / 30000.0) + " 0.5\n";
    }
    std::ofstream(dir_ / "long.bzc") << text;
    const RunResult r =
        run_meshedit({"render", (dir_ / "long.bzc").string(), "-o", (dir_ / "out.png").string(),
                      "--size", "64x48", "--level", "1", "--no-curve"},
                     kSeconds, kAddressSpace);
    EXPECT_FALSE(r.timed_out);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "out.png"));
}

// Textures that cannot be shown never stop the picture: missing, not an image, a FIFO, a
// header promising 100000 x 100000 pixels, one promising pixels that are not there. Each is
// one note naming the file and its material; the faces take the material's colour.
TEST_F(HostileRender, TexturesThatCannotBeShownAreNamedAndTheMeshDrawn) {
    std::ofstream(dir_ / "text.png") << "not an image\n";
    ASSERT_EQ(::mkfifo((dir_ / "pipe.png").c_str(), 0600), 0);
    // Headers promising 100000 x 100000 pixels, and 4096 x 4096 with 100 bytes of them.
    std::ofstream(dir_ / "huge.ppm", std::ios::binary) << "P6\n100000 100000\n255\n"
                                                       << std::string(100, '\x80');
    std::ofstream(dir_ / "lie.ppm", std::ios::binary) << "P6\n4096 4096\n255\n"
                                                      << std::string(100, '\x80');
    const char* names[] = {"missing.png", "text.png", "pipe.png", "huge.ppm", "lie.ppm"};
    std::ofstream mtl(dir_ / "t.mtl");
    std::ofstream obj(dir_ / "t.obj");
    obj << "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n";
    for (int i = 0; i < 5; ++i) {
        mtl << "newmtl m" << i << "\nKd 0.2 0.4 0.6\nmap_Kd " << names[i] << "\n";
        obj << "usemtl m" << i << "\nf 1/1 2/2 3/3\n";
    }
    mtl.close();
    obj.close();
    const RunResult r = run_meshedit(
        {"render", (dir_ / "t.obj").string(), "-o", (dir_ / "out.png").string(), "--size", "64x48"},
        kSeconds, kAddressSpace);
    EXPECT_FALSE(r.timed_out);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "out.png"));
    const std::vector<std::string> lines = split_lines(r.err);
    ASSERT_EQ(lines.size(), 5u) << r.err;
    const char* why[] = {"was not found", "is not an image", "is not a file",
                         "100000 × 100000 pixels, more than MeshEdit shows", "could not be read"};
    for (int i = 0; i < 5; ++i) {
        SCOPED_TRACE(names[i]);
        EXPECT_NE(lines[i].find(names[i]), std::string::npos) << lines[i];
        EXPECT_NE(lines[i].find("of material 'm" + std::to_string(i) + "'"), std::string::npos)
            << lines[i];
        EXPECT_NE(lines[i].find(why[i]), std::string::npos) << lines[i];
    }
}

}  // namespace
}  // namespace meshedit::test
