#include "core/scene/export_document.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "core/exchange/glb_writer.hpp"
#include "core/exchange/iges_writer.hpp"
#include "core/exchange/mesh_weld.hpp"
#include "core/exchange/obj_writer.hpp"
#include "core/exchange/step_writer.hpp"
#include "core/exchange/stl_binary.hpp"
#include "core/geom/work_budget.hpp"

namespace isoparm::scene {

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// "'Hat' (id 3)": how messages name an object.
std::string label(const doc::Object& o) {
    return "'" + o.name + "' (id " + std::to_string(o.id) + ")";
}

geom::Error nothing_to_write(const ExportResult& r, ExportFormat f) {
    std::string message = std::string("nothing to write as ") + export_format_label(f);
    for (const std::string& s : r.skipped) message += "; " + s;
    return geom::make_error_nopath(geom::ErrorCode::schema, message);
}

// Memory a mesh export holds per vertex at its peak (the tessellation in doubles, the welded
// copy, its hash cells and the file's bytes), measured with 1,000 x 1,000 samples of one
// surface: binary STL 250 bytes, glTF 300, PLY 360, OBJ 570.
double bytes_per_vertex(ExportFormat f) {
    switch (f) {
    case ExportFormat::stl:
        return 250;
    case ExportFormat::glb:
        return 300;
    case ExportFormat::ply:
        return 360;
    case ExportFormat::obj_mesh:
    case ExportFormat::obj: // exact formats hold no mesh: the most a format costs
    case ExportFormat::iges:
    case ExportFormat::step:
        return 570;
    }
    return 570;
}

// The budget of a mesh export, checked before anything is tessellated: its vertices at the
// format's cost must fit in 1 GiB (25 surfaces at --samples 1000 took 4.3 GB).
geom::Status check_mesh_budget(const std::vector<const doc::Object*>& objects,
                               const ExportOptions& options) {
    const double n = options.samples;
    double vertices = 0;
    for (const doc::Object* o : objects)
        vertices +=
            std::visit([&](const auto& k) { return mesh_vertices(k, options.samples); }, o->shape);
    const double bytes = vertices * bytes_per_vertex(options.format);
    if (bytes <= max_export_bytes) return geom::Ok{};
    const double per_surface = std::floor(std::sqrt(max_export_bytes / bytes * n * n));
    return geom::make_error_nopath(
        geom::ErrorCode::limit,
        geom::with_thousands(vertices) + " vertices (" + std::to_string(options.samples) + " x " +
            std::to_string(options.samples) + " samples of each surface) would take about " +
            geom::with_thousands(bytes / (1 << 20)) + " MiB as " +
            export_format_label(options.format) + ", more than the " +
            geom::with_thousands(max_export_bytes / (1 << 20)) +
            " MiB an export may use; at most " + geom::with_thousands(per_surface) +
            " samples per direction fit, or export fewer objects");
}

geom::Expected<ExportResult> exact(const std::vector<const doc::Object*>& objects,
                                   const ExportOptions& options) {
    ExportResult r;
    std::vector<exchange::ExactShape> shapes;
    for (const doc::Object* o : objects) {
        // Each kind says what its exact form is, or why it has none.
        doc::ExactForm form = std::visit([](const auto& k) { return exact_form(k); }, o->shape);
        if (const auto* none = std::get_if<doc::NoForm>(&form)) {
            r.skipped.push_back(label(*o) + ": " + none->why);
            continue;
        }
        exchange::ExactShape shape =
            std::visit(doc::overloaded{[](doc::NoForm&) { return exchange::ExactShape(); },
                                       [](auto& g) { return exchange::ExactShape(std::move(g)); }},
                       form);
        if (options.format != ExportFormat::obj)
            if (geom::Status st = exchange::check_positive_weights(shape); !st) {
                // The shared message ends with the protocol's format names; say the mesh
                // formats as files name them.
                std::string m = st.error().message;
                m = m.substr(0, m.find("; export a mesh"));
                return geom::make_error_nopath(
                    geom::ErrorCode::weights,
                    label(*o) + ": " + m + "; export a mesh instead (STL, PLY or OBJ mesh)");
            }
        shapes.push_back(std::move(shape));
    }
    if (shapes.empty()) return nothing_to_write(r, options.format);
    if (options.format == ExportFormat::obj) {
        r.bytes = exchange::obj_freeform_text(shapes);
        return r;
    }
    auto text = options.format == ExportFormat::iges ? exchange::iges_text(shapes, options.name)
                                                     : exchange::step_text(shapes, options.name);
    if (!text) return text.error(); // weights were checked above; nothing else fails
    r.bytes = std::move(*text);
    return r;
}

} // namespace

