#include "recording_benchmarks.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "calib/core/camera_simulator.h"
#include "recording/frame_codec.h"
#include "recording/recording_reader.h"
#include "recording/recording_writer.h"
#include "support/test_cameras.h"
#include "support/test_maps.h"

namespace vem::bench {
namespace {

namespace fs = std::filesystem;

constexpr int kSensorWidth = 1280;
constexpr int kSensorHeight = 1024;
constexpr int kFramesInFile = 16;

// A simulated Mono16 frame of the procedural sky through the test camera's log response, with
// read noise (the same frame the calibration benchmarks use).
struct RecordingFixture {
  recording::RecordingHeader header;
  vem::RawFrame frame;
  fs::path dir;

  RecordingFixture() {
    calib::CameraCalibration camera = testing::cameraTruth(kSensorWidth, kSensorHeight, 1);
    camera.camera.pixelFormat = {1, 16};
    camera.photometric->saturationCode = camera.camera.pixelFormat.maxCode();
    calib::SimulationOptions options;
    options.supersamples = 1;
    options.noise = {2.0, 0.0, 1};
    frame = calib::simulateFrame(
        calib::radianceFromMap(testing::proceduralSky(MapLayout::Sphere, 512, 256)), camera,
        options);
    header.cameraModel = camera.camera.model;
    header.cameraSerial = camera.camera.serial;
    header.sensorWidthPx = kSensorWidth;
    header.sensorHeightPx = kSensorHeight;
    header.pixelFormat = camera.camera.pixelFormat;
    header.nominalRateHz = 30.0;
    header.writerName = "vem_bench";
    dir = fs::temp_directory_path() / ("vem_bench_recording_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  ~RecordingFixture() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
  RecordingFixture(const RecordingFixture&) = delete;
  RecordingFixture& operator=(const RecordingFixture&) = delete;
};

void registerRecording(const std::string& name, std::function<void(benchmark::State&)> body) {
  benchmark::RegisterBenchmark(("recording/" + name).c_str(), std::move(body))
      ->Unit(benchmark::kMicrosecond)
      ->ComputeStatistics("min", [](const std::vector<double>& v) {
        return *std::min_element(v.begin(), v.end());
      });
}

void readDecompress(const std::shared_ptr<RecordingFixture>& f, benchmark::State& state) {
  const fs::path path = f->dir / "read.vem";
  fs::remove(path);
  {
    auto writer = recording::RecordingWriter::create(path, f->header, {.syncEveryFrames = 0});
    if (!writer) return state.SkipWithError(writer.error().message.c_str());
    for (int i = 0; i < kFramesInFile; ++i) {
      if (!writer->append(std::uint64_t(i), i * 33'333'333LL, f->frame)) {
        return state.SkipWithError("cannot write the recording");
      }
    }
    (void)writer->close();
  }
  auto reader = recording::RecordingReader::open(path);
  if (!reader) return state.SkipWithError(reader.error().message.c_str());
  recording::RecordedFrame frame;
  for (auto _ : state) {
    auto got = reader->next(frame);
    if (got && !*got) {
      reader->rewind();
      got = reader->next(frame);
    }
    if (!got || !*got) return state.SkipWithError("cannot read the recording");
    benchmark::DoNotOptimize(frame.frame.codes.data());
  }
  state.counters["file_bytes_per_frame"] = double(fs::file_size(path)) / kFramesInFile;
  state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(f->frame.codes.size()) * 2);
}

void writeCompress(const std::shared_ptr<RecordingFixture>& f, benchmark::State& state) {
  const fs::path path = f->dir / "write.vem";
  std::optional<recording::RecordingWriter> writer;
  std::uint64_t seq = 0;
  for (auto _ : state) {
    if (!writer || writer->framesWritten() == kFramesInFile) {
      state.PauseTiming();  // a fresh file every few frames keeps the page cache small
      writer.reset();
      fs::remove(path);
      auto made = recording::RecordingWriter::create(path, f->header, {.syncEveryFrames = 0});
      if (!made) return state.SkipWithError(made.error().message.c_str());
      writer.emplace(std::move(*made));
      state.ResumeTiming();
    }
    if (!writer->append(seq, std::int64_t(seq) * 33'333'333LL, f->frame)) {
      return state.SkipWithError("cannot write the recording");
    }
    ++seq;
  }
  writer.reset();
  fs::remove(path);
}

void compressLevel(const std::shared_ptr<RecordingFixture>& f, int level, benchmark::State& state) {
  recording::FrameCodec codec(level);
  std::vector<std::byte> record;
  for (auto _ : state) {
    codec.encodeRecord(0, 0, f->frame, nullptr, record);
    benchmark::DoNotOptimize(record.data());
  }
  state.counters["ratio"] = double(f->frame.codes.size() * 2) / double(record.size());
  state.counters["record_bytes"] = double(record.size());
}

}  // namespace

void registerRecordingBenchmarks() {
  auto fixture = std::make_shared<RecordingFixture>();
  registerRecording("read_decompress_Mono16",
                    [fixture](benchmark::State& s) { readDecompress(fixture, s); });
  registerRecording("write_compress_Mono16",
                    [fixture](benchmark::State& s) { writeCompress(fixture, s); });
  for (int level : {-5, -1, 1, 3, 6}) {
    registerRecording("compress_level_" + std::to_string(level),
                      [fixture, level](benchmark::State& s) { compressLevel(fixture, level, s); });
  }
}

}  // namespace vem::bench
