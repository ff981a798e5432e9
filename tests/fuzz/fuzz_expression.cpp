// libFuzzer target: any bytes as an implicit-surface expression; compiled programs are
// evaluated with their gradient at a few points.
#include <cstddef>
#include <cstdint>
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
    glm::dvec3 gradient;
    for (const glm::dvec3 p : {glm::dvec3(0.1, 0.2, 0.3), glm::dvec3(-1, 0, 2), glm::dvec3(0)})
        (void)program->value_and_gradient(p, gradient, params);
    return 0;
}
