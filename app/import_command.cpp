// `isoparm import FILE -o SCENE`: the curves and surfaces of an IGES, STEP or OBJ free-form
// file as a new scene, one object each (core/scene/import_document.hpp). IGES and STEP need the
// OCCT reader (built where OCCT is installed; main installs it). Exit status: 0 written; 2 bad
// input (options, a file that does not read, nothing importable), nothing written; 1 the scene
// could not be written (the old file, if any, is intact).
#include <iostream>
#include <memory>
#include <string>

#include "app/command_run.hpp"
#include "app/commands.hpp"
#include "core/doc/commands.hpp"
#include "core/json/out_of_memory.hpp"
#include "core/scene/atomic_file.hpp"
#include "core/scene/export_document.hpp"
#include "core/scene/import_document.hpp"
#include "core/scene/scene_io.hpp"
#include "ui/view/scene_budget.hpp"

namespace isoparm::app {

namespace {

struct ImportCommandOptions {
    std::string input, output;
};

int run_unguarded(const ImportCommandOptions& o) {
    auto fail = [](const std::string& message) {
        std::cerr << "isoparm import: " << message << "; nothing written\n";
        return 2;
    };
    if (!scene::import_format_for(o.input))
        return fail("cannot tell the format of '" + o.input + "' from its extension (" +
                    scene::import_extensions() + ")");
    // The output is a scene: an exchange format's extension is a slip (it would hold JSON).
    if (o.output != "-" &&
        (scene::import_format_for(o.output) || scene::export_format_for(o.output, false)))
        return fail("-o names the scene to write, not an exchange file: '" + o.output +
                    "' (name it .json)");
    if (geom::Status st = scene::check_output_path(o.output); !st) return fail(st.error().message);
    if (geom::Status st = scene::check_output_is_not_input(o.output, {o.input}); !st)
        return fail(st.error().message);
    auto imported = scene::import_file(o.input);
    if (!imported) return fail(imported.error().message);
    doc::Document document;
    for (doc::Object& object : imported->objects)
        if (geom::Status st = doc::add_object(std::move(object))->apply(document); !st)
            return fail(st.error().message); // import_file checked them: not expected
    // The scene written should be one the workstation and `isoparm render` can show: a part of
    // a thousand faces at the default density would need gigabytes, so the density is lowered
    // until it fits. Where nothing fits (140 bicubic 64 x 64 patches need 2.1 million vertices
    // even at two samples a span), the scene is written all the same at the lowest density, and
    // says so: the import's work is not thrown away, and `isoparm export` and `isoparm geom`
    // take the scene; the window and `isoparm render` refuse it with the same sentence.
    const int density = ui::display_density_that_fits(document);
    if (density == 0) {
        std::cerr << "isoparm import: warning: '" << o.input
                  << "': " << ui::scene_over_budget(document, 2, {})
                  << " (at display density 2); the scene is written at display density 2 "
                     "for `isoparm export` and `isoparm geom`, which do not show it\n";
        document.view.display.density = 2;
    } else if (density < document.view.display.density) {
        std::cerr << "isoparm import: display density " << document.view.display.density
                  << " lowered to " << density << " so that the " << document.objects.size()
                  << " objects can be shown\n";
        document.view.display.density = density;
    }
    return report_written("isoparm import: ", imported->skipped,
                          scene::save_scene(document, o.output));
}

} // namespace

Action register_import_command(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "import", "Read the curves and surfaces of an IGES, STEP or OBJ free-form file into a new "
                  "scene (format from FILE's extension)");
    auto o = std::make_shared<ImportCommandOptions>();
    sub->add_option("FILE", o->input, "the file to read: .igs/.iges, .stp/.step, .obj")->required();
    sub->add_option("-o,--output", o->output, "the scene to write (.json; - for standard output)")
        ->required();
    return [o]() -> int {
        return run_memory_guarded([&o] { return run_unguarded(*o); }, "isoparm import: ",
                                  " (importing '" + o->input + "'); nothing written");
    };
}

} // namespace isoparm::app
