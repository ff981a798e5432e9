#include "ui/exchange_actions.hpp"

#include <filesystem>

#include "core/doc/commands.hpp"
#include "core/scene/atomic_file.hpp"
#include "core/scene/export_document.hpp"
#include "core/scene/import_document.hpp"
#include "ui/actions.hpp"
#include "ui/platform/files.hpp"
#include "ui/view/scene_budget.hpp"

namespace isoparm::ui {

namespace {

namespace fs = std::filesystem;

void open_dialog(AppContext& ctx, FileDialog::Mode mode, std::string name) {
    FileDialog& fd = ctx.ui.file_dialog;
    fd.mode = mode;
    fd.just_opened = true;
    fd.error.clear();
    std::error_code ec;
    if (!ctx.file_path.empty() && fs::path(ctx.file_path).has_parent_path())
        fd.directory = fs::path(ctx.file_path).parent_path().string();
    if (fd.directory.empty()) fd.directory = fs::current_path(ec).string();
    fd.name = std::move(name);
}

std::string scene_stem(const AppContext& ctx) {
    return ctx.file_path.empty() ? "scene" : fs::path(ctx.file_path).stem().string();
}

std::string skipped_summary(const std::vector<std::string>& skipped) {
    if (skipped.empty()) return "";
    return "; skipped " + std::to_string(skipped.size()) + ": " + skipped.front() +
           (skipped.size() > 1 ? " ..." : "");
}

} // namespace

void request_export_dialog(AppContext& ctx) {
    open_dialog(ctx, FileDialog::Mode::export_file, scene_stem(ctx) + ".step");
}

void request_import_dialog(AppContext& ctx) {
    open_dialog(ctx, FileDialog::Mode::import_file, "");
}

bool is_exchange_file(const std::string& name) {
    return scene::import_format_for(name) || scene::export_format_for(name, false);
}

bool export_visible_objects(AppContext& ctx, const std::string& path, std::string& error) {
    const auto format = scene::export_format_for(path, false);
    if (!format) {
        error = "Cannot tell the format of '" + fs::path(path).filename().string() +
                "' from its extension (" + scene::export_extensions() + ").";
        return false;
    }
    std::vector<std::string> inputs;
    if (!ctx.file_path.empty()) inputs.push_back(ctx.file_path);
    if (geom::Status st = scene::check_output_is_not_input(path, inputs); !st) {
        error = st.error().message;
        return false;
    }
    const auto objects = scene::export_objects(ctx.doc, "");
    if (!objects) {
        error = objects.error().message;
        return false;
    }
    scene::ExportOptions options;
    options.format = *format;
    options.name = scene_stem(ctx);
    const auto result = scene::export_document(*objects, options);
    if (!result) {
        error = result.error().message;
        return false;
    }
    if (geom::Status st = scene::write_file_atomically(path, result->bytes); !st) {
        error = st.error().message;
        return false;
    }
    ctx.ui.status = std::string("Exported ") + scene::export_format_label(*format) + " " + path +
                    skipped_summary(result->skipped);
    files::hand_over(path); // the browser downloads it
    return true;
}

bool import_objects(AppContext& ctx, const std::string& path, std::string& error) {
    auto imported = scene::import_file(path);
    if (!imported) {
        error = imported.error().message;
        return false;
    }
    // The scene with the new objects must still be one the window can show: the density is
    // lowered until it fits, checked before the import is carried out; where nothing fits the
    // import is refused and the scene is left as it was.
    const int density = display_density_that_fits(ctx.doc, imported->objects);
    if (density == 0) {
        error = "'" + path + "': with its objects " +
                scene_over_budget(ctx.doc, 2, imported->objects) +
                " (at display density 2); nothing imported";
        return false;
    }
    const std::size_t count = imported->objects.size();
    const std::string label = "Import " + fs::path(path).filename().string();
    ctx.seal();
    if (!ctx.execute(doc::add_objects(std::move(imported->objects), label))) {
        error = ctx.ui.status; // the command's refusal, as execute reported it
        return false;
    }
    ctx.seal();
    std::string lowered;
    if (density < ctx.doc.view.display.density) {
        // Said before the path, which the status bar may cut.
        lowered = " (display density lowered from " + std::to_string(ctx.doc.view.display.density) +
                  " to " + std::to_string(density) + " to show them)";
        ctx.doc.view.display.density = density;
    }
    ctx.doc.view.selection = {ctx.doc.objects[ctx.doc.objects.size() - count].id, -1, -1};
    fit_view(ctx);
    ctx.ui.status = "Imported " + std::to_string(count) + (count == 1 ? " object" : " objects") +
                    lowered + " from " + path + skipped_summary(imported->skipped);
    return true;
}

} // namespace isoparm::ui
