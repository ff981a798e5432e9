// Trim commands: a shape edit of the surface kind's trim, the surface itself unchanged.
#include "core/doc/commands_trim.hpp"

#include "core/doc/shape_edit.hpp"

namespace isoparm::doc {

namespace {

std::unique_ptr<Command> trim_edit(std::uint64_t id, CommandSpec spec, geom::Trim trim) {
    const bool removing = trim.empty();
    detail::ShapeEditRule rule;
    rule.make = [trim = std::move(trim), removing](const Object& o) -> geom::Expected<Shape> {
        const auto* s = std::get_if<SurfaceObject>(&o.shape);
        if (!s)
            return kind_refusal(o, removing ? "only a surface has a trim to remove"
                                            : "only a surface can be trimmed");
        if (removing && s->trim.empty())
            return geom::make_error(geom::ErrorCode::schema,
                                    "'" + o.name + "' has no trim to remove", "/id");
        SurfaceObject trimmed = *s;
        trimmed.trim = trim;
        return Shape{std::move(trimmed)};
    };
    // validate_trim's paths are under the trim; the command's argument is "/trim".
    rule.shape_path = "";
    rule.label = [removing](const Shape&, const Shape& after) {
        if (removing) return std::string("Remove trim");
        const int loops = trim_of(after) ? trim_of(after)->loop_count() : 0;
        return "Trim (" + std::to_string(loops) + (loops == 1 ? " loop)" : " loops)");
    };
    return detail::shape_edit(id, std::move(spec), std::move(rule));
}

} // namespace

std::unique_ptr<Command> set_trim(std::uint64_t id, geom::Trim trim) {
    SetTrimSpec spec{id, trim};
    return trim_edit(id, std::move(spec), std::move(trim));
}

std::unique_ptr<Command> remove_trim(std::uint64_t id) {
    return trim_edit(id, RemoveTrimSpec{id}, geom::Trim{});
}

} // namespace isoparm::doc
