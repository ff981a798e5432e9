// Scene display cost against the work budget (see scene_budget.hpp).
#include "ui/view/scene_budget.hpp"

#include <fstream>
#include <sys/resource.h>
#include <unistd.h>
#include <variant>

#include "core/geom/work_budget.hpp"
#include "ui/view/tessellation_sampling.hpp"

namespace isoparm::ui {

SceneDisplayCost estimate_scene_display(const doc::Document& d) {
    return estimate_scene_display(d, d.view.display.density);
}

namespace {

void add_surface_cost(const geom::Surface& surface, int density, SceneDisplayCost& cost);

void add_object_cost(const doc::Object& o, int density, SceneDisplayCost& cost) {
    cost.control_points += static_cast<double>(doc::control_points_of(o.shape).size());
    // Surfaces' meshes and curves' polylines; implicit and triangle meshes have their own
    // budgets (polygonizer, degree cap).
    std::visit(doc::overloaded{
                   [&](const doc::SurfaceObject& s) { add_surface_cost(s.surface, density, cost); },
                   [&](const doc::CurveObject& c) {
                       cost.steps += geom::estimate_curve_evaluation(display_curve_evaluations,
                                                                     c.curve.degree, 0)
                                         .steps;
                   },
                   [](const doc::ImplicitObject&) {},
                   [](const doc::TriangleObject&) {},
               },
               o.shape);
}

void add_surface_cost(const geom::Surface& surface, int density, SceneDisplayCost& cost) {
    const geom::Surface* s = &surface;
    const auto [su, sv] = display_samples(*s, density);
    const double vertices = static_cast<double>(su) * sv;
    ++cost.surfaces;
    cost.vertices += vertices;
    cost.steps += geom::estimate_tessellation(su, sv, s->degree_u, s->degree_v).steps;
    cost.bytes += vertices * display_bytes_per_vertex + display_bytes_per_surface;
}

} // namespace

SceneDisplayCost estimate_scene_display(const doc::Document& d, int density,
                                        const std::vector<doc::Object>& added) {
    SceneDisplayCost cost;
    for (const doc::Object& o : d.objects) add_object_cost(o, density, cost);
    for (const doc::Object& o : added) add_object_cost(o, density, cost);
    cost.steps += cost.control_points * display_steps_per_control_point;
    cost.bytes += cost.control_points * display_bytes_per_control_point;
    return cost;
}

namespace {

double max_display_bytes() {
    return geom::max_answer_numbers * geom::bytes_per_answer_number;
}

bool fits(const SceneDisplayCost& cost) {
    return cost.bytes <= max_display_bytes() && cost.steps <= geom::max_work_steps;
}

} // namespace

std::string scene_over_budget(const doc::Document& d) {
    return scene_over_budget(d, d.view.display.density, {});
}

std::string scene_over_budget(const doc::Document& d, int density,
                              const std::vector<doc::Object>& added) {
    const SceneDisplayCost cost = estimate_scene_display(d, density, added);
    if (fits(cost)) return "";
    const double max_bytes = max_display_bytes();
    const double mib = cost.bytes / (1 << 20);
    return "the scene is too large to show: its " + std::to_string(cost.surfaces) +
           " surfaces make " + geom::with_thousands(cost.vertices) + " vertices and " +
           geom::with_thousands(cost.control_points) + " control points, which would need about " +
           geom::with_thousands(mib) + " MiB and " + geom::with_thousands(cost.steps) +
           " basis steps; the work budget allows about " +
           geom::with_thousands(max_bytes / (1 << 20)) + " MiB and " +
           geom::with_thousands(geom::max_work_steps) +
           " steps (about 10 s); a lower display density, fewer surfaces, fewer control points "
           "or lower degrees fit";
}

int display_density_that_fits(const doc::Document& d, const std::vector<doc::Object>& added) {
    for (int density : {256, 192, 128, 96, 64, 48, 32, 24, 16, 12, 8, 6, 4, 3, 2})
        if (density <= d.view.display.density && fits(estimate_scene_display(d, density, added)))
            return density;
    return 0;
}

namespace {

// The address space this process uses now (VmSize), in bytes; 0 when unknown.
double address_space_in_use() {
    std::ifstream statm("/proc/self/statm");
    double pages = 0;
    if (!(statm >> pages)) return 0;
    return pages * static_cast<double>(::sysconf(_SC_PAGESIZE));
}

} // namespace

std::string memory_limit_problem(const doc::Document& d, double driver_bytes) {
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return "";
    const double have = static_cast<double>(limit.rlim_cur);
    const double need = address_space_in_use() + driver_bytes + estimate_scene_display(d).bytes;
    if (need <= have) return "";
    const double mib = 1 << 20;
    return "not enough memory: the address-space limit (ulimit -v) is " +
           geom::with_thousands(have / mib) + " MiB, and showing this scene needs about " +
           geom::with_thousands(need / mib) + " MiB" +
           (driver_bytes > 0 ? " (the OpenGL driver takes about " +
                                   geom::with_thousands(driver_bytes / mib) + " of them)"
                             : std::string{});
}

} // namespace isoparm::ui
