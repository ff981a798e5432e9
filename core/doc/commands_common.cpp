// Helpers shared by the command implementations: lookup, validation, labels, sizes.
#include "core/doc/commands_common.hpp"

namespace isoparm::doc::detail {

using geom::ErrorCode;
using geom::make_error;

geom::Expected<Object*> find_object(Document& doc, std::uint64_t id) {
    if (Object* o = doc.find(id)) return o;
    return make_error(ErrorCode::schema, "there is no object with id " + std::to_string(id), "/id");
}

geom::Expected<const Object*> find_object(const Document& doc, std::uint64_t id) {
    if (const Object* o = doc.find(id)) return o;
    return make_error(ErrorCode::schema, "there is no object with id " + std::to_string(id), "/id");
}

geom::Status validate_shape(const Shape& shape) {
    return std::visit([](const auto& k) { return validate(k); }, shape);
}

geom::Status validate_name(const std::string& name) {
    if (name.empty()) return make_error(ErrorCode::schema, "an object needs a name", "/name");
    for (unsigned char ch : name)
        if (ch < 0x20 || ch == 0x7f)
            return make_error(ErrorCode::schema,
                              "an object name may not contain control characters", "/name");
    return geom::Ok{};
}

std::size_t shape_bytes(const Shape& shape) {
    return sizeof(Shape) + std::visit([](const auto& k) { return heap_bytes(k); }, shape);
}

} // namespace isoparm::doc::detail
