// The autosave policy (AutosaveTimer with a fake clock), the start-up's recovery list and the
// restore command.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <unistd.h>

#include "core/scene/autosave.hpp"
#include "core/scene/autosave_timer.hpp"
#include "core/doc/commands.hpp"
#include "core/doc/restore_command.hpp"
#include "core/scene/scene_io.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::scene;
using namespace isoparm::doc::testing;
using namespace std::chrono_literals;
namespace fs = std::filesystem;

namespace {

using Kind = AutosaveTimer::Step::Kind;
using Clock = AutosaveTimer::Clock;

const Clock::time_point t0{}; // a fake clock: the timer never reads a real one

// Counts how often the fingerprint is asked for (it serializes the document: once a minute).
struct Fingerprint {
    std::uint64_t value = 1;
    int calls = 0;
    std::function<std::uint64_t()> fn() {
        return [this] {
            ++calls;
            return value;
        };
    }
};

TEST(AutosaveTimer, WritesOncePerIntervalOnlyWhenDirty) {
    AutosaveTimer timer(t0, 60s);
    Fingerprint fp;
    EXPECT_EQ(timer.poll(t0 + 30s, true, "a.json", fp.fn()).kind, Kind::none);
    EXPECT_EQ(timer.poll(t0 + 59s, true, "a.json", fp.fn()).kind, Kind::none);
    EXPECT_EQ(fp.calls, 0); // no serialization between checks
    const AutosaveTimer::Step s = timer.poll(t0 + 60s, true, "a.json", fp.fn());
    EXPECT_EQ(s.kind, Kind::write);
    EXPECT_EQ(s.path, "a.json");
    EXPECT_EQ(s.fingerprint, 1u);
    timer.wrote(s.path, s.fingerprint);
    // The next check is a full interval later.
    EXPECT_EQ(timer.poll(t0 + 90s, true, "a.json", fp.fn()).kind, Kind::none);
    fp.value = 2;
    EXPECT_EQ(timer.poll(t0 + 120s, true, "a.json", fp.fn()).kind, Kind::write);
}

TEST(AutosaveTimer, CleanDocumentsAreNotWritten) {
    AutosaveTimer timer(t0, 60s);
    Fingerprint fp;
    EXPECT_EQ(timer.poll(t0 + 60s, false, "", fp.fn()).kind, Kind::none);
    EXPECT_EQ(fp.calls, 0);
    // Dirty only after the check: written at the next one, not at once.
    EXPECT_EQ(timer.poll(t0 + 61s, true, "", fp.fn()).kind, Kind::none);
    EXPECT_EQ(timer.poll(t0 + 120s, true, "", fp.fn()).kind, Kind::write);
}

TEST(AutosaveTimer, UnchangedDocumentIsNotWrittenAgain) {
    AutosaveTimer timer(t0, 60s);
    Fingerprint fp;
    timer.wrote("a.json", 1);
    EXPECT_EQ(timer.poll(t0 + 60s, true, "a.json", fp.fn()).kind, Kind::none);
    EXPECT_EQ(fp.calls, 1);
    // A failed write (wrote() not called) is retried at the next check.
    fp.value = 5;
    EXPECT_EQ(timer.poll(t0 + 120s, true, "a.json", fp.fn()).kind, Kind::write);
    EXPECT_EQ(timer.poll(t0 + 180s, true, "a.json", fp.fn()).kind, Kind::write);
}

TEST(AutosaveTimer, SaveDiscardsOnceAndForgets) {
    AutosaveTimer timer(t0, 60s);
    Fingerprint fp;
    timer.wrote("a.json", 1);
    // Still dirty: nothing to discard.
    EXPECT_EQ(timer.poll(t0 + 1s, true, "a.json", fp.fn()).kind, Kind::none);
    const AutosaveTimer::Step s = timer.poll(t0 + 2s, false, "a.json", fp.fn());
    EXPECT_EQ(s.kind, Kind::discard);
    EXPECT_EQ(s.path, "a.json");
    EXPECT_EQ(timer.poll(t0 + 3s, false, "a.json", fp.fn()).kind, Kind::none);
    EXPECT_FALSE(timer.on_exit().has_value());
}

TEST(AutosaveTimer, SaveAsDiscardsTheOldPath) {
    AutosaveTimer timer(t0, 60s);
    Fingerprint fp;
    timer.wrote("", 1); // untitled
    const AutosaveTimer::Step s = timer.poll(t0 + 1s, false, "/work/b.json", fp.fn());
    EXPECT_EQ(s.kind, Kind::discard);
    EXPECT_EQ(s.path, "");
}

TEST(AutosaveTimer, ExitDiscardsWhatThisSessionWrote) {
    AutosaveTimer timer(t0, 60s);
    EXPECT_FALSE(timer.on_exit().has_value());
    timer.wrote("a.json", 3);
    ASSERT_TRUE(timer.on_exit().has_value());
    EXPECT_EQ(*timer.on_exit(), "a.json");
}

TEST(AutosaveTimer, HeldPathIsNeitherWrittenNorDiscarded) {
    AutosaveTimer timer(t0, 60s);
    Fingerprint fp;
    timer.hold("");
    EXPECT_TRUE(timer.held(""));
    EXPECT_EQ(timer.poll(t0 + 60s, true, "", fp.fn()).kind, Kind::none);
    EXPECT_EQ(fp.calls, 0);
    EXPECT_FALSE(timer.on_exit().has_value());
    // Other paths still autosave.
    EXPECT_EQ(timer.poll(t0 + 120s, true, "a.json", fp.fn()).kind, Kind::write);
}

TEST(DocumentFingerprint, FollowsTheSceneText) {
    Document a = sample_document();
    const Document b = a;
    EXPECT_EQ(document_fingerprint(a), document_fingerprint(b));
    a.objects.front().name += "x";
    EXPECT_NE(document_fingerprint(a), document_fingerprint(b));
}

TEST(RestoreDocument, ReplacesAndUndoesBitForBit) {
    Document doc = default_document();
    const Document saved = doc;
    const Document recovered = sample_document();
    History history;
    history.mark_clean();
    ASSERT_TRUE(history.execute(doc, restore_document(recovered)).ok());
    EXPECT_TRUE(same_document(doc, recovered));
    EXPECT_FALSE(history.is_clean()); // the restored work is unsaved
    EXPECT_EQ(history.undo_label(), "Restore unsaved changes");
    ASSERT_TRUE(history.undo(doc));
    EXPECT_TRUE(same_document(doc, saved));
    EXPECT_TRUE(history.is_clean());
    ASSERT_TRUE(history.redo(doc));
    EXPECT_TRUE(same_document(doc, recovered));
}

// Recovery files found at start-up, with XDG_STATE_HOME pointed at a fresh directory.
class FindRecoveries : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("isoparm-findrec-" + std::to_string(::getpid()));
        fs::remove_all(root_);
        fs::create_directories(root_ / "work");
        if (const char* v = std::getenv("XDG_STATE_HOME")) old_ = v;
        ::setenv("XDG_STATE_HOME", (root_ / "state").c_str(), 1);
    }
    void TearDown() override {
        if (old_)
            ::setenv("XDG_STATE_HOME", old_->c_str(), 1);
        else
            ::unsetenv("XDG_STATE_HOME");
        std::error_code ec;
        fs::remove_all(root_, ec);
    }
    std::string work(const std::string& name) const { return (root_ / "work" / name).string(); }
    fs::path root_;
    std::optional<std::string> old_;
};

