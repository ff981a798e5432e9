// The tracing square while a trim loop is drawn in it (Surface > Trim > Draw ...): a click adds
// a corner (a click on the first corner closes the loop) instead of moving the indicator, and
// the loop so far is drawn over the square with its closing edge to the pointer.
#pragma once

#include "core/doc/document.hpp"
#include "ui/app_context.hpp"
#include "ui/view/layout.hpp"

namespace isoparm::ui {

// Whether the square's clicks draw a loop on `obj` this frame; a drawing begun on another
// surface is abandoned (the selection moved on).
bool drawing_loop_on(AppContext& ctx, const doc::Object& obj);
// The click on the square (its button is the last item), `square` the whole domain in pixels.
void loop_drawing_click(AppContext& ctx, const doc::Object& obj, const Rect& square);
// The corners and edges drawn so far, over the square, clipped to `canvas`.
void draw_loop_in_progress(const AppContext& ctx, const doc::Object& obj, const Rect& square,
                           const Rect& canvas);

} // namespace isoparm::ui
