// A script's checks on the document (docs/script-format.md: "expect"): counts, an object's
// kind, type, degree and knots, a control point's position and weight, a patch group's
// borders, and what the object is at a parameter (its point, a rational basis function and
// their sum, the curvatures). Read strictly; a check that does not hold says how, in words.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"
#include "core/geom/trim/trim_classify.hpp"

namespace isoparm::scene {

struct ExpectStep {
    std::optional<std::size_t> objects;
    std::optional<std::uint64_t> id;
    std::optional<doc::ObjectKind> kind;
    std::optional<int> i, j;
    std::optional<glm::dvec3> position; // of point (i, j), or the object's point at `at`
    std::optional<double> weight;
    geom::Dir direction = geom::Dir::u;
    std::optional<std::vector<double>> knots;
    std::optional<int> degree;
    std::optional<geom::SplineType> type;
    std::optional<std::uint64_t> group;
    std::optional<doc::Continuity> borders;
    // At a parameter: a surface's (u, v) or a curve's t (in `at->x`), in the object's domain.
    std::optional<glm::dvec2> at;
    std::optional<double> basis;     // R_ij(u, v) of point (i, j) (a curve: R_i(t))
    std::optional<double> basis_sum; // the sum of every R_ij (partition of unity: 1)
    std::optional<double> gaussian, mean;
    // Where `at` lies against the surface's trim: kept, cut away or on a loop (an untrimmed
    // surface keeps its whole domain).
    std::optional<geom::TrimSide> side;
    double tolerance = 1e-9;
};

// The "expect" member's value at `at` ("/steps/4/expect").
geom::Expected<ExpectStep> expect_from_json(const nlohmann::json& v, const std::string& at);
nlohmann::json expect_to_json(const ExpectStep& e);

// Every way the document differs from the expectation, one sentence each (empty: it holds).
std::vector<std::string> unmet_expectations(const ExpectStep& e, const doc::Document& d);

} // namespace isoparm::scene
