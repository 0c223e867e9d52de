#include "synthetic_recording.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "calib/io/camera_file.h"
#include "synth/default_camera.h"
#include "synth/synthetic_camera.h"

#ifndef VEMTOOL_VERSION
#define VEMTOOL_VERSION "unknown"
#endif

namespace vem::tool {

namespace fs = std::filesystem;

namespace {

// The writer's messages name the temporary file; the user knows only `to`.
std::string renamed(std::string message, const fs::path& from, const fs::path& to) {
  const std::string a = from.string(), b = to.string();
  for (std::size_t at = message.find(a); at != std::string::npos;
       at = message.find(a, at + b.size())) {
    message.replace(at, a.size(), b);
  }
  return message;
}

}  // namespace

std::expected<calib::CameraCalibration, std::string> loadRenderingCamera(
    const std::optional<std::string>& path) {
  auto camera = path ? calib::io::loadCameraFile(*path)
                     : calib::io::parseCameraFile(std::string(synth::exampleCameraToml()),
                                                  std::string(synth::kExampleCameraSource));
  if (!camera) return std::unexpected(camera.error().message);
  if (const auto problem = synth::syntheticCameraProblem(*camera)) {
    return std::unexpected(
        fmt::format("{}: {}", path ? *path : std::string(synth::kExampleCameraSource), *problem));
  }
  return std::move(*camera);
}

recording::RecordingHeader renderedRecordingHeader(const calib::CameraCalibration& camera,
                                                   double rateHz, const std::string& writerName) {
  recording::RecordingHeader header;
  header.cameraModel = camera.camera.model;
  header.cameraSerial = camera.camera.serial;
  header.sensorWidthPx = camera.camera.sensorWidthPx;
  header.sensorHeightPx = camera.camera.sensorHeightPx;
  header.pixelFormat = camera.camera.pixelFormat;
  header.nominalRateHz = rateHz;
  header.calibrationToml = calib::io::formatCameraFile(camera);
  header.createdUnixNs = std::chrono::duration_cast<std::chrono::nanoseconds>(
                             std::chrono::system_clock::now().time_since_epoch())
                             .count();
  header.writerName = writerName;
  header.writerVersion = VEMTOOL_VERSION;
  return header;
}

std::int64_t frameTimestampNs(std::uint64_t seq, double rateHz) {
  return std::llround(double(seq) * 1e9 / rateHz);
}

PendingRecording::PendingRecording(fs::path out, fs::path temporary,
                                   recording::RecordingWriter writer, bool overwrite)
    : out_(std::move(out)),
      temporary_(std::move(temporary)),
      writer_(std::move(writer)),
      overwrite_(overwrite) {}

PendingRecording::PendingRecording(PendingRecording&& other) noexcept
    : out_(std::move(other.out_)),
      temporary_(std::move(other.temporary_)),
      writer_(std::move(other.writer_)),
      overwrite_(other.overwrite_),
      committed_(other.committed_),
      bytes_(other.bytes_) {
  other.writer_.reset();
  other.temporary_.clear();
}

PendingRecording::~PendingRecording() {
  if (committed_ || temporary_.empty()) return;
  writer_.reset();
  std::error_code ignored;
  fs::remove(temporary_, ignored);
}

std::expected<PendingRecording, std::string> PendingRecording::create(
    const fs::path& out, const recording::RecordingHeader& header, bool overwrite) {
  std::error_code error;
  const fs::file_status status = fs::status(out, error);
  if (fs::is_directory(status)) {
    return std::unexpected(fmt::format("{}: a folder, not a recording file", out.string()));
  }
  if (fs::exists(status) && !overwrite) {
    return std::unexpected(fmt::format(
        "{}: a file is already there (refusing to overwrite it; --overwrite replaces it)",
        out.string()));
  }
  const fs::path folder = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::error_code createError;
  fs::create_directories(folder, createError);
  if (!fs::is_directory(folder, error)) {
    return std::unexpected(fmt::format("{}: cannot create the folder {} ({})", out.string(),
                                       folder.string(),
                                       createError ? createError.message() : "not a folder"));
  }
  const fs::path temporary =
      folder / fmt::format(".{}.partial-{}", out.filename().string(), ::getpid());
  recording::WriterOptions options;
  options.replaceExisting = true;  // a stale temporary of an earlier crash
  options.syncEveryFrames = 0;     // synced once, at close
  auto writer = recording::RecordingWriter::create(temporary, header, options);
  if (!writer) {
    fs::remove(temporary, error);
    return std::unexpected(renamed(writer.error().message, temporary, out));
  }
  return PendingRecording(out, temporary, std::move(*writer), overwrite);
}

std::string PendingRecording::aboutOut(std::string message) const {
  return renamed(std::move(message), temporary_, out_);
}

std::expected<void, std::string> PendingRecording::append(std::uint64_t seq,
                                                          std::int64_t timestampNs,
                                                          const RawFrame& frame) {
  if (auto appended = writer_->append(seq, timestampNs, frame); !appended) {
    return std::unexpected(aboutOut(appended.error().message));
  }
  return {};
}

std::uint64_t PendingRecording::bytesWritten() const {
  return committed_ || !writer_ ? bytes_ : writer_->bytesWritten();
}

std::expected<void, std::string> PendingRecording::commit() {
  if (auto closed = writer_->close(); !closed)
    return std::unexpected(aboutOut(closed.error().message));
  bytes_ = writer_->bytesWritten();
  writer_.reset();
  std::error_code error;
  if (!overwrite_ && fs::exists(out_, error)) {
    return std::unexpected(fmt::format(
        "{}: a file appeared there while recording (refusing to overwrite it)", out_.string()));
  }
  fs::rename(temporary_, out_, error);
  if (error) {
    return std::unexpected(fmt::format("{}: cannot move the finished recording into place ({})",
                                       out_.string(), error.message()));
  }
  committed_ = true;
  return {};
}

}  // namespace vem::tool
