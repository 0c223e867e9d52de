// Camera-path latency benchmarks (vem_camera_bench, docs/BENCHMARKS.md): for each backend path, a
// fake camera delivers 1280 x 1024 Mono16 frames of the synthetic sky through the real backend
// code (the Aravis fake GigE Vision camera over 127.0.0.1 inside a network namespace; the V4L2 and
// libcamera fakes behind their thin interfaces), and vemd's pipeline (1024 x 256 map, 1024
// lights, Paper9 filter, no clustering) turns each into lights on the same thread.
//
// Latency per frame, microseconds: from CapturedFrame::arrivalNs (the backend handed the frame
// over, CLOCK_MONOTONIC) to the pipeline's lights being ready. Each function runs `frames` frames
// after a short warm-up and returns every sample; vem_camera_bench reports median and p99.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "frames/frame_source.h"
#include "vemd/pipeline.h"

namespace vem::bench {

struct LatencyRun {
  std::string path;   // "aravis (fake GigE Vision camera, 127.0.0.1)", ...
  std::string notes;  // anything a reader needs: buffers, packet size, conversions
  std::vector<double> latencyUs;  // one per frame that made lights
  std::uint64_t framesLost = 0;   // incomplete, dropped or bad frames the backend counted
  std::string error;              // non-empty when the path could not run (the reason)
};

// The pipeline every camera path is measured with: 1024 x 256 polar map, 1024 lights, Paper9
// filter, no clustering.
[[nodiscard]] vem::ProcessingOptions cameraBenchProcessing();

// The measured loop all paths share: takes warmUpFrames + frames frames from `source`, makes lights
// with `pipeline` on this thread, recycles each frame and appends the latency of the last `frames`
// to run.latencyUs. Stops with run.error set at a lost device (NoDevice), after 20 source errors in
// a row, or at a frame the pipeline refuses.
void measureFrameToLights(vem::FrameSource& source, vemd::Pipeline& pipeline, int warmUpFrames,
                          int frames, LatencyRun& run);

[[nodiscard]] LatencyRun benchAravisFakeCamera(int frames);     // cameras/camera_bench_aravis.cpp
[[nodiscard]] LatencyRun benchV4l2FakeDevice(int frames);       // cameras/camera_bench_v4l2.cpp
[[nodiscard]] LatencyRun benchLibcameraFakeCamera(int frames);  // cameras/camera_bench_libcamera.cpp

}  // namespace vem::bench
