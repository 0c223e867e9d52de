// `vemtool import`: a recording from real environments. Each equirectangular HDR map (an EXR
// sequence, say) or each frame of an equirectangular video is shown to a calibrated camera (the
// built-in example or --camera) through the synthetic camera, and the raw frames it would deliver
// are recorded (docs/vem-format.md, docs/synthetic-scenes.md).
#include <glob.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "commands.h"
#include "util/cli_value_names.h"
#include "mapio/map_file.h"
#include "synth/synthetic_camera.h"
#include "synthetic_recording.h"

namespace vem::tool {
namespace {

namespace fs = std::filesystem;

constexpr std::array<std::string_view, 8> kVideoExtensions = {".mp4", ".m4v",  ".mov", ".avi",
                                                              ".mkv", ".webm", ".mpg", ".mpeg"};

struct ImportOptions {
  std::vector<std::string> inputs;
  double rateHz = 0.0;
  std::optional<std::string> camera;
  std::string out;
  double scale = 1.0;
  double noiseCode = 0.0;
  std::uint64_t seed = 1;
  int samples = 1;
  bool overwrite = false;
};


bool isVideo(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::ranges::transform(extension, extension.begin(),
                         [](unsigned char c) { return char(std::tolower(c)); });
  return std::ranges::find(kVideoExtensions, extension) != kVideoExtensions.end();
}

// The inputs in order, each glob pattern (quoted past the shell) replaced by its sorted matches.
std::expected<std::vector<std::string>, std::string> expandInputs(
    const std::vector<std::string>& arguments) {
  std::vector<std::string> files;
  for (const std::string& argument : arguments) {
    std::error_code error;
    if (fs::exists(argument, error) || argument.find_first_of("*?[") == std::string::npos) {
      if (!fs::is_regular_file(argument, error)) {
        return std::unexpected(fmt::format("{}: no such file", argument));
      }
      files.push_back(argument);
      continue;
    }
    glob_t matches{};
    const int status = ::glob(argument.c_str(), 0, nullptr, &matches);
    for (std::size_t i = 0; status == 0 && i < matches.gl_pathc; ++i) {
      files.emplace_back(matches.gl_pathv[i]);
    }
    ::globfree(&matches);
    if (status != 0)
      return std::unexpected(fmt::format("{}: no file matches the pattern", argument));
  }
  return files;
}

// An equirectangular map from a video frame (8-bit BGR): values / 255, taken as linear.
std::expected<EnvMap, std::string> mapFromVideoFrame(const cv::Mat& frame, const std::string& path,
                                                     int index) {
  if (frame.channels() != 3 || frame.cols != 2 * frame.rows) {
    return std::unexpected(fmt::format(
        "{}: frame {} is {} x {} with {} channels (expected an equirectangular colour video, "
        "width = 2 x height)",
        path, index, frame.cols, frame.rows, frame.channels()));
  }
  cv::Mat linear;
  frame.convertTo(linear, CV_32FC3, frame.depth() == CV_16U ? 1.0 / 65535.0 : 1.0 / 255.0);
  EnvMap map = EnvMap::filled(MapLayout::Sphere, frame.cols, frame.rows, glm::vec3(0.0F));
  for (int y = 0; y < linear.rows; ++y) {
    const auto* row = linear.ptr<cv::Vec3f>(y);
    for (int x = 0; x < linear.cols; ++x) map.set(x, y, {row[x][2], row[x][1], row[x][0]});
  }
  return map;
}

std::expected<EnvMap, std::string> loadEquirectangular(const std::string& path) {
  auto map = mapio::loadMap(path, MapLayout::Sphere);
  if (!map) return std::unexpected(map.error().message);
  if (map->width != 2 * map->height) {
    return std::unexpected(
        fmt::format("{}: the map is {} x {}, not equirectangular (expected width = 2 x height)",
                    path, map->width, map->height));
  }
  return std::move(*map);
}

// Renders maps into the recording, numbering the frames.
class Importer {
 public:
  Importer(const ImportOptions& o, const calib::CameraCalibration& camera, PendingRecording& out)
      : options_(o), camera_(camera, {o.samples, {o.noiseCode, 0.0, o.seed}}), out_(out) {}

  std::expected<void, std::string> add(const EnvMap& map) {
    synth::SceneState state;
    state.radiance = [lookup = calib::radianceFromMap(map), scale = options_.scale](
                         const glm::dvec3& dir) { return scale * lookup(dir); };
    camera_.render(state, seq_, frame_);
    auto appended = out_.append(seq_, frameTimestampNs(seq_, options_.rateHz), frame_);
    ++seq_;
    return appended;
  }

