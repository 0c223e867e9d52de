// The vemview loop, reading like its data flow:
//   input frame -> plan's frame decision -> shading lights -> renderer -> tone mapping -> window /
//   files, with the status line and the adaptive light count beside it.
// Returns the process exit code; every failure is one sentence on stderr.
#pragma once

#include "client/vemview/viewer_options.h"

namespace vem::view {

[[nodiscard]] int runViewer(const ViewerOptions& options);

}  // namespace vem::view
