// write_atomically and the writers built on it: a failed write never damages the target,
// never leaves a temporary file, and reports the target's name.

#include <gtest/gtest.h>
#include <unistd.h>

#include <stdexcept>

#include "io/formats_test_util.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/io.h"

namespace meshedit {
namespace {

using test::io_error_of;
namespace fs = std::filesystem;

TEST(AtomicWrite, SuccessReplacesTheTargetAndLeavesNoTemporary) {
    test::ScratchDir dir;
    test::spit(dir / "out.txt", "old contents");
    fs::path used;
    write_atomically(dir / "out.txt", [&](const fs::path& tmp) {
        used = tmp;
        test::spit(tmp, "new contents");
    });
    EXPECT_EQ(test::slurp(dir / "out.txt"), "new contents");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.txt"});
    // The temporary lived next to the target (so the rename cannot cross file systems).
    EXPECT_EQ(used.parent_path(), dir.path());
    EXPECT_NE(used.filename(), "out.txt");
}

TEST(AtomicWrite, ThrowingWriterLeavesTheOldTargetByteIdentical) {
    test::ScratchDir dir;
    const std::string old_bytes("v 1 2 3\n\0binary\xff tail", 21);
    test::spit(dir / "mesh.obj", old_bytes);
    const std::string what = io_error_of([&] {
        write_atomically(dir / "mesh.obj", [](const fs::path& tmp) {
            test::spit(tmp, "v 0 0 0\nv 1 0");  // half written, then the writer fails
            throw std::runtime_error("disk on fire");
        });
    });
    EXPECT_CONTAINS(what, (dir / "mesh.obj").string() + ": disk on fire");
    EXPECT_EQ(test::slurp(dir / "mesh.obj"), old_bytes);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"mesh.obj"});
}

TEST(AtomicWrite, IoErrorFromTheWriterIsRenamedToTheTarget) {
    test::ScratchDir dir;
    const std::string what = io_error_of([&] {
        write_atomically(dir / "a.dae", [](const fs::path& tmp) {
            throw IoError(tmp.string(), "<mesh>", "cannot encode");
        });
    });
    EXPECT_CONTAINS(what, (dir / "a.dae").string() + ": <mesh>: cannot encode");
    EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicWrite, MissingFolderNamesTheTargetAndCreatesNothing) {
    test::ScratchDir dir;
    const fs::path target = dir / "no" / "such" / "out.obj";
    EXPECT_CONTAINS(io_error_of([&] { write_mesh(shapes::cube(), target); }),
                    target.string() + ": the folder");
    EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicWrite, FolderThatIsARegularFileFailsEvenForRoot) {
    test::ScratchDir dir;
    test::spit(dir / "plain", "x");
    const fs::path target = dir / "plain" / "out.gltf";
    bool called = false;
    EXPECT_CONTAINS(
        io_error_of([&] { write_atomically(target, [&](const fs::path&) { called = true; }); }),
        target.string() + ": ");
    EXPECT_FALSE(called);
    EXPECT_CONTAINS(io_error_of([&] { write_mesh(shapes::cube(), target); }), target.string());
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"plain"});
    EXPECT_EQ(test::slurp(dir / "plain"), "x");
}

TEST(AtomicWrite, UnknownExtensionWritesNothing) {
    test::ScratchDir dir;
    EXPECT_CONTAINS(io_error_of([&] { write_mesh(shapes::cube(), dir / "cube.3mf"); }),
                    "cube.3mf: cannot write '.3mf' files");
    EXPECT_CONTAINS(io_error_of([&] { read_soup(dir / "cube.3mf"); }),
                    "cube.3mf: unknown extension '.3mf'");
    EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicWrite, KeepsThePermissionsOfTheReplacedFile) {
    test::ScratchDir dir;
    test::spit(dir / "private.obj", "old");
    fs::permissions(dir / "private.obj", fs::perms::owner_read | fs::perms::owner_write);
    write_mesh(shapes::tetrahedron(), dir / "private.obj");
    EXPECT_EQ(fs::status(dir / "private.obj").permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write);
}

TEST(AtomicWrite, TargetThatIsAFolderIsRefused) {
    test::ScratchDir dir;
    fs::create_directory(dir / "taken.obj");
    EXPECT_CONTAINS(io_error_of([&] { write_mesh(shapes::cube(), dir / "taken.obj"); }),
                    "taken.obj: is a folder");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken.obj"});
}

}  // namespace
}  // namespace meshedit
