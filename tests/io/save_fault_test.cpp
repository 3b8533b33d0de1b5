// Saving under faults: a full disk, a folder the process may not write, a target that is a
// symbolic link or the input itself, an owner to keep, and a process killed at random points
// of a large write. Whatever happens, the old file is intact or the new one complete — never
// partial — and no temporary file is left behind once a later write has run in that folder.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <random>
#include <thread>

#include "io/formats_test_util.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/io.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;
using test::io_error_of;

// Entries of `dir` that look like a writer's temporary files.
std::vector<std::string> temporaries(const fs::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name.find(".tmp-") != std::string::npos) {
            out.push_back(name);
        }
    }
    return out;
}

// Runs `body` in a child process as the unprivileged user `nobody`; returns its exit code.
int as_nobody(const std::function<int()>& body) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        if (::setgid(65534) != 0 || ::setuid(65534) != 0) {
            ::_exit(99);
        }
        ::_exit(body());
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(SaveFaults, DiskFullKeepsTheOldFile) {
    test::ScratchDir dir;
    const fs::path small = dir / "small";
    fs::create_directories(small);
    // A 256 KiB file system: room for the old file, none for a 40,000-face mesh.
    if (::mount("tmpfs", small.c_str(), "tmpfs", 0, "size=256k") != 0) {
        GTEST_SKIP() << "cannot mount a small tmpfs here (" << std::strerror(errno)
                     << "; needs root and CAP_SYS_ADMIN)";
    }
    struct Unmount {
        fs::path at;
        ~Unmount() { ::umount2(at.c_str(), MNT_DETACH); }
    } unmount{small};
    write_mesh(shapes::cube(), small / "mesh.obj");
    const std::string before = test::slurp(small / "mesh.obj");
    const std::string message =
        io_error_of([&] { write_mesh(shapes::torus(200, 100), small / "mesh.obj"); });
    EXPECT_CONTAINS(message, "mesh.obj: ");
    EXPECT_EQ(test::slurp(small / "mesh.obj"), before);
    EXPECT_TRUE(temporaries(small).empty());
}

TEST(SaveFaults, FolderThatCannotBeWrittenKeepsTheOldFile) {
    test::ScratchDir dir;
    const fs::path locked = dir / "locked";
    fs::create_directories(locked);
    write_mesh(shapes::cube(), locked / "mesh.obj");
    const std::string before = test::slurp(locked / "mesh.obj");
    fs::permissions(locked, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                fs::perms::others_read | fs::perms::others_exec);
    fs::permissions(dir.path(), fs::perms::others_exec | fs::perms::others_read,
                    fs::perm_options::add);
    const auto attempt = [&] {
        try {
            write_mesh(shapes::tetrahedron(), locked / "mesh.obj");
        } catch (const IoError& e) {
            const bool says_why =
                std::string(e.what()).find("cannot create a file in") != std::string::npos;
            return says_why ? 0 : 2;
        }
        return 1;
    };
    if (::geteuid() == 0) {
        // Root writes anywhere: the unprivileged user tries instead.
        const int code = as_nobody(attempt);
        ASSERT_NE(code, 99) << "cannot become nobody";
        EXPECT_EQ(code, 0);
    } else {
        fs::permissions(locked, fs::perms::owner_write, fs::perm_options::remove);
        EXPECT_EQ(attempt(), 0);
        fs::permissions(locked, fs::perms::owner_write, fs::perm_options::add);
    }
    EXPECT_EQ(test::slurp(locked / "mesh.obj"), before);
    EXPECT_TRUE(temporaries(locked).empty());
}

// As editors do: the link stays a link and the file it names gets the new content; a chain
// of links and a link whose file does not exist yet work the same way.
TEST(SaveFaults, SymbolicLinksSurviveAndTheirFileIsWritten) {
    test::ScratchDir dir;
    fs::create_directories(dir / "real");
    write_mesh(shapes::cube(), dir / "real" / "mesh.obj");
    fs::create_symlink("real/mesh.obj", dir / "link.obj");
    fs::create_symlink(dir / "link.obj", dir / "chain.obj");
    write_mesh(shapes::tetrahedron(), dir / "chain.obj");
    EXPECT_TRUE(fs::is_symlink(dir / "link.obj"));
    EXPECT_TRUE(fs::is_symlink(dir / "chain.obj"));
    EXPECT_EQ(read_mesh(dir / "real" / "mesh.obj").mesh.n_faces(), 4u);
    EXPECT_TRUE(temporaries(dir.path()).empty());
    EXPECT_TRUE(temporaries(dir / "real").empty());

    fs::create_symlink("real/new.obj", dir / "dangling.obj");
    write_mesh(shapes::cube(), dir / "dangling.obj");
    EXPECT_TRUE(fs::is_symlink(dir / "dangling.obj"));
    EXPECT_EQ(read_mesh(dir / "real" / "new.obj").mesh.n_faces(), 12u);
}

