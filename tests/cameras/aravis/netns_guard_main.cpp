// main() of vem_aravis_tests: refuses to run (exit 1, loudly) when any network interface but
// loopback is up, so the tests (Aravis's fake camera, device discovery) can never broadcast on a
// real network. CTest runs the binary through run_in_netns.sh, which gives it a namespace with
// loopback alone.
#include <cstdio>

#include <gtest/gtest.h>

#include "support/network_namespace.h"

int main(int argc, char** argv) {
  if (const auto up = vem::testing::nonLoopbackInterfacesUp(); !up.empty()) {
    std::fprintf(stderr,
                 "vem_aravis_tests: REFUSING TO RUN: network interface %s is up. These tests start "
                 "GigE Vision cameras and discovery; run them in a namespace with loopback only: "
                 "tests/support/run_in_netns.sh %s (ctest does).\n",
                 up.begin()->c_str(), argv[0]);
    return 1;
  }
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
