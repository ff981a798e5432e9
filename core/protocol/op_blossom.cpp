// The `blossom` op (geom-protocol-2.md): the polar form of one polynomial piece of a curve or
// surface at arbitrary arguments.
#include "core/geom/blossom.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::Expected;

namespace {

// Exactly `count` finite numbers at `name`.
Expected<std::vector<double>> read_args(const json& request, std::string_view name, int count,
                                        std::string_view degree_name) {
    const json* v = find_member(request, name);
    if (!v) return missing_member("", name);
    const std::string path = member_path("", name);
    if (!v->is_array() || static_cast<long long>(v->size()) != count)
        return schema_error(std::string(name) + " holds " + std::to_string(count) +
                                " numbers (one per degree of " + std::string(degree_name) + ")",
                            path);
    std::vector<double> args;
    args.reserve(v->size());
    for (std::size_t k = 0; k < v->size(); ++k) {
        Expected<double> x = read_finite((*v)[k], path + "/" + std::to_string(k), "an argument");
        if (!x) return x.error();
        args.push_back(*x);
    }
    return args;
}

// An explicit span index, read as an integer (`schema` otherwise); checked by the caller.
Expected<int> read_span_index(const json& v, const std::string& path) {
    Expected<std::int64_t> k = read_integer(v, path, "a span index", 0, 1 << 30);
    if (!k) return k.error();
    return static_cast<int>(*k);
}

json point_answer(const std::optional<glm::dvec3>& p, json span) {
    json answer = json::object();
    answer["point"] = optional_point(p);
    answer["span"] = std::move(span);
    return answer;
}

} // namespace

OpResult op_blossom(const json& request) {
    if (geom::Status s = check_fields(request, "blossom",
                                      {"curve", "surface", "args", "u_args", "v_args", "span"});
        !s)
        return s.error();
    Expected<Subject> subject = read_subject(request, true, true);
    if (!subject) return subject.error();
    const json* span = find_member(request, "span");
    if (!subject->is_surface) {
        for (const char* name : {"u_args", "v_args"})
            if (find_member(request, name))
                return schema_error("a curve takes args, not u_args and v_args",
                                    member_path("", name));
        const geom::Curve& c = subject->curve;
        Expected<std::vector<double>> args = read_args(request, "args", c.degree, "the curve");
        if (!args) return args.error();
        int J = geom::default_blossom_span(c.knots, c.degree, c.count(), (*args)[0]);
        if (span) {
            Expected<int> k = read_span_index(*span, "/span");
            if (!k) return k.error();
            if (geom::Status st =
                    geom::check_blossom_span(c.knots, c.degree, c.count(), *k, "/span");
                !st)
                return st.error();
            J = *k;
        }
        return point_answer(geom::curve_blossom(c, J, *args), J);
    }
    if (find_member(request, "args"))
        return schema_error("a surface takes u_args and v_args, not args", "/args");
    const geom::Surface& s = subject->surface;
    Expected<std::vector<double>> u_args = read_args(request, "u_args", s.degree_u, "u");
    if (!u_args) return u_args.error();
    Expected<std::vector<double>> v_args = read_args(request, "v_args", s.degree_v, "v");
    if (!v_args) return v_args.error();
    int J[2] = {geom::default_blossom_span(s.knots_u, s.degree_u, s.n_u, (*u_args)[0]),
                geom::default_blossom_span(s.knots_v, s.degree_v, s.n_v, (*v_args)[0])};
    if (span) {
        if (!span->is_array() || span->size() != 2)
            return schema_error("a surface's span is [J_u, J_v]", "/span");
        for (int d = 0; d < 2; ++d) {
            const std::string path = "/span/" + std::to_string(d);
            Expected<int> k = read_span_index((*span)[static_cast<std::size_t>(d)], path);
            if (!k) return k.error();
            const geom::Dir dir = d == 0 ? geom::Dir::u : geom::Dir::v;
            if (geom::Status st =
                    geom::check_blossom_span(s.knots(dir), s.degree(dir), s.count(dir), *k, path);
                !st)
                return st.error();
            J[d] = *k;
        }
    }
    return point_answer(geom::surface_blossom(s, J[0], J[1], *u_args, *v_args),
                        json::array({J[0], J[1]}));
}

} // namespace isoparm::protocol