  std::expected<void, std::string> addVideo(const std::string& path) {
    cv::VideoCapture video(path);
    if (!video.isOpened()) {
      return std::unexpected(
          fmt::format("{}: cannot open the video (OpenCV has no reader for it)", path));
    }
    cv::Mat frame;
    int index = 0;
    for (; video.read(frame); ++index) {
      const auto map = mapFromVideoFrame(frame, path, index);
      if (!map) return std::unexpected(map.error());
      if (auto added = add(*map); !added) return added;
    }
    if (index == 0)
      return std::unexpected(fmt::format("{}: the video has no frame OpenCV can read", path));
    return {};
  }

  [[nodiscard]] std::uint64_t frames() const { return seq_; }

 private:
  const ImportOptions& options_;
  synth::SyntheticCamera camera_;
  PendingRecording& out_;
  RawFrame frame_;
  std::uint64_t seq_ = 0;
};

int runImport(const ImportOptions& o) {
  const auto inputs = expandInputs(o.inputs);
  if (!inputs) return fail(inputs.error());
  const auto camera = loadRenderingCamera(o.camera);
  if (!camera) return fail(camera.error());
  auto pending = PendingRecording::create(
      o.out, renderedRecordingHeader(*camera, o.rateHz, "vemtool import"), o.overwrite);
  if (!pending) return fail(pending.error());
  Importer importer(o, *camera, *pending);
  for (const std::string& input : *inputs) {
    if (isVideo(input)) {
      if (auto added = importer.addVideo(input); !added) return fail(added.error());
      continue;
    }
    const auto map = loadEquirectangular(input);
    if (!map) return fail(map.error());
    if (auto added = importer.add(*map); !added) return fail(added.error());
  }
  if (auto committed = pending->commit(); !committed) return fail(committed.error());
  const calib::CameraIdentity& id = camera->camera;
  std::cout << fmt::format(
      "wrote {}: {} frames from {} files at {:g} Hz through {} ({} x {} {}), {} bytes\n", o.out,
      importer.frames(), inputs->size(), o.rateHz, id.model, id.sensorWidthPx, id.sensorHeightPx,
      pixelFormatName(id.pixelFormat), pending->bytesWritten());
  std::cout << fmt::format("next: vemtool export {} --frame 0 --out frame-0.exr\n", o.out);
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

}  // namespace

void addImportCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ImportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "import", "Record equirectangular HDR maps or video frames as a calibrated camera sees them");
  cmd->footer(
      "Example:\n  vemtool import --in ../shared/data/hdri/park.exr ../shared/data/hdri/sky.exr "
      "--rate 30 --out two.vem\n"
      "  vemtool import --in 'shots/frame-*.exr' --rate 24 --out shots.vem\n"
      "  vemtool import --in pano.mp4 --rate 30 --scale 100 --out pano.vem\n"
      "Each input, in order, becomes raw frames of the recording: an equirectangular map (.exr,\n"
      ".hdr, .pfm; width = 2 x height, values x --scale = cd/m2) is one frame; a video (.mp4,\n"
      ".mov, .avi, .mkv, .webm, ... read by OpenCV) gives one frame per video frame, its 8-bit\n"
      "values divided by 255 and TREATED AS LINEAR radiance (no sRGB decoding), times --scale.\n"
      "A quoted pattern is expanded in sorted order. Frames are numbered from 0 and stamped\n"
      "seq x 1e9 / rate ns. The recording appears at --out only once complete; on any error\n"
      "nothing is left there.");
  cmd->add_option("--in", o->inputs, "Maps, videos or quoted glob patterns, in order")
      ->required()
      ->expected(1, -1);
  cmd->add_option("--rate", o->rateHz, "Frames per second")->required()->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--out", o->out, "The recording to write (.vem)")->required();
  cmd->add_option(
      "--camera", o->camera,
      "Camera file to render through (default: the built-in config/camera-example.toml)");
  cmd->add_option("--scale", o->scale, "Input values times this are cd/m2 (default 1)")
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--noise", o->noiseCode, "Gaussian read noise in codes (default 0: exact codes)")
      ->check(help::quiet(CLI::NonNegativeNumber));
  cmd->add_option("--seed", o->seed, "Seed of the noise (default 1)");
  cmd->add_option("--samples", o->samples,
                  "Samples per pixel and axis (default 1: each pixel's centre)")
      ->type_name(help::rangeName(1, 8))
      ->check(help::quiet(CLI::Range(1, 8)));
  cmd->add_flag("--overwrite", o->overwrite, "Replace an existing --out");
  cmd->callback([o, &exitCode] { exitCode = runImport(*o); });
}

}  // namespace vem::tool
