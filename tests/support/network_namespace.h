// Which network interfaces other than loopback are up. Tests that listen beyond 127.0.0.1 or that
// broadcast (Aravis discovery) run only where the answer is none: inside a network namespace of
// their own with loopback alone (tests/support/run_in_netns.sh, which ctest uses for them).
#pragma once

#include <set>
#include <string>

namespace vem::testing {

// Names of the interfaces that are up and not loopback; {"(getifaddrs failed)"} when unknown.
[[nodiscard]] std::set<std::string> nonLoopbackInterfacesUp();

}  // namespace vem::testing
