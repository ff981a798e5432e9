// File > Export... and File > Import... without a window (ui/exchange_actions.hpp): refusals
// leave the dialog's reason and nothing written or added; an import is one undo step.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/scene/scene_io.hpp"
#include "tests/support/temp_dir.hpp"
#include "ui/actions.hpp"
#include "ui/app_context.hpp"
#include "ui/exchange_actions.hpp"

using namespace isoparm;
using namespace isoparm::ui;
namespace fs = std::filesystem;

namespace {

TEST(ExchangeActions, ExportRefusalsWriteNothingAndExportThenImportIsOneUndoStep) {
    isoparm::test::TempDir tmp("isoparm-ui-exchange");
    const std::string scene_path = tmp.path("scene.json");
    ASSERT_TRUE(scene::save_scene(doc::default_document(), scene_path));
    AppContext ctx;
    ctx.remember_settings = false;
    ASSERT_TRUE(open_file(ctx, scene_path));
    const std::size_t before = ctx.doc.objects.size();

    std::string error;
    EXPECT_FALSE(export_visible_objects(ctx, tmp.path("out.xyz"), error));
    EXPECT_NE(error.find("out.xyz"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(tmp.path("out.xyz")));
    // The scene's own file is never an export's output, whatever its name says.
    fs::create_symlink(scene_path, tmp.path("link.obj"));
    error.clear();
    EXPECT_FALSE(export_visible_objects(ctx, tmp.path("link.obj"), error));
    EXPECT_FALSE(error.empty());
    EXPECT_TRUE(scene::load_scene(scene_path));

    error.clear();
    ASSERT_TRUE(export_visible_objects(ctx, tmp.path("out.obj"), error)) << error;
    const std::size_t steps = ctx.history.size();
    ASSERT_TRUE(import_objects(ctx, tmp.path("out.obj"), error)) << error;
    EXPECT_EQ(ctx.doc.objects.size(), 2 * before);
    EXPECT_EQ(ctx.history.size(), steps + 1);
    EXPECT_EQ(ctx.history.undo_label(), "Import out.obj");
    EXPECT_EQ(ctx.doc.view.selection.object, ctx.doc.objects[before].id);
    undo(ctx);
    EXPECT_EQ(ctx.doc.objects.size(), before);

    // A file that does not import changes nothing and says why.
    error.clear();
    EXPECT_FALSE(import_objects(ctx, tmp.path("out.xyz"), error));
    EXPECT_NE(error.find("cannot tell the format"), std::string::npos) << error;
    EXPECT_EQ(ctx.doc.objects.size(), before);
}

} // namespace
