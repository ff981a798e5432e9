// The document: object lookup, exact comparison, the default scene and new planar grids.
#include "core/doc/document.hpp"

#include <bit>
#include <cassert>
#include <cstring>
#include <string>
#include <type_traits>

#include "core/doc/kinds/kind_common.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::doc {

ObjectKind kind_of(const Shape& shape) {
    return std::visit([](const auto& k) { return std::decay_t<decltype(k)>::kind; }, shape);
}

namespace {

// The kind K's part `member` of the shape, or nullptr when the shape is of another kind.
template <class K, class Part, class S> auto* part_of(S& shape, Part K::*member) {
    auto* k = std::get_if<K>(&shape);
    return k ? &(k->*member) : nullptr;
}

} // namespace

geom::Surface* surface_of(Shape& shape) {
    return part_of(shape, &SurfaceObject::surface);
}
const geom::Surface* surface_of(const Shape& shape) {
    return part_of(shape, &SurfaceObject::surface);
}
const geom::Trim* trim_of(const Shape& shape) {
    return part_of(shape, &SurfaceObject::trim);
}
bool is_trimmed(const Object& o) {
    const geom::Trim* t = trim_of(o.shape);
    return t && !t->empty();
}
CurveObject* curve_object_of(Shape& shape) {
    return std::get_if<CurveObject>(&shape);
}
const CurveObject* curve_object_of(const Shape& shape) {
    return std::get_if<CurveObject>(&shape);
}
geom::Curve* curve_of(Shape& shape) {
    return part_of(shape, &CurveObject::curve);
}
const geom::Curve* curve_of(const Shape& shape) {
    return part_of(shape, &CurveObject::curve);
}
ImplicitObject* implicit_of(Shape& shape) {
    return std::get_if<ImplicitObject>(&shape);
}
const ImplicitObject* implicit_of(const Shape& shape) {
    return std::get_if<ImplicitObject>(&shape);
}
geom::TrianglePatch* triangle_of(Shape& shape) {
    return part_of(shape, &TriangleObject::patch);
}
const geom::TrianglePatch* triangle_of(const Shape& shape) {
    return part_of(shape, &TriangleObject::patch);
}

std::span<glm::dvec3> control_points_of(Shape& shape) {
    return std::visit([](auto& k) { return control_points(k); }, shape);
}
std::span<const glm::dvec3> control_points_of(const Shape& shape) {
    return std::visit([](const auto& k) { return control_points(k); }, shape);
}
std::span<double> control_weights_of(Shape& shape) {
    return std::visit([](auto& k) { return control_weights(k); }, shape);
}
std::span<const double> control_weights_of(const Shape& shape) {
    return std::visit([](const auto& k) { return control_weights(k); }, shape);
}
bool has_control_point(const Shape& shape, int i, int j) {
    return std::visit([&](const auto& k) { return has_control_point(k, i, j); }, shape);
}
std::string point_label_of(const Shape& shape, PointName name, int i, int j) {
    return std::visit([&](const auto& k) { return point_label(k, name, i, j); }, shape);
}

geom::Error kind_refusal(const Object& o, const std::string& rest, const std::string& path) {
    return geom::make_error(geom::ErrorCode::schema,
                            "object '" + o.name + "' is " + kind_noun(o.kind()) + "; " + rest,
                            path);
}

Object* Document::find(std::uint64_t id) {
    if (id == 0) return nullptr;
    for (Object& o : objects)
        if (o.id == id) return &o;
    return nullptr;
}

const Object* Document::find(std::uint64_t id) const {
    if (id == 0) return nullptr;
    for (const Object& o : objects)
        if (o.id == id) return &o;
    return nullptr;
}

int Document::index_of(std::uint64_t id) const {
    if (id == 0) return -1;
    for (std::size_t k = 0; k < objects.size(); ++k)
        if (objects[k].id == id) return static_cast<int>(k);
    return -1;
}

namespace {

using detail::bit_equal;

bool same_bits(const Rgba& a, const Rgba& b) {
    return bit_equal(a.r, b.r) && bit_equal(a.g, b.g) && bit_equal(a.b, b.b) && bit_equal(a.a, b.a);
}

} // namespace

bool same_shape(const Shape& a, const Shape& b) {
    if (a.index() != b.index()) return false;
    return std::visit(
        [&](const auto& k) { return same_bits(k, std::get<std::decay_t<decltype(k)>>(b)); }, a);
}

namespace {

bool same_colors(const Colors& a, const Colors& b) {
    return same_bits(a.background, b.background) && same_bits(a.surface, b.surface) &&
           same_bits(a.selected_surface, b.selected_surface) &&
           same_bits(a.control_net, b.control_net) &&
           same_bits(a.control_points, b.control_points) &&
           same_bits(a.selected_point, b.selected_point) &&
           same_bits(a.knot_curves, b.knot_curves) && same_bits(a.indicator, b.indicator);
}

} // namespace

bool same_object(const Object& a, const Object& b) {
    return a.id == b.id && a.name == b.name && a.visible == b.visible &&
           a.patch_group == b.patch_group && same_shape(a.shape, b.shape) &&
           a.construction.has_value() == b.construction.has_value() &&
           (!a.construction || same_recipe(*a.construction, *b.construction));
}

bool same_geometry(const Document& a, const Document& b) {
    if (a.objects.size() != b.objects.size()) return false;
    for (std::size_t k = 0; k < a.objects.size(); ++k)
        if (!same_object(a.objects[k], b.objects[k])) return false;
    return same_colors(a.colors, b.colors);
}

