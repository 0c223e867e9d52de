// `vemtool export F.vem --frame K --out FILE`: one recorded frame out of a VEM recording, either
// calibrated into an environment map with the recording's own calibration (the camera file in its
// header, docs/vem-format.md) or, with --raw, as the sensor's codes in an image.
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "calib/core/polar_remap.h"
#include "calib/io/camera_file.h"
#include "calib/io/raw_frame_file.h"
#include "commands.h"
#include "util/cli_value_names.h"
#include "mapio/map_file.h"
#include "recording/recording_reader.h"

namespace vem::tool {
namespace {

struct ExportOptions {
  std::string input;
  std::uint64_t seq = 0;
  std::string out;
  bool raw = false;
  int width = 1024;
  MapLayout layout = MapLayout::Hemisphere;
};


// Frame `seq` of the recording, or why it cannot be read.
std::expected<recording::RecordedFrame, std::string> readFrame(recording::RecordingReader& reader,
                                                               std::uint64_t seq) {
  const std::string path = reader.path().string();
  auto found = reader.seek(seq);
  if (!found) return std::unexpected(found.error().message);
  std::optional<recording::RecordedFrame> frame;
  if (*found) {
    auto next = reader.next();
    if (!next) return std::unexpected(next.error().message);
    frame = std::move(*next);
  }
  if (frame && frame->seq == seq) return std::move(*frame);
  auto summary = reader.summarize();
  if (!summary || !summary->firstSeq) {
    return std::unexpected(
        fmt::format("{}: no frame with sequence number {} (the recording "
                    "holds no intact frame)",
                    path, seq));
  }
  return std::unexpected(
      fmt::format("{}: no frame with sequence number {} (its {} frames run from {} to {})", path,
                  seq, summary->frames, *summary->firstSeq, *summary->lastSeq));
}

// The recording's calibration, with the sections a map needs.
std::expected<calib::CameraCalibration, std::string> recordedCalibration(
    const recording::RecordingReader& reader) {
  const std::string path = reader.path().string();
  const std::string& toml = reader.header().calibrationToml;
  if (toml.empty()) {
    return std::unexpected(fmt::format(
        "{}: the recording holds no calibration, so its frames cannot become maps (--raw writes "
        "the codes)",
        path));
  }
  auto calibration = calib::io::parseCameraFile(toml, path + " (its header's camera file)");
  if (!calibration) return std::unexpected(calibration.error().message);
  if (!calibration->photometric || !calibration->lens) {
    return std::unexpected(fmt::format(
        "{}: the recording's calibration lacks its {} section, so its frames cannot become maps",
        path, calibration->photometric ? "geometric" : "photometric"));
  }
  return std::move(*calibration);
}

int exportMap(const ExportOptions& o, const recording::RecordingReader& reader,
              const recording::RecordedFrame& recorded) {
  const auto calibration = recordedCalibration(reader);
  if (!calibration) return fail(calibration.error());
  const RawFrame& frame = recorded.frame;
  const int height = o.layout == MapLayout::Hemisphere ? o.width / 4 : o.width / 2;
  if (height < 1) return fail(fmt::format("--width {} leaves no rows for the map", o.width));
  const calib::PolarRemap remap =
      calib::buildPolarRemap(*calibration->lens, calibration->orientation, frame.width,
                             frame.height, o.layout, o.width, height);
  const calib::CodeToLuminanceLut lut = calib::buildCodeToLuminanceLut(
      *calibration->photometric, frame.format, frame.exposureUs, frame.gain);
  EnvMap map;
  calib::applyPolarRemap(remap, frame, lut, map);
  if (auto saved = mapio::saveMap(map, o.out); !saved) return fail(saved.error().message);
  const float brightest = map.rgb.empty() ? 0.0F : *std::ranges::max_element(map.rgb);
  std::cout << fmt::format(
      "wrote {}: frame {} ({:.3f} s) as a {} x {} {} map of radiance in cd/m2, calibrated with "
      "the recording's camera file; {:.1f} % of its pixels are seen by the lens (the rest are "
      "0); brightest channel value {:.4g} cd/m2\n",
      o.out, recorded.seq, double(recorded.captureTsNs) * 1e-9, map.width, map.height,
      layoutName(map.layout), 100.0 * remap.validFraction(), double(brightest));
  std::cout << fmt::format("next: vemtool lights --in {} --count 64\n", o.out);
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

int exportRaw(const ExportOptions& o, const recording::RecordedFrame& recorded) {
  const RawFrame& frame = recorded.frame;
  if (auto saved = calib::io::saveRawFrame(frame, o.out); !saved) {
    return fail(saved.error().message);
  }
  std::cout << fmt::format(
      "wrote {}: frame {} ({:.3f} s) as the sensor's codes, {} x {} {} (exposure {:g} us, gain "
      "{:g})\n",
      o.out, recorded.seq, double(recorded.captureTsNs) * 1e-9, frame.width, frame.height,
      pixelFormatName(frame.format), frame.exposureUs, frame.gain);
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

int runExport(const ExportOptions& o) {
  auto reader = recording::RecordingReader::open(o.input);
  if (!reader) return fail(reader.error().message);
  const auto recorded = readFrame(*reader, o.seq);
  if (!recorded) return fail(recorded.error());
  return o.raw ? exportRaw(o, *recorded) : exportMap(o, *reader, *recorded);
}

}  // namespace

void addExportCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ExportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "export", "Write one frame of a VEM recording as a calibrated map (or its raw codes)");
  cmd->footer(
      "Example:\n  vemtool export sky.vem --frame 12 --out sky-12.exr\n"
      "  vemtool lights --in sky-12.exr --count 64\n"
      "  vemtool export sky.vem --frame 12 --raw --out sky-12.png\n"
      "The map is calibrated with the camera file stored in the recording's header: codes through\n"
      "its response at the frame's own exposure and gain, the fisheye resampled into a polar\n"
      "(hemisphere, W x W/4) or equirectangular (sphere, W x W/2) map in cd/m2, bilinearly\n"
      "(docs/calibration.md); pixels the lens does not see are 0. --raw writes the codes as a\n"
      "16-bit PNG (8-bit for 8-bit sensors). The file is replaced only once complete.");
  cmd->add_option("file", o->input, "The recording (.vem)")->required();
  cmd->add_option("--frame", o->seq, "The frame's sequence number (synth and import count from 0)")
      ->required();
  cmd->add_option("--out", o->out, "File to write: .exr, .hdr or .pfm map; with --raw .png")
      ->required();
  cmd->add_flag("--raw", o->raw, "Write the raw sensor codes instead of a map");
  cmd->add_option("--width", o->width, "Map width in pixels (default 1024)")
      ->type_name(help::rangeName(4, mapio::kMaxMapWidth))
      ->check(help::quiet(CLI::Range(4, mapio::kMaxMapWidth)));
  const std::map<std::string, MapLayout> layouts{{"sphere", MapLayout::Sphere},
                                                 {"hemisphere", MapLayout::Hemisphere}};
  cmd->add_option("--layout", o->layout, "hemisphere (default: the camera's polar map) | sphere")
      ->transform(CLI::CheckedTransformer(layouts, CLI::ignore_case));
  cmd->callback([o, &exitCode] { exitCode = runExport(*o); });
}

}  // namespace vem::tool
