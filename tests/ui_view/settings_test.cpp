// Settings: config directory, JSON round trip, tolerance to bad files, recent files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "ui/view/settings.hpp"

using namespace isoparm::ui;

TEST(Settings, ConfigDirFollowsXdgThenHome) {
    EXPECT_EQ(config_dir_from("/x", "/home/a"), "/x/isoparm");
    EXPECT_EQ(config_dir_from("", "/home/a"), "/home/a/.config/isoparm");
    EXPECT_EQ(config_dir_from(nullptr, "/home/a"), "/home/a/.config/isoparm");
    EXPECT_EQ(config_dir_from(nullptr, nullptr), "");
    // The XDG Base Directory specification: a relative value is invalid and ignored.
    EXPECT_EQ(config_dir_from("relative/config", "/home/a"), "/home/a/.config/isoparm");
    EXPECT_EQ(config_dir_from("relative/config", nullptr), "");
}

TEST(Settings, JsonRoundTrip) {
    Settings s;
    s.layout.left_width = 412;
    s.layout.right_shares = {0.3f, 0.7f};
    s.recent = {"/a/b.json", "/c.json"};
    s.window_sizes["1024x768"] = {900, 700};
    EXPECT_EQ(settings_from_json(settings_to_json(s)), s);
}

TEST(Settings, BadValuesFallBackToDefaults) {
    const nlohmann::json j = {{"layout", {{"left_width", "wide"}, {"right_width", -3}}},
                              {"recent", 5},
                              {"window_sizes", {{"1024x768", {10, 700}}}}};
    EXPECT_EQ(settings_from_json(j), Settings{});
    EXPECT_EQ(settings_from_json(nlohmann::json::array()), Settings{});
}

TEST(Settings, SaveThenLoadAndMissingOrBrokenFiles) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "isoparm_settings_test";
    std::filesystem::remove_all(dir);
    const std::string path = (dir / "sub" / "settings.json").string();
    EXPECT_EQ(load_settings(path), Settings{}); // missing
    Settings s;
    s.recent = {"/scene.json"};
    ASSERT_TRUE(save_settings(s, path)); // creates the directory
    EXPECT_EQ(load_settings(path), s);
    std::ofstream(path) << "{ not json";
    EXPECT_EQ(load_settings(path), Settings{});
    std::filesystem::remove_all(dir);
}

TEST(Settings, RecentFilesMoveToFrontWithoutDuplicates) {
    std::vector<std::string> r;
    add_recent(r, "a", 3);
    add_recent(r, "b", 3);
    add_recent(r, "a", 3);
    EXPECT_EQ(r, (std::vector<std::string>{"a", "b"}));
    add_recent(r, "c", 3);
    add_recent(r, "d", 3);
    EXPECT_EQ(r, (std::vector<std::string>{"d", "c", "a"}));
}
