// Protocol geometry for the work-budget tests and benchmarks: curves of any degree and a
// bicubic patch, as the `isoparm geom` requests spell them.
#pragma once

#include <nlohmann/json.hpp>

namespace isoparm::test {

// A clamped B-spline curve of degree p with p + 1 + extra points on [0, 1].
inline nlohmann::json curve_of_degree(int p, int extra = 0) {
    using nlohmann::json;
    const int n = p + 1 + extra;
    json knots = json::array();
    for (int k = 0; k <= p; ++k) knots.push_back(0.0);
    for (int k = 1; k <= extra; ++k) knots.push_back(static_cast<double>(k) / (extra + 1));
    for (int k = 0; k <= p; ++k) knots.push_back(1.0);
    json points = json::array();
    for (int k = 0; k < n; ++k) points.push_back({k, (k * 7) % 5, 0});
    return {{"type", "bspline"}, {"degree", p}, {"knots", knots}, {"points", points}};
}

// A bicubic Bezier patch over a 4x4 grid with a little relief.
inline nlohmann::json bicubic() {
    using nlohmann::json;
    json points = json::array();
    for (int i = 0; i < 4; ++i) {
        json row = json::array();
        for (int j = 0; j < 4; ++j) row.push_back({i, j, (i * j) % 3});
        points.push_back(row);
    }
    return {{"type", "bezier"}, {"degree", {3, 3}}, {"points", points}};
}

} // namespace isoparm::test
