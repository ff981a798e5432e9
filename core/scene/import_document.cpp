#include "core/scene/import_document.hpp"

#include <algorithm>
#include <cctype>

#include "core/doc/commands.hpp"
#include "core/exchange/cad_reader.hpp"
#include "core/exchange/obj_reader.hpp"
#include "core/json/input_file.hpp"

namespace isoparm::scene {

namespace {

std::string lower_extension(const std::string& path) {
    const auto slash = path.find_last_of('/');
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

std::string clean_name(const std::string& name) {
    std::string out = name;
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
    const auto first = out.find_first_not_of(' ');
    if (first == std::string::npos) return "";
    return out.substr(first, out.find_last_not_of(' ') - first + 1);
}

} // namespace

std::string import_extensions() {
    return extensions_text(import_extension_table);
}

std::optional<ImportFormat> import_format_for(const std::string& path) {
    return format_by_extension(import_extension_table, lower_extension(path));
}

geom::Expected<ImportedObjects> import_text(std::string_view text, ImportFormat format) {
    auto read =
        format == ImportFormat::obj
            ? exchange::read_obj_freeform(text)
            : exchange::read_cad(text, format == ImportFormat::iges ? exchange::CadFormat::iges
                                                                    : exchange::CadFormat::step);
    if (!read) return read.error();
    // The import's budget (the OBJ reader counts while it reads; a CAD reader's answer here).
    std::size_t points = 0;
    for (const exchange::ImportedShape& shape : read->objects)
        points += exchange::control_points_of(shape.shape).size();
    if (points > exchange::max_import_control_points)
        return geom::make_error(geom::ErrorCode::limit,
                                "the file's curves and surfaces have " + std::to_string(points) +
                                    " control points in all, more than the " +
                                    std::to_string(exchange::max_import_control_points) +
                                    " one import takes");
    ImportedObjects out;
    for (const exchange::SkippedEntity& s : read->skipped)
        out.skipped.push_back(s.entity + ": " + s.reason);
    if (read->objects.empty())
        return geom::make_error(geom::ErrorCode::schema,
                                std::string("the ") + import_format_label(format) +
                                    " file holds no curve or surface isoparm can import" +
                                    (out.skipped.empty()
                                         ? ""
                                         : " (skipped: " + out.skipped.front() +
                                               (out.skipped.size() > 1 ? ", ..." : "") + ")"));
    int k = 0;
    doc::Document scratch;
    for (exchange::ImportedShape& shape : read->objects) {
        ++k;
        doc::Object o;
        o.name = clean_name(shape.name);
        if (o.name.empty()) o.name = std::string(geom::name_of(format)) + " " + std::to_string(k);
        if (auto* c = std::get_if<geom::Curve>(&shape.shape)) {
            doc::CurveObject co;
            co.curve = std::move(*c);
            co.plane = doc::CurvePlane::free3d;
            co.knot_mode = doc::CurveKnotMode::custom;
            o.shape = std::move(co);
        } else if (auto* t = std::get_if<geom::TrimmedSurface>(&shape.shape)) {
            // A face of a solid: its surface and the loops of its wires.
            o.shape = doc::SurfaceObject{std::move(t->surface), std::move(t->trim)};
        } else {
            o.shape = doc::SurfaceObject{std::move(std::get<geom::Surface>(shape.shape)), {}};
        }
        // The document's own rules (add_object's checks, on a scratch document), so a scene
        // written from these loads again; an object they refuse is left out, with the reason.
        if (geom::Status st = doc::add_object(o)->apply(scratch); !st) {
            out.skipped.push_back("object " + std::to_string(k) + " ('" + o.name +
                                  "'): " + st.error().message);
            continue;
        }
        out.objects.push_back(std::move(o));
    }
    if (out.objects.empty())
        return geom::make_error(
            geom::ErrorCode::schema,
            std::string("the ") + import_format_label(format) +
                " file holds no curve or surface isoparm can import (skipped: " +
                out.skipped.front() + (out.skipped.size() > 1 ? ", ..." : "") + ")");
    return out;
}

geom::Expected<ImportedObjects> import_file(const std::string& path) {
    const auto format = import_format_for(path);
    if (!format)
        return geom::make_error(geom::ErrorCode::schema, "cannot tell the format of '" + path +
                                                             "' from its extension (" +
                                                             import_extensions() + ")");
    auto text = json_io::read_input_file(path);
    if (!text) return text.error();
    auto objects = import_text(*text, *format);
    if (!objects)
        return geom::make_error(objects.error().code, "'" + path + "': " + objects.error().message);
    return objects;
}

} // namespace isoparm::scene
