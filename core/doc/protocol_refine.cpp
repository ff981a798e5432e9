// The refinement ops (insert_knot, elevate_degree, split) through the document's commands.
#include <limits>

#include "core/doc/command.hpp"
#include "core/doc/commands.hpp"
#include "core/doc/json_geom.hpp"
#include "core/doc/json_values.hpp"
#include "core/doc/protocol_detail.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::doc::protocol {

using geom::ErrorCode;
using geom::Expected;

namespace {

// A scratch document holding the request's geometry as its one object.
struct Scratch {
    Document doc;
    History history;
    std::uint64_t id = 0;

    explicit Scratch(const Subject& subject) {
        Object obj;
        obj.id = doc.allocate_id();
        obj.name = subject.is_surface ? "surface" : "curve";
        if (subject.is_surface)
            obj.shape = SurfaceObject{subject.surface};
        else
            obj.shape = CurveObject{subject.curve, CurvePlane::free3d};
        id = obj.id;
        doc.objects.push_back(std::move(obj));
    }

    geom::Status run(std::unique_ptr<Command> cmd) { return history.execute(doc, std::move(cmd)); }
};

json shape_to_json(const Shape& shape) {
    if (const auto* s = std::get_if<SurfaceObject>(&shape)) return surface_to_json(s->surface);
    return curve_to_json(std::get<CurveObject>(shape).curve);
}

// The common start: fields, subject, direction.
struct Parsed {
    Subject subject;
    geom::Dir dir = geom::Dir::u;
};
Expected<Parsed> parse_common(const json& request, std::string_view op,
                              std::initializer_list<std::string_view> fields) {
    if (geom::Status s = check_fields(request, op, fields); !s) return s.error();
    Expected<Subject> subject = read_subject(request, true, true);
    if (!subject) return subject.error();
    Expected<geom::Dir> dir = read_direction(request, *subject);
    if (!dir) return dir.error();
    return Parsed{std::move(subject).value(), *dir};
}

// times: an integer >= 1 (convention 11), default 1. Kept as 64 bits: the ops bound it.
Expected<std::int64_t> read_times(const json& request) {
    return integer_option(request, "times", 1, 1, std::numeric_limits<std::int64_t>::max(),
                          "times is an integer >= 1");
}

// Commands take an int; beyond this no degree or size could accept the request anyway.
constexpr std::int64_t times_ceiling = std::int64_t{1} << 24;

} // namespace

OpResult op_insert_knot(const json& request) {
    Expected<Parsed> parsed =
        parse_common(request, "insert_knot", {"curve", "surface", "direction", "knot", "times"});
    if (!parsed) return parsed.error();
    Expected<double> knot = required_number(request, "knot");
    if (!knot) return knot.error();
    Expected<std::int64_t> times = read_times(request);
    if (!times) return times.error();
    const Subject& sub = parsed->subject;
    if (*times > times_ceiling) {
        // Too many for an int, and certainly above any degree: answer as the command would
        // (domain first, then multiplicity) but name the number given.
        const geom::Interval dom =
            sub.is_surface ? surface_domain(sub.surface, parsed->dir) : curve_domain(sub.curve);
        if (geom::Status s = check_in_domain(*knot, dom, "/knot", "knot"); !s) return s.error();
        const int p = sub.is_surface ? sub.surface.degree(parsed->dir) : sub.curve.degree;
        return geom::make_error(
            ErrorCode::multiplicity,
            "inserting " + geom::format_number(*knot) + " " + std::to_string(*times) +
                " time(s) would make its multiplicity exceed the degree " + std::to_string(p),
            "/times");
    }
    Scratch scratch(sub);
    if (geom::Status s =
            scratch.run(doc::insert_knot(scratch.id, parsed->dir, *knot, static_cast<int>(*times)));
        !s)
        return s.error();
    const Object* obj = scratch.doc.find(scratch.id);
    return json{{sub.is_surface ? "surface" : "curve", shape_to_json(obj->shape)}};
}

OpResult op_elevate_degree(const json& request) {
    Expected<Parsed> parsed =
        parse_common(request, "elevate_degree", {"curve", "surface", "direction", "times"});
    if (!parsed) return parsed.error();
    Expected<std::int64_t> times = read_times(request);
    if (!times) return times.error();
    if (*times > times_ceiling) {
        return geom::make_error(ErrorCode::limit,
                                "elevating the degree " + std::to_string(*times) +
                                    " times would need more than " +
                                    std::to_string(geom::max_points_per_direction) +
                                    " control points along the direction",
                                "/times");
    }
    const Subject& sub = parsed->subject;
    Scratch scratch(sub);
    if (geom::Status s =
            scratch.run(doc::elevate_degree(scratch.id, parsed->dir, static_cast<int>(*times)));
        !s)
        return s.error();
    const Object* obj = scratch.doc.find(scratch.id);
    return json{{sub.is_surface ? "surface" : "curve", shape_to_json(obj->shape)}};
}

OpResult op_split(const json& request) {
    Expected<Parsed> parsed =
        parse_common(request, "split", {"curve", "surface", "direction", "param"});
    if (!parsed) return parsed.error();
    Expected<double> t = required_number(request, "param");
    if (!t) return t.error();
    Scratch scratch(parsed->subject);
    if (geom::Status s = scratch.run(doc::split_object(scratch.id, parsed->dir, *t)); !s)
        return s.error();
    // The two pieces replace the object, in order (commands.hpp).
    const auto& objects = scratch.doc.objects;
    if (objects.size() != 2)
        return geom::make_error_nopath(ErrorCode::internal, "split did not give two pieces");
    json pieces = json::array({shape_to_json(objects[0].shape), shape_to_json(objects[1].shape)});
    return json{{"pieces", std::move(pieces)}};
}

} // namespace isoparm::doc::protocol
