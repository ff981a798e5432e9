// Recovery files: where they live, atomic writing, finding and discarding them.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

#include "core/scene/autosave.hpp"
#include "core/doc/commands.hpp"
#include "core/scene/scene_io.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::scene;
using namespace isoparm::doc::testing;
namespace fs = std::filesystem;

namespace {

// Points XDG_STATE_HOME (and HOME) at a fresh directory for the test, restoring them after.
class StateHome : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root_ = fs::temp_directory_path() /
                ("isoparm-autosave-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(root_);
        fs::create_directories(root_ / "state");
        fs::create_directories(root_ / "home");
        fs::create_directories(root_ / "work");
        save_env("XDG_STATE_HOME", old_state_);
        save_env("HOME", old_home_);
        ::setenv("XDG_STATE_HOME", (root_ / "state").c_str(), 1);
        ::setenv("HOME", (root_ / "home").c_str(), 1);
    }
    void TearDown() override {
        restore_env("XDG_STATE_HOME", old_state_);
        restore_env("HOME", old_home_);
        std::error_code ec;
        fs::remove_all(root_, ec);
    }
    std::string work(const std::string& name) const { return (root_ / "work" / name).string(); }
    fs::path state_dir() const { return root_ / "state" / "isoparm"; }
    fs::path root_;

private:
    static void save_env(const char* name, std::optional<std::string>& into) {
        if (const char* v = std::getenv(name)) into = v;
    }
    static void restore_env(const char* name, const std::optional<std::string>& value) {
        if (value)
            ::setenv(name, value->c_str(), 1);
        else
            ::unsetenv(name);
    }
    std::optional<std::string> old_state_, old_home_;
};

std::size_t files_in(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

} // namespace

TEST_F(StateHome, DirectoryFollowsXdgStateHomeThenHome) {
    EXPECT_EQ(*recovery_directory(), state_dir().string());
    // A relative XDG_STATE_HOME is ignored, as the XDG specification says.
    ::setenv("XDG_STATE_HOME", "relative/state", 1);
    EXPECT_EQ(*recovery_directory(), (root_ / "home" / ".local" / "state" / "isoparm").string());
    ::unsetenv("XDG_STATE_HOME");
    EXPECT_EQ(*recovery_directory(), (root_ / "home" / ".local" / "state" / "isoparm").string());
    ::unsetenv("HOME");
    auto none = recovery_directory();
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().code, geom::ErrorCode::internal);
    EXPECT_FALSE(write_recovery(default_document(), "").ok());
    EXPECT_FALSE(find_recovery("").has_value());
}

TEST_F(StateHome, PathsNameTheSceneAndTellFoldersApart) {
    const std::string untitled = *recovery_path("");
    EXPECT_EQ(untitled, (state_dir() / "untitled.recovery.json").string());

    const std::string a = *recovery_path(work("hill.json"));
    EXPECT_EQ(fs::path(a).parent_path(), state_dir());
    EXPECT_EQ(fs::path(a).filename().string().rfind("hill.json-", 0), 0u) << a;
    // The same file however it is spelled.
    EXPECT_EQ(*recovery_path(work("sub/../hill.json")), a);
    EXPECT_EQ(*recovery_path(work("./hill.json")), a);
    // Another folder's hill.json, and another name in this folder, get their own files.
    fs::create_directories(root_ / "other");
    EXPECT_NE(*recovery_path((root_ / "other" / "hill.json").string()), a);
    EXPECT_NE(*recovery_path(work("hill2.json")), a);
    EXPECT_NE(*recovery_path(work("hill.json")), untitled);

    // A relative path is taken from the current directory.
    const fs::path cwd = fs::current_path();
    fs::current_path(root_ / "work");
    const std::string relative = *recovery_path("hill.json");
    fs::current_path(cwd);
    EXPECT_EQ(relative, a);

    // Odd file names become a short, safe part of the recovery file's name.
    const std::string odd = *recovery_path(work(std::string(300, 'x') + " \xc3\xa9t\xc3\xa9.json"));
    const std::string name = fs::path(odd).filename().string();
    EXPECT_LE(name.size(), 64u + 1 + 16 + std::string(".recovery.json").size());
    EXPECT_EQ(name.find(' '), std::string::npos);
}

