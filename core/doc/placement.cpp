// Placement of new objects (see placement.hpp).
#include "core/doc/placement.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include <glm/common.hpp>

namespace isoparm::doc {

namespace {

void grow(std::optional<Box>& box, const glm::dvec3& p) {
    if (!box) {
        box = Box{p, p};
        return;
    }
    box->lo = glm::min(box->lo, p);
    box->hi = glm::max(box->hi, p);
}

template <class Points> std::optional<Box> box_of_points(const Points& points) {
    std::optional<Box> box;
    for (const auto& p : points) grow(box, glm::dvec3(p));
    return box;
}

void translate(Shape& shape, const glm::dvec3& d) {
    for (glm::dvec3& p : control_points_of(shape)) p += d;
}

} // namespace

std::optional<Box> bounds_of(const Shape& shape) {
    if (const ImplicitObject* f = implicit_of(shape)) return Box{f->lo, f->hi};
    return box_of_points(control_points_of(shape));
}

std::optional<Box> scene_bounds(const Document& doc) {
    std::optional<Box> box;
    for (const Object& o : doc.objects) {
        if (!o.visible) continue;
        if (const std::optional<Box> b = bounds_of(o.shape)) {
            grow(box, b->lo);
            grow(box, b->hi);
        }
    }
    return box;
}

ImplicitObject translated(const ImplicitObject& f, const glm::dvec3& d) {
    ImplicitObject out = f;
    out.lo += d;
    out.hi += d;
    // Identifiers are whole words: "exp" keeps its x, a parameter "xa" is not x.
    const std::string& e = f.expression;
    std::string r;
    std::size_t k = 0;
    auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    while (k < e.size()) {
        if (!ident(e[k])) {
            r += e[k++];
            continue;
        }
        std::size_t end = k;
        while (end < e.size() && ident(e[end])) ++end;
        const std::string word = e.substr(k, end - k);
        const bool number = std::isdigit(static_cast<unsigned char>(word[0])) != 0;
        const int axis = word == "x" ? 0 : word == "y" ? 1 : word == "z" ? 2 : -1;
        if (!number && axis >= 0 && d[axis] != 0)
            r += "(" + word + (d[axis] > 0 ? " - " : " + ") +
                 geom::format_number(std::abs(d[axis])) + ")";
        else
            r += word;
        // A number's exponent (1e-3) is one token with its sign: copy it as it is.
        k = end;
        if (number && k < e.size() && (e[k] == '-' || e[k] == '+') &&
            (r.back() == 'e' || r.back() == 'E'))
            r += e[k++];
    }
    out.expression = r;
    return out;
}

std::string unique_name(const Document& doc, const std::string& wanted, std::uint64_t except) {
    auto taken = [&](const std::string& n) {
        return std::any_of(doc.objects.begin(), doc.objects.end(),
                           [&](const Object& o) { return o.id != except && o.name == n; });
    };
    if (!taken(wanted)) return wanted;
    for (int n = 2;; ++n) {
        const std::string name = wanted + " (" + std::to_string(n) + ")";
        if (!taken(name)) return name;
    }
}

void place_beside_scene(const Document& doc, Shape& shape) {
    const std::optional<Box> scene = scene_bounds(doc);
    const std::optional<Box> own = bounds_of(shape);
    if (!scene || !own) return;
    const double width = own->hi.x - own->lo.x;
    const double gap = std::max(0.25 * width, 0.5);
    glm::dvec3 d{scene->hi.x + gap - own->lo.x, 0, 0};
    d.y = 0.5 * (scene->lo.y + scene->hi.y) - 0.5 * (own->lo.y + own->hi.y);
    // An implicit surface's formula is in absolute coordinates: it moves with its box.
    if (ImplicitObject* f = implicit_of(shape)) {
        *f = translated(*f, d);
        return;
    }
    translate(shape, d);
}

} // namespace isoparm::doc
