// Pure helpers of the implicit-surface editor: parameter detection, presets, the mesh cache
// key and the coarse-cell rule used while a slider moves. No GL, no ImGui.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "core/doc/document.hpp"

namespace isoparm::ui {

// The named parameters of an expression, in order of first appearance: every identifier
// that is not x, y, z or a function name (sin cos tan exp log sqrt abs). Numbers such as
// 1e-3 are skipped whole, so their exponent is not taken for a parameter.
std::vector<std::string> detect_parameters(std::string_view expression);

// The object with a new expression: parameters re-detected, values kept for names that
// stay, 1 for new names. Nothing is validated here (the command and compile do that).
doc::ImplicitObject with_expression(const doc::ImplicitObject& o, const std::string& expression);

// Everything the mesh depends on; equal keys give bit-identical meshes.
struct ImplicitKey {
    std::string expression;
    std::vector<std::string> names;
    std::vector<double> values;
    glm::dvec3 lo{0}, hi{0};
    double cell = 0;
    bool operator==(const ImplicitKey&) const = default;
};
ImplicitKey implicit_key(const doc::ImplicitObject& o, double cell);

// Cells along the longest axis beyond which a slider drag polygonizes coarser.
constexpr double coarse_cells_per_axis = 48;
// The cell used while a parameter slider moves: twice the cell, and at least the longest
// extent / 48 so the grid stays near 48^3; the cell itself when that grid is already small.
double coarse_cell(const glm::dvec3& lo, const glm::dvec3& hi, double cell);

struct ImplicitPreset {
    const char* name;
    doc::ImplicitObject object;
};
// Sphere, torus, Steiner's Roman surface, Clebsch cubic, a heart, a Goursat tangle, each
// with bounds that hold it and a cell that shows it well.
const std::vector<ImplicitPreset>& implicit_presets();

} // namespace isoparm::ui
