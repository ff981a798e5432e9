// The one atomic-write routine: regular files only, same-file refusal,
// symbolic links followed only where the kernel allows, mode kept, file-size limits and full
// disks as errors with the old file untouched and no temporary file left, NAME_MAX-long names.
#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/scene/atomic_file.hpp"
#include "tests/support/temp_dir.hpp"

namespace fs = std::filesystem;
using isoparm::scene::check_output_is_not_input;
using isoparm::scene::check_output_path;
using isoparm::scene::write_file_atomically;

namespace {

class AtomicFile : public ::testing::Test {
protected:
    std::string path(const std::string& name) const { return tmp_.path(name); }
    // Every name in the directory: a leftover temporary file shows up here.
    std::vector<std::string> names() const { return names_in(dir_); }
    static std::vector<std::string> names_in(const fs::path& dir) {
        std::vector<std::string> out;
        for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename());
        std::sort(out.begin(), out.end());
        return out;
    }
    isoparm::test::TempDir tmp_{"isoparm-atomic"};
    const fs::path& dir_ = tmp_.dir();
};

std::string read_file(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_plain(const std::string& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
}

TEST_F(AtomicFile, WritesANewFileAndReplacesAnOldOneLeavingNoTemporary) {
    ASSERT_TRUE(write_file_atomically(path("a.json"), "first"));
    EXPECT_EQ(read_file(path("a.json")), "first");
    ASSERT_TRUE(write_file_atomically(path("a.json"), "second"));
    EXPECT_EQ(read_file(path("a.json")), "second");
    EXPECT_EQ(names(), std::vector<std::string>{"a.json"});
}

TEST_F(AtomicFile, KeepsTheModeOfTheFileItReplaces) {
    write_plain(path("a.json"), "old");
    ASSERT_EQ(::chmod(path("a.json").c_str(), 0640), 0);
    ASSERT_TRUE(write_file_atomically(path("a.json"), "new"));
    struct stat st {};
    ASSERT_EQ(::stat(path("a.json").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0640u);
}

TEST_F(AtomicFile, KeepsTheOwnerWhereTheSystemAllows) {
    if (::geteuid() != 0) GTEST_SKIP() << "only root may give a file to another user";
    write_plain(path("a.json"), "old");
    ASSERT_EQ(::chown(path("a.json").c_str(), 65534, 65534), 0);
    ASSERT_TRUE(write_file_atomically(path("a.json"), "new"));
    struct stat st {};
    ASSERT_EQ(::stat(path("a.json").c_str(), &st), 0);
    EXPECT_EQ(st.st_uid, 65534u);
    EXPECT_EQ(st.st_gid, 65534u);
}

TEST_F(AtomicFile, AMissingDirectoryIsAnErrorNamingTheFileAskedFor) {
    const auto r = write_file_atomically(path("no/such/dir/a.json"), "x");
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("'" + path("no/such/dir/a.json") + "'"), std::string::npos)
        << r.error().message;
    EXPECT_NE(r.error().message.find("No such file or directory"), std::string::npos);
}

TEST_F(AtomicFile, RefusesADirectoryAFifoAndADevice) {
    fs::create_directory(path("d"));
    ASSERT_EQ(::mkfifo(path("f").c_str(), 0600), 0);
    const auto dir_result = write_file_atomically(path("d"), "x");
    ASSERT_FALSE(dir_result);
    EXPECT_NE(dir_result.error().message.find("a directory"), std::string::npos);
    EXPECT_NE(dir_result.error().message.find(path("d")), std::string::npos);
    const auto fifo_result = write_file_atomically(path("f"), "x"); // must not block either
    ASSERT_FALSE(fifo_result);
    EXPECT_NE(fifo_result.error().message.find("a FIFO"), std::string::npos);
    EXPECT_FALSE(check_output_path(path("f")));
    // As root, the old renderer turned /dev/null into a regular file.
    const auto null_result = write_file_atomically("/dev/null", "x");
    ASSERT_FALSE(null_result);
    EXPECT_NE(null_result.error().message.find("character device"), std::string::npos);
    struct stat st {};
    ASSERT_EQ(::stat("/dev/null", &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
    EXPECT_EQ(names(), (std::vector<std::string>{"d", "f"}));
}

TEST_F(AtomicFile, ALinkToADeviceIsRefusedToo) {
    fs::create_symlink("/dev/null", path("out.png"));
    EXPECT_FALSE(write_file_atomically(path("out.png"), "x"));
    EXPECT_TRUE(fs::is_symlink(path("out.png")));
}

TEST_F(AtomicFile, ThroughASymbolicLinkTheFileItPointsToIsReplaced) {
    fs::create_directory(path("real"));
    write_plain(path("real/scene.json"), "old");
    ASSERT_EQ(::chmod(path("real/scene.json").c_str(), 0600), 0);
    fs::create_symlink("real/scene.json", path("link.json"));
    ASSERT_TRUE(write_file_atomically(path("link.json"), "new"));
    EXPECT_TRUE(fs::is_symlink(path("link.json")));
    EXPECT_EQ(read_file(path("real/scene.json")), "new");
    EXPECT_EQ(fs::status(path("real/scene.json")).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(names_in(path("real")), std::vector<std::string>{"scene.json"});
}

TEST_F(AtomicFile, ALinkToNothingIsRefused) {
    fs::create_symlink("missing.json", path("link.json"));
    const auto r = write_file_atomically(path("link.json"), "new");
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("does not exist"), std::string::npos);
    EXPECT_FALSE(fs::exists(path("missing.json")));
}

// A link planted in a sticky world-writable directory by another user must
// not be followed where the kernel (fs.protected_symlinks) would refuse. The old code resolved
// the link itself and overwrote the file behind it; this one lets the kernel follow it. Only
// meaningful as root (to plant a link owned by someone else) with protected_symlinks on.
TEST_F(AtomicFile, APlantedLinkInAStickyDirectoryIsNotFollowed) {
    if (::geteuid() != 0) GTEST_SKIP() << "needs root to plant another user's link";
    std::ifstream flag("/proc/sys/fs/protected_symlinks");
    int protected_symlinks = 0;
    if (!(flag >> protected_symlinks) || protected_symlinks != 1)
        GTEST_SKIP() << "fs.protected_symlinks is off";
    fs::create_directory(path("sticky"));
    ASSERT_EQ(::chmod(path("sticky").c_str(), 01777), 0);
    write_plain(path("victim.json"), "precious");
    const std::string planted = path("sticky/scene.json");
    fs::create_symlink(path("victim.json"), planted);
    ASSERT_EQ(::lchown(planted.c_str(), 65534, 65534), 0); // the link belongs to "nobody"
    const auto r = write_file_atomically(planted, "attack");
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find(planted), std::string::npos);
    EXPECT_EQ(read_file(path("victim.json")), "precious");
    EXPECT_EQ(names_in(path("sticky")), std::vector<std::string>{"scene.json"});
    EXPECT_EQ(names(), (std::vector<std::string>{"sticky", "victim.json"}));
}

// Where fs.protected_symlinks is off the kernel cannot show its refusal; what remains testable
// is that links are resolved as the kernel resolves them (a relative link inside a linked
// directory points beside the real directory, not beside the link), never by string handling.
TEST_F(AtomicFile, LinksAreResolvedAsTheKernelResolvesThem) {
    fs::create_directories(path("a/b"));
    write_plain(path("a/target.json"), "old");
    write_plain(path("target.json"), "decoy");
    fs::create_directory_symlink("a/b", path("dir"));
    fs::create_symlink("../target.json", path("a/b/link.json"));
    ASSERT_TRUE(write_file_atomically(path("dir/link.json"), "new"));
    EXPECT_EQ(read_file(path("a/target.json")), "new");
    EXPECT_EQ(read_file(path("target.json")), "decoy");
    EXPECT_TRUE(fs::is_symlink(path("a/b/link.json")));
}

TEST_F(AtomicFile, ANameNearNameMaxStillGetsATemporaryFileThatFits) {
    const std::string name = std::string(250, 'n') + ".json"; // 255 bytes, NAME_MAX
    ASSERT_TRUE(write_file_atomically(path(name), "first"));
    ASSERT_TRUE(write_file_atomically(path(name), "second"));
    EXPECT_EQ(read_file(path(name)), "second");
    EXPECT_EQ(names(), std::vector<std::string>{name});
}

TEST_F(AtomicFile, TheSameFileUnderAnotherNameIsRefusedAsOutput) {
    write_plain(path("scene.json"), "scene");
    fs::create_directory(path("sub"));
    fs::create_symlink("scene.json", path("alias.json"));
    const std::vector<std::string> inputs{path("scene.json")};
    EXPECT_FALSE(check_output_is_not_input(path("scene.json"), inputs));
    EXPECT_FALSE(check_output_is_not_input(path("sub/../scene.json"), inputs));
    EXPECT_FALSE(check_output_is_not_input(path("alias.json"), inputs));
    ASSERT_EQ(::link(path("scene.json").c_str(), path("hard.json").c_str()), 0);
    EXPECT_FALSE(check_output_is_not_input(path("hard.json"), inputs));
    EXPECT_TRUE(check_output_is_not_input(path("other.png"), inputs));
    EXPECT_TRUE(check_output_is_not_input("-", inputs));
}

// `ulimit -f`: SIGXFSZ used to kill the writer and leave "<name>.tmp-<pid>" behind. Run in a
// child (the limit and the signal disposition are per process); the child reports by its exit
// status, so a SIGXFSZ death fails the test.
TEST_F(AtomicFile, AFileSizeLimitIsAnErrorAndTheOldFileStays) {
    write_plain(path("big.png"), "old picture");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::signal(SIGXFSZ, SIG_DFL); // as a fresh process has it
        const rlimit limit{4096, 4096};
        if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(10);
        const auto r = write_file_atomically(path("big.png"), std::string(1 << 20, 'p'));
        if (r) ::_exit(11);
        if (r.error().message.find("File too large") == std::string::npos) ::_exit(12);
        if (r.error().message.find(path("big.png")) == std::string::npos) ::_exit(13);
        ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_EQ(read_file(path("big.png")), "old picture");
    EXPECT_EQ(names(), std::vector<std::string>{"big.png"});
}

// A full disk: a small tmpfs (root only, where mounting is allowed).
TEST_F(AtomicFile, AFullDiskIsAnErrorAndTheOldFileStays) {
    if (::geteuid() != 0) GTEST_SKIP() << "mounting a small tmpfs needs root";
    const std::string mnt = path("small");
    fs::create_directory(mnt);
    if (::mount("isoparm-test", mnt.c_str(), "tmpfs", 0, "size=256k") != 0)
        GTEST_SKIP() << "cannot mount a tmpfs here: " << std::strerror(errno);
    const std::string target = mnt + "/out.png";
    write_plain(target, std::string(100 << 10, 'o'));
    const auto r = write_file_atomically(target, std::string(200 << 10, 'n'));
    const std::string old = read_file(target);
    const std::vector<std::string> left = names_in(mnt);
    ::umount(mnt.c_str());
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("No space left on device"), std::string::npos);
    EXPECT_EQ(old, std::string(100 << 10, 'o'));
    EXPECT_EQ(left, std::vector<std::string>{"out.png"});
}

TEST_F(AtomicFile, ADirectoryThatCannotBeWrittenIsAnErrorNamingTheFile) {
    if (::geteuid() == 0) GTEST_SKIP() << "root writes anywhere";
    fs::create_directory(path("ro"));
    ASSERT_EQ(::chmod(path("ro").c_str(), 0500), 0);
    const auto r = write_file_atomically(path("ro/a.json"), "x");
    ::chmod(path("ro").c_str(), 0700);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("Permission denied"), std::string::npos);
}

} // namespace
