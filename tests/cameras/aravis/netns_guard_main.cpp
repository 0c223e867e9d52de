// main() of vem_aravis_tests: refuses to run (exit 1, loudly) when any network interface but
// loopback is up, so the tests (Aravis's fake camera, device discovery) can never broadcast on a
// real network. CTest runs the binary through run_in_netns.sh, which gives it a namespace with
// loopback alone.
#include <ifaddrs.h>
#include <net/if.h>

#include <cstdio>
#include <set>
#include <string>

#include <gtest/gtest.h>

namespace {

std::set<std::string> nonLoopbackInterfacesUp() {
  std::set<std::string> up;
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return {"(getifaddrs failed)"};
  for (ifaddrs* i = list; i != nullptr; i = i->ifa_next) {
    if ((i->ifa_flags & IFF_UP) != 0 && (i->ifa_flags & IFF_LOOPBACK) == 0) up.insert(i->ifa_name);
  }
  freeifaddrs(list);
  return up;
}

}  // namespace

int main(int argc, char** argv) {
  if (const auto up = nonLoopbackInterfacesUp(); !up.empty()) {
    std::fprintf(stderr,
                 "vem_aravis_tests: REFUSING TO RUN: network interface %s is up. These tests start "
                 "GigE Vision cameras and discovery; run them in a namespace with loopback only: "
                 "tests/cameras/aravis/run_in_netns.sh %s (ctest does).\n",
                 up.begin()->c_str(), argv[0]);
    return 1;
  }
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
