#include "vemd_benchmarks.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "calib/io/camera_file.h"
#include "recording/recording_writer.h"
#include "support/test_cameras.h"
#include "synth/sky_scene.h"
#include "synth/synthetic_camera.h"
#include "vemd/daemon_loop.h"
#include "vemd/pipeline_setup.h"
#include "vemd/replay_source.h"

namespace vem::bench {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 1280;
constexpr int kHeight = 1024;
constexpr int kFrames = 30;
// One benchmark iteration replays the recording three times over (--loop --frames 90): the
// start of a run (thread start, the first frame read before processing can begin, the code
// table) is then spread over more frames, as in a daemon that runs for hours.
constexpr int kFramesPerPass = 3 * kFrames;

std::map<std::string, double>& counters() {
  static std::map<std::string, double> last;
  return last;
}

// The test camera's 190-degree lens with a log response spread over 16-bit codes: eight decades
// from black 1024 to 65535, like the 12-bit sensor's but 16 times finer.
calib::CameraCalibration mono16Camera() {
  calib::CameraCalibration camera = testing::cameraTruth(kWidth, kHeight, 1);
  camera.camera.pixelFormat = {1, 16};
  calib::PhotometricCalibration& p = *camera.photometric;
  p.blackLevelCode = 1024.0;
  p.saturationCode = 65535.0;
  const double b = (65535.0 - 1024.0) / std::log(1e8);
  calib::LogResponse log;
  for (std::size_t c = 0; c < 3; ++c) {
    log.bCodePerLn[c] = b;
    log.aCode[c] = 1024.0 + b * std::log(1e3);  // 1e-3 cd/m^2 at the black level
  }
  p.response = log;
  return camera;
}

struct VemdFixture {
  fs::path dir;
  fs::path recording;
  std::string calibrationToml;

  VemdFixture() {
    const calib::CameraCalibration camera = mono16Camera();
    calibrationToml = calib::io::formatCameraFile(camera);
    dir = fs::temp_directory_path() / ("vem_bench_vemd_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    recording = dir / "sky-mono16.vem";
    recording::RecordingHeader header;
    header.cameraModel = camera.camera.model;
    header.cameraSerial = camera.camera.serial;
    header.sensorWidthPx = kWidth;
    header.sensorHeightPx = kHeight;
    header.pixelFormat = camera.camera.pixelFormat;
    header.nominalRateHz = 30.0;
    header.calibrationToml = calibrationToml;
    header.writerName = "vem_bench";
    auto writer = recording::RecordingWriter::create(recording, header, {.syncEveryFrames = 0});
    if (!writer) return;
    const synth::SkyScene scene;
    synth::SyntheticCamera synthetic(camera, {1, {16.0, 0.0, 1}});  // 1 code of 12 bits
    vem::RawFrame frame;
    for (int i = 0; i < kFrames; ++i) {
      synthetic.render(scene.at(i / 30.0), std::uint64_t(i), frame);
      if (!writer->append(std::uint64_t(i), i * 33'333'333LL, frame)) return;
    }
    (void)writer->close();
  }
  ~VemdFixture() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
  VemdFixture(const VemdFixture&) = delete;
  VemdFixture& operator=(const VemdFixture&) = delete;
};

vem::ProcessingOptions benchmarkProcessing() {
  vem::ProcessingOptions o;  // the defaults are the issue's: 1024 x 256, 1024 lights
  o.filter = FilterPreset::Paper9;
  o.clustering = true;
  o.clusterBudget = 72;
  return o;
}

// A replay source that also times its reads (capture thread).
class TimedReplay final : public vem::FrameSource {
 public:
  explicit TimedReplay(std::unique_ptr<vemd::ReplaySource> inner) : inner_(std::move(inner)) {}
  vem::SourceDescription describe() const override { return inner_->describe(); }
  std::expected<vem::CapturedFrame, vem::SourceError> next() override {
    const auto start = std::chrono::steady_clock::now();
    auto frame = inner_->next();
    if (frame) {
      readMicros_ +=
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
              .count();
      ++reads_;
    }
    return frame;
  }
  void recycle(vem::CapturedFrame&& spent) override { inner_->recycle(std::move(spent)); }
  void interrupt() override { inner_->interrupt(); }
  [[nodiscard]] double meanReadMicros() const { return reads_ > 0 ? readMicros_ / reads_ : 0.0; }

