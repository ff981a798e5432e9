// Shared subexpressions (Program::share_subexpressions): fewer instructions run, the same bits
// from every evaluator and the same meshes as computing every occurrence again.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/geom/implicit/polygonize.hpp"

namespace isoparm::geom::implicit {
namespace {

template <class T> bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

struct Surface {
    std::string text;
    std::vector<std::string> names;
    std::vector<double> values;
    glm::dvec3 lo, hi;
    double cell;
};

// The implicit gallery's six surfaces (assets/scenes/implicit-gallery.json) at twice its cells,
// and expressions that reach every instruction, NaN, infinities and signed zeros included.
const std::vector<Surface>& surfaces() {
    static const std::vector<Surface> all = {
        {"(x + 4)^2 + (y - 2)^2 + z^2 - r^2",
         {"r"},
         {1.0},
         {-5.25, 0.75, -1.25},
         {-2.75, 3.25, 1.25},
         0.1},
        {"((x/0.9)^2 + ((y - 2)/0.9)^2 + (z/0.9)^2 + R^2 - r^2)^2 - 4*R^2*((x/0.9)^2 + "
         "((y - 2)/0.9)^2)",
         {"R", "r"},
         {1.0, 0.4},
         {-1.35, 0.65, -0.54},
         {1.35, 3.35, 0.54},
         0.054},
        {"((x - 4)/2.4)^2*((y - 2)/2.4)^2 + ((y - 2)/2.4)^2*(z/2.4)^2 + (z/2.4)^2*((x - 4)/2.4)^2 "
         "- r^2*((x - 4)/2.4)*((y - 2)/2.4)*(z/2.4)",
         {"r"},
         {1.0},
         {2.56, 0.56, -1.44},
         {5.44, 3.44, 1.44},
         0.072},
        {"81*(((x + 4)/1.3)^3 + ((y + 2)/1.3)^3 + (z/1.3)^3) - 189*(((x + 4)/1.3)^2*((y + 2)/1.3) "
         "+ ((x + 4)/1.3)^2*(z/1.3) + ((y + 2)/1.3)^2*((x + 4)/1.3) + ((y + 2)/1.3)^2*(z/1.3) + "
         "(z/1.3)^2*((x + 4)/1.3) + (z/1.3)^2*((y + 2)/1.3)) + 54*((x + 4)/1.3)*((y + 2)/1.3)*"
         "(z/1.3) + 126*(((x + 4)/1.3)*((y + 2)/1.3) + ((x + 4)/1.3)*(z/1.3) + ((y + 2)/1.3)*"
         "(z/1.3)) - 9*(((x + 4)/1.3)^2 + ((y + 2)/1.3)^2 + (z/1.3)^2) - 9*(((x + 4)/1.3) + "
         "((y + 2)/1.3) + (z/1.3)) + 1",
         {},
         {},
         {-5.3, -3.3, -1.3},
         {-2.7, -0.7, 1.3},
         0.065},
        {"(x^2 + 9/4*(y + 2)^2 + z^2 - 1)^3 - x^2*z^3 - 9/80*(y + 2)^2*z^3",
         {},
         {},
         {-1.4, -3.0, -1.4},
         {1.4, -1.0, 1.4},
         0.05},
        {"((x - 4)/0.5)^4 - 5*((x - 4)/0.5)^2 + ((y + 2)/0.5)^4 - 5*((y + 2)/0.5)^2 + (z/0.5)^4 - "
         "5*(z/0.5)^2 + c",
         {"c"},
         {11.8},
         {2.7, -3.3, -1.3},
         {5.3, -0.7, 1.3},
         0.06},
        {"sin(3*x)*cos(3*y) + sin(3*y)*cos(3*z) + sin(3*z)*cos(3*x) + 0.1*sin(3*x)*cos(3*y)",
         {},
         {},
         {-1.5, -1.5, -1.5},
         {1.5, 1.5, 1.5},
         0.1},
        {"sqrt(x^2 + y^2) - 0.6 + abs(z)^1.5 + exp(-x^2) - exp(-x^2) + log(abs(y) + 1)*0 + "
         "tan(0.1*z)*sqrt(x^2 + y^2)*0.01",
         {},
         {},
         {-1, -1, -1},
         {1, 1, 1},
         0.08},
        {"(x - y)^2 + (x - y)^(z + 2)*0 + 1/(x - y) * 0 + (x^2 + y^2 + z^2)^0.5 - 0.7 + "
         "(x^2 + y^2 + z^2)*0",
         {},
         {},
         {-1, -1, -1},
         {1, 1, 1},
         0.0625},
    };
    return all;
}

Program compiled(const Surface& s, bool sharing) {
    Program p = std::move(compile(s.text, s.names)).value();
    p.share_subexpressions(sharing);
    return p;
}

TEST(ImplicitSharing, RepeatsRunOnce) {
    // The torus repeats (x/0.9)^2 and ((y - 2)/0.9)^2; the Clebsch cubic its scaled
    // coordinates, about a third of its instructions.
    const Program torus = compiled(surfaces()[1], true);
    EXPECT_LT(torus.shared_instruction_count(), torus.instruction_count());
    const Program clebsch = compiled(surfaces()[3], true);
    EXPECT_LT(3 * clebsch.shared_instruction_count(), 2 * clebsch.instruction_count());
    // Nothing repeats in a sphere: the same code.
    const Program sphere = compiled(surfaces()[0], true);
    EXPECT_EQ(sphere.shared_instruction_count(), sphere.instruction_count());
}

TEST(ImplicitSharing, EveryEvaluatorGivesTheSameBits) {
    std::mt19937_64 rng(38);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (const Surface& s : surfaces()) {
        const Program shared = compiled(s, true), plain = compiled(s, false);
        const double* pv = s.values.empty() ? nullptr : s.values.data();
        std::vector<glm::dvec3> points, directions;
        for (int k = 0; k < 300; ++k) {
            points.emplace_back(u(rng), u(rng), u(rng));
            directions.emplace_back(u(rng), u(rng), u(rng));
        }
        points.emplace_back(0.0, 0.0, 0.0); // 1/(x - y), log(0), 0^0.5: NaN and infinities
        directions.emplace_back(1.0, -1.0, 0.0);
        for (std::size_t k = 0; k < points.size(); ++k) {
            EXPECT_TRUE(same_bits(shared.value(points[k], pv), plain.value(points[k], pv)))
                << s.text;
            glm::dvec3 ga, gb;
            double da = 0, db = 0;
            EXPECT_TRUE(same_bits(shared.value_and_gradient(points[k], ga, pv),
                                  plain.value_and_gradient(points[k], gb, pv)));
            EXPECT_TRUE(std::memcmp(&ga, &gb, sizeof ga) == 0) << s.text;
            EXPECT_TRUE(same_bits(shared.value_and_derivative(points[k], directions[k], da, pv),
                                  plain.value_and_derivative(points[k], directions[k], db, pv)));
            EXPECT_TRUE(same_bits(da, db)) << s.text;
        }
        const std::size_t n = points.size();
        std::vector<double> va(n), vb(n), sa(n), sb(n), scratch;
        std::vector<glm::dvec3> gra(n), grb(n);
        shared.values_and_derivatives(points.data(), directions.data(), n, va.data(), sa.data(), pv,
                                      scratch);
        plain.values_and_derivatives(points.data(), directions.data(), n, vb.data(), sb.data(), pv,
                                     scratch);
        EXPECT_TRUE(same_bits(va, vb) && same_bits(sa, sb)) << s.text;
        shared.values_and_gradients(points.data(), n, va.data(), gra.data(), pv, scratch);
        plain.values_and_gradients(points.data(), n, vb.data(), grb.data(), pv, scratch);
        EXPECT_TRUE(same_bits(va, vb) && same_bits(gra, grb)) << s.text;
        std::vector<double> xs(n);
        for (std::size_t k = 0; k < n; ++k) xs[k] = points[k].x;
        shared.values_along_x(xs.data(), n, 0.25, 0.0, va.data(), pv, scratch);
        plain.values_along_x(xs.data(), n, 0.25, 0.0, vb.data(), pv, scratch);
        EXPECT_TRUE(same_bits(va, vb)) << s.text;
    }
}

TEST(ImplicitSharing, TheSameMeshes) {
    for (const Surface& s : surfaces()) {
        PolygonizeOptions o;
        o.lo = s.lo;
        o.hi = s.hi;
        o.cell = s.cell;
        o.parameters = s.values;
        auto a = polygonize(compiled(s, true), o);
        auto b = polygonize(compiled(s, false), o);
        ASSERT_TRUE(a.ok() && b.ok()) << s.text;
        EXPECT_FALSE(a->triangles.empty()) << s.text;
        EXPECT_TRUE(same_bits(a->positions, b->positions)) << s.text;
        EXPECT_TRUE(same_bits(a->normals, b->normals)) << s.text;
        EXPECT_TRUE(same_bits(a->triangles, b->triangles)) << s.text;
    }
}

} // namespace
} // namespace isoparm::geom::implicit
