#include "ui/view/control_net.hpp"

namespace isoparm::ui {

int ControlNet::find(int i, int j) const {
    for (std::size_t k = 0; k < ids.size(); ++k)
        if (ids[k] == std::pair(i, j)) return static_cast<int>(k);
    return -1;
}

namespace {

ControlNet surface_net(const geom::Surface& s) {
    ControlNet net;
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) {
            net.ids.emplace_back(i, j);
            net.points.push_back(s.point(i, j));
        }
    auto at = [&](int i, int j) { return i * s.n_v + j; };
    for (int i = 0; i < s.n_u; ++i) {
        std::vector<int>& row = net.lines.emplace_back();
        for (int j = 0; j < s.n_v; ++j) row.push_back(at(i, j));
    }
    for (int j = 0; j < s.n_v; ++j) {
        std::vector<int>& column = net.lines.emplace_back();
        for (int i = 0; i < s.n_u; ++i) column.push_back(at(i, j));
    }
    return net;
}

ControlNet triangle_net(const geom::TrianglePatch& t) {
    ControlNet net;
    const int n = t.degree;
    // In the patch's own order: point (i, j) is at TrianglePatch::index(n, i, j).
    net.points = t.points;
    net.ids.resize(t.points.size());
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j)
            net.ids[static_cast<std::size_t>(geom::TrianglePatch::index(n, i, j))] = {i, j};
    auto at = [n](int i, int j) { return geom::TrianglePatch::index(n, i, j); };
    for (int c = 0; c < n; ++c) { // a line of c + 1 .. n + 1 points: c = 0 is an edge
        std::vector<int>& i_const = net.lines.emplace_back();
        for (int j = 0; j <= n - c; ++j) i_const.push_back(at(c, j));
        std::vector<int>& j_const = net.lines.emplace_back();
        for (int i = 0; i <= n - c; ++i) j_const.push_back(at(i, c));
        std::vector<int>& k_const = net.lines.emplace_back();
        for (int i = 0; i <= n - c; ++i) k_const.push_back(at(i, n - c - i));
    }
    return net;
}

ControlNet curve_net(const geom::Curve& c) {
    ControlNet net;
    std::vector<int>& polygon = net.lines.emplace_back();
    for (int i = 0; i < c.count(); ++i) {
        net.ids.emplace_back(i, -1);
        net.points.push_back(c.points[static_cast<std::size_t>(i)]);
        polygon.push_back(i);
    }
    return net;
}

} // namespace

ControlNet control_net_of(const doc::Object& o) {
    if (const geom::Surface* s = o.surface()) return surface_net(*s);
    if (const geom::TrianglePatch* t = o.triangle()) return triangle_net(*t);
    if (const geom::Curve* c = o.curve()) return curve_net(*c);
    return {};
}

} // namespace isoparm::ui