TEST_F(FindRecoveries, NewestFirstEachFileOnce) {
    const Document doc = sample_document();
    ASSERT_TRUE(write_recovery(doc, work("a.json")).ok());
    ASSERT_TRUE(write_recovery(doc, "").ok());
    // Make the untitled one clearly newer, whatever the file system's time resolution.
    const auto a = recovery_path(work("a.json"));
    ASSERT_TRUE(a.ok());
    fs::last_write_time(*a, fs::last_write_time(*a) - 10s);
    const std::string spelled_twice = (root_ / "work" / "." / "a.json").string();
    const std::vector<RecoveryInfo> found =
        find_recoveries({work("a.json"), "", spelled_twice, work("none.json")});
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].origin, "");
    EXPECT_EQ(found[1].origin, work("a.json"));
    EXPECT_GT(found[0].written, found[1].written);
    auto loaded = load_scene(found[1].path);
    ASSERT_TRUE(loaded.ok());
    EXPECT_TRUE(same_geometry(*loaded, doc));
}

TEST_F(FindRecoveries, NoneWhenNothingWasWritten) {
    EXPECT_TRUE(find_recoveries({"", work("a.json")}).empty());
}

TEST(NormalizedScenePath, AbsoluteAndNormal) {
    EXPECT_EQ(normalized_scene_path(""), "");
    EXPECT_EQ(normalized_scene_path("/x/./y/../z.json"), "/x/z.json");
    EXPECT_TRUE(fs::path(normalized_scene_path("rel.json")).is_absolute());
}

} // namespace