 private:
  std::unique_ptr<vemd::ReplaySource> inner_;
  double readMicros_ = 0.0;
  int reads_ = 0;
};

void replayMax(const std::shared_ptr<VemdFixture>& f, benchmark::State& state) {
  vemd::LoopOptions loop;
  loop.reportEveryS = 0.0;
  loop.maxFrames = kFramesPerPass;
  const std::atomic<bool> stop{false};
  std::map<std::string, double> stageSums;
  double readSum = 0.0;
  double loopSeconds = 0.0;
  std::uint64_t frames = 0;
  for (auto _ : state) {
    state.PauseTiming();
    // A fresh pipeline per pass: the replay starts again at seq 0, which the temporal filter of
    // the last pass would reject as stale (and skip filtering and clustering).
    auto pipeline =
        vemd::pipelineFromCameraFile(f->calibrationToml, "benchmark camera", benchmarkProcessing());
    if (!pipeline) return state.SkipWithError(pipeline.error().c_str());
    auto replay =
        vemd::ReplaySource::open(f->recording, {{vemd::SourceRate::Mode::Max, 0.0}, true});
    if (!replay) return state.SkipWithError(replay.error().message.c_str());
    TimedReplay source(std::move(*replay));
    vemd::SinkSet sinks;
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    const vemd::LoopResult result = vemd::runDaemonLoop(source, *pipeline, sinks, loop, stop);
    loopSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.PauseTiming();
    if (result.totals.processed != std::uint64_t(kFramesPerPass)) {
      return state.SkipWithError("the replay did not process every frame");
    }
    for (const vemd::StageStat& s : result.totals.stages) stageSums[s.stage] += s.micros.sum;
    readSum += source.meanReadMicros() * kFramesPerPass;
    frames += result.totals.processed;
    state.ResumeTiming();
  }
  state.SetItemsProcessed(std::int64_t(frames));
  auto& last = counters();
  last["frames_per_s"] = double(frames) / loopSeconds;
  state.counters["frames_per_s"] = benchmark::Counter(double(frames), benchmark::Counter::kIsRate);
  for (const auto& [stage, sum] : stageSums) {
    if (stage == "sinks") continue;
    state.counters["us_" + stage] = sum / double(frames);
    last["us_" + stage] = sum / double(frames);
  }
  state.counters["us_read"] = readSum / double(frames);
  last["us_read"] = readSum / double(frames);
  state.counters["file_bytes_per_frame"] = double(fs::file_size(f->recording)) / kFrames;
  last["file_bytes_per_frame"] = double(fs::file_size(f->recording)) / kFrames;
}

// The pipeline alone on frames already in memory, one thread, no capture thread beside it.
void pipelineOnly(const std::shared_ptr<VemdFixture>& f, benchmark::State& state) {
  auto replay = vemd::ReplaySource::open(f->recording, {{vemd::SourceRate::Mode::Max, 0.0}, false});
  if (!replay) return state.SkipWithError(replay.error().message.c_str());
  std::vector<vem::CapturedFrame> frames;
  while (auto frame = (*replay)->next()) frames.push_back(std::move(*frame));
  auto pipeline =
      vemd::pipelineFromCameraFile(f->calibrationToml, "benchmark camera", benchmarkProcessing());
  if (!pipeline || frames.empty()) return state.SkipWithError("no pipeline or no frames");
  std::map<std::string, double> sums;
  std::uint64_t seq = 0;
  for (auto _ : state) {
    vem::CapturedFrame& frame = frames[seq % frames.size()];
    frame.seq = seq++;
    const vem::ProcessedFrame& p = pipeline->process(frame);
    for (const vem::StageTiming& t : p.timings) sums[t.stage] += t.micros;
    benchmark::DoNotOptimize(p.lights.lights.data());
  }
  auto& last = counters();
  for (const auto& [stage, sum] : sums) {
    state.counters["us_" + stage] = sum / double(seq);
    last["alone_us_" + stage] = sum / double(seq);
  }
}

}  // namespace

const std::map<std::string, double>& vemdBenchmarkCounters() { return counters(); }

std::string vemdReportSection() {
  const auto& c = counters();
  const auto at = [&](const std::string& key) {
    const auto it = c.find(key);
    return it == c.end() ? std::nan("") : it->second;
  };
  const double fps = at("frames_per_s");
  std::string md = fmt::format(
      "## vemd replaying as fast as possible\n\n"
      "`vemd/replay_max_Mono16`: 30 synthetic 1280x1024 Mono16 frames (the sky scene through a "
      "190-degree log camera with read noise; {:.2f} MB per frame at zstd level 1) replayed three "
      "times over by vemd's own loop at `--rate max --loop --frames 90`: the capture thread reads "
      "and decompresses, one processing thread calibrates into a 1024x256 polar map, makes 1024 "
      "Havran lights, filters them (Paper9) and clusters them (Q = 72); no sinks. Microseconds "
      "per frame, mean over the run; \"alone\" is the pipeline on frames already in memory with "
      "no capture thread beside it (`vemd/pipeline_Mono16`), which cycles through the 30 frames "
      "(79 MB) in memory, whereas in the replay each frame has just been decompressed.\n\n"
      "| stage | in the replay | alone |\n|---|---:|---:|\n",
      at("file_bytes_per_frame") * 1e-6);
  for (const char* stage : {"read", "calibrate", "tables", "lights", "filter", "cluster"}) {
    const std::string key = std::string("us_") + stage;
    md += fmt::format("| {}{} | {:.0f} | {} |\n", stage,
                      std::string(stage) == "read" ? " (capture thread)" : "", at(key),
                      std::string(stage) == "read" ? std::string("-")
                                                   : fmt::format("{:.0f}", at("alone_" + key)));
  }
  md += fmt::format(
      "\nTarget: at least 300 frames/s including decompression with one processing thread: "
      "**{:.0f} frames/s, {}**.\n\n",
      fps, fps >= 300.0 ? "met" : "NOT met");
  return md;
}

void registerVemdBenchmarks() {
  spdlog::set_level(spdlog::level::warn);  // no report lines from every pass
  auto fixture = std::make_shared<VemdFixture>();
  benchmark::RegisterBenchmark("vemd/replay_max_Mono16",
                               [fixture](benchmark::State& s) { replayMax(fixture, s); })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->MeasureProcessCPUTime();
  benchmark::RegisterBenchmark("vemd/pipeline_Mono16", [fixture](benchmark::State& s) {
    pipelineOnly(fixture, s);
  })->Unit(benchmark::kMicrosecond);
}

}  // namespace vem::bench
