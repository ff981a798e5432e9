// LeakSanitizer reports after main returns, when glfwTerminate has already unloaded the GL
// driver (libGL, libGLX_mesa, swrast_dri): a driver's leak then has no library name, so
// tests/lsan.supp cannot tell it from ours and every window test fails on Mesa's driconf
// strings. Under AddressSanitizer this keeps every library loaded so far mapped to the end;
// elsewhere it does nothing.
#pragma once

namespace isoparm::app {

void keep_libraries_loaded_for_leak_reports();

} // namespace isoparm::app