std::string export_extensions() {
    return extensions_text(export_extension_table);
}

std::optional<ExportFormat> export_format_for(const std::string& path, bool mesh) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return std::nullopt;
    const std::optional<ExportFormat> format =
        format_by_extension(export_extension_table, lower(path.substr(dot)));
    if (!format || !mesh) return format;
    if (*format == ExportFormat::obj) return ExportFormat::obj_mesh;
    return is_mesh_format(*format) ? format : std::nullopt; // no exact format as a mesh
}

bool is_mesh_format(ExportFormat f) {
    return f == ExportFormat::obj_mesh || f == ExportFormat::stl || f == ExportFormat::ply ||
           f == ExportFormat::glb;
}

geom::Expected<std::vector<const doc::Object*>> export_objects(const doc::Document& doc,
                                                               const std::string& which) {
    std::vector<const doc::Object*> out;
    if (which.empty()) {
        for (const doc::Object& o : doc.objects)
            if (o.visible) out.push_back(&o);
        if (out.empty())
            return geom::make_error_nopath(geom::ErrorCode::schema,
                                           "the scene has no visible object to export");
        return out;
    }
    std::uint64_t id = 0;
    const auto [end, ec] = std::from_chars(which.data(), which.data() + which.size(), id);
    if (ec == std::errc{} && end == which.data() + which.size())
        for (const doc::Object& o : doc.objects)
            if (o.id == id) return std::vector<const doc::Object*>{&o};
    std::string ids;
    for (const doc::Object& o : doc.objects)
        if (o.name == which) {
            out.push_back(&o);
            ids += (ids.empty() ? "" : ", ") + std::to_string(o.id);
        }
    if (out.size() == 1) return out;
    if (out.size() > 1)
        return geom::make_error_nopath(geom::ErrorCode::schema,
                                       std::to_string(out.size()) + " objects are named '" + which +
                                           "' (ids " + ids + "): name one by its id");
    std::string names;
    for (const doc::Object& o : doc.objects) names += (names.empty() ? "" : ", ") + label(o);
    return geom::make_error_nopath(geom::ErrorCode::schema,
                                   "no object has the id or name '" + which + "' (the scene has " +
                                       (names.empty() ? "none" : names) + ")");
}

geom::Expected<ExportResult> export_document(const std::vector<const doc::Object*>& objects,
                                             const ExportOptions& options) {
    if (!is_mesh_format(options.format)) return exact(objects, options);
    if (options.samples < 2 || options.samples > 1000)
        return geom::make_error_nopath(geom::ErrorCode::schema,
                                       "samples " + std::to_string(options.samples) +
                                           " must be 2..1000 (points per direction of a "
                                           "surface's tessellation)");
    if (geom::Status st = check_mesh_budget(objects, options); !st) return st.error();
    ExportResult r;
    std::vector<geom::Mesh> meshes;
    for (const doc::Object* o : objects) {
        // Each kind says what its mesh is, or why it has none.
        auto form =
            std::visit([&](const auto& k) { return mesh_form(k, options.samples); }, o->shape);
        if (!form)
            return geom::make_error_nopath(form.error().code,
                                           label(*o) + ": " + form.error().message);
        if (const auto* none = std::get_if<doc::NoForm>(&*form)) {
            r.skipped.push_back(label(*o) + ": " + none->why);
            continue;
        }
        geom::Mesh mesh = std::get<geom::Mesh>(std::move(*form));
        exchange::weld(mesh);
        meshes.push_back(std::move(mesh));
    }
    if (meshes.empty()) return nothing_to_write(r, options.format);
    if (options.format == ExportFormat::obj_mesh) r.bytes = exchange::obj_mesh_text(meshes);
    if (options.format == ExportFormat::ply) r.bytes = exchange::ply_text(meshes);
    if (options.format == ExportFormat::stl)
        r.bytes = exchange::stl_binary_bytes(meshes, options.name);
    if (options.format == ExportFormat::glb) {
        auto bytes = exchange::glb_bytes(meshes, options.name);
        if (!bytes) return bytes.error();
        r.bytes = std::move(*bytes);
    }
    return r;
}

} // namespace isoparm::scene
