// OpenCASCADE's evaluation of the same grids, for the comparison benchmark (bench_sisl.cpp):
// a Geom_BSplineSurface through GeomAdaptor_Surface, whose D0 / D1 keep a cache of the
// current span's polynomial (BSplSLib_Cache), point after point along the rows, as a
// tessellator using OCCT would. Kept in its own file so OCCT's headers stay out of the rest.
#pragma once

#include <memory>
#include <vector>

#include "core/geom/types.hpp"

namespace isoparm::bench {

class OcctGrid {
public:
    explicit OcctGrid(const geom::Surface& s);
    ~OcctGrid();
    OcctGrid(const OcctGrid&) = delete;
    OcctGrid& operator=(const OcctGrid&) = delete;

    // Positions (x, y, z per point, t_u major) at every (t[i], t[j]).
    void positions(const std::vector<double>& t, double* out) const;
    // Positions and unit normals (D1U x D1V normalized).
    void normals(const std::vector<double>& t, double* pos, double* nrm) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace isoparm::bench
