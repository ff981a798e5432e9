// The work budget (core/geom/work_budget.hpp) applied to showing a scene: a scene whose surfaces
// would take minutes to tessellate or gigabytes to hold is refused when it is loaded, by
// `isoparm render` and by the window alike, with the same sentence.
#pragma once

#include <string>
#include <vector>

#include "core/doc/document.hpp"

namespace isoparm::ui {

// Memory the renderer holds per displayed vertex (tessellation in doubles, its interleaved
// float copy, triangle and wire indices, the driver's copy of the buffers), measured: a
// 250-patch scene of 16,384-vertex surfaces at ~11 MB per surface.
inline constexpr double display_bytes_per_vertex = 700;
// Memory the renderer holds per surface whatever its size (buffers, vertex arrays).
inline constexpr double display_bytes_per_surface = 64 * 1024;
// Per control point shown (its sprite, label, net lines and the panels listing it), measured:
// a 300 x 300 net costs ~280 MB and ~3.5 s more than the same scene without points and net;
// a 600 x 600 one (a 8.5 MB scene) took 13 s and 0.96 GB. Counted whether or not the scene
// shows them now: the window can turn them on with one key.
inline constexpr double display_bytes_per_control_point = 3072;
inline constexpr double display_steps_per_control_point = 3500;

// Points evaluated per curve when the workstation shows it (the 3D view's polyline of 200, the
// curve designer's and the basis plot's), each costing a de Boor evaluation of its degree:
// measured, a degree-4095 curve scene took 108 s to render when only its control points were
// counted.
inline constexpr double display_curve_evaluations = 3 * 200;

struct SceneDisplayCost {
    int surfaces = 0;
    double control_points = 0; // of surfaces and curves
    double vertices = 0;       // displayed tessellation vertices, all surfaces
    double steps = 0;          // basis steps to tessellate them (the protocol's estimate)
    double bytes = 0;          // memory to hold them
};

SceneDisplayCost estimate_scene_display(const doc::Document& d);
// The same at another display density, with `added` objects beside the document's own (an
// import checked before it is carried out).
SceneDisplayCost estimate_scene_display(const doc::Document& d, int density,
                                        const std::vector<doc::Object>& added = {});

// "" when the scene fits the budget, else one sentence naming the scene's size and the budget.
std::string scene_over_budget(const doc::Document& d);
// The same at `density` with `added` objects beside the document's own.
std::string scene_over_budget(const doc::Document& d, int density,
                              const std::vector<doc::Object>& added);

// The largest display density, at most the scene's own, at which it fits the budget with the
// `added` objects (256, 192, 128, 96, 64, 48, 32, 24, 16, 12, 8, 6, 4, 3, 2 are tried), or 0
// when it does not fit even at 2: what an import sets so that the scene it writes (or adds to)
// can be shown (an imported 1,018-face part needed about 1,900 MiB at the default 32).
int display_density_that_fits(const doc::Document& d, const std::vector<doc::Object>& added = {});

// Address space the OpenGL driver (Mesa's llvmpipe: its threads, code and buffers) takes when
// a headless context is created, measured: below ~750 MiB of `ulimit -v` even a one-patch
// scene fails inside the driver.
inline constexpr double display_driver_bytes = 768.0 * (1 << 20);

// "" when the address-space limit (`ulimit -v`, RLIMIT_AS) leaves room for this process as it
// is now, plus `driver_bytes` still to come, plus the scene's display; else one sentence.
// Why check first: the driver allocates with malloc and crashes (SIGSEGV, SIGABRT) when that
// fails, so running out inside it cannot be turned into an error afterwards.
std::string memory_limit_problem(const doc::Document& d, double driver_bytes);

} // namespace isoparm::ui
