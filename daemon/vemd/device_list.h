// The cameras every backend can see, for `vemd --list-devices`: one line per camera with the
// --source spec that opens it, its model and serial, then one indented line per mode
// ("Mono16 1280x1024"). A backend that cannot list (no permission, its library failing) gets one
// line saying why; the others are listed all the same.
//
// Aravis discovery broadcasts on every network interface of the machine (GigE Vision discovery);
// run it on a camera network, not on a network that must not see broadcasts.
#pragma once

#include <string>

namespace vem::vemd {

// The listing as text (ends with a newline); never fails.
[[nodiscard]] std::string deviceListText();

}  // namespace vem::vemd
