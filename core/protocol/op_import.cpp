// The `import` op (geom-protocol-2.md, Exchange): the curves and surfaces of an IGES, STEP or
// OBJ free-form file's text, in file order, and what was skipped. OBJ is read by
// core/exchange/obj_reader; IGES and STEP by the OCCT reader the program installed
// (core/exchange/cad_reader.hpp), and without it the op says so (`schema` at /format).
#include "core/exchange/cad_reader.hpp"
#include "core/exchange/obj_reader.hpp"
#include "core/json/shapes.hpp"
#include "core/json/trim_json.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

namespace {

enum class Format { iges, step, obj };
constexpr geom::EnumName<Format> format_names[] = {
    {Format::iges, "iges"}, {Format::step, "step"}, {Format::obj, "obj"}};
static_assert(geom::in_declaration_order(format_names));
constexpr std::span<const geom::EnumName<Format>> enum_names(Format) {
    return format_names;
}

} // namespace

OpResult op_import(const json& request) {
    if (geom::Status s = check_fields(request, "import", {"text", "format"}); !s) return s.error();
    const json* text = find_member(request, "text");
    if (!text) return missing_member("", "text");
    if (!text->is_string()) return schema_error("text is the file's content, a string", "/text");
    const json* format = find_member(request, "format");
    if (!format) return missing_member("", "format");
    const std::optional<Format> named = enum_value<Format>(*format);
    if (!named)
        return schema_error("format must be one of " + geom::names_list<Format>(", "), "/format");
    const std::string& content = text->get_ref<const std::string&>();
    geom::Expected<exchange::ImportResult> read =
        *named == Format::obj
            ? exchange::read_obj_freeform(content)
            : exchange::read_cad(content, *named == Format::iges ? exchange::CadFormat::iges
                                                                 : exchange::CadFormat::step);
    if (!read) {
        // A reader that is not there is about the request's format; a bad file about its text.
        if (!exchange::has_cad_reader() && *named != Format::obj)
            return read.error().under("/format");
        return read.error().under("/text");
    }
    json objects = json::array();
    for (const exchange::ImportedShape& shape : read->objects) {
        json o = json::object();
        if (const auto* c = std::get_if<geom::Curve>(&shape.shape)) {
            o["curve"] = curve_to_json(*c);
        } else {
            o["surface"] = surface_to_json(*exchange::surface_of(shape.shape));
            if (const auto* t = std::get_if<geom::TrimmedSurface>(&shape.shape))
                o["trim"] = trim_to_json(t->trim);
        }
        objects.push_back(std::move(o));
    }
    json skipped = json::array();
    for (const exchange::SkippedEntity& s : read->skipped)
        skipped.push_back({{"entity", s.entity}, {"reason", s.reason}});
    json answer = json::object();
    answer["objects"] = std::move(objects);
    answer["skipped"] = std::move(skipped);
    return answer;
}

} // namespace isoparm::protocol
