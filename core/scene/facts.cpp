// The document's facts as expectations (facts.hpp).
#include "core/scene/facts.hpp"

#include <set>

#include "core/doc/patches.hpp"
#include "core/geom/basis.hpp"
#include "core/geom/curvature.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"

namespace isoparm::scene {

namespace {

std::string num(double x) {
    return geom::format_number(x);
}

std::string point_text(const glm::dvec3& p) {
    return "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ")";
}

std::string knots_text(const geom::Knots& U) {
    std::string out;
    for (std::size_t k = 0; k < U.size(); ++k) out += (k ? ", " : "") + num(U[k]);
    return "[" + out + "]";
}

// The object the facts are about: the selected one, else the first surface or curve.
const doc::Object* subject(const doc::Document& d) {
    if (const doc::Object* o = d.selected()) return o;
    for (const doc::Object& o : d.objects)
        if (o.surface() || o.curve()) return &o;
    return nullptr;
}

void object_facts(const doc::Document& d, const doc::Object& o, std::vector<Fact>& out) {
    const std::string name = "'" + o.name + "'";
    auto fact = [&](std::string text, ExpectStep e) {
        e.id = o.id;
        out.push_back({std::move(text), std::move(e)});
    };
    {
        ExpectStep e;
        e.kind = o.kind();
        fact(name + " is a " + doc::kind_name(o.kind()), e);
    }
    const geom::Surface* s = o.surface();
    const geom::Curve* c = o.curve();
    if (!s && !c) return;
    {
        ExpectStep e;
        e.type = s ? s->type : c->type;
        fact(name + " is a " + geom::label_of(*e.type), e);
    }
    for (geom::Dir dir : {geom::Dir::u, geom::Dir::v}) {
        if (c && dir == geom::Dir::v) break;
        const std::string in = s ? std::string(" in ") + geom::name_of(dir) : "";
        ExpectStep deg;
        deg.direction = dir;
        deg.degree = s ? s->degree(dir) : c->degree;
        fact(name + " has degree " + std::to_string(*deg.degree) + in, deg);
        ExpectStep kn;
        kn.direction = dir;
        kn.knots = s ? s->knots(dir) : c->knots;
        fact(name + "'s knots" + in + " are " + knots_text(*kn.knots), kn);
    }
    const doc::Selection& sel = d.view.selection;
    const bool has_point =
        sel.object == o.id && sel.has_point() && doc::has_control_point(o.shape, sel.i, sel.j);
    const std::string label =
        "P" + std::to_string(sel.i) + (s ? "," + std::to_string(sel.j) : std::string());
    if (has_point) {
        const std::size_t index = static_cast<std::size_t>(s ? s->index(sel.i, sel.j) : sel.i);
        ExpectStep pos;
        pos.i = sel.i;
        if (s) pos.j = sel.j;
        pos.position = s ? s->points[index] : c->points[index];
        fact(label + " of " + name + " is at " + point_text(*pos.position), pos);
        ExpectStep w;
        w.i = pos.i;
        w.j = pos.j;
        w.weight = s ? s->weights[index] : c->weights[index];
        fact("the weight of " + label + " of " + name + " is " + num(*w.weight), w);
    }
    // At the indicator: the tracing square's (u, v) over the group's (or the surface's) domain.
    glm::dvec2 at{0};
    if (s) {
        const geom::ParamRect r = doc::tracing_domain(d, o);
        at = {r.u.lo + d.view.indicator.x * (r.u.hi - r.u.lo),
              r.v.lo + d.view.indicator.y * (r.v.hi - r.v.lo)};
        if (!geom::domain(*s).contains(at)) return; // another patch of the group holds it
    } else {
        const geom::Interval r = geom::domain(*c);
        at = {r.lo + d.view.indicator.x * (r.hi - r.lo), 0};
    }
    const std::string where =
        s ? "(u, v) = (" + num(at.x) + ", " + num(at.y) + ")" : "t = " + num(at.x);
    const std::optional<glm::dvec3> p =
        s ? geom::surface_point(*s, at.x, at.y) : geom::curve_point(*c, at.x);
    if (!p) return;
    ExpectStep point;
    point.at = at;
    point.position = *p;
    fact((s ? "S" : "C") + std::string("(") + (s ? num(at.x) + ", " + num(at.y) : num(at.x)) +
             ") = " + point_text(*p),
         point);
    ExpectStep unity;
    unity.at = at;
    unity.basis_sum = 1;
    unity.tolerance = 1e-12;
    fact("the basis functions of " + name + " sum to 1 at " + where, unity);
    if (has_point) {
        std::optional<double> r;
        if (s) {
            r = geom::rational_basis_ij(*s, sel.i, sel.j, at.x, at.y);
        } else if (auto R = geom::rational_basis(c->knots, c->degree, c->weights, at.x)) {
            r = (*R)[0][static_cast<std::size_t>(sel.i)];
        }
        if (r) {
            ExpectStep b;
            b.at = at;
            b.i = sel.i;
            if (s) b.j = sel.j;
            b.basis = *r;
            fact("R" + label.substr(1) + " = " + num(*r) + " at " + where, b);
        }
    }
    if (s)
        if (const auto k = geom::surface_curvature(*s, at.x, at.y)) {
            ExpectStep g;
            g.at = at;
            g.gaussian = k->gaussian;
            g.tolerance = 1e-6;
            fact("the Gaussian curvature of " + name + " at " + where + " is " + num(k->gaussian),
                 g);
        }
}

} // namespace

std::vector<Fact> document_facts(const doc::Document& d) {
    std::vector<Fact> out;
    {
        ExpectStep e;
        e.objects = d.objects.size();
        out.push_back({"the scene holds " + std::to_string(d.objects.size()) +
                           (d.objects.size() == 1 ? " object" : " objects"),
                       e});
    }
    if (const doc::Object* o = subject(d)) object_facts(d, *o, out);
    std::set<std::uint64_t> groups;
    for (const doc::Object& o : d.objects)
        if (o.patch_group != 0) groups.insert(o.patch_group);
    for (std::uint64_t g : groups) {
        for (doc::Continuity c : {doc::Continuity::c1, doc::Continuity::c0}) {
            ExpectStep e;
            e.group = g;
            e.borders = c;
            if (!unmet_expectations(e, d).empty()) continue;
            out.push_back({"the borders of patch group " + std::to_string(g) + " are " +
                               doc::continuity_name(c),
                           e});
            break;
        }
    }
    return out;
}

} // namespace isoparm::scene