bool same_view(const ViewState& a, const ViewState& b) {
    return a.selection == b.selection && bit_equal(a.indicator.x, b.indicator.x) &&
           bit_equal(a.indicator.y, b.indicator.y) &&
           bit_equal(a.barycentric[0], b.barycentric[0]) &&
           bit_equal(a.barycentric[1], b.barycentric[1]) &&
           bit_equal(a.barycentric[2], b.barycentric[2]) && a.display == b.display &&
           a.object_display == b.object_display;
}

ObjectDisplay defaults_of(const DisplaySettings& d) {
    return {d.control_points, d.control_net, d.point_ids, d.knot_curves};
}

ObjectDisplay display_of(const ViewState& view, std::uint64_t id) {
    const auto it = view.object_display.find(id);
    return it != view.object_display.end() ? it->second : defaults_of(view.display);
}

bool same_document(const Document& a, const Document& b) {
    return same_geometry(a, b) && same_view(a.view, b.view) && a.continuity == b.continuity;
}

Document default_document() {
    // A gentle hill over [-2, 2]^2, a little off-centre so that it does not look like a
    // textbook bump from every side. Heights are literals (not computed), so the scene is the
    // same number for number on every machine.
    // clang-format off
    static constexpr double height[5][5] = {
        {0.0, 0.1, 0.2, 0.1, 0.0},
        {0.1, 0.6, 0.9, 0.6, 0.2},
        {0.2, 0.9, 1.6, 1.0, 0.3},
        {0.1, 0.6, 1.0, 0.7, 0.2},
        {0.0, 0.2, 0.3, 0.2, 0.0},
    };
    // clang-format on
    geom::Surface s;
    s.type = geom::SplineType::nurbs;
    s.degree_u = s.degree_v = 3;
    s.n_u = s.n_v = 5;
    s.knots_u = geom::clamped_uniform_knots(5, 3);
    s.knots_v = s.knots_u;
    s.points.resize(25);
    s.weights.assign(25, 1.0);
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) s.point(i, j) = {i - 2.0, j - 2.0, height[i][j]};
    // Two weights that are not 1, so the rational side is visible from the start: the top
    // pulls the surface up, a lighter shoulder lets it sag a little.
    s.weight(2, 2) = 2.0;
    s.weight(1, 3) = 0.5;

    Document doc;
    Object hill;
    hill.id = doc.allocate_id();
    hill.name = "hill";
    hill.shape = SurfaceObject{std::move(s)};
    doc.objects.push_back(std::move(hill));
    doc.view.selection = Selection{doc.objects[0].id, 2, 2};
    doc.view.indicator = {0.5, 0.5};
    return doc;
}

geom::Expected<geom::Surface> make_planar_grid_checked(int rows, int cols, int degree_u,
                                                       int degree_v, geom::SplineType type) {
    using geom::ErrorCode;
    using geom::make_error;
    if (degree_u < 1)
        return make_error(ErrorCode::degree,
                          "the degree in u must be at least 1, got " + std::to_string(degree_u),
                          "/degree_u");
    if (degree_v < 1)
        return make_error(ErrorCode::degree,
                          "the degree in v must be at least 1, got " + std::to_string(degree_v),
                          "/degree_v");
    const bool bezier = geom::is_bezier(type);
    auto check_count = [&](int count, int degree, const char* what, const char* dir,
                           const char* path) -> geom::Status {
        if (bezier && count != degree + 1)
            return make_error(ErrorCode::degree,
                              std::string("a Bezier surface of degree ") + std::to_string(degree) +
                                  " in " + dir + " needs " + std::to_string(degree + 1) + " " +
                                  what + ", got " + std::to_string(count),
                              path);
        if (count < degree + 1)
            return make_error(ErrorCode::degree,
                              std::string("degree ") + std::to_string(degree) + " in " + dir +
                                  " needs at least " + std::to_string(degree + 1) + " " + what +
                                  ", got " + std::to_string(count),
                              path);
        if (count > geom::max_points_per_direction)
            return make_error(ErrorCode::limit,
                              std::string("at most ") +
                                  std::to_string(geom::max_points_per_direction) + " " + what +
                                  " are allowed, got " + std::to_string(count),
                              path);
        return geom::Ok{};
    };
    if (auto st = check_count(rows, degree_u, "rows", "u", "/rows"); !st) return st.error();
    if (auto st = check_count(cols, degree_v, "columns", "v", "/cols"); !st) return st.error();
    if (static_cast<long>(rows) * cols > geom::max_points_per_surface)
        return make_error(ErrorCode::limit,
                          "at most " + std::to_string(geom::max_points_per_surface) +
                              " control points are allowed, got " + std::to_string(rows) + " x " +
                              std::to_string(cols),
                          "/cols");

    geom::Surface s;
    s.type = type;
    s.degree_u = degree_u;
    s.degree_v = degree_v;
    s.n_u = rows;
    s.n_v = cols;
    s.knots_u = bezier ? geom::bezier_knots(degree_u) : geom::clamped_uniform_knots(rows, degree_u);
    s.knots_v = bezier ? geom::bezier_knots(degree_v) : geom::clamped_uniform_knots(cols, degree_v);
    s.points.resize(static_cast<std::size_t>(rows) * cols);
    s.weights.assign(s.points.size(), 1.0);
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < cols; ++j)
            s.point(i, j) = {(2.0 * i - (rows - 1)) / (rows - 1),
                             (2.0 * j - (cols - 1)) / (cols - 1), 0.0};
    return s;
}

geom::Surface make_planar_grid(int rows, int cols, int degree_u, int degree_v,
                               geom::SplineType type) {
    auto s = make_planar_grid_checked(rows, cols, degree_u, degree_v, type);
    assert(s.ok() && "make_planar_grid: invalid arguments (use make_planar_grid_checked)");
    return std::move(s).value();
}

} // namespace isoparm::doc
