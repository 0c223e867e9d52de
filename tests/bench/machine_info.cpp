#include "machine_info.h"

#include <fstream>
#include <thread>

#include <fmt/format.h>

namespace vem::bench {

std::string machineDescription() {
  std::ifstream in("/proc/cpuinfo");
  std::string model = "unknown CPU";
  bool virtualMachine = false;
  bool modelFound = false;
  for (std::string line; std::getline(in, line);) {
    if (!modelFound && line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      modelFound = true;
    }
    if (line.rfind("flags", 0) == 0 && line.find(" hypervisor") != std::string::npos) {
      virtualMachine = true;
    }
  }
  return fmt::format("{}, {} hardware threads{}", model, std::thread::hardware_concurrency(),
                     virtualMachine ? ", a virtual machine" : "");
}

}  // namespace vem::bench
