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
#include "core/geom/implicit/expression.hpp"
#include "core/geom/implicit/polygonize.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/triangle.hpp"
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

geom::Expected<geom::Mesh> implicit_mesh(const doc::Object& o) {
    const doc::ImplicitObject& im = *o.implicit();
    auto program = geom::implicit::compile(im.expression, im.parameter_names);
    if (!program)
        return geom::make_error_nopath(program.error().code,
                                       label(o) + ": " + program.error().message);
    geom::implicit::PolygonizeOptions options;
    options.lo = im.lo;
    options.hi = im.hi;
    options.cell = im.cell;
    options.parameters = im.parameter_values;
    auto mesh = geom::implicit::polygonize(*program, options);
    if (!mesh)
        return geom::make_error_nopath(mesh.error().code, label(o) + ": " + mesh.error().message);
    return mesh;
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
    default:
        return 570;
    }
}

// The budget of a mesh export, checked before anything is tessellated: its vertices at the
// format's cost must fit in 1 GiB (25 surfaces at --samples 1000 took 4.3 GB).
geom::Status check_mesh_budget(const std::vector<const doc::Object*>& objects,
                               const ExportOptions& options) {
    const double n = options.samples;
    double vertices = 0;
    for (const doc::Object* o : objects) {
        if (o->surface()) vertices += n * n;
        if (o->triangle()) vertices += n * (n + 1) / 2;
    }
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
        if (o->implicit()) {
            r.skipped.push_back(label(*o) +
                                ": an implicit surface has no exact form (export a mesh: STL, "
                                "PLY, glTF or OBJ mesh)");
            continue;
        }
        if (o->triangle()) {
            r.skipped.push_back(label(*o) +
                                ": IGES, STEP and OBJ free-form have no triangular Bezier patch "
                                "(export a mesh: STL, PLY, glTF or OBJ mesh)");
            continue;
        }
        exchange::ExactShape shape =
            o->surface() ? exchange::ExactShape(*o->surface()) : exchange::ExactShape(*o->curve());
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

const char* const export_extensions = ".igs/.iges, .stp/.step, .obj, .stl, .ply, .glb";

std::optional<ExportFormat> export_format_for(const std::string& path, bool mesh) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return std::nullopt;
    const std::string ext = lower(path.substr(dot));
    if (ext == ".obj") return mesh ? ExportFormat::obj_mesh : ExportFormat::obj;
    if (ext == ".stl") return ExportFormat::stl;
    if (ext == ".ply") return ExportFormat::ply;
    if (ext == ".glb") return ExportFormat::glb;
    if (mesh) return std::nullopt;
    if (ext == ".igs" || ext == ".iges") return ExportFormat::iges;
    if (ext == ".stp" || ext == ".step") return ExportFormat::step;
    return std::nullopt;
}

bool is_mesh_format(ExportFormat f) {
    return f == ExportFormat::obj_mesh || f == ExportFormat::stl || f == ExportFormat::ply ||
           f == ExportFormat::glb;
}

const char* export_format_label(ExportFormat f) {
    switch (f) {
    case ExportFormat::iges:
        return "IGES";
    case ExportFormat::step:
        return "STEP";
    case ExportFormat::obj:
        return "OBJ free-form";
    case ExportFormat::obj_mesh:
        return "OBJ mesh";
    case ExportFormat::stl:
        return "binary STL";
    case ExportFormat::ply:
        return "PLY";
    case ExportFormat::glb:
        return "glTF binary";
    }
    return "?";
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
        if (o->curve()) {
            r.skipped.push_back(label(*o) + ": a curve has no mesh (export IGES, STEP or OBJ "
                                            "free-form)");
            continue;
        }
        geom::Mesh mesh;
        if (o->implicit()) {
            auto m = implicit_mesh(*o);
            if (!m) return m.error();
            if (m->triangles.empty()) {
                r.skipped.push_back(label(*o) + ": the implicit surface was not found in its box");
                continue;
            }
            mesh = std::move(*m);
        } else if (const geom::TrianglePatch* t = o->triangle()) {
            // `samples` points along each edge: (samples - 1)^2 triangles.
            mesh = geom::tessellate_triangle(*t, options.samples - 1);
        } else {
            mesh = geom::tessellate(*o->surface(), options.samples, options.samples);
        }
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
