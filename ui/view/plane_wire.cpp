// An object's isocurves and edges for the four-view layout's planes.
#include "ui/view/plane_wire.hpp"

#include <algorithm>
#include <variant>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/triangle.hpp"

namespace isoparm::ui {

namespace {

// Appends the points of f over `ts`, breaking the polyline where f has no value.
template <class F> void sampled(std::vector<Polyline3>& out, const std::vector<double>& ts, F f) {
    Polyline3 run;
    for (double t : ts) {
        if (const std::optional<glm::dvec3> p = f(t)) {
            run.push_back(*p);
        } else if (!run.empty()) {
            if (run.size() > 1) out.push_back(std::move(run));
            run.clear();
        }
    }
    if (run.size() > 1) out.push_back(std::move(run));
}

// The distinct knots within the domain [U[p], U[n]] (its ends included).
std::vector<double> domain_knots(const geom::Knots& U, int p, int n) {
    std::vector<double> out;
    for (const geom::KnotRun& r : geom::knot_runs(U))
        if (r.value >= U[static_cast<std::size_t>(p)] && r.value <= U[static_cast<std::size_t>(n)])
            out.push_back(r.value);
    return out;
}

} // namespace

std::vector<Polyline3> object_wire(const doc::Object& o, int samples) {
    samples = std::max(samples, 2);
    std::vector<Polyline3> out;
    auto surface = [&](const geom::Surface* s) {
        const geom::ParamRect d = geom::domain(*s);
        const std::vector<double> us = geom::uniform_params(d.u.lo, d.u.hi, samples);
        const std::vector<double> vs = geom::uniform_params(d.v.lo, d.v.hi, samples);
        for (double u : domain_knots(s->knots_u, s->degree_u, s->n_u))
            sampled(out, vs, [&](double v) { return geom::surface_point(*s, u, v); });
        for (double v : domain_knots(s->knots_v, s->degree_v, s->n_v))
            sampled(out, us, [&](double u) { return geom::surface_point(*s, u, v); });
    };
    auto curve = [&](const geom::Curve* c) {
        const geom::Interval d = geom::domain(*c);
        const int spans =
            std::max(1, static_cast<int>(domain_knots(c->knots, c->degree, c->count()).size()) - 1);
        std::vector<double> ts = geom::uniform_params(d.lo, d.hi, samples * spans);
        for (double k : domain_knots(c->knots, c->degree, c->count())) ts.push_back(k);
        std::sort(ts.begin(), ts.end());
        sampled(out, ts, [&](double t) { return geom::curve_point(*c, t); });
    };
    auto triangle = [&](const geom::TrianglePatch* t) {
        const std::vector<double> ts = geom::uniform_params(0, 1, samples);
        for (int edge = 0; edge < 3; ++edge)
            sampled(out, ts, [&](double a) {
                geom::Barycentric b{0, 0, 0};
                b[static_cast<std::size_t>(edge)] = 1 - a;
                b[static_cast<std::size_t>((edge + 1) % 3)] = a;
                return geom::triangle_point(*t, b);
            });
    };
    // An implicit surface has no parameter lines: the plane views draw its mesh's section.
    std::visit(doc::overloaded{
                   [&](const doc::SurfaceObject& s) { surface(&s.surface); },
                   [&](const doc::CurveObject& c) { curve(&c.curve); },
                   [](const doc::ImplicitObject&) {},
                   [&](const doc::TriangleObject& t) { triangle(&t.patch); },
               },
               o.shape);
    return out;
}

} // namespace isoparm::ui
