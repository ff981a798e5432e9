// Parameter detection, presets, cache key and coarse-cell rule of the implicit editor.
#include "ui/view/implicit_support.hpp"

#include <algorithm>
#include <cctype>

namespace isoparm::ui {

namespace {

bool is_reserved(std::string_view name) {
    static constexpr std::string_view reserved[] = {"x",   "y",   "z",   "sin",  "cos",
                                                    "tan", "exp", "log", "sqrt", "abs"};
    return std::find(std::begin(reserved), std::end(reserved), name) != std::end(reserved);
}

bool ident_start(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool ident_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool digit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

doc::ImplicitObject preset(std::string expression, std::vector<std::string> names,
                           std::vector<double> values, glm::dvec3 lo, glm::dvec3 hi, double cell) {
    doc::ImplicitObject o;
    o.expression = std::move(expression);
    o.parameter_names = std::move(names);
    o.parameter_values = std::move(values);
    o.lo = lo;
    o.hi = hi;
    o.cell = cell;
    return o;
}

} // namespace

std::vector<std::string> detect_parameters(std::string_view s) {
    std::vector<std::string> out;
    std::size_t k = 0;
    while (k < s.size()) {
        const char c = s[k];
        if (digit(c) || (c == '.' && k + 1 < s.size() && digit(s[k + 1]))) {
            // A number: digits, fraction, exponent (e, sign, digits).
            while (k < s.size() && (digit(s[k]) || s[k] == '.')) ++k;
            if (k < s.size() && (s[k] == 'e' || s[k] == 'E')) {
                std::size_t m = k + 1;
                if (m < s.size() && (s[m] == '+' || s[m] == '-')) ++m;
                if (m < s.size() && digit(s[m])) {
                    k = m;
                    while (k < s.size() && digit(s[k])) ++k;
                }
            }
        } else if (ident_start(c)) {
            const std::size_t b = k;
            while (k < s.size() && ident_char(s[k])) ++k;
            const std::string name(s.substr(b, k - b));
            if (!is_reserved(name) && std::find(out.begin(), out.end(), name) == out.end())
                out.push_back(name);
        } else {
            ++k;
        }
    }
    return out;
}

doc::ImplicitObject with_expression(const doc::ImplicitObject& o, const std::string& expression) {
    doc::ImplicitObject r = o;
    r.expression = expression;
    r.parameter_names = detect_parameters(expression);
    r.parameter_values.assign(r.parameter_names.size(), 1.0);
    for (std::size_t k = 0; k < r.parameter_names.size(); ++k)
        for (std::size_t m = 0; m < o.parameter_names.size() && m < o.parameter_values.size(); ++m)
            if (o.parameter_names[m] == r.parameter_names[k])
                r.parameter_values[k] = o.parameter_values[m];
    return r;
}

ImplicitKey implicit_key(const doc::ImplicitObject& o, double cell) {
    return {o.expression, o.parameter_names, o.parameter_values, o.lo, o.hi, cell};
}

double coarse_cell(const glm::dvec3& lo, const glm::dvec3& hi, double cell) {
    const glm::dvec3 e = hi - lo;
    const double extent = std::max({e.x, e.y, e.z});
    if (!(cell > 0) || extent / cell <= coarse_cells_per_axis) return cell;
    return std::max(2 * cell, extent / coarse_cells_per_axis);
}

const std::vector<ImplicitPreset>& implicit_presets() {
    static const std::vector<ImplicitPreset> presets = {
        {"Sphere", preset("x^2 + y^2 + z^2 - r^2", {"r"}, {1.0}, {-1.25, -1.25, -1.25},
                          {1.25, 1.25, 1.25}, 0.05)},
        // R: distance of the tube's centre from the axis, r: the tube's radius.
        {"Torus", preset("(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + y^2)", {"R", "r"},
                         {1.0, 0.4}, {-1.5, -1.5, -0.6}, {1.5, 1.5, 0.6}, 0.03)},
        // Steiner's Roman surface x^2 y^2 + y^2 z^2 + z^2 x^2 - r^2 x y z = 0.
        {"Steiner's Roman surface", preset("x^2*y^2 + y^2*z^2 + z^2*x^2 - r^2*x*y*z", {"r"}, {1.0},
                                           {-0.6, -0.6, -0.6}, {0.6, 0.6, 0.6}, 0.015)},
        // Clebsch diagonal cubic in the affine chart x + y + z + w = 0, w = 1 (27 real lines).
        {"Clebsch cubic",
         preset("81*(x^3 + y^3 + z^3) - 189*(x^2*y + x^2*z + y^2*x + y^2*z + z^2*x + z^2*y)"
                " + 54*x*y*z + 126*(x*y + x*z + y*z) - 9*(x^2 + y^2 + z^2) - 9*(x + y + z) + 1",
                {}, {}, {-1, -1, -1}, {1, 1, 1}, 0.025)},
        // Taubin's heart (x^2 + 9/4 y^2 + z^2 - 1)^3 - x^2 z^3 - 9/80 y^2 z^3 = 0.
        {"Heart", preset("(x^2 + 9/4*y^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*y^2*z^3", {}, {},
                         {-1.4, -1.0, -1.4}, {1.4, 1.0, 1.4}, 0.025)},
        // Goursat's tangle x^4 - 5x^2 + y^4 - 5y^2 + z^4 - 5z^2 + c = 0 (c = 11.8: the cube
        // with tunnels; larger c separates the lobes).
        {"Goursat tangle", preset("x^4 - 5*x^2 + y^4 - 5*y^2 + z^4 - 5*z^2 + c", {"c"}, {11.8},
                                  {-2.6, -2.6, -2.6}, {2.6, 2.6, 2.6}, 0.06)},
    };
    return presets;
}

} // namespace isoparm::ui