TEST_F(StateHome, WriteFindLoadDiscard) {
    const std::string scene = work("hill.json");
    EXPECT_FALSE(find_recovery(scene).has_value());
    EXPECT_TRUE(discard_recovery(scene).ok()) << "no recovery file is not an error";

    Document doc = sample_document();
    const auto before = std::chrono::system_clock::now() - std::chrono::seconds(2);
    ASSERT_TRUE(write_recovery(doc, scene).ok());
    // The directory is created, private to the user.
    struct stat st {};
    ASSERT_EQ(::stat(state_dir().c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0700u);

    auto info = find_recovery(scene);
    ASSERT_TRUE(info.has_value());
    EXPECT_EQ(info->path, *recovery_path(scene));
    EXPECT_GE(info->written, before);
    EXPECT_LE(info->written, std::chrono::system_clock::now() + std::chrono::seconds(2));
    EXPECT_FALSE(info->older_than_scene) << "there is no scene file yet";
    auto back = load_scene(info->path);
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(same_document(*back, doc));
    // Only the named scene has one.
    EXPECT_FALSE(find_recovery("").has_value());
    EXPECT_FALSE(find_recovery(work("other.json")).has_value());

    // A later autosave replaces it, leaving no temporary file behind.
    History history;
    ASSERT_TRUE(
        history.execute(doc, move_control_point(hill_id, 1, 1, glm::dvec3(0.5, 0.5, 2.0))).ok());
    ASSERT_TRUE(write_recovery(doc, scene).ok());
    EXPECT_EQ(files_in(state_dir()), 1u);
    back = load_scene(find_recovery(scene)->path);
    ASSERT_TRUE(back.ok());
    EXPECT_TRUE(same_document(*back, doc));

    ASSERT_TRUE(discard_recovery(scene).ok());
    EXPECT_FALSE(find_recovery(scene).has_value());
    EXPECT_EQ(files_in(state_dir()), 0u);
}

TEST_F(StateHome, UntitledDocumentsRecoverToo) {
    const Document doc = sample_document();
    ASSERT_TRUE(write_recovery(doc, "").ok());
    auto info = find_recovery("");
    ASSERT_TRUE(info.has_value());
    auto back = load_scene(info->path);
    ASSERT_TRUE(back.ok());
    EXPECT_TRUE(same_document(*back, doc));
    ASSERT_TRUE(discard_recovery("").ok());
    EXPECT_FALSE(find_recovery("").has_value());
}

TEST_F(StateHome, RecoveryOlderThanTheSceneIsFlagged) {
    const std::string scene = work("hill.json");
    const Document doc = default_document();
    ASSERT_TRUE(write_recovery(doc, scene).ok());
    ASSERT_TRUE(save_scene(doc, scene).ok());
    // Modification times have coarse granularity on some file systems: set them explicitly.
    const auto now = fs::file_time_type::clock::now();
    fs::last_write_time(*recovery_path(scene), now - std::chrono::minutes(5));
    fs::last_write_time(scene, now);
    auto info = find_recovery(scene);
    ASSERT_TRUE(info.has_value());
    EXPECT_TRUE(info->older_than_scene);

    fs::last_write_time(*recovery_path(scene), now + std::chrono::minutes(1));
    EXPECT_FALSE(find_recovery(scene)->older_than_scene);
}

TEST_F(StateHome, FailuresAreReportedNotThrown) {
    // The state directory cannot be created (a file is in the way).
    { std::ofstream(root_ / "state" / "isoparm") << "not a directory"; }
    auto st = write_recovery(default_document(), work("hill.json"));
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, geom::ErrorCode::internal);
    EXPECT_FALSE(st.error().message.empty());
    // A directory where the recovery file should be is not a recovery file.
    fs::remove(root_ / "state" / "isoparm");
    fs::create_directories(*recovery_path(work("hill.json")));
    EXPECT_FALSE(find_recovery(work("hill.json")).has_value());
    EXPECT_FALSE(discard_recovery(work("hill.json")).ok());
}
