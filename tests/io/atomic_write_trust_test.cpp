// What the atomic write trusts: symbolic links only when they and their folder are the running
// user's (or root's), and stale temporaries only when they are ours, for the same target.
// Giving a file to another user needs root; those cases skip elsewhere.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/formats_test_util.h"
#include "meshedit/files/files.h"

namespace meshedit {
namespace {

using test::io_error_of;
namespace fs = std::filesystem;

constexpr uid_t kOther = 65534;  // "nobody"

// A pid no process has (above the kernel's largest pid_max, 2^22).
constexpr long kDeadPid = 99999999;

void give_away(const fs::path& path) {
    ASSERT_EQ(::lchown(path.c_str(), kOther, kOther), 0) << path;
}

void write_text(const fs::path& target, const std::string& text) {
    write_atomically(target, [&](const fs::path& tmp) { test::spit(tmp, text); });
}

TEST(AtomicWriteTrust, OwnLinkIsWrittenThrough) {
    test::ScratchDir dir;
    test::spit(dir / "real.obj", "old");
    fs::create_symlink("real.obj", dir / "link.obj");
    write_text(dir / "link.obj", "new");
    EXPECT_TRUE(fs::is_symlink(dir / "link.obj"));
    EXPECT_EQ(test::slurp(dir / "real.obj"), "new");
}

TEST(AtomicWriteTrust, LinkOfAnotherUserIsRefusedAndItsTargetKept) {
    if (::geteuid() != 0) {
        GTEST_SKIP() << "only root can give a link to another user";
    }
    test::ScratchDir dir;
    test::spit(dir / "victim.conf", "precious");
    fs::create_symlink(dir / "victim.conf", dir / "out.obj");
    give_away(dir / "out.obj");
    const std::string what = io_error_of([&] { write_text(dir / "out.obj", "overwritten"); });
    EXPECT_CONTAINS(what, "out.obj");
    EXPECT_CONTAINS(what, "belongs to another user (uid 65534)");
    EXPECT_EQ(test::slurp(dir / "victim.conf"), "precious");
    EXPECT_TRUE(fs::is_symlink(dir / "out.obj"));
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.obj", "victim.conf"}));
}

TEST(AtomicWriteTrust, LinkInAnotherUsersStickyFolderIsRefused) {
    if (::geteuid() != 0) {
        GTEST_SKIP() << "only root can give a folder to another user";
    }
    // As the system temporary folder is to a normal user: world-writable, sticky, not ours.
    test::ScratchDir dir;
    test::spit(dir / "victim.conf", "precious");
    fs::create_directory(dir / "shared");
    fs::create_symlink(dir / "victim.conf", dir / "shared" / "out.obj");
    give_away(dir / "shared");
    ASSERT_EQ(::chmod((dir / "shared").c_str(), 01777), 0);
    const std::string what =
        io_error_of([&] { write_text(dir / "shared" / "out.obj", "overwritten"); });
    EXPECT_CONTAINS(what, "its folder belongs to another user");
    EXPECT_EQ(test::slurp(dir / "victim.conf"), "precious");
}

TEST(AtomicWriteTrust, ChainThroughAForeignLinkIsRefused) {
    if (::geteuid() != 0) {
        GTEST_SKIP() << "only root can give a link to another user";
    }
    // Our link → a link another user planted → the victim: the second hop is refused.
    test::ScratchDir dir;
    test::spit(dir / "victim.conf", "precious");
    fs::create_symlink(dir / "victim.conf", dir / "planted.obj");
    give_away(dir / "planted.obj");
    fs::create_symlink("planted.obj", dir / "mine.obj");
    EXPECT_CONTAINS(io_error_of([&] { write_text(dir / "mine.obj", "x"); }),
                    "planted.obj': it belongs to another user");
    EXPECT_EQ(test::slurp(dir / "victim.conf"), "precious");
}

TEST(AtomicWriteTrust, StaleTemporaryOfTheSameTargetIsRemoved) {
    test::ScratchDir dir;
    const std::string stale = ".out.obj.tmp-" + std::to_string(kDeadPid) + "-0-1";
    test::spit(dir / stale, "half");
    write_text(dir / "out.obj", "whole");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.obj"});
}

TEST(AtomicWriteTrust, TemporariesOfOtherTargetsAndLiveWritersAreKept) {
    test::ScratchDir dir;
    const std::string other = ".report.txt.tmp-" + std::to_string(kDeadPid) + "-0-1";
    const std::string live = ".out.obj.tmp-" + std::to_string(::getppid()) + "-0-1";
    test::spit(dir / other, "another program's");
    test::spit(dir / live, "in use");
    write_text(dir / "out.obj", "whole");
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{live, other, "out.obj"}));
}

TEST(AtomicWriteTrust, StaleTemporaryOfAnotherUserIsKept) {
    if (::geteuid() != 0) {
        GTEST_SKIP() << "only root can give a file to another user";
    }
    test::ScratchDir dir;
    const std::string theirs = ".out.obj.tmp-" + std::to_string(kDeadPid) + "-0-1";
    test::spit(dir / theirs, "their half-written file");
    give_away(dir / theirs);
    write_text(dir / "out.obj", "whole");
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{theirs, "out.obj"}));
    EXPECT_EQ(test::slurp(dir / theirs), "their half-written file");
}

}  // namespace
}  // namespace meshedit
