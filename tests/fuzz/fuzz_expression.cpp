// libFuzzer target: any bytes as an implicit-surface expression; compiled programs are
// evaluated with their gradient at a few points, and the batch forms must give the one-point
// calls' bits.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "core/geom/implicit/expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::vector<std::string> names{"a", "b", "c"};
    auto program = isoparm::geom::implicit::compile(text, names);
    if (!program.ok()) {
        if (program.error().message.empty()) __builtin_trap();
        return 0;
    }
    const double params[3] = {0.5, -1.25, 2.0};
    const glm::dvec3 points[3] = {glm::dvec3(0.1, 0.2, 0.3), glm::dvec3(-1, 0, 2), glm::dvec3(0)};
    const glm::dvec3 directions[3] = {glm::dvec3(1, 0, 0), glm::dvec3(0.5, -2, 0.25),
                                      glm::dvec3(0, 0, 0.05)};
    double values[3], derivatives[3], gradient_values[3];
    glm::dvec3 gradients[3];
    std::vector<double> scratch;
    program->values_and_derivatives(points, directions, 3, values, derivatives, params, scratch);
    program->values_and_gradients(points, 3, gradient_values, gradients, params, scratch);
    auto same = [](double a, double b) {
        return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
    };
    for (int k = 0; k < 3; ++k) {
        glm::dvec3 gradient;
        double derivative = 0;
        const double v = program->value_and_gradient(points[k], gradient, params);
        const double vd =
            program->value_and_derivative(points[k], directions[k], derivative, params);
        if (!same(v, gradient_values[k]) || !same(vd, values[k]) ||
            !same(derivative, derivatives[k]))
            __builtin_trap();
        for (int i = 0; i < 3; ++i)
            if (!same(gradient[i], gradients[k][i])) __builtin_trap();
    }
    return 0;
}
