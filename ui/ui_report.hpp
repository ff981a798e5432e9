// Where things are on screen, for the GUI scenario tests (tests/ui/scenarios): when the
// environment variable ISOPARM_UI_REPORT names a file, each drawn frame that moved or showed
// anything new rewrites it (atomically) as JSON: the named rectangles of panels, menu labels,
// canvases and handles, in window pixels, plus a few facts of the document. A real window
// driven by xdotool then clicks where a person would. Without the variable nothing is
// recorded and nothing is written.
#pragma once

#include <string>
#include <vector>

namespace isoparm::ui {

struct AppContext;

bool ui_report_enabled();
// The rectangle of the last ImGui item (a menu label, a canvas, a button) under `name`.
void report_item(const std::string& name);
// A rectangle or a point (a draggable handle's centre) under `name`.
void report_rect(const std::string& name, float x, float y, float w, float h);
void report_point(const std::string& name, float x, float y);
// A number a panel shows (e.g. how many patch borders are kept), under "facts".
void report_fact(const std::string& name, double value);
// A tuple of numbers shown together (a barycentric (r, s, t)), as a JSON array under "facts".
void report_fact(const std::string& name, const std::vector<double>& values);
// At the end of a frame: writes the report when it differs from the last one written.
void flush_ui_report(const AppContext& ctx);

} // namespace isoparm::ui

namespace isoparm::ui {

// ImGui::BeginMenu and ImGui::MenuItem that also report their label's rectangle as
// "menu/<label>" (a scenario test opens a menu, then clicks an item, as a person does).
bool begin_menu(const char* label, bool enabled = true);
bool menu_item(const char* label, const char* shortcut = nullptr, bool selected = false,
               bool enabled = true);
bool menu_item(const char* label, const char* shortcut, bool* selected, bool enabled = true);

} // namespace isoparm::ui
