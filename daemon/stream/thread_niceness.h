// Thread niceness: the stream's threads yield to capture and processing. On Linux a thread's nice
// value is its own (setpriority on its thread id), and raising it needs no privilege. vemd's capture
// and processing threads keep nice 0; the stream server's io thread runs at kIoThreadNice (clients
// are served when capture and processing leave a core free) and the cube-map worker at
// kCubemapWorkerNice below that. When both cores are busy, a client's work waits, never a frame.
#pragma once

#include <sys/resource.h>
#include <unistd.h>

namespace vem::stream {

inline constexpr int kIoThreadNice = 5;
inline constexpr int kCubemapWorkerNice = 10;

// Sets the calling thread's nice value; false when the system refused (the thread then keeps its
// priority, and nothing else changes).
inline bool setThisThreadNice(int nice) {
  return ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), nice) == 0;
}

}  // namespace vem::stream
