// Keeps every shared library loaded so far in memory until the process ends.
//
// Called once the GL context exists, so the GL driver it loaded (Mesa's swrast_dri.so under
// Xvfb) outlives glfwTerminate. The driver keeps pointers to blocks it allocated in its own
// static data; once dlclose unmapped it, LeakSanitizer could no longer see them and reported
// them at exit (240 bytes in 3 blocks) although nothing was lost. Nothing is hidden from the
// leak check this way: the driver's memory is simply still reachable, as it is while running.
#pragma once

namespace upf::viewer {

void pin_loaded_libraries();

}  // namespace upf::viewer
