#include "tests/bench/compare/occt_grid.hpp"

#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <cmath>

namespace isoparm::bench {

namespace {

// Distinct knots and multiplicities of a knot vector, as OCCT stores them.
void distinct(const std::vector<double>& knots, std::vector<double>& values,
              std::vector<int>& mult) {
    for (double k : knots) {
        if (!values.empty() && values.back() == k) {
            ++mult.back();
        } else {
            values.push_back(k);
            mult.push_back(1);
        }
    }
}

} // namespace

struct OcctGrid::Impl {
    Handle(Geom_BSplineSurface) surface;
    GeomAdaptor_Surface adaptor;
};

OcctGrid::OcctGrid(const geom::Surface& s) : impl_(std::make_unique<Impl>()) {
    TColgp_Array2OfPnt poles(1, s.n_u, 1, s.n_v);
    TColStd_Array2OfReal weights(1, s.n_u, 1, s.n_v);
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) {
            const glm::dvec3& p = s.point(i, j);
            poles.SetValue(i + 1, j + 1, gp_Pnt(p.x, p.y, p.z));
            weights.SetValue(i + 1, j + 1, s.weight(i, j));
        }
    std::vector<double> ku, kv;
    std::vector<int> mu, mv;
    distinct(s.knots_u, ku, mu);
    distinct(s.knots_v, kv, mv);
    TColStd_Array1OfReal uk(1, static_cast<int>(ku.size())), vk(1, static_cast<int>(kv.size()));
    TColStd_Array1OfInteger um(1, static_cast<int>(mu.size())), vm(1, static_cast<int>(mv.size()));
    for (size_t k = 0; k < ku.size(); ++k) {
        uk.SetValue(static_cast<int>(k) + 1, ku[k]);
        um.SetValue(static_cast<int>(k) + 1, mu[k]);
    }
    for (size_t k = 0; k < kv.size(); ++k) {
        vk.SetValue(static_cast<int>(k) + 1, kv[k]);
        vm.SetValue(static_cast<int>(k) + 1, mv[k]);
    }
    impl_->surface =
        new Geom_BSplineSurface(poles, weights, uk, vk, um, vm, s.degree_u, s.degree_v);
    impl_->adaptor.Load(impl_->surface);
}

OcctGrid::~OcctGrid() = default;

void OcctGrid::positions(const std::vector<double>& t, double* out) const {
    const GeomAdaptor_Surface& a = impl_->adaptor;
    gp_Pnt p;
    for (double u : t)
        for (double v : t) {
            a.D0(u, v, p);
            out[0] = p.X();
            out[1] = p.Y();
            out[2] = p.Z();
            out += 3;
        }
}

void OcctGrid::normals(const std::vector<double>& t, double* pos, double* nrm) const {
    const GeomAdaptor_Surface& a = impl_->adaptor;
    gp_Pnt p;
    gp_Vec du, dv;
    for (double u : t)
        for (double v : t) {
            a.D1(u, v, p, du, dv);
            const gp_Vec n = du.Crossed(dv);
            const double len = n.Magnitude();
            pos[0] = p.X();
            pos[1] = p.Y();
            pos[2] = p.Z();
            nrm[0] = len > 0 ? n.X() / len : 0;
            nrm[1] = len > 0 ? n.Y() / len : 0;
            nrm[2] = len > 0 ? n.Z() / len : 0;
            pos += 3;
            nrm += 3;
        }
}

} // namespace isoparm::bench
