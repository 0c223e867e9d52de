// The machine a benchmark ran on, in one line for its report: the CPU model of /proc/cpuinfo, the
// hardware threads, and whether it is a virtual machine (the "hypervisor" CPU flag). Every report
// (vem_bench's header, vem_render_bench's study) names the machine through this one function.
#pragma once

#include <string>

namespace vem::bench {

// "AMD EPYC, 2 hardware threads, a virtual machine".
[[nodiscard]] std::string machineDescription();

}  // namespace vem::bench
