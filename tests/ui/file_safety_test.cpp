// Files in the window: two windows saving one scene ask before replacing each other's work,
// and a scene too large to show is refused on open with the same sentence `isoparm render`
// prints.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/scene/scene_io.hpp"
#include "tests/support/temp_dir.hpp"
#include "ui/actions.hpp"
#include "ui/app_context.hpp"
#include "ui/view/scene_budget.hpp"

using namespace isoparm;
using namespace isoparm::ui;
namespace fs = std::filesystem;

namespace {

class FileSafety : public ::testing::Test {
protected:
    void SetUp() override {
        scene_ = (dir_ / "scene.json").string();
        ASSERT_TRUE(scene::save_scene(doc::default_document(), scene_));
    }
    static std::string read(const std::string& p) {
        std::ifstream in(p);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    static AppContext window() {
        AppContext ctx;
        ctx.remember_settings = false;
        return ctx;
    }
    isoparm::test::TempDir tmp_{"isoparm-ui-files"};
    const fs::path& dir_ = tmp_.dir();
    std::string scene_;
};

TEST_F(FileSafety, SavingOverAFileAnotherWindowSavedAsksFirst) {
    AppContext first = window(), second = window();
    ASSERT_TRUE(open_file(first, scene_));
    ASSERT_TRUE(open_file(second, scene_));
    // The first window saves a change; the second, unaware, saves its own.
    first.doc.objects[0].name = "first window's work";
    ASSERT_TRUE(save(first));
    second.doc.objects[0].name = "second window's work";
    EXPECT_FALSE(save(second)); // nothing written: the question is asked instead
    EXPECT_TRUE(second.ui.confirm_overwrite_changed);
    EXPECT_NE(read(scene_).find("first window's work"), std::string::npos);
    // Answered "save anyway": written, and later saves of that window no longer ask.
    ASSERT_TRUE(save_as(second, second.file_path));
    EXPECT_NE(read(scene_).find("second window's work"), std::string::npos);
    second.ui.confirm_overwrite_changed = false;
    EXPECT_TRUE(save(second));
    EXPECT_FALSE(second.ui.confirm_overwrite_changed);
}

TEST_F(FileSafety, SavingAgainWithoutOutsideChangesDoesNotAsk) {
    AppContext ctx = window();
    ASSERT_TRUE(open_file(ctx, scene_));
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(save(ctx));
        EXPECT_FALSE(ctx.ui.confirm_overwrite_changed);
    }
}

TEST_F(FileSafety, ASceneTooLargeToShowIsRefusedOnOpen) {
    // 250 copies of the default 5x5 bicubic surface at density 256: 16,384 vertices each.
    doc::Document big = doc::default_document();
    big.view.display.density = 256;
    const doc::Object hill = big.objects[0];
    for (int k = 1; k < 250; ++k) {
        doc::Object copy = hill;
        copy.id = big.allocate_id();
        big.objects.push_back(copy);
    }
    const std::string message = scene_over_budget(big);
    ASSERT_FALSE(message.empty());
    EXPECT_NE(message.find("250 surfaces"), std::string::npos) << message;
    const std::string path = (dir_ / "big.json").string();
    ASSERT_TRUE(scene::save_scene(big, path));
    AppContext ctx = window();
    EXPECT_FALSE(open_file(ctx, path));
    EXPECT_TRUE(ctx.ui.show_error);
    EXPECT_NE(ctx.ui.error_message.find("too large to show"), std::string::npos);
    EXPECT_TRUE(ctx.file_path.empty()); // the current document stays
    // A handful of surfaces is fine.
    big.objects.resize(5);
    EXPECT_EQ(scene_over_budget(big), "");
}

} // namespace
