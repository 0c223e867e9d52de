#include "support/network_namespace.h"

#include <ifaddrs.h>
#include <net/if.h>

namespace vem::testing {

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

}  // namespace vem::testing
