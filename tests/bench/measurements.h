// Small measuring helpers shared by the benchmark programs: a quantile of samples, now on
// CLOCK_REALTIME (to compare with the stream's publish_unix_ns), and the CPU
// time a process has used so far (all its threads, user + system, from /proc/PID/stat) and the
// whole machine (/proc/stat), which the stream and MQTT benchmarks read before and after a window
// to tell who used the shared cores. CPU times come in clock ticks (10 ms at USER_HZ 100).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <vector>

namespace vem::bench {

// The q-quantile (0..1) of `values`, linearly interpolated; 0 when empty.
[[nodiscard]] double quantile(std::vector<double> values, double q);

// Now on CLOCK_REALTIME, in nanoseconds since the Unix epoch.
[[nodiscard]] std::int64_t realtimeNs();

// The CPU time the whole machine has been busy so far, all cores together, in ms (user, nice,
// system, irq and softirq of /proc/stat: what no process's own figure shows, such as the
// kernel's loopback work in softirq); 0 when it cannot be read.
[[nodiscard]] double machineBusyMs();

// The CPU time `pid` has used so far (utime + stime of all its threads) in ms; 0 when
// /proc/PID/stat cannot be read (the process is gone).
[[nodiscard]] double processCpuMs(pid_t pid);

}  // namespace vem::bench
