#include "bench/cameras/camera_latency.h"

#include <algorithm>
#include <utility>

namespace vem::bench {

vem::ProcessingOptions cameraBenchProcessing() {
  vem::ProcessingOptions options;
  options.mapWidth = 1024;
  options.mapHeight = 256;
  options.lightCount = 1024;
  options.filter = FilterPreset::Paper9;
  options.clustering = false;
  return options;
}

void measureFrameToLights(vem::FrameSource& source, vemd::Pipeline& pipeline, int warmUpFrames,
                          int frames, LatencyRun& run) {
  constexpr int kMaxErrorsInARow = 20;
  run.latencyUs.reserve(run.latencyUs.size() + std::size_t(std::max(frames, 0)));
  int errorsInARow = 0;
  for (int taken = 0; taken < warmUpFrames + frames;) {
    auto captured = source.next();
    if (!captured) {
      if (captured.error().cause == vem::SourceErrorCause::NoDevice ||
          ++errorsInARow >= kMaxErrorsInARow) {
        run.error = captured.error().message;
        return;
      }
      continue;
    }
    errorsInARow = 0;
    if (auto problem = pipeline.frameProblem(captured->frame)) {
      run.error = *problem;
      return;
    }
    (void)pipeline.process(*captured);
    const std::int64_t readyNs = vem::monotonicNowNs();
    if (taken >= warmUpFrames) run.latencyUs.push_back(double(readyNs - captured->arrivalNs) / 1e3);
    source.recycle(std::move(*captured));
    ++taken;
  }
}

}  // namespace vem::bench
