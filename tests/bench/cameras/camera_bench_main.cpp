// vem_camera_bench: the latency from a camera backend handing over a frame to vemd's lights, per
// backend path, each against its fake (camera_latency.h). Writes a markdown section for
// docs/BENCHMARKS.md (the `bench` target includes it) and prints it.
//
//   vem_camera_bench [--frames N] [--report FILE.md]
//
// The Aravis path opens a fake GigE Vision camera on 127.0.0.1: run this only inside its own
// network namespace (the `bench` target does: unshare -n), never on a machine's real network.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "bench/cameras/camera_latency.h"
#include "bench/markdown_output.h"
#include "bench/measurements.h"

namespace {

using vem::bench::quantile;

std::string report(const std::vector<vem::bench::LatencyRun>& runs, int frames) {
  std::string md = fmt::format(
      "## Camera backends: frame to lights\n\n"
      "`vem_camera_bench --frames {}` (run by the `bench` target inside its own network namespace): "
      "each backend path delivers 1280x1024 Mono16 frames of the synthetic sky from its fake "
      "camera through the real backend code, and vemd's pipeline (1024x256 map, 1024 lights, "
      "Paper9 filter, no clustering) turns each into lights on the same thread. Latency from the "
      "backend handing the frame over (`arrivalNs`) to the lights being ready, microseconds.\n\n"
      "| path | frames | median | p99 | max | lost | notes |\n|---|---:|---:|---:|---:|---:|---|\n",
      frames);
  for (const auto& run : runs) {
    if (!run.error.empty()) {
      md += fmt::format("| {} | - | - | - | - | - | did not run: {} |\n", run.path, run.error);
      continue;
    }
    md += fmt::format("| {} | {} | {:.0f} | {:.0f} | {:.0f} | {} | {} |\n", run.path,
                      run.latencyUs.size(), quantile(run.latencyUs, 0.5),
                      quantile(run.latencyUs, 0.99),
                      run.latencyUs.empty() ? 0.0 : std::ranges::max(run.latencyUs),
                      run.framesLost, run.notes);
  }
  return md;
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 200;
  std::string reportPath;
  CLI::App app{"Latency from a frame handed over by each camera backend (against its fake) to lights"};
  app.add_option("--frames", frames, "Frames measured per backend")->check(CLI::Range(10, 1000000));
  app.add_option("--report", reportPath, "Also write the markdown section to this file");
  CLI11_PARSE(app, argc, argv);
  std::vector<vem::bench::LatencyRun> runs;
  runs.push_back(vem::bench::benchAravisFakeCamera(frames));
  runs.push_back(vem::bench::benchV4l2FakeDevice(frames));
  runs.push_back(vem::bench::benchLibcameraFakeCamera(frames));
  if (!vem::bench::emitMarkdown("vem_camera_bench", report(runs, frames), reportPath)) return 1;
  return 0;
}
