// vemview: draws a scene lit by the lights vemd streams (or a light file, or a map file), with
// shadows from many lights; in a window, or headless into PNG and EXR frames (docs/vemview.md).
#include <cstdlib>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "client/vemview/viewer_loop.h"
#include "client/vemview/viewer_options.h"

int main(int argc, char** argv) {
  // Diagnostics go to stderr, one line each: "vemview: error: ...".
  auto logger = spdlog::stderr_color_st("vemview");
  logger->set_pattern("vemview: %^%l%$: %v");
  spdlog::set_default_logger(logger);
  auto options = vem::view::parseViewerOptions(argc, argv);
  if (!options) {
    return options.error();
  }
  return vem::view::runViewer(*options);
}
