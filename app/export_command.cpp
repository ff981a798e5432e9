// `isoparm export SCENE -o FILE [--object NAME|ID] [--samples N] [--mesh]`: a scene's objects
// as an IGES, STEP, OBJ, STL, PLY or glTF binary file, the format chosen by FILE's extension
// (core/scene/export_document.hpp). Exit status: 0 written; 2 bad input (options, scene, an
// object that cannot be written in that format), nothing written; 1 the file could not be
// written (the old file, if any, is intact).
#include <iostream>
#include <memory>
#include <string>

#include "app/command_run.hpp"
#include "app/commands.hpp"
#include "core/json/out_of_memory.hpp"
#include "core/scene/atomic_file.hpp"
#include "core/scene/export_document.hpp"
#include "core/scene/scene_io.hpp"

namespace isoparm::app {

namespace {

struct ExportCommandOptions {
    std::string scene, output, object;
    long long samples = 32; // wide: any number typed meets the 2..1000 rule, not a conversion
    bool mesh = false;
};

// The scene file's name without folders and extension: the model name inside the file.
std::string stem(const std::string& path) {
    const auto slash = path.find_last_of('/');
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    const auto dot = name.find_last_of('.');
    return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

int run_unguarded(const ExportCommandOptions& o) {
    auto fail = [](const std::string& message) {
        std::cerr << "isoparm export: " << message << "; nothing written\n";
        return 2;
    };
    const auto format = scene::export_format_for(o.output, o.mesh);
    if (!format)
        return fail(
            o.mesh ? "--mesh asks for a mesh: name the output .obj, .stl, .ply or .glb, not '" +
                         o.output + "'"
                   : "cannot tell the format of '" + o.output + "' from its extension (" +
                         scene::export_extensions() + "; .obj --mesh for an OBJ mesh)");
    if (geom::Status st = scene::check_output_path(o.output); !st) return fail(st.error().message);
    if (geom::Status st = scene::check_output_is_not_input(o.output, {o.scene}); !st)
        return fail(st.error().message);
    const auto doc = scene::load_scene(o.scene);
    if (!doc)
        return fail("'" + o.scene + "': " + doc.error().message +
                    (doc.error().has_path ? " (at " + doc.error().path + ")" : ""));
    const auto objects = scene::export_objects(*doc, o.object);
    if (!objects) return fail(objects.error().message);
    scene::ExportOptions options;
    options.format = *format;
    if (o.samples < 2 || o.samples > 1000)
        return fail("--samples " + std::to_string(o.samples) +
                    " must be 2..1000 (points per direction of a surface's tessellation)");
    options.samples = static_cast<int>(o.samples);
    options.name = stem(o.scene);
    const auto result = scene::export_document(*objects, options);
    if (!result) return fail(result.error().message);
    return report_written("isoparm export: ", result->skipped,
                          scene::write_file_atomically(o.output, result->bytes));
}

} // namespace

Action register_export_command(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "export", "Write a scene's objects as IGES, STEP, OBJ, STL, PLY or glTF (format from -o's "
                  "extension)");
    auto o = std::make_shared<ExportCommandOptions>();
    sub->add_option("SCENE", o->scene, "scene file")->required();
    sub->add_option("-o,--output", o->output,
                    "the file to write: .igs/.iges, .stp/.step, .obj (exact free-form; with "
                    "--mesh triangles), .stl (binary), .ply, .glb (glTF 2.0 binary)")
        ->required();
    sub->add_option("--object", o->object,
                    "the object to write, by id or name (default: every visible object)");
    sub->add_option("--samples", o->samples,
                    "mesh formats: points per direction of each surface's tessellation, 2..1000 "
                    "(default 32; implicit surfaces use their own cell)");
    sub->add_flag("--mesh", o->mesh, "with .obj: write a triangle mesh instead of exact geometry");
    return [o]() -> int {
        return run_memory_guarded([&o] { return run_unguarded(*o); }, "isoparm export: ",
                                  " (exporting '" + o->scene + "'); nothing written");
    };
}

} // namespace isoparm::app