// Atomic replacement gives the name a new file: another hard link to the old file keeps the
// old content (the choice docs/cli.md states; writing in place could leave it half written).
TEST(SaveFaults, HardLinksKeepTheOldContent) {
    test::ScratchDir dir;
    write_mesh(shapes::cube(), dir / "a.obj");
    fs::create_hard_link(dir / "a.obj", dir / "b.obj");
    write_mesh(shapes::tetrahedron(), dir / "a.obj");
    EXPECT_EQ(read_mesh(dir / "a.obj").mesh.n_faces(), 4u);
    EXPECT_EQ(read_mesh(dir / "b.obj").mesh.n_faces(), 12u);
}

TEST(SaveFaults, TheInputItselfCanBeTheTarget) {
    test::ScratchDir dir;
    write_mesh(shapes::cube(), dir / "same.obj");
    LoadedMesh loaded = read_mesh(dir / "same.obj");
    ASSERT_TRUE(split(loaded.mesh, Edge(0)));
    write_mesh(loaded.mesh, dir / "same.obj");
    EXPECT_EQ(read_mesh(dir / "same.obj").mesh.n_faces(), 14u);
}

TEST(SaveFaults, OwnerAndModeAreKeptWhenRootRewrites) {
    if (::geteuid() != 0) {
        GTEST_SKIP() << "only root can give a file to another owner";
    }
    test::ScratchDir dir;
    write_mesh(shapes::cube(), dir / "theirs.obj");
    ASSERT_EQ(::chown((dir / "theirs.obj").c_str(), 65534, 65534), 0);
    ASSERT_EQ(::chmod((dir / "theirs.obj").c_str(), 0640), 0);
    write_mesh(shapes::tetrahedron(), dir / "theirs.obj");
    struct stat st {};
    ASSERT_EQ(::stat((dir / "theirs.obj").c_str(), &st), 0);
    EXPECT_EQ(st.st_uid, 65534u);
    EXPECT_EQ(st.st_gid, 65534u);
    EXPECT_EQ(st.st_mode & 07777, 0640u);
}

// 100 children (20 in unoptimised sanitizer builds) each start writing a 60,000-face mesh
// over the same file and are killed at a random moment. After every kill the file is the old
// mesh or the new one, whole; the temporary files the dead children left are removed by the
// next write into the folder.
TEST(SaveFaults, KilledMidWriteNeverLeavesAPartialFile) {
    test::ScratchDir dir;
    const fs::path target = dir / "big.obj";
    const Mesh small = shapes::cube();
    const Mesh big = shapes::torus(200, 150);
#ifdef NDEBUG
    constexpr int kKills = 100;
#else
    constexpr int kKills = 20;
#endif
    write_mesh(small, target);
    std::mt19937 rng(7);
    // A write takes some tens of ms; kill anywhere from before it starts to after it ends.
    const auto start = std::chrono::steady_clock::now();
    write_mesh(big, dir / "timing.obj");
    const auto full = std::chrono::steady_clock::now() - start;
    fs::remove(dir / "timing.obj");
    std::uniform_int_distribution<long> delay(
        0, std::chrono::duration_cast<std::chrono::microseconds>(full).count() * 3 / 2);
    int old_kept = 0, new_whole = 0;
    for (int i = 0; i < kKills; ++i) {
        const pid_t pid = ::fork();
        if (pid == 0) {
            try {
                write_mesh(i % 2 == 0 ? big : small, target);
            } catch (...) {
                ::_exit(1);
            }
            ::_exit(0);
        }
        std::this_thread::sleep_for(std::chrono::microseconds(delay(rng)));
        ::kill(pid, SIGKILL);
        int status = 0;
        ::waitpid(pid, &status, 0);
        const std::size_t faces = read_mesh(target).mesh.n_faces();
        ASSERT_TRUE(faces == small.n_faces() || faces == big.n_faces())
            << "kill " << i << ": " << faces << " faces";
        (faces == big.n_faces() ? new_whole : old_kept) += 1;
    }
    RecordProperty("old_kept", old_kept);
    RecordProperty("new_whole", new_whole);
    write_mesh(small, target);  // removes what the killed writers left
    EXPECT_TRUE(temporaries(dir.path()).empty());
}

}  // namespace
}  // namespace meshedit
